// `cyclecert rules`, `params` and `profiles`: the catalogues a user looks things up in.
#include <iomanip>
#include <iostream>
#include <map>

#include "harness/cli/cli_support.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"

namespace cyclecert::cli {

namespace {

const char* kRulesHelp = R"HELP(Usage: cyclecert rules [--cycle C] [--uncited] [--json] [--specs DIR]

Lists every rule of specs/rules.json with its source seed and section, its summary, and how many
spec cases under specs/cases cite it.

Options:
  --cycle C     only the rules of one cycle (G70, G71, G72, G73, G74_1, LCYC95, CYCLE95, …)
  --uncited     only the rules no spec case cites (exit 1 if there are any in scope; a rule marked
                out of scope in rules.json, with its reason, is listed apart and does not fail)
  --json        machine-readable output
  --specs DIR   the specs directory (default: the repository's specs/)
)HELP";

const char* kParamsHelp = R"HELP(Usage: cyclecert params [--json]

Lists every machine parameter the reference models: number, mnemonic, default, unit, meaning and
the rule IDs it serves. Profiles may change defaults (see `cyclecert profiles`).
)HELP";

const char* kProfilesHelp = R"HELP(Usage: cyclecert profiles

Lists the controller profiles and the parameter defaults in which they differ.
)HELP";

}  // namespace

static int commandRules(const std::vector<std::string>& args) {
  std::string cycle, specs = defaultSpecsDir();
  bool uncitedOnly = false, json = false;
  const auto positional = parseOptions(args,
                                       {{"--uncited", [&] { uncitedOnly = true; }},
                                        {"--json", [&] { json = true; }},
                                        {"--cycle", [&](const std::string& v) { cycle = v; }},
                                        {"--specs", [&](const std::string& v) { specs = v; }}},
                                       "rules");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  const RuleCatalogue catalogue = loadRuleCatalogue(specs + "/rules.json");
  std::map<std::string, int> citations;
  for (const std::string& file : findSpecCaseFiles(specs + "/cases")) {
    for (const std::string& rule : loadSpecCase(file).rules) ++citations[rule];
  }
  nlohmann::json out = nlohmann::json::array();
  int uncited = 0, outOfScope = 0;
  for (const RuleEntry& r : catalogue.rules) {
    if (!cycle.empty() && r.cycle != cycle) continue;
    const int n = citations.count(r.id) ? citations.at(r.id) : 0;
    if (n == 0) ++(r.outOfScope.empty() ? uncited : outOfScope);
    if (uncitedOnly && n > 0) continue;
    if (json) {
      out.push_back({{"id", r.id}, {"cycle", r.cycle}, {"seed", r.seed}, {"section", r.section},
                     {"summary", r.summary}, {"cases", n}, {"notes", r.notes}});
      if (!r.outOfScope.empty()) out.back()["out_of_scope"] = r.outOfScope;
    } else {
      std::cout << std::left << std::setw(22) << r.id << std::right << std::setw(4) << n << " case(s)  "
                << (r.outOfScope.empty() ? r.summary : "out of scope: " + r.outOfScope) << "\n";
    }
  }
  if (json) {
    std::cout << out.dump(2) << "\n";
  } else {
    std::cout << uncited << " rule(s) cited by no spec case";
    if (outOfScope > 0) std::cout << "; " << outOfScope << " more out of scope (no case can cite them: the reason above)";
    std::cout << "\n";
  }
  return uncitedOnly && uncited > 0 ? 1 : kExitOk;
}

static int commandParams(const std::vector<std::string>& args) {
  bool json = false;
  const auto positional = parseOptions(args, {{"--json", [&] { json = true; }}}, "params");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  if (json) {
    nlohmann::json out = nlohmann::json::array();
    for (const ParamSpec& p : MachineParams::catalogue()) {
      out.push_back({{"number", p.number}, {"mnemonic", p.mnemonic}, {"bit", p.isBit}, {"default", p.defaultValue},
                     {"unit", p.unit}, {"description", p.description}, {"rules", p.rules}});
    }
    std::cout << out.dump(2) << "\n";
    return kExitOk;
  }
  for (const ParamSpec& p : MachineParams::catalogue()) {
    std::cout << std::left << std::setw(8) << p.number << std::setw(6) << p.mnemonic << "default " << std::setw(4)
              << p.defaultValue << " " << p.unit << "\n        " << p.description << "\n        rules:";
    for (const auto& r : p.rules) std::cout << " " << r;
    std::cout << "\n";
  }
  return kExitOk;
}

static int commandProfiles(const std::vector<std::string>& args) {
  const auto positional = parseOptions(args, {}, "profiles");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  const MachineParams base;
  for (const Profile& p : allProfiles()) {
    std::cout << p.name << "\n    " << p.description << "\n    follows seed " << p.seed << "\n";
    for (const ParamSpec& spec : MachineParams::catalogue()) {
      if (p.defaults.get(spec.number) != base.get(spec.number)) {
        std::cout << "    default " << spec.number << (spec.mnemonic.empty() ? "" : " (" + spec.mnemonic + ")")
                  << " = " << p.defaults.get(spec.number) << "\n";
      }
    }
  }
  return kExitOk;
}

extern const Command kRulesCommand{"rules", kRulesHelp, commandRules};
extern const Command kParamsCommand{"params", kParamsHelp, commandParams};
extern const Command kProfilesCommand{"profiles", kProfilesHelp, commandProfiles};

}  // namespace cyclecert::cli
