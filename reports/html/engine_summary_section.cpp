// The summary per engine: one row per engine, so that engines compare down a column, with three
// column groups — spec and regression cases, the fuzz campaign (with its seeds), rule verdicts.
#include <algorithm>
#include <map>
#include <vector>

#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"
#include "reports/html/sections.h"
#include "reports/html/verdict_style.h"
#include "reports/model/report_model.h"

namespace cyclecert::html {

namespace {

constexpr std::size_t kSeedsShown = 6;  // a long campaign's seeds stay in report.json

struct VerdictCount {
  const char* verdict;
  const char* field;  // its count's name in "totals" and "fuzz"
};
constexpr VerdictCount kCaseVerdicts[] = {
    {"pass", "pass"}, {"fail", "fail"}, {"engine-failure", "engine_failure"}, {"not-applicable", "not_applicable"}};
constexpr const char* kRuleVerdicts[] = {"pass", "fail", "engine-failure", "not-applicable", "untested"};

std::string countCell(std::string_view verdict, std::uint64_t n, bool groupStart = false) {
  const VerdictStyle s = verdictStyle(verdict);
  return "<td class=\"num " + std::string(s.cssClass) + (n == 0 ? " zero" : "") + (groupStart ? " group-start" : "") +
         "\">" + std::to_string(n) + "</td>";
}

std::string verdictHead(std::string_view verdict) {
  const VerdictStyle s = verdictStyle(verdict);
  return "<th scope=\"col\" class=\"num\" title=\"" + std::string(s.label) + "\"><span class=\"sym " +
         std::string(s.cssClass) + "\">" + std::string(s.symbol) + "</span> " + std::string(s.shortLabel) + "</th>";
}

std::string header() {
  std::string out =
      "<thead><tr><th rowspan=\"2\" scope=\"col\">Engine</th>"
      "<th colspan=\"5\" class=\"group-start\">Spec and regression cases</th>"
      "<th colspan=\"6\" class=\"group-start\">Fuzz campaign <span class=\"muted\">(passes counted, not listed)</span></th>"
      "<th colspan=\"5\" class=\"group-start\">Rules</th><th rowspan=\"2\" class=\"group-start\">Failures</th></tr>\n<tr>";
  for (int group = 0; group < 2; ++group) {
    out += "<th scope=\"col\" class=\"num group-start\">cases</th>";
    for (const VerdictCount& v : kCaseVerdicts) out += verdictHead(v.verdict);
    if (group == 1) out += "<th scope=\"col\">seeds</th>";
  }
  bool first = true;
  for (const char* v : kRuleVerdicts) {
    std::string head = verdictHead(v);
    if (first) head.replace(head.find("class=\"num\""), 11, "class=\"num group-start\"");
    out += head;
    first = false;
  }
  return out + "</tr></thead>\n";
}

std::string caseCounts(const nlohmann::json& counts) {
  std::string out = "<td class=\"num total group-start\">" + std::to_string(countMember(counts, "cases")) + "</td>";
  for (const VerdictCount& v : kCaseVerdicts) out += countCell(v.verdict, countMember(counts, v.field));
  return out;
}

std::string seedsCell(const nlohmann::json& fuzz) {
  const nlohmann::json& seeds = listMember(fuzz, "seeds");
  if (seeds.empty()) return "<td class=\"seeds muted\">none</td>";
  std::string out = "<td class=\"seeds\">";
  for (std::size_t i = 0; i < seeds.size() && i < kSeedsShown; ++i) {
    out += (i ? " " : "") + std::string("<code>") + htmlEscape(scalarText(seeds[i])) + "</code>";
  }
  if (seeds.size() > kSeedsShown) {
    out += " <span class=\"muted\">and " + std::to_string(seeds.size() - kSeedsShown) + " more</span>";
  }
  return out + "</td>";
}

std::string ruleCounts(const EngineIndex& e) {
  std::map<std::string, std::uint64_t> counts;
  for (const nlohmann::json& rule : listMember(*e.engine, "rules")) ++counts[textMember(rule, "verdict")];
  std::string out;
  bool first = true;
  for (const char* v : kRuleVerdicts) {
    out += countCell(v, counts[v], first);
    first = false;
  }
  return out;
}

// " (3 expected)" when the run's expectation file expected some of the failures.
std::string expectedNote(const EngineIndex& e) {
  const auto n = std::count_if(e.failures.begin(), e.failures.end(),
                               [&](const FailureRef& f) { return expectedFailure(e.cases()[f.caseIndex]); });
  return n == 0 ? "" : " <span class=\"muted\">(" + std::to_string(n) + " expected)</span>";
}

std::string engineRow(const EngineIndex& e) {
  const std::string version = textMember(*e.engine, "version");
  std::string out = "<tr><th scope=\"row\" class=\"engine\">" + htmlEscape(e.name) +
                    (version.empty() ? "" : "<div class=\"version\">" + htmlEscape(version) + "</div>") + "</th>";
  out += caseCounts(member(*e.engine, "totals"));
  out += caseCounts(member(*e.engine, "fuzz")) + seedsCell(member(*e.engine, "fuzz"));
  out += ruleCounts(e);
  out += "<td class=\"num group-start\">" +
         (e.failures.empty() ? std::string("<span class=\"muted\">none</span>")
                             : "<a href=\"#" + e.failures.front().anchor + "\">" + std::to_string(e.failures.size()) +
                                   " \u2193</a>" + expectedNote(e)) +
         "</td></tr>\n";
  return out;
}

}  // namespace

std::string engineSummarySection(const nlohmann::json& /*report*/, const ReportIndex& index) {
  std::string out = "<section id=\"engines\">\n<h2>Summary per engine</h2>\n";
  if (index.engines.empty()) return out + "<p class=\"muted\">No engine in this report.</p>\n</section>\n";
  out += "<div class=\"table-wrap\"><table class=\"engine-summary\">\n" + header() + "<tbody>\n";
  for (const EngineIndex& e : index.engines) out += engineRow(e);
  return out + "</tbody></table></div>\n</section>\n";
}

}  // namespace cyclecert::html
