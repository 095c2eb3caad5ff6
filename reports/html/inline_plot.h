#pragma once
// A failure's plot (svg/plot_json.h) drawn by the toolpath plotter and made fit to sit inside the
// page: one report holds many plots, so their element ids get a per-plot prefix (ids must be unique
// in a document), and the XML declaration and namespace attribute, which inline SVG in HTML does not
// need, are dropped (the page then names no URL at all).
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace cyclecert::html {

struct DrawnPlot {
  std::string svg;    // the <svg> element, when the plot could be read
  std::string error;  // else why not (the plot reader names the field)
};

// Never throws: a plot that cannot be read or drawn comes back as an error to report in its place.
DrawnPlot drawInlinePlot(const nlohmann::json& plot, std::string_view idPrefix, std::string_view description);

// The plotter's standalone document turned into an inline <svg> element (exposed for the tests).
std::string inlineSvg(std::string document, std::string_view idPrefix, std::string_view description);

}  // namespace cyclecert::html
