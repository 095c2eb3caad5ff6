// `cyclecert judge`: a toolpath (any engine's, as JSON) judged with every oracle.
#include <iostream>

#include "harness/cli/cli_support.h"
#include "harness/io/input_file.h"
#include "harness/judge/judging.h"
#include "harness/spec/spec_case.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert::cli {

namespace {

const char* kJudgeHelp = R"HELP(Usage: cyclecert judge CASE.json TOOLPATH.json [options]
       cyclecert judge --program FILE.nc [--profile P] [--param N=V]… TOOLPATH.json [options]
       cyclecert judge CASE.json --reference [options]

Judges a toolpath with every oracle, from the program's finish shape, allowances and stock alone
(never from the reference planner): no-gouge, rapids-in-air, complete, depth-per-pass, pass-levels,
retract, pocket-entry, returns-to-start, feeds, alarm. TOOLPATH.json is the canonical toolpath JSON (see `cyclecert plan
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

}  // namespace

static int commandJudge(const std::vector<std::string>& args) {
  std::string casePath, programPath, toolpathPath, svgOut, profile;
  std::vector<std::string> params;
  bool json = false, reference = false, mdi = false;
  std::optional<double> epsilon, noseRadius;
  std::optional<std::size_t> materialAfterMove;
  std::optional<int> tip;
  const auto positional = parseOptions(
      args,
      {{"--program", [&](const std::string& v) { programPath = v; }},
       {"--profile", [&](const std::string& v) { profile = v; }},
       {"--param", [&](const std::string& v) { params.push_back(v); }},
       {"--svg", [&](const std::string& v) { svgOut = v; }},
       {"--json", [&] { json = true; }},
       {"--reference", [&] { reference = true; }},
       {"--mdi", [&] { mdi = true; }},
       {"--epsilon", [&](const std::string& v) { epsilon = numberArg("--epsilon", v, 1e-9, 10); }},
       {"--material-after",
        [&](const std::string& v) { materialAfterMove = static_cast<std::size_t>(numberArg("--material-after", v, 0, 1e9)); }},
       {"--nose-radius", [&](const std::string& v) { noseRadius = numberArg("--nose-radius", v, 0, 100); }},
       {"--tip", [&](const std::string& v) { tip = static_cast<int>(numberArg("--tip", v, 0, 9)); }}},
      "judge");
  // CASE.json TOOLPATH.json, --program FILE.nc TOOLPATH.json, or CASE.json --reference.
  if (positional.size() > 2 || (positional.size() == 2 && !programPath.empty())) {
    throw UsageError("unexpected argument '" + positional.back() + "'");
  }
  if (positional.size() == 2) {
    casePath = positional[0];
    toolpathPath = positional[1];
  } else if (positional.size() == 1) {
    (reference && programPath.empty() ? casePath : toolpathPath) = positional[0];
  }
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
    const std::string text = toolpathPath == "-" ? readInputStream(std::cin, "standard input") : readFile(toolpathPath);
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

extern const Command kJudgeCommand{"judge", kJudgeHelp, commandJudge};

}  // namespace cyclecert::cli
