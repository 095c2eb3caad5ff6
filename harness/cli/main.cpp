// cyclecert — the command line. Exit codes (for CI):
//   0 success · 1 the controller alarmed (outputs still written) · 2 bad usage or unreadable input
//   3 the program needs something the reference does not plan yet
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cyclecert_version.h"
#include "harness/check_run.h"
#include "harness/engines/engine.h"
#include "harness/judging.h"
#include "harness/reference_plan.h"
#include "harness/rule_catalogue.h"
#include "harness/spec_case.h"
#include "harness/spec_check.h"
#include "reference/model/alarms.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/model/program.h"
#include "reference/model/toolpath_json.h"

namespace {

using namespace cyclecert;

constexpr int kExitOk = 0, kExitAlarm = 1, kExitUsage = 2, kExitNotSupported = 3;

const char* kMainHelp = R"HELP(cyclecert — conformance and differential testing of lathe roughing canned cycles

Usage: cyclecert <command> [options]

Commands:
  plan       plan every cycle of a program (or a spec case) with the reference engine;
             write the toolpath as JSON and SVG
  check      run every spec case against an engine (reference, process:COMMAND, mutant:NAME)
  engines    list the engines
  judge      judge a toolpath (any engine's, as JSON) with every oracle
  rules      list the rule catalogue with, per rule, how many spec cases cite it
  params     list the machine parameters, their defaults and the rules they serve
  profiles   list the controller profiles
  help       show this help, or `cyclecert help <command>`

Options: --help (on every command), --version.
Exit codes: 0 ok, 1 the controller alarmed, 2 bad usage or input, 3 not supported yet.
)HELP";

const char* kPlanHelp = R"HELP(Usage: cyclecert plan PROGRAM.nc [options]
       cyclecert plan --case CASE.json [options]

Plans every G71/G72 cycle of the program with the reference engine (type I; FANUC 0i-F or GSK).

Options:
  --profile P          controller profile (default: the program's "(profile: P)" header comment,
                       else fanuc-0i-f; see `cyclecert profiles`)
  --param NAME=VALUE   set a machine parameter by number or mnemonic, e.g. --param 5105#1=1 or
                       --param RF1=1 (repeatable; see `cyclecert params`); applied after the case's
  --case CASE.json     plan a spec case: its program, profile and parameters; reports whether the
                       reference meets the case's expectation
  --nose-radius R      the active tool's nose radius in mm, for G41/G42 (default 0)
  --tip T              its imaginary tool-nose direction 0…9 (FANUC chart, X up, Z right)
  --mdi                run the program as in MDI mode (the cycles alarm: G72.MDI)
  --json OUT           write the toolpath JSON to OUT ("-" for standard output)
  --svg OUT            write an SVG plot (contour, rough contour, rapids dashed, feeds solid)
  --help               this help

Without --json and --svg, the toolpath JSON goes to standard output.
JSON: {"profile", "units": "mm", "plane", "start", "moves": [{"kind": "rapid"|"feed",
       "shape": "line"|"arc_cw"|"arc_ccw", "to": {"x", "z"}, "center"?, "feed"?, "phase", "rules"}],
       "alarm": null | {"code", "message", "line"}, "warnings", "cycles"}   (x = radius, mm)
Exit: 0 planned, 1 the controller alarmed (JSON still written), 2 bad usage or unreadable or
malformed input, 3 not supported by the reference yet.
)HELP";

const char* kParamsHelp = R"HELP(Usage: cyclecert params [--json]

Lists every machine parameter the reference models: number, mnemonic, default, unit, meaning and
the rule IDs it serves. Profiles may change defaults (see `cyclecert profiles`).
)HELP";

const char* kJudgeHelp = R"HELP(Usage: cyclecert judge CASE.json TOOLPATH.json [options]
       cyclecert judge --program FILE.nc [--profile P] [--param N=V]… TOOLPATH.json [options]
       cyclecert judge CASE.json --reference [options]

