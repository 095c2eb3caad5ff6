#include "reports/model/report_model.h"

#include <algorithm>
#include <filesystem>
#include <set>
#include <stdexcept>

#include "reports/svg/plot_json.h"

namespace cyclecert {

using nlohmann::json;

namespace {

const char* const kVerdictNames[] = {"pass", "fail", "not-applicable", "engine-failure"};

// A whole number ≥ 0: read from text it is unsigned, built in code it may be signed.
bool isCount(const json& j) {
  return j.is_number_unsigned() || (j.is_number_integer() && j.get<std::int64_t>() >= 0);
}

[[noreturn]] void invalid(const std::string& field, const std::string& expected) {
  throw std::invalid_argument("/" + field + ": expected " + expected);
}

std::string stringField(const json& line, const char* key) {
  if (!line.contains(key) || !line[key].is_string()) invalid(key, "a string");
  return line[key].get<std::string>();
}

// An optional field of the given JSON type, or `fallback` when it is absent or null.
json optionalField(const json& line, const char* key, json::value_t type, const char* expected, json fallback) {
  if (!line.contains(key) || line[key].is_null()) return fallback;
  const json& value = line[key];
  const bool numeric = type == json::value_t::number_float && value.is_number();
  if (value.type() != type && !numeric) invalid(key, expected);
  return value;
}

std::optional<std::uint64_t> seedOf(const json& line) {
  if (!line.contains("seed") || line["seed"].is_null()) return std::nullopt;
  const json& seed = line["seed"];
  if (!isCount(seed)) invalid("seed", "a whole number from 0 to 2^64-1, or null");
  return seed.get<std::uint64_t>();
}

std::vector<std::string> stringList(const json& value, const std::string& field) {
  std::vector<std::string> out;
  if (value.is_null()) return out;
  if (!value.is_array()) invalid(field, "an array of strings");
  for (const json& item : value) {
    if (!item.is_string()) invalid(field, "an array of strings");
    out.push_back(item.get<std::string>());
  }
  return out;
}

// A finding as the report keeps it: its witness is in the plot.
json reportFinding(const json& finding, std::size_t i) {
  const std::string where = "findings/" + std::to_string(i);
  if (!finding.is_object()) invalid(where, "a finding object");
  json out{{"oracle", finding.value("oracle", std::string())},
           {"rules", stringList(finding.value("rules", json::array()), where + "/rules")},
           {"message", finding.value("message", std::string())}};
  if (finding.contains("move") && isCount(finding["move"])) out["move"] = finding["move"];
  return out;
}

constexpr const char* kExpectationStatuses[] = {"expected-failure", "new-failure", "unexpected-pass"};

// What a run's expectation file made of the case (harness/results/expectations.h), as the report keeps it.
json reportExpectation(const json& value) {
  if (!value.is_object()) invalid("expectation", "an object {\"status\", \"reason\"?, \"source\"?}");
  const std::string status = value.contains("status") && value["status"].is_string() ? value["status"].get<std::string>() : "";
  if (std::find(std::begin(kExpectationStatuses), std::end(kExpectationStatuses), status) == std::end(kExpectationStatuses)) {
    invalid("expectation/status", "expected-failure, new-failure or unexpected-pass");
  }
  json out{{"status", status}};
  for (const char* key : {"reason", "source"}) {
    if (value.contains(key) && value[key].is_string() && !value[key].get<std::string>().empty()) out[key] = value[key];
  }
  return out;
}

// Per engine, how many listed cases each expectation status has; null when none has one.
json expectationCounts(const std::vector<const json*>& cases) {
  long counts[3] = {0, 0, 0};
  bool any = false;
  for (const json* c : cases) {
    if (!c->contains("expectation")) continue;
    const std::string status = (*c)["expectation"]["status"];
    const auto at = std::find(std::begin(kExpectationStatuses), std::end(kExpectationStatuses), status);
    ++counts[at - std::begin(kExpectationStatuses)];
    any = true;
  }
  if (!any) return nullptr;
  return {{"expected_failure", counts[0]}, {"new_failure", counts[1]}, {"unexpected_pass", counts[2]}};
}

struct RuleTally {
  std::vector<std::string> cases, failing;
  bool engineFailure = false, pass = false, notApplicable = false;
  std::string verdict() const {
    if (!failing.empty()) return "fail";
    if (engineFailure) return "engine-failure";
    if (pass) return "pass";
    if (notApplicable) return "not-applicable";
    return "untested";
  }
};

json totalsJson(long cases, const long (&byVerdict)[4]) {
  return {{"cases", cases}, {"pass", byVerdict[0]}, {"fail", byVerdict[1]}, {"not_applicable", byVerdict[2]},
          {"engine_failure", byVerdict[3]}};
}

}  // namespace

bool expectedFailure(const json& c) {
  return c.contains("expectation") && c["expectation"].is_object() &&
         c["expectation"].value("status", std::string()) == "expected-failure";
}

std::string caseKind(const json& line) {
  if (line.contains("seed") && !line["seed"].is_null()) return "fuzz";
  const std::string id = line.value("case", std::string());
  const std::string name = id.substr(id.rfind('/') == std::string::npos ? 0 : id.rfind('/') + 1);
  if (name.rfind("fuzz-", 0) == 0) return "regression";
  const json& file = line.contains("file") && line["file"].is_string() ? line["file"] : json("");
  for (const auto& part : std::filesystem::path(file.get<std::string>()).parent_path()) {
    if (part == "regressions") return "regression";
  }
  return "spec";
}

std::vector<std::string> failedRules(const json& failingCase) {
  std::vector<std::string> rules;
  for (const json& f : failingCase.value("findings", json::array())) {
    for (const json& r : f.value("rules", json::array())) {
      const std::string id = r.get<std::string>();
      if (std::find(rules.begin(), rules.end(), id) == rules.end()) rules.push_back(id);
    }
  }
  if (rules.empty()) rules = failingCase.value("rules", std::vector<std::string>{});
  return rules;
}

ReportBuilder::ReportBuilder(std::vector<ReportRule> catalogue, std::vector<json> runs)
    : rules_(std::move(catalogue)), runs_(std::move(runs)) {}

ReportBuilder::EngineResults& ReportBuilder::engine(const std::string& name) {
  const auto [it, inserted] = engineIndex_.try_emplace(name, engines_.size());
  if (inserted) engines_.push_back(EngineResults{name, {}, {}, {}, {}});
  return engines_[it->second];
}

void ReportBuilder::add(const json& line) {
  if (!line.is_object()) throw std::invalid_argument("expected a result object");
  const std::string engineName = stringField(line, "engine");
  const std::string caseId = stringField(line, "case");
  const std::string verdictText = stringField(line, "verdict");
  const auto known = std::find(std::begin(kVerdictNames), std::end(kVerdictNames), verdictText);
  if (known == std::end(kVerdictNames)) invalid("verdict", "pass, fail, not-applicable or engine-failure");
  const Verdict verdict = static_cast<Verdict>(known - std::begin(kVerdictNames));
  const std::optional<std::uint64_t> seed = seedOf(line);
  const std::string kind = caseKind(line);
  const bool listed = kind != "fuzz" || verdict != Pass;

  json reportCase;  // built only for a case the report lists: passes of a campaign are only counted
  if (listed) {
    reportCase = {{"id", caseId},
                  {"kind", kind},
                  {"file", optionalField(line, "file", json::value_t::string, "a string", "")},
                  {"rules", stringList(line.value("rules", json::array()), "rules")},
                  {"verdict", verdictText},
                  {"detail", optionalField(line, "detail", json::value_t::string, "a string", "")},
                  {"findings", json::array()},
                  {"seconds", optionalField(line, "seconds", json::value_t::number_float, "a number", 0.0)}};
    const json findings = optionalField(line, "findings", json::value_t::array, "an array of findings", json::array());
    for (std::size_t i = 0; i < findings.size(); ++i) reportCase["findings"].push_back(reportFinding(findings[i], i));
    if (seed) reportCase["seed"] = *seed;
    for (const char* key : {"program", "reproduce"}) {
      const json value = optionalField(line, key, json::value_t::string, "a string", "");
      if (!value.get<std::string>().empty()) reportCase[key] = value;
    }
    if (line.contains("expectation") && !line["expectation"].is_null()) {
      reportCase["expectation"] = reportExpectation(line["expectation"]);
    }
    if (line.contains("plot") && !line["plot"].is_null()) {
      try {
        plotFromJson(line["plot"]);  // the writers draw it: it must be a plot
        reportCase["plot"] = line["plot"];
      } catch (const std::exception& e) {
        warnings_.push_back(engineName + ": " + caseId + ": plot left out: " + e.what());
      }
    }
  }

  EngineResults& e = engine(engineName);
  Slot* slot = nullptr;
  bool fresh = false;
  if (seed) {
    const auto [it, inserted] = e.fuzz.try_emplace(*seed);
    slot = &it->second, fresh = inserted;
  } else {
    const auto [it, inserted] = e.suite.try_emplace(caseId);
    slot = &it->second, fresh = inserted;
  }
  // A later line for the same case replaces the earlier one, in the earlier one's place.
  if (!fresh && seed) e.fuzzCounts.add(slot->verdict, -1);
  if (listed) {
    if (slot->listed) {
      e.cases[*slot->listed] = std::move(reportCase);
    } else {
      slot->listed = e.cases.size();
      e.cases.push_back(std::move(reportCase));
    }
  } else if (slot->listed) {
    e.cases[*slot->listed] = nullptr;
    slot->listed.reset();
  }
  slot->verdict = verdict;
  if (seed) e.fuzzCounts.add(verdict, 1);
}

namespace {

// A run record's text field, or "unknown" (records come from files that may be older or edited).
std::string recordText(const json& run, const char* key) {
  return run.contains(key) && run[key].is_string() ? run[key].get<std::string>() : std::string("unknown");
}

std::string recordStart(const json& run) {
  return run.contains("started") && run["started"].is_string() ? run["started"].get<std::string>() : std::string();
}

// Each rule's tally over an engine's listed cases: a case passes, fails, or is not applicable to or
// an engine failure on each rule it cites — fails the rules failedRules() names.
std::map<std::string, RuleTally> tallyRules(const std::vector<const json*>& cases) {
  std::map<std::string, RuleTally> tallies;
  for (const json* c : cases) {
    const std::string id = (*c)["id"], verdict = (*c)["verdict"];
    const std::vector<std::string> failed = verdict == "fail" ? failedRules(*c) : std::vector<std::string>{};
    for (const std::string& rule : (*c)["rules"].get<std::vector<std::string>>()) {
      RuleTally& t = tallies[rule];
      t.cases.push_back(id);
      if (verdict == "engine-failure") t.engineFailure = true;
      else if (verdict == "not-applicable") t.notApplicable = true;
      else if (std::find(failed.begin(), failed.end(), rule) == failed.end()) t.pass = true;
    }
    for (const std::string& rule : failed) tallies[rule].failing.push_back(id);
  }
  return tallies;
}

}  // namespace

const json* ReportBuilder::latestRun(const std::string& engine) const {
  const json* latest = nullptr;
  for (const json& run : runs_) {
    if (!engine.empty() && recordText(run, "engine") != engine) continue;
    if (!latest || recordStart(run) >= recordStart(*latest)) latest = &run;
  }
  return latest;
}

std::string ReportBuilder::engineVersion(const std::string& name) const {
  const json* run = latestRun(name);
  return run ? recordText(*run, "engine_version") : "unknown";
}

json ReportBuilder::build() const {
  // The engines with results, then those with only a run record (a run killed before its first case).
  std::vector<EngineResults> recordOnly;
  for (const json& run : runs_) {
    const std::string name = recordText(run, "engine");
    const auto named = [&](const EngineResults& e) { return e.name == name; };
    if (!engineIndex_.count(name) && std::none_of(recordOnly.begin(), recordOnly.end(), named)) {
      recordOnly.push_back(EngineResults{name, {}, {}, {}, {}});
    }
  }
  std::vector<const EngineResults*> engines;
  for (const EngineResults& e : engines_) engines.push_back(&e);
  for (const EngineResults& e : recordOnly) engines.push_back(&e);

  std::vector<std::string> ruleOrder;
  std::set<std::string> known;
  for (const ReportRule& r : rules_) {
    if (known.insert(r.id).second) ruleOrder.push_back(r.id);
  }
  json rules = json::array();
  for (const ReportRule& r : rules_) {
    rules.push_back({{"id", r.id}, {"cycle", r.cycle}, {"seed", r.seed}, {"section", r.section}, {"summary", r.summary}});
  }

  std::vector<std::map<std::string, RuleTally>> tallies;
  std::vector<std::vector<const json*>> listed(engines.size());
  for (std::size_t i = 0; i < engines.size(); ++i) {
    for (const json& c : engines[i]->cases) {
      if (!c.is_null()) listed[i].push_back(&c);
    }
    tallies.push_back(tallyRules(listed[i]));
    // Rules cited but missing from the catalogue are still reported, after the catalogue's.
    for (const json* c : listed[i]) {
      std::vector<std::string> cited = (*c)["rules"].get<std::vector<std::string>>();
      for (const std::string& r : failedRules(*c)) cited.push_back(r);
      for (const std::string& r : cited) {
        if (!known.insert(r).second) continue;
        ruleOrder.push_back(r);
        rules.push_back({{"id", r}, {"cycle", ""}, {"seed", ""}, {"section", ""}, {"summary", "not in specs/rules.json"}});
      }
    }
  }

  json engineReports = json::array(), identities = json::array();
  long total = 0, totalByVerdict[4] = {0, 0, 0, 0};
  std::map<std::string, json> nonconforming;  // rule → engines failing it
  for (std::size_t i = 0; i < engines.size(); ++i) {
    const EngineResults& e = *engines[i];
    json cases = json::array();
    Counts suite;
    for (const json* c : listed[i]) {
      cases.push_back(*c);
      if ((*c)["kind"] == "fuzz") continue;
      const auto v = std::find(std::begin(kVerdictNames), std::end(kVerdictNames), (*c)["verdict"].get<std::string>());
      suite.add(static_cast<Verdict>(v - std::begin(kVerdictNames)), 1);
    }
    json ruleVerdicts = json::array();
    for (const std::string& id : ruleOrder) {
      const auto t = tallies[i].find(id);
      const RuleTally none;
      const RuleTally& tally = t == tallies[i].end() ? none : t->second;
      ruleVerdicts.push_back({{"id", id}, {"verdict", tally.verdict()}, {"cases", tally.cases}, {"failing", tally.failing}});
      if (!tally.failing.empty()) nonconforming[id].push_back(e.name);
    }
    json seeds = json::array();
    for (const json& run : runs_) {
      if (recordText(run, "engine") != e.name || recordText(run, "command") != "fuzz") continue;
      if (run.contains("seed") && isCount(run["seed"]) &&
          std::find(seeds.begin(), seeds.end(), run["seed"]) == seeds.end()) {
        seeds.push_back(run["seed"]);
      }
    }
    json fuzz = totalsJson(e.fuzzCounts.cases, e.fuzzCounts.byVerdict);
    fuzz["seeds"] = seeds;
    const std::string version = engineVersion(e.name);
    engineReports.push_back({{"name", e.name},
                             {"version", version},
                             {"totals", totalsJson(suite.cases, suite.byVerdict)},
                             {"fuzz", fuzz},
                             {"rules", ruleVerdicts},
                             {"cases", std::move(cases)}});
    if (const json counts = expectationCounts(listed[i]); !counts.is_null()) engineReports.back()["expectations"] = counts;
    identities.push_back({{"name", e.name}, {"version", version}});
    total += suite.cases;
    for (int v = 0; v < 4; ++v) totalByVerdict[v] += suite.byVerdict[v];
  }

  json nonconformingRules = json::array();
  for (const std::string& id : ruleOrder) {
    if (const auto it = nonconforming.find(id); it != nonconforming.end()) {
      nonconformingRules.push_back({{"rule", id}, {"engines", it->second}});
    }
  }
  const json* latest = latestRun("");
  const auto fromLatest = [&](const char* key) { return latest ? recordText(*latest, key) : std::string("unknown"); };
  json certification{{"cyclecert_version", fromLatest("cyclecert_version")},
                     {"git_revision", fromLatest("git_revision")},
                     {"spec_suite_hash", fromLatest("spec_suite_hash")},
                     {"date", latest && !recordStart(*latest).empty() ? json(recordStart(*latest)) : json(nullptr)},
                     {"engines", identities},
                     {"totals", totalsJson(total, totalByVerdict)},
                     {"nonconforming_rules", nonconformingRules}};
  return {{"format", "cyclecert-report/1"},
          {"certification", certification},
          {"rules", rules},
          {"engines", engineReports}};
}

json buildReport(const std::vector<json>& lines, const std::vector<json>& runs, const std::vector<ReportRule>& catalogue) {
  ReportBuilder builder(catalogue, runs);
  for (const json& line : lines) builder.add(line);
  return builder.build();
}

}  // namespace cyclecert
