// `cyclecert baseline`: an expectation file (harness/results/expectations.h) from a run's results.
#include <iostream>

#include "harness/cli/cli_support.h"
#include "harness/results/expectations.h"

namespace cyclecert::cli {

namespace {

const char* kBaselineHelp = R"HELP(Usage: cyclecert baseline OUT [--engine E] [--format json|text] > FILE

Writes, on standard output, an expectation file for the run in directory OUT (its results.jsonl,
from `check`, `fuzz` or `merge`): one entry per failing or engine-failure case, by case id, with
its outcome and a reason naming the kinds of its findings and its first detail. Give it to
`check --expectations FILE` (or `fuzz`, with the same --seed) and the run is green until something
new fails. Edit the reasons to say why each failure is expected (a dialect difference, a defect
filed elsewhere) and group entries by rule or kind where that is honest (README "Expectation
files").

Options:
  --engine E        the engine whose results to take, when OUT holds several (a merge)
  --format F        json (default: {"expectations": [{"case", "outcome", "reason"}, …]}) or text
                    (`ID OUTCOME # reason` lines)
Exit: 0 written, 2 bad usage, no OUT/results.jsonl, or several engines in it and no --engine.
)HELP";

}  // namespace

static int commandBaseline(const std::vector<std::string>& args) {
  std::string engine, format = "json";
  const auto positional = parseOptions(args,
                                       {{"--engine", [&](const std::string& v) { engine = v; }},
                                        {"--format", [&](const std::string& v) { format = v; }}},
                                       "baseline");
  if (positional.empty()) throw UsageError("give the run's directory OUT (see `cyclecert baseline --help`)");
  if (positional.size() > 1) throw UsageError("more than one directory given ('" + positional[0] + "', '" + positional[1] + "')");
  if (format != "json" && format != "text") throw UsageError("--format expects json or text, got '" + format + "'");
  const Expectations e = baselineOfRun(positional.front(), engine);
  std::cout << (format == "json" ? expectationsJson(e) : expectationsText(e));
  std::cerr << "baseline: " << e.entries.size() << " expected failure(s) from " << positional.front() << "/results.jsonl\n";
  return kExitOk;
}

extern const Command kBaselineCommand{"baseline", kBaselineHelp, commandBaseline};

}  // namespace cyclecert::cli
