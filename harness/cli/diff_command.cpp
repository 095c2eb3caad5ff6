// `cyclecert diff`: two engines on one program or spec case — their outcomes, where they first
// part (with the moves around it side by side), and an SVG of both toolpaths.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <tuple>

#include <nlohmann/json.hpp>

#include "harness/cli/cli_support.h"
#include "harness/engines/engine.h"
#include "harness/engines/reference_plan.h"
#include "harness/judge/engine_diff.h"
#include "harness/judge/metamorphic_run.h"
#include "harness/judge/toolpath_compare.h"
#include "harness/results/failure_plot.h"
#include "harness/spec/program_case.h"
#include "harness/spec/spec_case.h"
#include "reference/model/profile.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert::cli {

namespace {

using nlohmann::ordered_json;  // the --json output, in the order the help lists its fields

const char* kDiffHelp = R"HELP(Usage: cyclecert diff --engine A --vs B PROGRAM.nc|CASE.json [options]

Runs engines A and B (`cyclecert engines`) on one program or spec case and compares what they
planned, move by move: kind, shape, end point, centre and feed within the tolerance; alarms by code
and line (an engine's own alarm codes are matched on the line). Shows each engine's outcome and,
when they differ, the first divergence with the moves around it side by side ('>' marks it). A
case's expectation is not judged here (that is `cyclecert check`): only the two engines are compared.

Options:
  --engine A           the first engine: reference | linuxcnc | process:COMMAND | mutant:NAME
  --vs B               the engine to compare it with
  --profile P          controller profile (default: the case's; for a program its "(profile: P)"
                       header comment, else fanuc-0i-f)
  --param NAME=VALUE   set a machine parameter by number or mnemonic (repeatable; applied after
                       the case's)
  --tolerance T        mm (default: the case's tolerance, else 0.001)
  --context N          moves shown before and after the divergence (default 3)
  --svg OUT            write an SVG of both toolpaths over the contours (A rapids dashed red, feeds
                       blue; B rapids dashed purple, feeds green), the first divergence ringed
  --timeout S          per-run timeout for engines in another process (default 10)
  --metamorphic        also run every metamorphic relation that applies (oracles/metamorphic) on
                       each engine: its follow-up programs through the same engine, whose toolpaths
                       must be the relation's transformations of its own; shows per engine the
                       relations run, held, violated (with the first divergence and the follow-up
                       program) and skipped
  --json               the result as JSON on standard output instead of the text
  --help               this help

A file ending in .json is a spec case; anything else is a program.
JSON: {"input", "profile", "tolerance", "engines": [{"name", "outcome", "moves", "alarm", "detail",
       "seconds"}, …], "comparable", "agree", "divergence": null | {"text", "move": N | null},
       "context": [{"move", "a", "b"}], "svg"}   (moves are numbered from 0); with --metamorphic
       also "metamorphic": {ENGINE: {"counts", "violations": [{"relation", "rules", "divergence",
       "move", "follow_up": {"profile", "program"}}], "engine_failure"}}
Exit: 0 the engines agree (and, with --metamorphic, neither violates a relation or fails on a
follow-up), 1 they diverge — or either engine is not applicable or failed, so they cannot be
compared, or a relation is violated —, 2 bad usage or unreadable input.
)HELP";

struct DiffArgs {
  std::string input, engineA, engineB, profile, svgOut;
  std::vector<std::string> params;
  std::optional<double> tolerance;
  std::size_t context = 3;
  EngineOptions engineOptions;
  bool json = false;
  bool metamorphic = false;
};

DiffArgs parseDiffArgs(const std::vector<std::string>& args) {
  DiffArgs d;
  const auto positional = parseOptions(
      args,
      {{"--engine", [&](const std::string& v) { d.engineA = v; }},
       {"--vs", [&](const std::string& v) { d.engineB = v; }},
       {"--profile", [&](const std::string& v) { d.profile = v; }},
       {"--param", [&](const std::string& v) { d.params.push_back(v); }},
       {"--tolerance", [&](const std::string& v) { d.tolerance = numberArg("--tolerance", v, 0, 1000); }},
       {"--context",
        [&](const std::string& v) {
          const double n = numberArg("--context", v, 0, 1000);
          if (n != std::floor(n)) throw UsageError("--context expects a whole number of moves, got '" + v + "'");
          d.context = static_cast<std::size_t>(n);
        }},
       {"--svg", [&](const std::string& v) { d.svgOut = v; }},
       {"--timeout", [&](const std::string& v) { d.engineOptions.timeoutSeconds = numberArg("--timeout", v, 0.01, 86400); }},
       {"--json", [&] { d.json = true; }},
       {"--metamorphic", [&] { d.metamorphic = true; }}},
      "diff");
  if (positional.size() > 1) throw UsageError("more than one input given ('" + positional[0] + "', '" + positional[1] + "')");
  if (positional.empty()) throw UsageError("give a PROGRAM.nc or CASE.json (see `cyclecert diff --help`)");
  if (d.engineA.empty() || d.engineB.empty()) throw UsageError("give both --engine A and --vs B (see `cyclecert engines`)");
  if (d.json && d.svgOut == "-") throw UsageError("--json and --svg - would both write to standard output");
  d.input = positional.front();
  return d;
}

SpecCase diffedCase(const DiffArgs& a) {
  const auto params = parsedParams(a.params);
  if (isSpecCaseFile(a.input)) return withCaseOverrides(parseSpecCase(readFile(a.input), a.input), a.profile, params);
  return specCaseForProgram(a.input, readFile(a.input), "diff",
                            {a.profile, params, a.tolerance, "`cyclecert diff` to compare two engines on it"});
}

// ---- reporting ------------------------------------------------------------------------------

std::string outcomeText(const EngineResult& r) {
  switch (r.kind) {
    case EngineResult::Planned:
      return "planned " + std::to_string(r.path.moves.size()) + " moves";
    case EngineResult::Alarmed: {
      std::string s = "alarm " + r.path.alarm->code + " at line " + std::to_string(r.path.alarm->line) + ": " +
                      r.path.alarm->message;
      if (!r.path.moves.empty()) s += " (after " + std::to_string(r.path.moves.size()) + " moves)";
      return s;
    }
    case EngineResult::NotApplicable: return "not applicable: " + r.detail;
    case EngineResult::Failed: return "engine failure: " + r.detail;
  }
  return "engine failure: " + r.detail;
}

// What the person reads when the engines agree.
std::string agreementText(const EngineResult& a, const EngineResult& b, double tolerance) {
  std::ostringstream s;
  if (a.kind == EngineResult::Alarmed) {
    s << "the engines agree (both alarm: " << a.path.alarm->code << " at line " << a.path.alarm->line << ", "
      << b.path.alarm->code << " at line " << b.path.alarm->line << ")";
  } else {
    s << "the engines agree (" << a.path.moves.size() << " moves within " << tolerance << " mm)";
  }
  return s.str();
}

// Why the two could not be compared: the engine(s) that gave no toolpath and no alarm.
std::string notComparableText(const EngineResult& a, const std::string& aName, const EngineResult& b,
                              const std::string& bName) {
  std::string who;
  for (const auto& [r, name] : {std::pair{&a, &aName}, std::pair{&b, &bName}}) {
    if (hasOutcome(*r)) continue;
    if (!who.empty()) who += " and ";
    who += *name + (r->kind == EngineResult::NotApplicable ? " is not applicable" : " failed");
  }
  return "cannot compare the engines: " + who;
}

struct ContextRow {
  std::size_t move;
  std::optional<std::string> a, b;  // nothing where that engine has no such move
};

std::vector<ContextRow> contextRows(const Toolpath& a, const Toolpath& b, std::size_t at, std::size_t context) {
  std::vector<ContextRow> rows;
  const std::size_t count = std::max(a.moves.size(), b.moves.size());
  if (count == 0) return rows;
  const std::size_t first = at > context ? at - context : 0;
  const std::size_t last = std::min(count - 1, at + context);
  for (std::size_t i = first; i <= last; ++i) {
    ContextRow row{i, {}, {}};
    if (i < a.moves.size()) row.a = describeMove(a.moves[i]);
    if (i < b.moves.size()) row.b = describeMove(b.moves[i]);
    rows.push_back(row);
  }
  return rows;
}

void printContext(std::ostream& out, const std::vector<ContextRow>& rows, std::size_t at, const std::string& aName,
                  const std::string& bName) {
  const std::string none = "(no move)";
  std::size_t width = aName.size();
  for (const ContextRow& r : rows) width = std::max(width, r.a.value_or(none).size());
  out << "\n  " << std::setw(5) << "move" << "  " << std::left << std::setw(static_cast<int>(width)) << aName << "  "
      << bName << std::right << "\n";
  for (const ContextRow& r : rows) {
    out << (r.move == at ? "> " : "  ") << std::setw(5) << r.move << "  " << std::left
        << std::setw(static_cast<int>(width)) << r.a.value_or(none) << "  " << r.b.value_or(none) << std::right << "\n";
  }
  out << "\n";
}

ordered_json engineJson(const std::string& name, const EngineResult& r) {
  ordered_json j = {{"name", name}, {"outcome", kindName(r.kind)}, {"moves", r.path.moves.size()}, {"alarm", nullptr},
            {"detail", nullptr}, {"seconds", r.seconds}};
  if (r.path.alarm) {
    j["alarm"] = {{"code", r.path.alarm->code}, {"line", r.path.alarm->line}, {"message", r.path.alarm->message}};
  }
  if (!r.detail.empty()) j["detail"] = r.detail;
  return j;
}

std::string svgLabel(const std::string& name, const EngineResult& r) {
  return hasOutcome(r) ? name : name + " (" + kindName(r.kind) + ")";
}

// Engine B's toolpath over engine A's, on A's contours (B's when A recorded no cycle), with a ring
// at the end of the diverging move of each.
std::string diffSvg(const std::string& title, const EngineResult& a, const std::string& aName, const EngineResult& b,
                    const std::string& bName, const std::optional<EngineDivergence>& divergence) {
  PlotInput in = plotInputFor(a.path.cycles.empty() ? b.path : a.path, title);
  in.path = a.path;
  addComparison(in, svgLabel(aName, a), {svgLabel(bName, b), b.path, divergence ? divergence->move : std::nullopt});
  return renderToolpathSvg(in);
}

}  // namespace

static int commandDiff(const std::vector<std::string>& args) {
  const DiffArgs a = parseDiffArgs(args);
  // Both engines first, so that a misspelt --vs is reported before anything runs.
  const auto engineA = makeEngine(a.engineA, a.engineOptions);
  const auto engineB = makeEngine(a.engineB, a.engineOptions);
  const SpecCase c = diffedCase(a);
  if (!findProfile(c.profile)) throw UnknownProfile(c.profile);
  const double tolerance = a.tolerance.value_or(c.tolerance);

  // The same engine twice is allowed (is it deterministic?); its two runs need telling apart.
  const bool sameName = a.engineA == a.engineB;
  const std::string aName = sameName ? a.engineA + " [A]" : a.engineA;
  const std::string bName = sameName ? a.engineB + " [B]" : a.engineB;

  const EngineResult resultA = engineA->run(c);
  const EngineResult resultB = engineB->run(c);
  const bool canCompare = hasOutcome(resultA) && hasOutcome(resultB);
  const auto divergence = compareEngineResults(resultA, aName, resultB, bName, tolerance);
  const bool agree = canCompare && !divergence;
  std::vector<ContextRow> rows;
  if (divergence && divergence->move) rows = contextRows(resultA.path, resultB.path, *divergence->move, a.context);
  // --metamorphic: each engine against itself, on the case it planned (or alarmed on).
  std::vector<std::pair<std::string, RelationsVerdict>> relations;
  if (a.metamorphic) {
    for (const auto& [engine, result, name] :
         {std::tuple{engineA.get(), &resultA, &aName}, std::tuple{engineB.get(), &resultB, &bName}}) {
      if (hasOutcome(*result)) relations.emplace_back(*name, checkRelations(*engine, c, result->path, tolerance));
    }
  }
  const bool relationsHold =
      std::all_of(relations.begin(), relations.end(), [](const auto& r) { return relationsClean(r.second); });

  if (!a.svgOut.empty()) {
    // The file's name, not its path, so that the title stays on the canvas.
    const std::string title = "diff: " + aName + " vs " + bName + " \u2014 " + std::filesystem::path(a.input).filename().string();
    writeFile(a.svgOut, diffSvg(title, resultA, aName, resultB, bName, divergence));
  }

  if (a.json) {
    ordered_json out = {{"input", a.input},
                        {"profile", c.profile},
                        {"tolerance", tolerance},
                        {"engines", ordered_json::array({engineJson(aName, resultA), engineJson(bName, resultB)})},
                        {"comparable", canCompare},
                        {"agree", agree},
                        {"divergence", nullptr},
                        {"context", ordered_json::array()},
                        {"svg", a.svgOut.empty() ? ordered_json(nullptr) : ordered_json(a.svgOut)}};
    if (divergence) {
      out["divergence"] = {{"text", divergence->text},
                           {"move", divergence->move ? ordered_json(*divergence->move) : ordered_json(nullptr)}};
    }
    for (const ContextRow& r : rows) {
      const auto text = [](const std::optional<std::string>& t) { return t ? ordered_json(*t) : ordered_json(nullptr); };
      out["context"].push_back({{"move", r.move}, {"a", text(r.a)}, {"b", text(r.b)}});
    }
    if (a.metamorphic) {
      out["metamorphic"] = ordered_json::object();
      for (const auto& [name, verdict] : relations) out["metamorphic"][name] = relationsJson(verdict);
    }
    // Replies of external engines may hold anything; the output must still be JSON.
    std::cout << out.dump(2, ' ', false, ordered_json::error_handler_t::replace) << "\n";
  } else {
    std::cout << "diff of " << a.input << " (profile " << c.profile << ", tolerance " << tolerance << " mm)\n";
    const std::size_t width = std::max(aName.size(), bName.size());
    std::cout << "  " << std::left << std::setw(static_cast<int>(width)) << aName << "  " << outcomeText(resultA) << "\n"
              << "  " << std::setw(static_cast<int>(width)) << bName << "  " << outcomeText(resultB) << std::right << "\n";
    if (!canCompare) {
      std::cout << notComparableText(resultA, aName, resultB, bName) << "\n";
    } else if (agree) {
      std::cout << agreementText(resultA, resultB, tolerance) << "\n";
    } else {
      std::cout << "first divergence: " << divergence->text << "\n";
      if (!rows.empty()) printContext(std::cout, rows, *divergence->move, aName, bName);
    }
    for (const auto& [name, verdict] : relations) std::cout << relationsText(name, verdict);
    if (!a.svgOut.empty() && a.svgOut != "-") std::cout << "svg written to " << a.svgOut << "\n";
  }
  return agree && relationsHold ? kExitOk : kExitAlarm;
}

extern const Command kDiffCommand{"diff", kDiffHelp, commandDiff};

}  // namespace cyclecert::cli