Judges a toolpath with every oracle, from the program's finish shape, allowances and stock alone
(never from the reference planner): no-gouge, rapids-in-air, complete, depth-per-pass, pass-levels,
retract, returns-to-start, feeds, alarm. TOOLPATH.json is the canonical toolpath JSON (see `cyclecert plan
--help`; "-" reads standard input); --reference judges the reference engine's own plan.

Options:
  --profile P, --param NAME=VALUE, --nose-radius R, --tip T, --mdi   as for `plan` (with --program)
  --epsilon E          tolerance in mm (default: the case's tolerance, else 0.001)
  --json               findings as JSON on standard output
  --svg OUT            plot: contour, rough contour, stock, the path, each finding's witness in magenta
  --material-after K   in the plot, the material standing after move K instead of the stock
  --help               this help

Exit: 0 no finding, 1 findings, 2 bad usage or bad input (the message names the file, the field and
the move index), 3 the program needs a cycle the reference does not read yet.
)HELP";

const char* kCheckHelp = R"HELP(Usage: cyclecert check --engine E [--specs DIR] [--out DIR] [--resume] [--timeout S]

Runs every spec case under DIR/cases (default: the repository's specs/) against engine E
(`cyclecert engines`). A case passes when the engine meets its expectation — the toolpath within
the case's tolerance, or the alarm — and every oracle finds nothing on its toolpath. Each result
is appended to OUT/results.jsonl (default build/check) as soon as it is known, so a killed run keeps
every result; --resume skips the cases already there.

Options:
  --engine E     reference | linuxcnc | process:COMMAND | mutant:NAME
  --timeout S    per-case timeout for engines in another process (default 10)
Exit: 0 every case passes (or is not applicable), 1 a case fails or the engine failed, 2 bad usage.
)HELP";

const char* kEnginesHelp = R"HELP(Usage: cyclecert engines

Lists the engines `check` can run: the reference, any external program speaking JSON lines
(process:COMMAND, see the README), and the mutants (the reference with one seeded fault).
)HELP";

const char* kRulesHelp = R"HELP(Usage: cyclecert rules [--cycle C] [--uncited] [--json] [--specs DIR]

Lists every rule of specs/rules.json with its source seed and section, its summary, and how many
spec cases under specs/cases cite it.

Options:
  --cycle C     only the rules of one cycle (G70, G71, G72, G73, G74_1, LCYC95, CYCLE95, …)
  --uncited     only the rules no spec case cites (exit 1 if there are any)
  --json        machine-readable output
  --specs DIR   the specs directory (default: the repository's specs/)
)HELP";

const char* kProfilesHelp = R"HELP(Usage: cyclecert profiles

Lists the controller profiles and the parameter defaults in which they differ.
)HELP";

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

bool wantsHelp(const std::vector<std::string>& args) {
  for (const auto& a : args) if (a == "--help" || a == "-h") return true;
  return false;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("cannot read '" + path + "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeFile(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  std::ofstream out(path, std::ios::binary);
  if (!out || !(out << text)) throw UsageError("cannot write '" + path + "'");
}

struct PlanArgs {
  std::string program, casePath, profile, jsonOut, svgOut;
  std::vector<std::string> params;
  bool mdi = false;
  std::optional<double> noseRadius;
  std::optional<int> tip;
};

double numberArg(const std::string& option, const std::string& text, double min, double max) {
  std::size_t used = 0;
  double v = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v) || v < min || v > max) {
    std::ostringstream s;
    s << option << " expects a number from " << min << " to " << max << ", got '" << text << "'";
    throw UsageError(s.str());
  }
  return v;
}

PlanArgs parsePlanArgs(const std::vector<std::string>& args) {
  PlanArgs p;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--profile") p.profile = value();
    else if (a == "--param") p.params.push_back(value());
    else if (a == "--case") p.casePath = value();
    else if (a == "--json") p.jsonOut = value();
    else if (a == "--svg") p.svgOut = value();
    else if (a == "--mdi") p.mdi = true;
    else if (a == "--nose-radius") p.noseRadius = numberArg(a, value(), 0, 100);
    else if (a == "--tip") {
      const double t = numberArg(a, value(), 0, 9);
      if (t != std::floor(t)) throw UsageError("--tip expects a whole number 0…9");
      p.tip = static_cast<int>(t);
    }
    else if (!a.empty() && a[0] == '-' && a != "-") throw UsageError("unknown option " + a);
    else if (p.program.empty()) p.program = a;
    else throw UsageError("more than one program given ('" + p.program + "', '" + a + "')");
  }
  if (p.program.empty() == p.casePath.empty()) throw UsageError("give either a PROGRAM.nc or --case CASE.json");
  return p;
}

