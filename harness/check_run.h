#pragma once
// `cyclecert check`: every spec case against one engine. A case passes when the engine meets its
// expectation (the toolpath within the case's tolerance, or the alarm) and, for a planned toolpath,
// every oracle finds nothing. Each result is appended to OUT/results.jsonl as it finishes, so a
// killed run keeps every result; --resume skips the cases already there.
#include <iosfwd>
#include <string>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/metamorphic_run.h"
#include "harness/results_file.h"

namespace cyclecert {

// With `relations` (--metamorphic), every metamorphic relation's follow-up runs through the engine
// too and is counted there (harness/metamorphic_run.h).
CaseResult checkCase(Engine& engine, const SpecCase& c, MetamorphicTally* relations = nullptr);

struct CheckOptions {
  std::string specsDir;  // holds cases/
  std::string regressionsDir;  // shrunk fuzz failures (spec cases) run after the specs; "" for none
  std::string outDir;    // results.jsonl goes here
  bool resume = false;
  bool metamorphic = false;  // --metamorphic: every case's follow-ups too
};

struct CheckSummary {
  int pass = 0, fail = 0, notApplicable = 0, engineFailure = 0, skipped = 0;
  MetamorphicTally metamorphic;  // with --metamorphic
  bool clean() const { return fail == 0 && engineFailure == 0; }
};

// Runs the cases, reporting progress on `progress` for runs longer than a few seconds.
CheckSummary runCheck(Engine& engine, const CheckOptions& options, std::ostream& progress);

}  // namespace cyclecert
