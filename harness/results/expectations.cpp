#include "harness/results/expectations.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace cyclecert {

using nlohmann::json;

namespace {

// ---- Matching -------------------------------------------------------------------------------------

// The rules a result fails: its findings', else the rules it cites (report_model.h's failedRules).
std::vector<std::string> rulesFailed(const CaseResult& r) {
  std::vector<std::string> rules;
  for (const Finding& f : r.findings) {
    for (const std::string& rule : f.rules) {
      if (std::find(rules.begin(), rules.end(), rule) == rules.end()) rules.push_back(rule);
    }
  }
  return rules.empty() ? r.rules : rules;
}

bool hasKind(const CaseResult& r, const std::string& kind, const std::string& wanted) {
  if (kind == wanted || (r.verdict == "engine-failure" && wanted == "engine-failure")) return true;
  return std::any_of(r.findings.begin(), r.findings.end(), [&](const Finding& f) { return f.oracle == wanted; });
}

bool covers(const Expectation& x, const CaseResult& r, const std::string& kind) {
  if (x.outcome != r.verdict) return false;
  switch (x.key) {
    case Expectation::Key::Case: return x.id == r.caseId;
    case Expectation::Key::Rule: {
      const auto rules = rulesFailed(r);
      return std::find(rules.begin(), rules.end(), x.id) != rules.end();
    }
    case Expectation::Key::Kind: return hasKind(r, kind, x.id);
  }
  return false;
}

std::string clipped(std::string text, std::size_t most) {
  if (text.size() <= most) return text;
  std::size_t cut = most;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return text.substr(0, cut) + "…";
}
}  // namespace

const char* statusName(ExpectationStatus s) {
  switch (s) {
    case ExpectationStatus::Expected: return "expected-failure";
    case ExpectationStatus::NewFailure: return "new-failure";
    case ExpectationStatus::UnexpectedPass: return "unexpected-pass";
    case ExpectationStatus::None: break;
  }
  return "";
}

ExpectationMatcher::ExpectationMatcher(const Expectations& expectations)
    : expectations_(expectations), used_(expectations.entries.size(), false) {}

const Expectation* ExpectationMatcher::matching(const CaseResult& r, const std::string& kind) const {
  for (const Expectation::Key key : {Expectation::Key::Case, Expectation::Key::Rule, Expectation::Key::Kind}) {
    for (const Expectation& x : expectations_.entries) {
      if (x.key == key && covers(x, r, kind)) return &x;
    }
  }
  return nullptr;
}

const Expectation* ExpectationMatcher::namingCase(const std::string& caseId) const {
  for (const Expectation& x : expectations_.entries) {
    if (x.key == Expectation::Key::Case && x.id == caseId) return &x;
  }
  return nullptr;
}

ExpectationStatus ExpectationMatcher::apply(CaseResult& r, const std::string& kind) {
  const bool failing = r.verdict == "fail" || r.verdict == "engine-failure";
  ExpectationStatus status = ExpectationStatus::None;
  const Expectation* entry = matching(r, kind);
  if (entry) status = ExpectationStatus::Expected;
  else if (failing) status = ExpectationStatus::NewFailure;
  else if ((entry = namingCase(r.caseId))) status = ExpectationStatus::UnexpectedPass;
  if (entry) used_[static_cast<std::size_t>(entry - expectations_.entries.data())] = true;
  if (status != ExpectationStatus::None) {
    r.expectation = ResultExpectation{statusName(status), entry ? entry->reason : "", entry ? entry->source : ""};
  }
  return status;
}

std::vector<const Expectation*> ExpectationMatcher::unused() const {
  std::vector<const Expectation*> out;
  for (std::size_t i = 0; i < used_.size(); ++i) {
    if (!used_[i]) out.push_back(&expectations_.entries[i]);
  }
  return out;
}

std::string unexpectedPassText(const CaseResult& r) {
  const std::string source = r.expectation ? r.expectation->source : std::string();
  return "unexpectedly passing: " + r.caseId + " is " + r.verdict + " now; " + source +
         " expects it to fail (remove the entry, or run `cyclecert baseline` again)";
}

std::string unusedExpectationText(const Expectation& x) {
  return "unexpectedly passing: " + x.source + " (" + keyName(x.key) + " " + x.id + ", " + x.outcome +
         ") matched no result of this run: " +
         (x.key == Expectation::Key::Case ? "its case is not among those run, or fails another way now" : "nothing fails that way any more") +
         " (remove the entry, or run `cyclecert baseline` again)";
}

std::string expectationCountsText(long expectedFailures, long unexpectedPasses) {
  std::string out;
  if (expectedFailures) out += ", " + std::to_string(expectedFailures) + " expected failure(s)";
  if (unexpectedPasses) out += ", " + std::to_string(unexpectedPasses) + " unexpectedly passing";
  return out;
}

Expectations baselineOf(const std::vector<json>& resultLines) {
  std::map<std::string, Expectation> byCase;  // sorted by case id
  for (const json& line : resultLines) {
    const std::string id = line.value("case", std::string()), verdict = line.value("verdict", std::string());
    if (verdict != "fail" && verdict != "engine-failure") {
      byCase.erase(id);  // a later pass replaces an earlier failure
      continue;
    }
    std::vector<std::string> kinds;
    for (const json& f : line.value("findings", json::array())) {
      const std::string oracle = f.value("oracle", std::string());
      if (!oracle.empty() && std::find(kinds.begin(), kinds.end(), oracle) == kinds.end()) kinds.push_back(oracle);
    }
    std::string reason;
    for (const std::string& k : kinds) reason += (reason.empty() ? "" : ", ") + k;
    if (reason.empty()) reason = verdict;
    reason += ": " + clipped(line.value("detail", std::string()), 200);
    byCase[id] = Expectation{Expectation::Key::Case, id, verdict, reason, ""};
  }
  Expectations out;
  for (auto& [id, x] : byCase) out.entries.push_back(std::move(x));
  return out;
}

Expectations baselineOfRun(const std::string& outDir, const std::string& engine) {
  const std::string file = outDir + "/results.jsonl";
  if (!std::filesystem::is_regular_file(file)) {
    throw std::invalid_argument("no results in '" + outDir + "' (expected " + file + ", written by check or fuzz)");
  }
  std::vector<json> lines;
  std::set<std::string> engines;
  for (const ResultLines::Line& line : readResultLines(file).lines) {
    engines.insert(line.key.first);
    if (engine.empty() || line.key.first == engine) lines.push_back(json::parse(line.text));
  }
  std::string names;
  for (const std::string& e : engines) names += (names.empty() ? "" : ", ") + e;
  if (!engine.empty() && !engines.count(engine)) {
    throw std::invalid_argument("no results of engine '" + engine + "' in " + file + " (it holds: " + names + ")");
  }
  if (engine.empty() && engines.size() > 1) {
    throw std::invalid_argument(file + " holds the results of several engines (" + names +
                                "); an expectation file is one engine's: give --engine NAME");
  }
  return baselineOf(lines);
}

}  // namespace cyclecert