std::vector<std::pair<std::string, double>> parsedParams(const std::vector<std::string>& texts) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& t : texts) {
    MachineParams probe;
    probe.setFromText(t);  // validates the name and value
    const auto eq = t.find('=');
    out.emplace_back(t.substr(0, eq), probe.get(t.substr(0, eq)));
  }
  return out;
}

int commandPlan(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kPlanHelp;
    return kExitOk;
  }
  const PlanArgs a = parsePlanArgs(args);
  std::optional<SpecCase> specCase;
  PlanRequest request;
  std::string title;
  if (!a.casePath.empty()) {
    specCase = loadSpecCase(a.casePath);
    request = {specCase->program, a.casePath + "#/program", specCase->profile, specCase->params, {}};
    request.options.mdi = specCase->mdi;
    if (specCase->tool) request.options.tool = *specCase->tool;
    title = specCase->id + " — " + specCase->title;
  } else {
    request = {readFile(a.program), a.program, "", {}, {}};
    title = a.program;
  }
  if (!a.profile.empty()) request.profile = a.profile;
  if (a.mdi) request.options.mdi = true;
  if (a.noseRadius) request.options.tool.noseRadius = *a.noseRadius;
  if (a.tip) request.options.tool.tip = *a.tip;
  for (auto& p : parsedParams(a.params)) request.params.push_back(p);

  const Toolpath path = planWithReference(request);
  const std::string json = toJson(path).dump(2) + "\n";
  if (a.jsonOut.empty() && a.svgOut.empty()) std::cout << json;
  if (!a.jsonOut.empty()) writeFile(a.jsonOut, json);
  if (!a.svgOut.empty()) writeFile(a.svgOut, renderToolpathSvg(plotInputFor(path, title)));

  std::ostream& report = (a.jsonOut == "-" || (a.jsonOut.empty() && a.svgOut.empty())) ? std::cerr : std::cout;
  for (const Warning& w : path.warnings) report << "warning: line " << w.line << ": " << w.message << "\n";
  if (path.alarm) {
    report << "alarm " << path.alarm->code << " at line " << path.alarm->line << ": " << path.alarm->message << "\n";
  } else if (!a.jsonOut.empty() || !a.svgOut.empty()) {
    report << "planned " << path.cycles.size() << " cycle(s), " << path.moves.size() << " moves\n";
  }
  if (specCase) {
    const auto unmet = unmetExpectation(*specCase, path);
    report << "case " << specCase->id << ": " << (unmet ? "FAIL: " + *unmet : std::string("expectation met")) << "\n";
  }
  return path.alarm ? kExitAlarm : kExitOk;
}

int commandParams(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kParamsHelp;
    return kExitOk;
  }
  for (const auto& a : args) if (a != "--json") throw UsageError("unknown option " + a);
  if (!args.empty()) {
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

int commandRules(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kRulesHelp;
    return kExitOk;
  }
  std::string cycle, specs = defaultSpecsDir();
  bool uncitedOnly = false, json = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--uncited") uncitedOnly = true;
    else if (args[i] == "--json") json = true;
    else if (args[i] == "--cycle" && i + 1 < args.size()) cycle = args[++i];
    else if (args[i] == "--specs" && i + 1 < args.size()) specs = args[++i];
    else throw UsageError("unknown option " + args[i] + " (see `cyclecert rules --help`)");
  }
  const RuleCatalogue catalogue = loadRuleCatalogue(specs + "/rules.json");
  std::map<std::string, int> citations;
  for (const std::string& file : findSpecCaseFiles(specs + "/cases")) {
    for (const std::string& rule : loadSpecCase(file).rules) ++citations[rule];
  }
  nlohmann::json out = nlohmann::json::array();
  int uncited = 0;
  for (const RuleEntry& r : catalogue.rules) {
    if (!cycle.empty() && r.cycle != cycle) continue;
    const int n = citations.count(r.id) ? citations.at(r.id) : 0;
    if (n == 0) ++uncited;
    if (uncitedOnly && n > 0) continue;
    if (json) {
      out.push_back({{"id", r.id}, {"cycle", r.cycle}, {"seed", r.seed}, {"section", r.section},
                     {"summary", r.summary}, {"cases", n}, {"notes", r.notes}});
    } else {
      std::cout << std::left << std::setw(22) << r.id << std::right << std::setw(4) << n << " case(s)  " << r.summary
                << "\n";
    }
  }
  if (json) std::cout << out.dump(2) << "\n";
  else std::cout << uncited << " rule(s) cited by no spec case\n";
  return uncitedOnly && uncited > 0 ? 1 : kExitOk;
}

