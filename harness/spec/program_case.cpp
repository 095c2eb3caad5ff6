#include "harness/spec/program_case.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <regex>
#include <set>
#include <sstream>

#include "harness/engines/reference_plan.h"
#include "reference/model/params.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

using nlohmann::json;

json everyOracleExpectation() { return {{"oracles", "pass"}}; }

json alarmExpectation(const std::string& code, int line) { return {{"alarm", {{"code", code}, {"line", line}}}}; }

bool isSpecCaseFile(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".json";
}

void setCaseParam(json& params, const std::string& name, double value) {
  const ParamSpec* spec = MachineParams::find(name);
  for (auto it = params.begin(); it != params.end();) {
    const ParamSpec* other = MachineParams::find(it.key());
    if (spec && other && other->number == spec->number) it = params.erase(it);
    else ++it;
  }
  params[name] = value;
}

namespace {

// The rules the "(rules: …)" header comment lists, in order, each once.
std::vector<std::string> rulesOfHeader(const std::string& text) {
  static const std::regex header(R"(\(\s*rules\s*:\s*([^)]*)\))", std::regex::icase);
  std::vector<std::string> ids;
  if (std::smatch m; std::regex_search(text, m, header)) {
    std::istringstream list(std::regex_replace(m[1].str(), std::regex(","), " "));
    for (std::string id; list >> id;) ids.push_back(id);
  }
  return ids;
}

// The format rule of each cycle the program calls (comments skipped), in order of the calls.
std::vector<std::string> rulesOfCyclesCalled(const std::string& text) {
  static const std::regex comment(R"(\([^)]*\))");
  static const std::regex cycle(R"(G0*(7[0-3])(?![0-9.]))", std::regex::icase);
  const std::string code = std::regex_replace(text, comment, " ");
  std::vector<std::string> ids;
  for (auto it = std::sregex_iterator(code.begin(), code.end(), cycle); it != std::sregex_iterator(); ++it) {
    const std::string g = (*it)[1].str();
    ids.push_back(g == "70" ? "G70.EX" : g == "71" ? "G71.FMT.ZX" : g == "72" ? "G72.FMT" : "G73.EX");
  }
  return ids;
}

// "<profile>/<folder>/<file stem>", within the schema's id pattern.
std::string caseIdFor(const std::string& path, const std::string& profile, const std::string& folder) {
  std::string name = std::filesystem::path(path).stem().string();
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '.' && c != '-') c = '_';
  }
  if (name.empty() || name[0] == '.' || name[0] == '-') name = "program" + name;
  return profile + "/" + folder + "/" + name;
}

}  // namespace

std::vector<std::string> rulesOfProgram(const std::string& text) {
  static const std::regex ruleId(R"(^[A-Z0-9_]+(\.[A-Z0-9_]+)*$)");
  std::vector<std::string> rules;
  std::set<std::string> seen;
  const auto add = [&](const std::vector<std::string>& ids) {
    for (const std::string& id : ids) {
      if (std::regex_match(id, ruleId) && seen.insert(id).second) rules.push_back(id);
    }
  };
  add(rulesOfHeader(text));
  if (rules.empty()) add(rulesOfCyclesCalled(text));
  if (rules.empty()) add({"G71.FMT.ZX"});  // a program without a cycle: still one rule for a valid case
  return rules;
}

SpecCase specCaseForProgram(const std::string& path, const std::string& text, const std::string& folder,
                            const ProgramCaseSettings& settings) {
  const std::string profile =
      profileNameOrDefault(settings.profile.empty() ? profileFromHeader(text) : settings.profile);
  json params = json::object();
  for (const auto& [name, value] : settings.params) setCaseParam(params, name, value);
  json expect = everyOracleExpectation();
  if (settings.tolerance && *settings.tolerance > 0) expect["tolerance"] = *settings.tolerance;  // the schema wants it positive
  const json c = {{"id", caseIdFor(path, profile, folder)},
                  {"title", path},
                  {"rules", rulesOfProgram(text)},
                  {"profile", profile},
                  {"params", params},
                  {"program", text},
                  {"expect", expect},
                  {"derivation", "not a spec case: " + path + " wrapped by " + settings.wrappedBy +
                                     "; nothing was derived by hand"}};
  // Invalid UTF-8 (a comment in a legacy encoding) becomes U+FFFD, the same for every engine.
  return parseSpecCase(c.dump(-1, ' ', false, json::error_handler_t::replace), path);
}

SpecCase withCaseOverrides(const SpecCase& c, const std::string& profile,
                           const std::vector<std::pair<std::string, double>>& params) {
  if (profile.empty() && params.empty()) return c;
  json raw = c.raw;
  if (!profile.empty()) raw["profile"] = profile;
  if (!raw.contains("params")) raw["params"] = json::object();
  for (const auto& [name, value] : params) setCaseParam(raw["params"], name, value);
  return parseSpecCase(raw.dump(), c.file);
}

}  // namespace cyclecert
