#pragma once
// Expectation files (`check`/`fuzz --expectations FILE`, written by `cyclecert baseline`): the
// failures an engine is known to have — a dialect it speaks, a defect filed elsewhere — so that a
// nightly run goes red only on something new. README "Expectation files" documents the formats:
//
//   JSON:  {"expectations": [{"case": ID | "rule": RULE-ID | "kind": KIND,
//                             "outcome": "fail" | "engine-failure" | "not-applicable",
//                             "reason": "…"}]}          (a bare array of the entries is read too)
//   text:  one entry a line, `ID OUTCOME # reason`; `rule:RULE-ID` / `kind:KIND` for the other keys;
//          blank lines and lines starting with # are skipped.
//
// A result matches an entry when its verdict is the entry's outcome and: its case id is the
// entry's case; or (rule) a rule it fails — the rules its findings name, else the rules it cites —
// is the entry's rule; or (kind) the kind of its failure (the oracle of a finding, "diverges",
// "expected-alarm", "engine-failure") is the entry's kind.
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/results/results_file.h"

namespace cyclecert {

struct Expectation {
  enum class Key { Case, Rule, Kind };
  Key key = Key::Case;
  std::string id;       // the case id, rule id or failure kind
  std::string outcome;  // "fail", "engine-failure" or "not-applicable"
  std::string reason;
  std::string source;   // FILE:LINE (text) or FILE: /expectations/N (JSON), for messages
};

const char* keyName(Expectation::Key k);  // "case", "rule", "kind"

struct Expectations {
  std::string file;
  std::vector<Expectation> entries;
};

// A malformed expectation file: the message names the file and line:column or JSON path, what was
// expected and what would be accepted. `cyclecert` exits 2 on it.
struct ExpectationsError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The file read: JSON when its first non-blank character is `{` or `[`, else the text list.
Expectations readExpectations(const std::string& path);
Expectations parseExpectations(const std::string& text, const std::string& file);

// What an expectation file makes of one result (the `expectation` field of its results line).
enum class ExpectationStatus {
  None,            // no entry concerns it (a pass, or a not-applicable case nobody expected)
  Expected,        // it fails as an entry says: reported apart, does not fail the run
  NewFailure,      // it fails, and no entry covers that: fails the run
  UnexpectedPass,  // an entry names its case, and it no longer fails that way (it passes, or is not applicable)
};
const char* statusName(ExpectationStatus s);  // "expected-failure", "new-failure", "unexpected-pass", ""

// Judges `r` (its failure `kind` as fuzz names it; "" to take its findings' oracles), sets
// r.expectation and returns the status. Records which entries were used.
class ExpectationMatcher {
 public:
  explicit ExpectationMatcher(const Expectations& expectations);
  ExpectationStatus apply(CaseResult& r, const std::string& kind = "");
  // The entries that matched no result so far (for `check`: stale entries).
  std::vector<const Expectation*> unused() const;

 private:
  const Expectation* matching(const CaseResult& r, const std::string& kind) const;
  const Expectation* namingCase(const std::string& caseId) const;

  const Expectations& expectations_;
  std::vector<bool> used_;
};

// The warnings a run prints: a result an entry names that no longer fails that way (r.expectation
// set by apply()), and an entry that matched no result of a whole run.
std::string unexpectedPassText(const CaseResult& r);
std::string unusedExpectationText(const Expectation& x);

// ", 3 expected failure(s), 1 unexpectedly passing" for a run's summary line ("" for none of either).
std::string expectationCountsText(long expectedFailures, long unexpectedPasses);

// An expectation file for the failures in a run's results lines (`cyclecert baseline`): every
// failing and engine-failure result, by case id, with a reason naming its finding kinds and first
// detail. A later line for the same (engine, case) replaces an earlier one.
Expectations baselineOf(const std::vector<nlohmann::json>& resultLines);
// The same for the run in `outDir` (its results.jsonl), of `engine` — "" when the run has one
// engine. Throws std::invalid_argument when there are no results, or several engines and none named.
Expectations baselineOfRun(const std::string& outDir, const std::string& engine);
std::string expectationsJson(const Expectations& e);  // the JSON format, pretty-printed
std::string expectationsText(const Expectations& e);  // the text format

}  // namespace cyclecert
