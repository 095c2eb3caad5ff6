#include "reports/html/inline_plot.h"

#include <exception>

#include "reports/html/html_text.h"
#include "reports/svg/plot_json.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert::html {

namespace {

void replaceFirst(std::string& s, std::string_view from, std::string_view to) {
  const auto at = s.find(from);
  if (at != std::string::npos) s.replace(at, from.size(), to);
}

void replaceAll(std::string& s, std::string_view from, std::string_view to) {
  for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) {
    s.replace(at, from.size(), to);
  }
}

}  // namespace

std::string inlineSvg(std::string document, std::string_view idPrefix, std::string_view description) {
  if (document.rfind("<?xml", 0) == 0) {
    const auto end = document.find("?>");
    document.erase(0, end == std::string::npos ? 0 : end + 2);
    if (!document.empty() && document.front() == '\n') document.erase(0, 1);
  }
  replaceFirst(document, " xmlns=\"http://www.w3.org/2000/svg\"", "");
  replaceFirst(document, "<svg ",
               "<svg class=\"plot-svg\" role=\"img\" aria-label=\"" + htmlEscape(description) + "\" ");
  // Text is escaped (a quote is &quot;), so ` id="` can only be markup.
  replaceAll(document, " id=\"", " id=\"" + std::string(idPrefix) + "-");
  return document;
}

DrawnPlot drawInlinePlot(const nlohmann::json& plot, std::string_view idPrefix, std::string_view description) {
  try {
    return {inlineSvg(renderToolpathSvg(plotFromJson(plot)), idPrefix, description), ""};
  } catch (const std::exception& e) {
    return {"", e.what()};
  }
}

}  // namespace cyclecert::html
