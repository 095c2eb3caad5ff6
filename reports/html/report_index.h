#pragma once
// What several sections must agree on, worked out once before any is written: the anchor of each
// rule's matrix row, and per engine the numbering and anchors of its failures (F1, F2, … in report
// order), so that the certification summary, the matrix and the failure sections link to the same
// places.
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace cyclecert::html {

struct FailureRef {
  std::size_t caseIndex = 0;  // in the engine's "cases"
  int number = 0;             // F<number>, from 1 per engine
  std::string anchor;         // "failure-<engine number>-<number>"
};

struct EngineIndex {
  const nlohmann::json* engine = nullptr;
  std::string name;
  std::map<std::string, std::size_t> caseIndexById;   // id → index in "cases"
  std::map<std::string, const nlohmann::json*> ruleById;  // id → the engine's verdict entry
  std::vector<FailureRef> failures;                    // cases with verdict fail or engine-failure
  std::map<std::string, std::size_t> failureByCaseId;  // id → index in failures

  const nlohmann::json& cases() const;
  // The failure of that case, or nullptr when it did not fail (or is not listed).
  const FailureRef* failureOf(const std::string& caseId) const;
  // The case object with that id, or nullptr.
  const nlohmann::json* findCase(const std::string& caseId) const;
};

struct ReportIndex {
  std::vector<EngineIndex> engines;             // report["engines"] order
  std::map<std::string, std::string> ruleAnchor;  // rule id → unique "rule-…" anchor

  std::string anchorOfRule(const std::string& ruleId) const;  // "" for a rule not in report["rules"]
};

ReportIndex indexReport(const nlohmann::json& report);

// Whether a case's verdict puts it in the failure sections.
bool isFailureVerdict(const std::string& verdict);

}  // namespace cyclecert::html
