// renderReportHtml: indexes the report once, then writes the sections in reading order.
#include "reports/html/report_html.h"

#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"
#include "reports/html/report_index.h"
#include "reports/html/sections.h"

namespace cyclecert {

namespace {

constexpr std::string_view kFormat = "cyclecert-report/1";

std::string pageTitle(const nlohmann::json& report, const html::ReportIndex& index) {
  std::string engines;
  for (const html::EngineIndex& e : index.engines) engines += (engines.empty() ? "" : ", ") + e.name;
  std::string title = "cyclecert report";
  if (!engines.empty()) title += " \u2014 " + engines;
  const std::string date = html::textMember(html::member(report, "certification"), "date");
  if (!date.empty()) title += " \u2014 " + date;
  return title;
}

// The page is drawn anyway; a reader is told when the document is not the format it was made for.
std::string formatWarning(const nlohmann::json& report) {
  const std::string format = html::textMember(report, "format");
  if (format == kFormat) return "";
  return "<p class=\"format-warning\">This document's format is \u201c" +
         html::htmlEscape(format.empty() ? "(none)" : format) + "\u201d; this page is written for " +
         std::string(kFormat) + ", so parts may be missing.</p>\n";
}

std::string footer(const nlohmann::json& report) {
  const std::string version = html::textMember(html::member(report, "certification"), "cyclecert_version", "unknown");
  return "<footer>Written by cyclecert " + html::htmlEscape(version) + " from report.json (" + std::string(kFormat) +
         "; reports/README.md). The page is self-contained: it loads nothing.</footer>\n";
}

}  // namespace

std::string renderReportHtml(const nlohmann::json& report) { return renderReportHtml(report, HtmlReportOptions{}); }

std::string renderReportHtml(const nlohmann::json& report, const HtmlReportOptions& options) {
  const html::ReportIndex index = html::indexReport(report);
  std::string body = formatWarning(report);
  body += html::certificationSection(report, index);
  body += html::engineSummarySection(report, index);
  body += html::metamorphicSection(report);
  body += html::matrixSection(report, index);
  body += html::failuresSection(report, index, options.maxPlotsPerEngine);
  body += footer(report);
  // Engines' text may be any bytes (an in-memory document is not checked); the file is UTF-8.
  return html::validUtf8(html::htmlPage(pageTitle(report, index), body));
}

}  // namespace cyclecert
