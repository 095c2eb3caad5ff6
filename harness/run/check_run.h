#pragma once
// `cyclecert check`: every spec case against one engine. A case passes when the engine meets its
// expectation (the toolpath within the case's tolerance, or the alarm) and, for a planned toolpath,
// every oracle finds nothing. Each result is appended to OUT/results.jsonl as it finishes, so a
// killed run keeps every result; --resume skips the cases already there.
#include <iosfwd>
#include <string>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/judge/metamorphic_run.h"
#include "harness/results/expectations.h"
#include "harness/results/results_file.h"
#include "harness/run/worker_engines.h"

namespace cyclecert {

// With `relations` (--metamorphic), every metamorphic relation's follow-up runs through the engine
// too and is counted there (harness/judge/metamorphic_run.h).
CaseResult checkCase(Engine& engine, const SpecCase& c, MetamorphicTally* relations = nullptr);

struct CheckOptions {
  std::string specsDir;  // holds cases/
  std::string regressionsDir;  // shrunk fuzz failures (spec cases) run after the specs; "" for none
  std::string outDir;    // results.jsonl goes here
  bool resume = false;
  const Expectations* expectations = nullptr;  // --expectations: known failures do not fail the run
  int jobs = 1;               // workers (--jobs), each with its own engine; the results do not depend on it
  int shard = 1, shards = 1;  // run shard K of N (1-based): case i of the list (specs, then regressions) when i mod N = K − 1
  bool metamorphic = false;  // --metamorphic: every case's follow-ups too
};

struct CheckSummary {
  int pass = 0, fail = 0, notApplicable = 0, engineFailure = 0, skipped = 0;
  // With expectations: fail and engineFailure count only the failures no entry covers.
  int expectedFailures = 0, unexpectedPasses = 0;
  std::vector<Expectation> unusedExpectations;  // entries no result of a whole run matched (not with --resume)
  MetamorphicTally metamorphic;  // with --metamorphic
  bool clean() const { return fail == 0 && engineFailure == 0; }
  bool strictClean() const { return clean() && unexpectedPasses == 0 && unusedExpectations.empty(); }
};

// Runs the cases, reporting progress on `progress` for runs longer than a few seconds.
// With options.jobs workers, each with the engine makeEngines makes (its vs is not used); the
// results and their order in results.jsonl are those of one worker (harness/run/parallel_run.h).
CheckSummary runCheck(const EnginesMaker& makeEngines, const CheckOptions& options, std::ostream& progress);
// On one worker with this engine (options.jobs is not used).
CheckSummary runCheck(Engine& engine, const CheckOptions& options, std::ostream& progress);

}  // namespace cyclecert
