// Per engine, every case that failed or hit an engine failure, as the person fixing the engine
// needs it: the findings, the picture (contour, stock, the engine's path over the expected one,
// the witnesses and the first divergence), the program and the command that reproduces it.
#include <vector>

#include "reports/html/html_text.h"
#include "reports/html/inline_plot.h"
#include "reports/html/report_fields.h"
#include "reports/html/sections.h"
#include "reports/html/verdict_style.h"
#include "reports/model/report_model.h"

namespace cyclecert::html {

namespace {

constexpr std::size_t kFindingsShown = 12;  // a path failing every pass repeats one finding per pass

std::string ruleLinks(const nlohmann::json& rules, const ReportIndex& index) {
  std::string out;
  for (const nlohmann::json& r : rules) {
    const std::string id = scalarText(r);
    const std::string anchor = index.anchorOfRule(id);
    out += (out.empty() ? "" : " ") +
           (anchor.empty() ? "<code>" + htmlEscape(id) + "</code>"
                           : "<a href=\"#" + anchor + "\"><code>" + htmlEscape(id) + "</code></a>");
  }
  return out.empty() ? "<span class=\"muted\">none</span>" : out;
}

std::string findingsList(const nlohmann::json& findings, const ReportIndex& index) {
  if (findings.empty()) return "";
  std::string out = "<ul class=\"findings\">\n";
  for (std::size_t i = 0; i < findings.size() && i < kFindingsShown; ++i) {
    const nlohmann::json& f = findings[i];
    const std::string move = textMember(f, "move");
    out += "<li><span class=\"oracle\">" + htmlEscape(textMember(f, "oracle", "finding")) + "</span>" +
           (move.empty() ? "" : " <span class=\"move\">move " + htmlEscape(move) + "</span>") + " " +
           htmlEscape(textMember(f, "message")) + " <span class=\"finding-rules\">" +
           ruleLinks(listMember(f, "rules"), index) + "</span></li>\n";
  }
  if (findings.size() > kFindingsShown) {
    out += "<li class=\"muted\">and " + std::to_string(findings.size() - kFindingsShown) +
           " more findings (in report.json)</li>\n";
  }
  return out + "</ul>\n";
}

// A <pre> drops one newline right after its start tag, so one is written to keep the text's own.
std::string preBlock(std::string_view cls, const std::string& text) {
  return "<pre class=\"" + std::string(cls) + "\">\n" + htmlEscape(text) + "</pre>\n";
}

struct PlotBudget {
  std::size_t left;
};

std::string plotFigure(const nlohmann::json& c, const FailureRef& f, PlotBudget& budget, std::size_t cap) {
  const nlohmann::json& plot = member(c, "plot");
  if (plot.is_null()) return "<p class=\"no-plot\">No plot recorded for this case.</p>\n";
  if (budget.left == 0) {
    return "<p class=\"no-plot\">Plot left out: this page draws at most " + std::to_string(cap) +
           " plots per engine (the plot is kept in report.json).</p>\n";
  }
  --budget.left;
  const DrawnPlot drawn = drawInlinePlot(plot, f.anchor, "plot of case " + textMember(c, "id"));
  if (!drawn.error.empty()) {
    return "<p class=\"plot-error\">The plot of this case could not be read: " + htmlEscape(drawn.error) + "</p>\n";
  }
  return "<figure class=\"plot\">" + drawn.svg + "</figure>\n";
}

std::string failureArticle(const nlohmann::json& c, const FailureRef& f, const ReportIndex& index,
                           PlotBudget& budget, std::size_t cap) {
  const std::string verdict = textMember(c, "verdict");
  const std::string seed = textMember(c, "seed");
  const std::string file = textMember(c, "file");
  const std::string detail = textMember(c, "detail");
  const std::string program = textMember(c, "program");
  const std::string reproduce = textMember(c, "reproduce");
  const bool expected = expectedFailure(c);
  std::string out = "<article class=\"failure " + std::string(verdictStyle(verdict).cssClass) +
                    (expected ? " v-expected" : "") + "\" id=\"" + f.anchor + "\">\n<header><a class=\"fid\" href=\"#" +
                    f.anchor + "\">F" + std::to_string(f.number) + "</a> " + verdictBadge(verdict) +
                    (expected ? " " + verdictBadge("expected-failure") : "") + " <code class=\"case-id\">" +
                    htmlEscape(textMember(c, "id")) + "</code> <span class=\"kind\">" +
                    htmlEscape(textMember(c, "kind", "case")) + "</span></header>\n";
  out += "<div class=\"failure-body\">\n<div class=\"failure-text\">\n<dl class=\"case-facts\">\n";
  if (expected) {
    const nlohmann::json& e = member(c, "expectation");
    out += "<dt>Expected</dt><dd>" + htmlEscape(textMember(e, "reason")) + " <span class=\"muted\">(" +
           htmlEscape(textMember(e, "source")) + ")</span></dd>\n";
  }
  out += "<dt>Rules</dt><dd>" + ruleLinks(listMember(c, "rules"), index) + "</dd>\n";
  if (!file.empty()) out += "<dt>File</dt><dd><code>" + htmlEscape(file) + "</code></dd>\n";
  if (!seed.empty()) out += "<dt>Seed</dt><dd><code>" + htmlEscape(seed) + "</code></dd>\n";
  out += "</dl>\n";
  if (!detail.empty()) out += "<p class=\"detail\">" + htmlEscape(detail) + "</p>\n";
  out += findingsList(listMember(c, "findings"), index);
  if (!program.empty()) out += "<h4>Program</h4>\n" + preBlock("program", program);
  out += "<h4>Reproduce</h4>\n";
  out += reproduce.empty() ? "<p class=\"muted\">No reproducing command recorded.</p>\n"
                           : preBlock("reproduce", reproduce);
  out += "</div>\n<div class=\"failure-plot\">\n" + plotFigure(c, f, budget, cap) + "</div>\n</div>\n";
  return out + "</article>\n";
}

std::string engineFailures(const EngineIndex& engine, std::size_t engineNumber, const ReportIndex& index,
                           std::size_t cap) {
  const nlohmann::json& cases = engine.cases();
  std::size_t withPlot = 0;
  std::size_t engineFailed = 0;
  std::vector<const FailureRef*> unexpected, expected;  // expected failures are shown apart, after the others
  for (const FailureRef& f : engine.failures) {
    if (!member(cases[f.caseIndex], "plot").is_null()) ++withPlot;
    if (textMember(cases[f.caseIndex], "verdict") == "engine-failure") ++engineFailed;
    (expectedFailure(cases[f.caseIndex]) ? expected : unexpected).push_back(&f);
  }
  std::string out = "<section class=\"engine-failures\" id=\"failures-" + std::to_string(engineNumber) +
                    "\">\n<h3>" + htmlEscape(engine.name) + " <span class=\"muted\">\u00b7 " +
                    std::to_string(engine.failures.size()) + " failure" + (engine.failures.size() == 1 ? "" : "s");
  if (engineFailed > 0) out += ", of which " + std::to_string(engineFailed) + " engine failure" + (engineFailed == 1 ? "" : "s");
  out += "</span></h3>\n";
  if (!expected.empty()) {
    out += "<p>" + verdictPill("expected-failure", expected.size()) + ", " + std::to_string(unexpected.size()) +
           " not expected. Expected failures are those the run's expectation file (--expectations) lists: they did "
           "not fail the run, and are listed after the others.</p>\n";
  }
  if (engine.failures.empty()) {
    return out + "<p class=\"muted\">No failure: every listed case passed or was not applicable.</p>\n</section>\n";
  }
  if (withPlot > cap) {
    out += "<p class=\"note\">This page draws the first " + std::to_string(cap) + " plots of this engine; " +
           std::to_string(withPlot - cap) + " plot" + (withPlot - cap == 1 ? " is" : "s are") +
           " left out (the failures are all listed, and every plot is kept in report.json).</p>\n";
  }
  PlotBudget budget{cap};
  for (const FailureRef* f : unexpected) out += failureArticle(cases[f->caseIndex], *f, index, budget, cap);
  if (!expected.empty()) {
    out += "<h4 class=\"expected-failures\">Expected failures \u00b7 " + std::to_string(expected.size()) + "</h4>\n";
  }
  for (const FailureRef* f : expected) out += failureArticle(cases[f->caseIndex], *f, index, budget, cap);
  return out + "</section>\n";
}

}  // namespace

std::string failuresSection(const nlohmann::json& /*report*/, const ReportIndex& index, std::size_t maxPlotsPerEngine) {
  std::string out = "<section id=\"failures\">\n<h2>Failures</h2>\n";
  out += "<p class=\"section-note\">Each case an engine failed or could not run, with its findings. The plot "
         "draws the finish contour, the rough contour (dashed orange), the stock, the engine's path (rapids "
         "dashed, feeds solid) over the expected path or the other engine's, each finding's witness in "
         "magenta, and the first divergence marked.</p>\n";
  for (std::size_t i = 0; i < index.engines.size(); ++i) {
    out += engineFailures(index.engines[i], i + 1, index, maxPlotsPerEngine);
  }
  return out + "</section>\n";
}

}  // namespace cyclecert::html
