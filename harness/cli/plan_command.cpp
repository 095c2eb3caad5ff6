// `cyclecert plan`: a program or a spec case planned by the reference engine.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

#include "harness/cli/cli_support.h"
#include "harness/engines/reference_plan.h"
#include "harness/judge/spec_check.h"
#include "harness/spec/spec_case.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert::cli {

namespace {

const char* kPlanHelp = R"HELP(Usage: cyclecert plan PROGRAM.nc [options]
       cyclecert plan --case CASE.json [options]

Plans the program with the reference engine: every move from the first positioning on (phase
"program") and every G70/G71/G72/G73 cycle (and G74.1 under gsk), or LCYC95/CYCLE95 under the
SINUMERIK profiles (`cyclecert profiles` lists the dialects). A SINUMERIK contour subprogram is
read from after the main program (a line `L42.spf`, then its blocks), or from `L42.spf`/`L42.SPF`
beside PROGRAM.nc.

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
       "shape": "line"|"arc_cw"|"arc_ccw", "to": {"x", "z"}, "center"?, "feed"?, "dwell"?, "phase", "rules"}],
       "alarm": null | {"code", "message", "line"}, "warnings", "cycles"}   (x = radius, mm)
Exit: 0 planned, 1 the controller alarmed (JSON still written), 2 bad usage or unreadable or
malformed input, 3 not supported by the reference yet.
)HELP";

struct PlanArgs {
  std::string program, casePath, profile, jsonOut, svgOut;
  std::vector<std::string> params;
  bool mdi = false;
  std::optional<double> noseRadius;
  std::optional<int> tip;
};

PlanArgs parsePlanArgs(const std::vector<std::string>& args) {
  PlanArgs p;
  const auto positional = parseOptions(
      args,
      {{"--profile", [&](const std::string& v) { p.profile = v; }},
       {"--param", [&](const std::string& v) { p.params.push_back(v); }},
       {"--case", [&](const std::string& v) { p.casePath = v; }},
       {"--json", [&](const std::string& v) { p.jsonOut = v; }},
       {"--svg", [&](const std::string& v) { p.svgOut = v; }},
       {"--mdi", [&] { p.mdi = true; }},
       {"--nose-radius", [&](const std::string& v) { p.noseRadius = numberArg("--nose-radius", v, 0, 100); }},
       {"--tip",
        [&](const std::string& v) {
          const double t = numberArg("--tip", v, 0, 9);
          if (t != std::floor(t)) throw UsageError("--tip expects a whole number 0…9");
          p.tip = static_cast<int>(t);
        }}},
      "plan");
  if (positional.size() > 1) throw UsageError("more than one program given ('" + positional[0] + "', '" + positional[1] + "')");
  if (!positional.empty()) p.program = positional.front();
  if (p.program.empty() == p.casePath.empty()) throw UsageError("give either a PROGRAM.nc or --case CASE.json");
  return p;
}

// The directory of a program file ("." for a bare file name).
std::string siblingDirectoryOf(const std::string& program) {
  const std::string parent = std::filesystem::path(program).parent_path().string();
  return parent.empty() ? "." : parent;
}

}  // namespace

static int commandPlan(const std::vector<std::string>& args) {
  const PlanArgs a = parsePlanArgs(args);
  std::optional<SpecCase> specCase;
  PlanRequest request;
  std::string title;
  if (!a.casePath.empty()) {
    specCase = loadSpecCase(a.casePath);
    request = planRequestFor(*specCase);
    title = specCase->id + " — " + specCase->title;
  } else {
    request = {readFile(a.program), a.program, "", {}, {}};
    request.subprogramDirectory = siblingDirectoryOf(a.program);  // SIEMENS.SUB: NAME.spf next to it
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

extern const Command kPlanCommand{"plan", kPlanHelp, commandPlan};

}  // namespace cyclecert::cli
