#pragma once
// specs/rules.json: the rule IDs spec cases, moves and findings cite.
#include <map>
#include <string>
#include <vector>

namespace cyclecert {

struct RuleEntry {
  std::string id, cycle, seed, section, summary;
  std::vector<std::string> notes;
  // Why no spec case can cite the rule (rules.json "out_of_scope": a cycle the seed names without
  // describing it); empty for a rule in scope. `rules --uncited` lists such rules apart.
  std::string outOfScope;
};

struct RuleCatalogue {
  std::vector<RuleEntry> rules;  // in catalogue order
  bool contains(const std::string& id) const;
};

RuleCatalogue loadRuleCatalogue(const std::string& path);  // throws std::runtime_error naming the file

// The repository's specs/ directory (CYCLECERT_SPECS_DIR in the environment overrides it).
std::string defaultSpecsDir();
// Where `fuzz` writes shrunk failures as spec cases and `check` runs them (corpus/regressions, or
// $CYCLECERT_REGRESSIONS_DIR).
std::string defaultRegressionsDir();

}  // namespace cyclecert
