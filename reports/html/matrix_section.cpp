// The rule × engine traceability matrix: one row per rule of the catalogue (grouped by cycle), one
// column per engine, each cell coloured and labelled by the engine's verdict on the rule, its
// cases listed in the tooltip and its failures linked (F<n>) to their sections below.
#include <algorithm>
#include <map>
#include <set>
#include <vector>

#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"
#include "reports/html/sections.h"
#include "reports/html/verdict_style.h"

namespace cyclecert::html {

namespace {

constexpr std::size_t kCaseIdsInTooltip = 20;
constexpr std::size_t kFailureLinksInCell = 8;

struct CycleGroup {
  std::string cycle;
  std::vector<const nlohmann::json*> rules;
};

// Cycles in the order they first appear in the catalogue, each with its rules in catalogue order
// (a rule listed twice is shown once: its row is the target of every link to it).
std::vector<CycleGroup> groupByCycle(const nlohmann::json& rules) {
  std::vector<CycleGroup> groups;
  std::map<std::string, std::size_t> position;
  std::set<std::string> seen;
  for (const nlohmann::json& rule : rules) {
    if (!seen.insert(textMember(rule, "id")).second) continue;
    const std::string cycle = textMember(rule, "cycle", "(no cycle)");
    auto [it, added] = position.emplace(cycle, groups.size());
    if (added) groups.push_back({cycle, {}});
    groups[it->second].rules.push_back(&rule);
  }
  return groups;
}

std::vector<std::string> stringList(const nlohmann::json& j, std::string_view key) {
  std::vector<std::string> out;
  for (const nlohmann::json& v : listMember(j, key)) out.push_back(scalarText(v));
  return out;
}

std::string idList(const std::vector<std::string>& ids) {
  std::string out;
  for (std::size_t i = 0; i < ids.size() && i < kCaseIdsInTooltip; ++i) out += (i ? ", " : "") + ids[i];
  if (ids.size() > kCaseIdsInTooltip) out += " and " + std::to_string(ids.size() - kCaseIdsInTooltip) + " more";
  return out;
}

// The cases a cell links to: those failing the rule, then those citing it that hit an engine failure.
std::vector<std::string> linkedCases(const EngineIndex& engine, const std::vector<std::string>& citing,
                                     const std::vector<std::string>& failing) {
  std::vector<std::string> linked = failing;
  for (const std::string& id : citing) {
    const nlohmann::json* c = engine.findCase(id);
    if (c && textMember(*c, "verdict") == "engine-failure" &&
        std::find(linked.begin(), linked.end(), id) == linked.end()) {
      linked.push_back(id);
    }
  }
  return linked;
}

std::string cellTooltip(const EngineIndex& engine, const std::string& ruleId, std::string_view label,
                        const std::vector<std::string>& citing, const std::vector<std::string>& failing) {
  std::string t = engine.name + " \u00b7 " + ruleId + ": " + std::string(label);
  if (citing.empty() && failing.empty()) return t + " (no case cites this rule)";
  t += " \u2014 " + std::to_string(citing.size()) + " case" + (citing.size() == 1 ? " cites" : "s cite") + " it";
  if (!failing.empty()) t += "; " + std::to_string(failing.size()) + " fail" + (failing.size() == 1 ? "s" : "") + " it: " + idList(failing);
  return citing.empty() ? t : t + "\nciting: " + idList(citing);
}

std::string matrixCell(const EngineIndex& engine, const std::string& ruleId) {
  const auto found = engine.ruleById.find(ruleId);
  static const nlohmann::json kNoVerdict;
  const nlohmann::json& entry = found == engine.ruleById.end() ? kNoVerdict : *found->second;
  const std::string verdict = found == engine.ruleById.end() ? "untested" : textMember(entry, "verdict");
  const VerdictStyle style = verdictStyle(verdict);
  const std::vector<std::string> citing = stringList(entry, "cases");
  const std::vector<std::string> failing = stringList(entry, "failing");

  std::string out = "<td class=\"cell " + std::string(style.cssClass) + "\" data-engine=\"" +
                    htmlEscape(engine.name) + "\" data-verdict=\"" + htmlEscape(verdict) + "\" title=\"" +
                    htmlEscape(cellTooltip(engine, ruleId, style.label, citing, failing)) + "\">";
  out += "<span class=\"sym\">" + std::string(style.symbol) + "</span> <span class=\"word\">" +
         std::string(style.shortLabel) + "</span>";
  // A failed cell names its failures by link; any other tells how many cases stand behind it.
  if (failing.empty() && !citing.empty()) out += " <span class=\"n\">" + std::to_string(citing.size()) + "</span>";
  std::vector<const FailureRef*> failures;
  for (const std::string& id : linkedCases(engine, citing, failing)) {
    if (const FailureRef* f = engine.failureOf(id)) failures.push_back(f);
  }
  std::string links;
  for (std::size_t i = 0; i < failures.size() && i < kFailureLinksInCell; ++i) {
    const nlohmann::json& c = engine.cases()[failures[i]->caseIndex];
    links += "<a href=\"#" + failures[i]->anchor + "\" title=\"" + htmlEscape(textMember(c, "id")) + "\">F" +
             std::to_string(failures[i]->number) + "</a> ";
  }
  if (failures.size() > kFailureLinksInCell) {
    links += "<span class=\"more\">+" + std::to_string(failures.size() - kFailureLinksInCell) + "</span>";
  }
  if (!links.empty()) out += "<span class=\"links\">" + links + "</span>";
  return out + "</td>";
}

std::string ruleRow(const nlohmann::json& rule, const ReportIndex& index) {
  const std::string id = textMember(rule, "id");
  bool nonconforming = false;
  std::string cells;
  for (const EngineIndex& engine : index.engines) {
    const auto found = engine.ruleById.find(id);
    const std::string verdict = found == engine.ruleById.end() ? "" : textMember(*found->second, "verdict");
    nonconforming = nonconforming || isFailureVerdict(verdict);
    cells += matrixCell(engine, id);
  }
  const std::string section = textMember(rule, "section");
  const std::string seed = textMember(rule, "seed");
  const std::string summary = textMember(rule, "summary");
  const std::string source = (seed.empty() ? "" : "seed " + seed + " \u00b7 ") + section;
  return "<tr class=\"rule\" id=\"" + index.anchorOfRule(id) + "\" data-rule=\"" + htmlEscape(id) +
         "\" data-nonconforming=\"" + (nonconforming ? "1" : "0") + "\"><th scope=\"row\" class=\"rule-id\" title=\"" +
         htmlEscape(source) + "\"><code>" + htmlEscape(id) + "</code></th><td class=\"summary\" title=\"" +
         htmlEscape(summary + (source.empty() ? "" : "\n(" + source + ")")) + "\">" + htmlEscape(summary) +
         "</td>" + cells + "</tr>\n";
}

std::string legend() {
  std::string out = "<p class=\"legend\">";
  for (const char* v : {"pass", "fail", "engine-failure", "not-applicable", "untested"}) {
    const VerdictStyle s = verdictStyle(v);
    out += "<span class=\"key cell " + std::string(s.cssClass) + "\"><span class=\"sym\">" + std::string(s.symbol) +
           "</span> " + std::string(s.label) + "</span> ";
  }
  return out + "<span class=\"legend-note\">A number counts the cases citing the rule; <b>F<i>n</i></b> links to a "
               "failure of the rule (or an engine failure) below; hover a cell for its cases.</span></p>\n";
}

// Shown only when the script runs (html.js); the matrix is complete without it.
std::string toolbar(std::size_t rules) {
  return "<div class=\"toolbar\"><label><input type=\"checkbox\" id=\"matrix-only-nonconforming\"> only rules "
         "some engine does not conform to</label> <input type=\"search\" id=\"matrix-filter\" "
         "placeholder=\"filter rules (ID or text)\" aria-label=\"filter rules\"> <span id=\"matrix-shown\" "
         "class=\"muted\">" + std::to_string(rules) + " rules</span></div>\n";
}

}  // namespace

std::string matrixSection(const nlohmann::json& report, const ReportIndex& index) {
  const nlohmann::json& rules = listMember(report, "rules");
  std::string out = "<section id=\"matrix-section\">\n<h2>Rule \u00d7 engine traceability matrix</h2>\n";
  out += legend() + toolbar(rules.size());
  out += "<div class=\"matrix-wrap\"><table id=\"matrix\" class=\"matrix\">\n<thead><tr><th scope=\"col\">Rule</th>"
         "<th scope=\"col\">Summary</th>";
  for (const EngineIndex& e : index.engines) {
    out += "<th scope=\"col\" class=\"engine\" data-engine=\"" + htmlEscape(e.name) + "\">" + htmlEscape(e.name) + "</th>";
  }
  out += "</tr></thead>\n";
  const std::string span = std::to_string(index.engines.size() + 2);
  for (const CycleGroup& group : groupByCycle(rules)) {
    out += "<tbody class=\"cycle-group\" data-cycle=\"" + htmlEscape(group.cycle) + "\">\n<tr class=\"cycle\"><th colspan=\"" +
           span + "\">" + htmlEscape(group.cycle) + " <span class=\"muted\">\u00b7 " + std::to_string(group.rules.size()) +
           " rule" + (group.rules.size() == 1 ? "" : "s") + "</span></th></tr>\n";
    for (const nlohmann::json* rule : group.rules) out += ruleRow(*rule, index);
    out += "</tbody>\n";
  }
  if (rules.empty()) {
    out += "<tbody><tr><td colspan=\"" + span + "\" class=\"muted\">The report lists no rule.</td></tr></tbody>\n";
  }
  return out + "</table></div>\n</section>\n";
}

}  // namespace cyclecert::html
