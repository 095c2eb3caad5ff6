#pragma once
// report.json (format cyclecert-report/1, reports/README.md; schema specs/schema/report.schema.json)
// from a run's results.jsonl lines, its run.json records and the rule catalogue. The lines are
// streamed: a fuzz campaign's million passes are counted, never kept. A later line for the same
// (engine, case) replaces an earlier one.
//
// Where the contract leaves room, this is what the document holds:
// - a case's kind: "fuzz" when its line has a seed; "regression" when its file lies in a
//   directory named "regressions" or its name (the id's last part) starts with "fuzz-" (a shrunk
//   failure kept by `fuzz`); else "spec";
// - an engine's "totals" count its spec and regression cases, "fuzz" its generated ones;
//   certification.totals adds up the engines' totals;
// - rule verdicts are drawn from the cases the report lists (spec, regression, and generated cases
//   that did not pass), so that every verdict has its cases behind it; a rule a case or finding
//   cites that is not in the catalogue is appended to "rules" with an empty cycle and section;
// - an engine's version, and the certification's versions, revision and suite hash, come from the
//   latest run record (by start) naming it; "unknown" without one, and date null.
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

namespace cyclecert {

// One rule of specs/rules.json, as the report lists it.
struct ReportRule {
  std::string id, cycle, seed, section, summary;
};

class ReportBuilder {
 public:
  ReportBuilder(std::vector<ReportRule> catalogue, std::vector<nlohmann::json> runs);

  // One results.jsonl line. Throws std::invalid_argument naming the field when it is not a result
  // (the caller counts and reports it).
  void add(const nlohmann::json& line);

  // Things kept out of the report with the reason (e.g. a plot that cannot be read).
  const std::vector<std::string>& warnings() const { return warnings_; }

  nlohmann::json build() const;

 private:
  enum Verdict : std::uint8_t { Pass, Fail, NotApplicable, EngineFailure };
  struct Counts {
    long cases = 0, byVerdict[4] = {0, 0, 0, 0};
    void add(Verdict v, long n) { cases += n, byVerdict[v] += n; }
  };
  struct Slot {
    Verdict verdict = Pass;
    std::optional<std::size_t> listed;  // index into EngineResults::cases
  };
  struct EngineResults {
    std::string name;
    std::vector<nlohmann::json> cases;  // listed cases in first-seen order; null once replaced by a pass
    std::map<std::string, Slot> suite;  // spec and regression cases by id
    std::unordered_map<std::uint64_t, Slot> fuzz;  // generated cases by seed (one per case id)
    Counts fuzzCounts;
  };

  EngineResults& engine(const std::string& name);
  std::string engineVersion(const std::string& name) const;
  const nlohmann::json* latestRun(const std::string& engine) const;  // the latest started; engine "" for any

  std::vector<ReportRule> rules_;
  std::vector<nlohmann::json> runs_;
  std::vector<EngineResults> engines_;
  std::map<std::string, std::size_t> engineIndex_;
  std::vector<std::string> warnings_;
};

// The whole report in one call, for inputs that fit in memory (tests, small runs).
nlohmann::json buildReport(const std::vector<nlohmann::json>& lines, const std::vector<nlohmann::json>& runs,
                           const std::vector<ReportRule>& catalogue);

// "spec", "regression" or "fuzz" for a results line (see above).
std::string caseKind(const nlohmann::json& line);

// Whether a report case failed as the run's expectation file said (its "expectation" status is
// "expected-failure"): the report shows it apart, and it did not fail the run.
bool expectedFailure(const nlohmann::json& reportCase);

// The rules a failing case fails: those its findings name, else — an unmet expectation — all the
// rules it cites. Takes a results line or a report case.
std::vector<std::string> failedRules(const nlohmann::json& failingCase);

}  // namespace cyclecert
