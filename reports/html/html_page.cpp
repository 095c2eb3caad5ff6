// The document around the sections: doctype, charset, viewport, the inline style and script, a
// navigation bar; nothing is fetched (no link, no src), so the file opens anywhere, offline.
#include "reports/html/html_text.h"
#include "reports/html/page_style.h"
#include "reports/html/sections.h"

namespace cyclecert::html {

std::string htmlPage(std::string_view title, std::string_view body) {
  std::string out;
  out.reserve(body.size() + kPageStyle.size() + kPageScript.size() + 1024);
  out += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
         "<meta name=\"generator\" content=\"cyclecert\">\n<title>";
  out += htmlEscape(title);
  out += "</title>\n<style>";
  out += kPageStyle;
  out += "</style>\n</head>\n<body>\n<nav class=\"top\"><span class=\"brand\">cyclecert</span>"
         "<a href=\"#certification\">Certification</a><a href=\"#engines\">Engines</a>"
         "<a href=\"#matrix-section\">Matrix</a><a href=\"#failures\">Failures</a></nav>\n<main>\n";
  out += body;
  out += "</main>\n<script>";
  out += kPageScript;
  out += "</script>\n</body>\n</html>\n";
  return out;
}

}  // namespace cyclecert::html
