#include "harness/spec/spec_case.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <utility>

#include "harness/io/input_file.h"
#include "reference/model/profile.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert {

using nlohmann::json;

SpecError::SpecError(const std::string& file, const std::string& field, const std::string& expected)
    : std::runtime_error(file + ": " + field + ": expected " + expected) {}

namespace {

const json& required(const json& j, const char* key, const std::string& file) {
  if (!j.contains(key)) throw SpecError(file, std::string("/") + key, "a value (field missing)");
  return j[key];
}

std::string requiredString(const json& j, const char* key, const std::string& file) {
  const json& v = required(j, key, file);
  if (!v.is_string() || v.get<std::string>().empty()) {
    throw SpecError(file, std::string("/") + key, "a non-empty string");
  }
  return v.get<std::string>();
}

void readTolerance(const json& expect, SpecCase& c) {
  if (expect.contains("tolerance")) {
    if (!expect["tolerance"].is_number() || expect["tolerance"].get<double>() <= 0) {
      throw SpecError(c.file, "/expect/tolerance", "a positive number");
    }
    c.tolerance = expect["tolerance"].get<double>();
  }
}

void readExpectation(const json& expect, SpecCase& c) {
  if (!expect.is_object()) throw SpecError(c.file, "/expect", "an object with \"toolpath\", \"alarm\" or \"oracles\"");
  if (expect.contains("toolpath") + expect.contains("alarm") + expect.contains("oracles") != 1) {
    throw SpecError(c.file, "/expect", "exactly one of \"toolpath\", \"alarm\" and \"oracles\"");
  }
  if (expect.contains("oracles")) {
    if (expect["oracles"] != "pass") throw SpecError(c.file, "/expect/oracles", "\"pass\"");
    c.oraclesOnly = true;
    if (expect.contains("agrees_with")) {
      if (!expect["agrees_with"].is_string()) throw SpecError(c.file, "/expect/agrees_with", "an engine name");
      c.agreesWith = expect["agrees_with"].get<std::string>();
    }
  }
  if (expect.contains("alarm")) {
    const json& a = expect["alarm"];
    ExpectedAlarm alarm;
    if (a.is_string()) {
      alarm.code = a.get<std::string>();
    } else if (a.is_object() && a.contains("code") && a["code"].is_string()) {
      alarm.code = a["code"].get<std::string>();
      if (a.contains("line")) {
        if (!a["line"].is_number_integer() || a["line"].get<int>() < 1) {
          throw SpecError(c.file, "/expect/alarm/line", "a line number ≥ 1");
        }
        alarm.line = a["line"].get<int>();
      }
      if (a.contains("when")) {
        if (!a["when"].is_string()) throw SpecError(c.file, "/expect/alarm/when", "\"cycle block\", \"before the cycle\" or \"during the cycle\"");
        alarm.when = a["when"].get<std::string>();
      }
    } else {
      throw SpecError(c.file, "/expect/alarm", "an alarm code string or {\"code\": …, \"line\": …}");
    }
    c.expectedAlarm = alarm;
    return;
  }
  if (c.oraclesOnly) {
    readTolerance(expect, c);
    return;
  }
  const json& moves = expect["toolpath"];
  if (!moves.is_array() || moves.empty()) throw SpecError(c.file, "/expect/toolpath", "a non-empty array of moves");
  std::vector<Move> parsed;
  for (std::size_t i = 0; i < moves.size(); ++i) {
    try {
      parsed.push_back(moveFromJson(moves[i], "/expect/toolpath/" + std::to_string(i)));
    } catch (const ToolpathFormatError& e) {
      throw std::runtime_error(c.file + ": " + e.what());
    }
  }
  c.expectedMoves = std::move(parsed);
  if (expect.contains("warnings")) {
    const json& w = expect["warnings"];
    if (!w.is_array()) throw SpecError(c.file, "/expect/warnings", "an array of strings");
    for (std::size_t i = 0; i < w.size(); ++i) {
      if (!w[i].is_string()) throw SpecError(c.file, "/expect/warnings/" + std::to_string(i), "a string");
      c.expectedWarnings.push_back(w[i].get<std::string>());
    }
  }
  readTolerance(expect, c);
}

// The profile is one cyclecert knows and every parameter a value it can take there: a case that
// names another is refused here, naming the file and the field, not later by the engine.
void checkProfileAndParams(const SpecCase& c) {
  const Profile* profile = findProfile(c.profile);
  if (!profile) {
    std::string known;
    for (const Profile& p : allProfiles()) known += (known.empty() ? "" : ", ") + p.name;
    throw SpecError(c.file, "/profile", "one of " + known + " (`cyclecert profiles`); unknown profile '" + c.profile + "'");
  }
  MachineParams params = profile->defaults;
  for (const auto& [name, value] : c.params) {
    try {
      params.set(name, value);
    } catch (const std::invalid_argument& e) {
      throw SpecError(c.file, "/params/" + name, std::string("a valid value: ") + e.what());
    }
  }
}

}  // namespace

