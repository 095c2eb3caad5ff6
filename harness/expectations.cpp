#include "harness/expectations.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "harness/input_file.h"

namespace cyclecert {

using nlohmann::json;

namespace {

constexpr const char* kOutcomes[] = {"fail", "engine-failure", "not-applicable"};
constexpr const char* kOutcomeList = "fail, engine-failure or not-applicable";

bool knownOutcome(const std::string& outcome) {
  return std::find(std::begin(kOutcomes), std::end(kOutcomes), outcome) != std::end(kOutcomes);
}

const char* keyName(Expectation::Key k) {
  switch (k) {
    case Expectation::Key::Case: return "case";
    case Expectation::Key::Rule: return "rule";
    case Expectation::Key::Kind: return "kind";
  }
  return "case";
}

[[noreturn]] void fail(const std::string& where, const std::string& what) { throw ExpectationsError(where + ": " + what); }

// Two entries for the same case, rule or kind would make the file say two things.
void refuseDuplicates(const Expectations& e) {
  std::map<std::pair<Expectation::Key, std::string>, const Expectation*> seen;
  for (const Expectation& x : e.entries) {
    const auto [it, fresh] = seen.try_emplace({x.key, x.id}, &x);
    if (!fresh) {
      fail(x.source, std::string(keyName(x.key)) + " '" + x.id + "' already has an entry at " + it->second->source +
                         "; keep one entry for it");
    }
  }
}

// ---- JSON -----------------------------------------------------------------------------------------

std::string lineColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') ++line, column = 1;
    else ++column;
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

std::string textField(const json& entry, const char* key, const std::string& where, const std::string& expected) {
  const auto it = entry.find(key);
  if (it == entry.end()) fail(where, "missing \"" + std::string(key) + "\": expected " + expected);
  if (!it->is_string() || it->get<std::string>().empty()) {
    fail(where + "/" + key, "expected " + expected + ", got " + it->dump());
  }
  return it->get<std::string>();
}

Expectation jsonEntry(const json& entry, const std::string& where) {
  if (!entry.is_object()) {
    fail(where, "expected an entry object {\"case\" | \"rule\" | \"kind\": …, \"outcome\": …, \"reason\": …}, got " +
                    entry.dump());
  }
  Expectation x;
  x.source = where;
  int keys = 0;
  for (const auto& [name, value] : entry.items()) {
    Expectation::Key key;
    if (name == "case") key = Expectation::Key::Case;
    else if (name == "rule") key = Expectation::Key::Rule;
    else if (name == "kind") key = Expectation::Key::Kind;
    else if (name == "outcome" || name == "reason") continue;
    else fail(where + "/" + name, "unknown field; an entry has \"case\", \"rule\" or \"kind\", \"outcome\" and \"reason\"");
    x.key = key;
    x.id = textField(entry, name.c_str(), where, "a non-empty string");
    ++keys;
  }
  if (keys != 1) fail(where, "expected exactly one of \"case\" (a case id), \"rule\" (a rule id) or \"kind\" (a failure kind)");
  x.outcome = textField(entry, "outcome", where, std::string("one of ") + kOutcomeList);
  if (!knownOutcome(x.outcome)) fail(where + "/outcome", "expected one of " + std::string(kOutcomeList) + ", got \"" + x.outcome + "\"");
  x.reason = textField(entry, "reason", where, "a non-empty string saying why the failure is expected");
  return x;
}

Expectations parseJson(const std::string& text, const std::string& file) {
  json document;
  try {
    document = json::parse(text);
  } catch (const json::parse_error& e) {
    fail(file + ":" + lineColumn(text, e.byte == 0 ? 0 : e.byte - 1), std::string("not valid JSON: ") + e.what());
  }
  Expectations out{file, {}};
  const json* list = &document;
  std::string path = file + ": ";
  if (document.is_object()) {
    for (const auto& [name, value] : document.items()) {
      if (name != "expectations") fail(path + "/" + name, "unknown field; the file is {\"expectations\": [entries]}");
    }
    if (!document.contains("expectations")) fail(path + "/", "missing \"expectations\": expected {\"expectations\": [entries]}");
    list = &document["expectations"];
    path += "/expectations";
  }
  if (!list->is_array()) fail(path.size() == file.size() + 2 ? path + "/" : path, "expected an array of entries, got " + list->dump());
  for (std::size_t i = 0; i < list->size(); ++i) out.entries.push_back(jsonEntry((*list)[i], path + "/" + std::to_string(i)));
  return out;
}

// ---- Text -----------------------------------------------------------------------------------------

Expectation textEntry(const std::string& line, const std::string& where) {
  const std::size_t hash = line.find('#');
  std::istringstream words(line.substr(0, hash));
  std::string id, outcome, extra;
  words >> id >> outcome;
  const auto column = [&](const std::string& word) {
    return where + ":" + std::to_string(line.find(word) + 1);
  };
  if (outcome.empty()) {
    fail(where + ":" + std::to_string(line.find(id) + 1 + id.size()),
         "expected an outcome after '" + id + "' (" + kOutcomeList + "): `ID OUTCOME # reason`");
  }
  if (!knownOutcome(outcome)) fail(column(outcome), "expected an outcome (" + std::string(kOutcomeList) + "), got '" + outcome + "'");
  if (words >> extra) fail(column(extra), "unexpected '" + extra + "': put the reason after '#' (`ID OUTCOME # reason`)");
  Expectation x;
  x.source = where;
  x.outcome = outcome;
  x.id = id;
  for (const auto& [prefix, key] : {std::pair{"rule:", Expectation::Key::Rule}, std::pair{"kind:", Expectation::Key::Kind},
                                    std::pair{"case:", Expectation::Key::Case}}) {
    if (id.rfind(prefix, 0) == 0) x.key = key, x.id = id.substr(std::string(prefix).size());
  }
  if (x.id.empty()) fail(column(id), "expected an id after '" + id + "'");
  if (hash != std::string::npos) {
    const std::string reason = line.substr(hash + 1);
    const auto first = reason.find_first_not_of(" \t\r");
    if (first != std::string::npos) x.reason = reason.substr(first, reason.find_last_not_of(" \t\r") + 1 - first);
  }
  if (x.reason.empty()) {
    fail(where + ":" + std::to_string(hash == std::string::npos ? line.size() + 1 : hash + 1),
         "expected a reason after '#' saying why the failure is expected: `" + id + " " + outcome + " # reason`");
  }
  return x;
}

Expectations parseText(const std::string& text, const std::string& file) {
  Expectations out{file, {}};
  std::istringstream lines(text);
  int number = 0;
  for (std::string line; std::getline(lines, line);) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    out.entries.push_back(textEntry(line, file + ":" + std::to_string(number)));
  }
  return out;
}

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

Expectations parseExpectations(const std::string& text, const std::string& file) {
  const auto first = text.find_first_not_of(" \t\r\n");
  Expectations e = first != std::string::npos && (text[first] == '{' || text[first] == '[') ? parseJson(text, file)
                                                                                            : parseText(text, file);
  refuseDuplicates(e);
  return e;
}

Expectations readExpectations(const std::string& path) {
  try {
    return parseExpectations(readInputFile(path), path);
  } catch (const ExpectationsError&) {
    throw;
  } catch (const std::exception& e) {
    throw ExpectationsError(std::string("--expectations: ") + e.what());
  }
}

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

std::string expectationsJson(const Expectations& e) {
  std::string out = "{\n  \"expectations\": [";
  for (std::size_t i = 0; i < e.entries.size(); ++i) {
    const Expectation& x = e.entries[i];
    const json entry{{keyName(x.key), x.id}, {"outcome", x.outcome}, {"reason", x.reason}};
    // One entry a line, in the order written (case|rule|kind, outcome, reason), so that diffs stay small.
    out += std::string(i ? "," : "") + "\n    {\"" + keyName(x.key) + "\": " + entry[keyName(x.key)].dump() +
           ", \"outcome\": " + entry["outcome"].dump() +
           ", \"reason\": " + entry["reason"].dump(-1, ' ', false, json::error_handler_t::replace) + "}";
  }
  return out + (e.entries.empty() ? "]\n}\n" : "\n  ]\n}\n");
}

std::string expectationsText(const Expectations& e) {
  std::string out = "# cyclecert expectations: ID OUTCOME # reason (rule:RULE-ID and kind:KIND for the other keys)\n";
  for (const Expectation& x : e.entries) {
    std::string reason = x.reason;
    std::replace(reason.begin(), reason.end(), '\n', ' ');
    out += (x.key == Expectation::Key::Case ? "" : std::string(keyName(x.key)) + ":") + x.id + " " + x.outcome + " # " +
           reason + "\n";
  }
  return out;
}

}  // namespace cyclecert
