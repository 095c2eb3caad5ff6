#pragma once
// index.html: the report for people, drawn from report.json's document alone (reports/README.md)
// as one self-contained HTML5 file — no network, no external script, style, font or image; inline
// CSS and a little inline script (matrix filtering) that the page does not need to be read.
//
// In order: the certification summary (engines and versions, cyclecert version and revision, spec
// suite hash, date, totals, the rules not conformed to); a summary per engine (case and fuzz
// counts, seeds, rule verdicts); the rule × engine traceability matrix (rows by cycle, a cell per
// engine coloured and labelled by verdict, linking the failures behind it); then per engine each
// failed or engine-failed case with its findings, an inline SVG plot, the program and the command
// that reproduces it.
//
// Deterministic (the same report gives the same bytes), every piece of report text escaped, never
// throws on a report with missing or malformed parts (a plot that cannot be read is reported in its
// place).
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

namespace cyclecert {

struct HtmlReportOptions {
  // Plots drawn per engine; later failures are listed without one (each plot is ~10-20 KB, so a
  // campaign with a thousand failures still gives a page a browser opens at once).
  std::size_t maxPlotsPerEngine = 40;
};

std::string renderReportHtml(const nlohmann::json& report);
std::string renderReportHtml(const nlohmann::json& report, const HtmlReportOptions& options);

}  // namespace cyclecert
