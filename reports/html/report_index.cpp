#include "reports/html/report_index.h"

#include <set>

#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"

namespace cyclecert::html {

const nlohmann::json& EngineIndex::cases() const { return listMember(*engine, "cases"); }

const FailureRef* EngineIndex::failureOf(const std::string& caseId) const {
  const auto it = failureByCaseId.find(caseId);
  return it == failureByCaseId.end() ? nullptr : &failures[it->second];
}

const nlohmann::json* EngineIndex::findCase(const std::string& caseId) const {
  const auto it = caseIndexById.find(caseId);
  return it == caseIndexById.end() ? nullptr : &cases()[it->second];
}

std::string ReportIndex::anchorOfRule(const std::string& ruleId) const {
  const auto it = ruleAnchor.find(ruleId);
  return it == ruleAnchor.end() ? std::string() : it->second;
}

bool isFailureVerdict(const std::string& verdict) {
  return verdict == "fail" || verdict == "engine-failure";
}

namespace {

// Rule IDs are already anchor-safe by the schema; anything else is made safe, and a clash between
// two made-safe IDs gets a numeric suffix so every link still leads to its own row.
std::map<std::string, std::string> ruleAnchors(const nlohmann::json& report) {
  std::map<std::string, std::string> anchors;
  std::set<std::string> taken;
  for (const nlohmann::json& rule : listMember(report, "rules")) {
    const std::string id = textMember(rule, "id");
    if (anchors.count(id)) continue;
    const std::string base = "rule-" + anchorName(id);
    std::string anchor = base;
    for (int n = 2; taken.count(anchor); ++n) anchor = base + "-" + std::to_string(n);
    taken.insert(anchor);
    anchors.emplace(id, anchor);
  }
  return anchors;
}

EngineIndex indexEngine(const nlohmann::json& engine, std::size_t engineNumber) {
  EngineIndex e;
  e.engine = &engine;
  e.name = textMember(engine, "name", "(unnamed engine)");
  for (const nlohmann::json& rule : listMember(engine, "rules")) e.ruleById.emplace(textMember(rule, "id"), &rule);
  const nlohmann::json& cases = e.cases();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string id = textMember(cases[i], "id");
    if (!e.caseIndexById.emplace(id, i).second) continue;  // a repeated id keeps its first entry
    if (!isFailureVerdict(textMember(cases[i], "verdict"))) continue;
    FailureRef f;
    f.caseIndex = i;
    f.number = static_cast<int>(e.failures.size()) + 1;
    f.anchor = "failure-" + std::to_string(engineNumber) + "-" + std::to_string(f.number);
    e.failureByCaseId.emplace(id, e.failures.size());
    e.failures.push_back(f);
  }
  return e;
}

}  // namespace

ReportIndex indexReport(const nlohmann::json& report) {
  ReportIndex index;
  index.ruleAnchor = ruleAnchors(report);
  const nlohmann::json& engines = listMember(report, "engines");
  for (std::size_t i = 0; i < engines.size(); ++i) index.engines.push_back(indexEngine(engines[i], i + 1));
  return index;
}

}  // namespace cyclecert::html
