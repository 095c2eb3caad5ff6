#include "harness/spec/rule_catalogue.h"

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "harness/io/input_file.h"

namespace cyclecert {

bool RuleCatalogue::contains(const std::string& id) const {
  return std::any_of(rules.begin(), rules.end(), [&](const RuleEntry& r) { return r.id == id; });
}

RuleCatalogue loadRuleCatalogue(const std::string& path) {
  const std::string text = readInputFile(path);  // a directory or FIFO named as the catalogue is refused
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::runtime_error(path + ": invalid JSON: " + e.what());
  }
  if (!j.contains("rules") || !j["rules"].is_array()) throw std::runtime_error(path + ": /rules: expected an array");
  RuleCatalogue c;
  for (const auto& r : j["rules"]) {
    RuleEntry e;
    e.id = r.value("id", "");
    e.cycle = r.value("cycle", "");
    e.seed = r.value("seed", "");
    e.section = r.value("section", "");
    e.summary = r.value("summary", "");
    e.outOfScope = r.value("out_of_scope", "");
    if (r.contains("notes") && r["notes"].is_array()) {
      for (const auto& n : r["notes"]) if (n.is_string()) e.notes.push_back(n.get<std::string>());
    }
    c.rules.push_back(std::move(e));
  }
  return c;
}

std::string defaultSpecsDir() {
  if (const char* env = std::getenv("CYCLECERT_SPECS_DIR")) return env;
  return std::string(CYCLECERT_SOURCE_DIR) + "/specs";
}

std::string defaultRegressionsDir() {
  if (const char* env = std::getenv("CYCLECERT_REGRESSIONS_DIR")) return env;
  return std::string(CYCLECERT_SOURCE_DIR) + "/corpus/regressions";
}

}  // namespace cyclecert