int commandJudge(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kJudgeHelp;
    return kExitOk;
  }
  std::string casePath, programPath, toolpathPath, svgOut, profile;
  std::vector<std::string> params;
  bool json = false, reference = false, mdi = false;
  std::optional<double> epsilon, noseRadius;
  std::optional<std::size_t> materialAfterMove;
  std::optional<int> tip;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--program") programPath = value();
    else if (a == "--profile") profile = value();
    else if (a == "--param") params.push_back(value());
    else if (a == "--svg") svgOut = value();
    else if (a == "--json") json = true;
    else if (a == "--reference") reference = true;
    else if (a == "--mdi") mdi = true;
    else if (a == "--epsilon") epsilon = numberArg(a, value(), 1e-9, 10);
    else if (a == "--material-after") materialAfterMove = static_cast<std::size_t>(numberArg(a, value(), 0, 1e9));
    else if (a == "--nose-radius") noseRadius = numberArg(a, value(), 0, 100);
    else if (a == "--tip") tip = static_cast<int>(numberArg(a, value(), 0, 9));
    else if (!a.empty() && a[0] == '-' && a != "-") throw UsageError("unknown option " + a);
    else if (casePath.empty() && programPath.empty() && a.size() > 5 && a.substr(a.size() - 5) == ".json" && toolpathPath.empty() && !reference && args.size() > 1 && i + 1 < args.size())
      casePath = a;
    else if (toolpathPath.empty()) toolpathPath = a;
    else throw UsageError("unexpected argument '" + a + "'");
  }
  // A lone JSON argument with --reference is the case.
  if (reference && casePath.empty() && programPath.empty()) std::swap(casePath, toolpathPath);
  if (casePath.empty() && programPath.empty() && !toolpathPath.empty() && !reference) {
    throw UsageError("give the toolpath to judge after the case (CASE.json TOOLPATH.json), or --reference");
  }
  if (casePath.empty() == programPath.empty()) throw UsageError("give a CASE.json or --program FILE.nc");
  if (reference == !toolpathPath.empty()) throw UsageError("give a TOOLPATH.json, or --reference");

  JudgeRequest request;
  std::string title;
  if (!casePath.empty()) {
    const SpecCase c = loadSpecCase(casePath);
    request = judgeRequestFor(c);
    title = c.id;
  } else {
    request.program = {readFile(programPath), programPath, profile, {}, {}};
    title = programPath;
  }
  if (!profile.empty()) request.program.profile = profile;
  for (auto& p : parsedParams(params)) request.program.params.push_back(p);
  if (mdi) request.program.options.mdi = true;
  if (noseRadius) request.program.options.tool.noseRadius = *noseRadius;
  if (tip) request.program.options.tool.tip = *tip;
  if (epsilon) request.settings.epsilon = *epsilon;

  Toolpath path;
  if (reference) {
    path = planWithReference(request.program);
  } else {
    const std::string text = toolpathPath == "-" ? std::string(std::istreambuf_iterator<char>(std::cin), {}) : readFile(toolpathPath);
    try {
      const nlohmann::json j = parseJsonDocument(text, toolpathPath);
      path = toolpathFromJson(j);
      if (!j.contains("start")) path.start = {};
    } catch (const ToolpathFormatError& e) {
      const std::string what = e.what();
      throw UsageError("expected a toolpath JSON document: " + (what.rfind(toolpathPath, 0) == 0 ? what : toolpathPath + ": " + what));
    }
  }
  JudgeInput in = judgeInputFor(request, path);
  if (!reference && !in.program.cycles.empty() && path.start == Point{}) in.path.start = in.program.cycles.front().start;
  const std::vector<Finding> findings = judge(in);
  if (json) std::cout << findingsJson(findings).dump(2) << "\n";
  else if (findings.empty()) std::cout << "no finding: every oracle passes\n";
  else std::cout << findingsText(findings) << findings.size() << " finding(s)\n";
  if (!svgOut.empty()) writeFile(svgOut, renderToolpathSvg(judgePlot(in, findings, title, materialAfterMove)));
  return findings.empty() ? kExitOk : kExitAlarm;
}

