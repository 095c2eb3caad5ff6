// Expectation files read and written (harness/results/expectations.h): the JSON and the text format.
#include <algorithm>
#include <map>
#include <sstream>

#include "harness/io/input_file.h"
#include "harness/results/expectations.h"

namespace cyclecert {

using nlohmann::json;

namespace {

constexpr const char* kOutcomes[] = {"fail", "engine-failure", "not-applicable"};
constexpr const char* kOutcomeList = "fail, engine-failure or not-applicable";

bool knownOutcome(const std::string& outcome) {
  return std::find(std::begin(kOutcomes), std::end(kOutcomes), outcome) != std::end(kOutcomes);
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
  const auto at = [&](const std::string& pointer) { return file + ": " + (pointer.empty() ? "/" : pointer); };
  const json* list = &document;
  std::string pointer;  // of the list of entries
  if (document.is_object()) {
    for (const auto& [name, value] : document.items()) {
      if (name != "expectations") fail(at("/" + name), "unknown field; the file is {\"expectations\": [entries]}");
    }
    if (!document.contains("expectations")) fail(at(""), "missing \"expectations\": expected {\"expectations\": [entries]}");
    list = &document["expectations"];
    pointer = "/expectations";
  }
  if (!list->is_array()) fail(at(pointer), "expected an array of entries, got " + list->dump());
  for (std::size_t i = 0; i < list->size(); ++i) {
    out.entries.push_back(jsonEntry((*list)[i], at(pointer + "/" + std::to_string(i))));
  }
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

}  // namespace

const char* keyName(Expectation::Key k) {
  switch (k) {
    case Expectation::Key::Case: return "case";
    case Expectation::Key::Rule: return "rule";
    case Expectation::Key::Kind: return "kind";
  }
  return "case";
}

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

std::string expectationsJson(const Expectations& e) {
  const auto quoted = [](const std::string& text) {
    return json(text).dump(-1, ' ', false, json::error_handler_t::replace);
  };
  // One entry a line, its fields in the order people read them, so that a file's diffs stay small.
  std::string out = "{\n  \"expectations\": [";
  for (std::size_t i = 0; i < e.entries.size(); ++i) {
    const Expectation& x = e.entries[i];
    out += std::string(i ? "," : "") + "\n    {\"" + keyName(x.key) + "\": " + quoted(x.id) + ", \"outcome\": " +
           quoted(x.outcome) + ", \"reason\": " + quoted(x.reason) + "}";
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
