// `cyclecert report`: a run's report files from its results, and the same at the end of `check`
// and `fuzz`.
#include <iostream>

#include "harness/cli/cli_support.h"
#include "harness/results/report_files.h"
#include "harness/spec/rule_catalogue.h"

namespace cyclecert::cli {

namespace {

const char* kReportHelp = R"HELP(Usage: cyclecert report OUT [--specs DIR]

Writes the report of the run in directory OUT — OUT/report.json (format cyclecert-report/1, schema
specs/schema/report.schema.json), OUT/junit.xml (for CI) and OUT/index.html (for people) — from
OUT/results.jsonl (one run, or runs and shards joined by `cyclecert merge`), OUT/run.json (which
engines, versions, revision, spec suite and seeds) and the rule catalogue DIR/rules.json. `check`
and `fuzz` write the same files at the end of their run; this regenerates them, e.g. after a
killed run or a merge.

The report says, per engine, which rules it conforms to (a rule fails when a case fails it, see
reports/README.md), every spec and regression case's verdict with its findings, and the fuzz
campaign's counts with each failing generated case, its seed and the command that reproduces it.
A line of results.jsonl that is not a result (the torn last line of a killed run) is skipped,
counted and named (file:line) on stderr; progress goes to stderr too.

Options:
  --specs DIR   where rules.json is (default: the repository's specs/)
Exit: 0 written, 2 bad usage, no OUT/results.jsonl, or an OUT/run.json that cannot be read.
)HELP";

}  // namespace

void writeRunReport(const std::string& outDir, const std::string& specsDir) {
  const ReportFiles r = writeReportFiles(outDir, specsDir, std::cerr);
  std::cout << "report of " << r.lines << " result(s)";
  if (r.corrupt) std::cout << " (" << r.corrupt << " line(s) skipped)";
  std::cout << ": " << reportHeadline(r) << "; in " << outDir << "/report.json, " << outDir << "/junit.xml";
  if (!r.indexHtml.empty()) std::cout << ", " << r.indexHtml;
  std::cout << "\n";
}

static int commandReport(const std::vector<std::string>& args) {
  std::string specsDir = defaultSpecsDir();
  const auto positional = parseOptions(args, {{"--specs", [&](const std::string& v) { specsDir = v; }}}, "report");
  if (positional.empty()) throw UsageError("give the run's directory OUT (see `cyclecert report --help`)");
  if (positional.size() > 1) throw UsageError("more than one directory given ('" + positional[0] + "', '" + positional[1] + "')");
  writeRunReport(positional.front(), specsDir);
  return kExitOk;
}

extern const Command kReportCommand{"report", kReportHelp, commandReport};

}  // namespace cyclecert::cli