int commandEngines(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kEnginesHelp;
    return kExitOk;
  }
  if (!args.empty()) throw UsageError("unknown option " + args.front());
  for (const auto& [name, description] : listEngines()) std::cout << std::left << std::setw(28) << name << description << "\n";
  return kExitOk;
}

int commandCheck(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kCheckHelp;
    return kExitOk;
  }
  std::string engineName;
  CheckOptions options{defaultSpecsDir(), "build/check", false};
  EngineOptions engineOptions;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw UsageError(a + " needs a value");
      return args[++i];
    };
    if (a == "--engine") engineName = value();
    else if (a == "--specs") options.specsDir = value();
    else if (a == "--out") options.outDir = value();
    else if (a == "--resume") options.resume = true;
    else if (a == "--timeout") engineOptions.timeoutSeconds = numberArg(a, value(), 0.01, 86400);
    else throw UsageError("unknown option " + a + " (see `cyclecert check --help`)");
  }
  if (engineName.empty()) throw UsageError("give --engine (see `cyclecert engines`)");
  const auto engine = makeEngine(engineName, engineOptions);
  const CheckSummary s = runCheck(*engine, options, std::cerr);
  std::cout << "check " << engine->name() << ": " << s.pass << " pass, " << s.fail << " fail, " << s.notApplicable
            << " not applicable, " << s.engineFailure << " engine failure(s)";
  if (s.skipped) std::cout << ", " << s.skipped << " already done";
  std::cout << "; results in " << options.outDir << "/results.jsonl\n";
  return s.clean() ? kExitOk : kExitAlarm;
}

int commandProfiles(const std::vector<std::string>& args) {
  if (wantsHelp(args)) {
    std::cout << kProfilesHelp;
    return kExitOk;
  }
  if (!args.empty()) throw UsageError("unknown option " + args.front());
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

int run(const std::vector<std::string>& argv) {
  if (argv.empty()) {
    std::cerr << kMainHelp;
    return kExitUsage;
  }
  const std::string command = argv.front();
  const std::vector<std::string> args(argv.begin() + 1, argv.end());
  if (command == "--help" || command == "-h") {
    std::cout << kMainHelp;
    return kExitOk;
  }
  if (command == "help") {
    if (args.empty()) std::cout << kMainHelp;
    else return run({args.front(), "--help"});
    return kExitOk;
  }
  if (command == "--version") {
    std::cout << "cyclecert " << CYCLECERT_VERSION << "\n";
    return kExitOk;
  }
  if (command == "plan") return commandPlan(args);
  if (command == "params") return commandParams(args);
  if (command == "rules") return commandRules(args);
  if (command == "judge") return commandJudge(args);
  if (command == "check") return commandCheck(args);
  if (command == "engines") return commandEngines(args);
  if (command == "profiles") return commandProfiles(args);
  throw UsageError("unknown command '" + command + "' (try `cyclecert --help`)");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  } catch (const ParseError& e) {
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  } catch (const NotSupported& e) {
    std::cerr << "cyclecert: not supported yet: " << e.what() << "\n";
    return kExitNotSupported;
  } catch (const std::exception& e) {  // unknown profile or parameter, bad spec case, I/O
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  }
}