SpecCase parseSpecCase(const std::string& text, const std::string& file) {
  json j;
  try {
    j = parseJsonDocument(text, file);
  } catch (const ToolpathFormatError& e) {
    throw std::runtime_error(e.what());
  }
  return specCaseFrom(std::move(j), file);
}

SpecCase specCaseFrom(json j, const std::string& file) {
  if (!j.is_object()) throw SpecError(file, "(document)", "a JSON object");
  SpecCase c;
  c.file = file;
  c.id = requiredString(j, "id", file);
  c.title = requiredString(j, "title", file);
  c.profile = requiredString(j, "profile", file);
  c.program = requiredString(j, "program", file);
  c.derivation = requiredString(j, "derivation", file);
  const json& rules = required(j, "rules", file);
  if (!rules.is_array() || rules.empty()) throw SpecError(file, "/rules", "a non-empty array of rule IDs");
  for (std::size_t i = 0; i < rules.size(); ++i) {
    if (!rules[i].is_string()) throw SpecError(file, "/rules/" + std::to_string(i), "a rule ID string");
    c.rules.push_back(rules[i].get<std::string>());
  }
  if (j.contains("params")) {
    if (!j["params"].is_object()) throw SpecError(file, "/params", "an object of parameter → number");
    for (const auto& [name, value] : j["params"].items()) {
      if (!value.is_number()) throw SpecError(file, "/params/" + name, "a number");
      c.params.emplace_back(name, value.get<double>());
    }
  }
  if (j.contains("tool")) {
    const json& t = j["tool"];
    if (!t.is_object() || !t.contains("nose_radius") || !t["nose_radius"].is_number() ||
        t["nose_radius"].get<double>() < 0) {
      throw SpecError(file, "/tool/nose_radius", "a nose radius ≥ 0 (mm)");
    }
    if (!t.contains("tip") || !t["tip"].is_number_integer() || t["tip"].get<int>() < 0 || t["tip"].get<int>() > 9) {
      throw SpecError(file, "/tool/tip", "an imaginary tip direction 0…9");
    }
    c.tool = ToolOffset{t["nose_radius"].get<double>(), t["tip"].get<int>()};
  }
  if (j.contains("stock")) {
    const json& s = j["stock"];
    CaseStock stock;
    if (!s.is_object() || !s.contains("kind")) throw SpecError(file, "/stock", "{\"kind\": \"bar\" | \"polygon\", …}");
    if (s["kind"] == "bar") {
      for (const char* k : {"diameter", "length"}) {
        if (!s.contains(k) || !s[k].is_number() || s[k].get<double>() <= 0) throw SpecError(file, std::string("/stock/") + k, "a positive number (mm)");
      }
      stock.diameter = s["diameter"];
      stock.length = s["length"];
      stock.frontZ = s.value("front_z", 0.0);
    } else if (s["kind"] == "polygon") {
      stock.bar = false;
      if (!s.contains("points") || !s["points"].is_array() || s["points"].size() < 3) {
        throw SpecError(file, "/stock/points", "at least 3 points {\"x\": radius, \"z\": z}");
      }
      for (std::size_t i = 0; i < s["points"].size(); ++i) {
        try {
          stock.outline.push_back(pointFromJson(s["points"][i], "/stock/points/" + std::to_string(i)));
        } catch (const ToolpathFormatError& e) {
          throw std::runtime_error(file + ": " + e.what());
        }
      }
    } else {
      throw SpecError(file, "/stock/kind", "\"bar\" or \"polygon\"");
    }
    c.stock = stock;
  }
  if (j.contains("subprograms")) {
    if (!j["subprograms"].is_object()) throw SpecError(file, "/subprograms", "an object of subprogram name → program text");
    for (const auto& [name, text] : j["subprograms"].items()) {
      if (!text.is_string()) throw SpecError(file, "/subprograms/" + name, "the subprogram's text (a string)");
      c.subprograms.emplace_back(name, text.get<std::string>());
    }
  }
  if (j.contains("mode")) {
    if (j["mode"] != "mdi" && j["mode"] != "memory") throw SpecError(file, "/mode", "\"memory\" or \"mdi\"");
    c.mdi = j["mode"] == "mdi";
  }
  checkProfileAndParams(c);
  readExpectation(required(j, "expect", file), c);
  c.raw = std::move(j);
  return c;
}

SpecCase loadSpecCase(const std::string& path) { return parseSpecCase(readInputFile(path), path); }

std::vector<std::string> findSpecCaseFiles(const std::string& dir) {
  std::error_code error;
  if (!std::filesystem::is_directory(dir, error)) {
    const std::filesystem::path parent = std::filesystem::path(dir).parent_path();
    const std::string what = std::filesystem::exists(dir, error) ? dir + ": not a directory"
                             : std::filesystem::is_regular_file(parent, error)
                                 ? parent.string() + ": a file, not a folder"
                                 : dir + ": no such directory";
    throw InputFileError(what + " (the spec cases are read from a suite's cases/ folder: --specs DIR takes the folder "
                                "holding cases/ and rules.json, e.g. --specs specs)");
  }
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace cyclecert
