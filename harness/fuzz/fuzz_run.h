#pragma once
// `cyclecert fuzz`: generated cases (case_generator.h) through an engine and every oracle and,
// with --vs, compared with a second engine. A failure is shrunk to a minimal case (RapidCheck's
// shrink tree, keeping the same kind of failure), printed with the seed that regenerates it, and
// written as a spec case to the regressions directory, which `check` runs.
//
// Case i of a run with seed S is generated from the case seed S + i·φ (φ = 0x9E3779B97F4A7C15),
// so `--seed <case seed> --cases 1` regenerates exactly that case, and shard K of N runs the cases
// with i mod N = K − 1 — the union of the shards is the unsharded run.
#include <cstdint>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/fuzz/case_generator.h"
#include "harness/judge/metamorphic_run.h"
#include "harness/results/expectations.h"
#include "harness/results/results_file.h"
#include "harness/run/worker_engines.h"

namespace cyclecert {

struct FuzzOptions {
  std::uint64_t seed = 1;
  std::optional<long> cases;      // stop after this many cases (of the whole campaign, all shards)
  std::optional<double> seconds;  // stop after this long
  int shard = 1, shards = 1;      // run shard K of N (1-based)
  std::string outDir = "build/fuzz";
  std::string regressionsDir;     // where shrunk failures are written ("" for nowhere)
  bool resume = false;
  int shrinkBudget = 400;         // engine runs spent shrinking one failure at most
  std::optional<long> maxFailures;  // stop once this many cases have failed
  double tolerance = 1e-3;        // mm, for the oracles and the comparison with --vs
  CycleFormats formats = kDefaultCycleFormats;  // the cycle formats drawn (--formats)
  FuzzCycles cycles = kDefaultFuzzCycles;       // the cycles drawn (--cycles)
  const Expectations* expectations = nullptr;   // --expectations: known failures are neither counted as failing nor shrunk
  int jobs = 1;                   // workers (--jobs), each with its own engines; the results do not depend on it
  bool metamorphic = false;  // --metamorphic: the relations too (harness/fuzz/fuzz_relations.h)
};

inline constexpr long kDefaultFuzzCases = 2000;

struct FuzzFailure {
  std::uint64_t caseSeed = 0;
  std::string kind;       // the oracle that found it, "diverges", or "engine-failure"
  std::string detail;     // of the shrunk case
  std::vector<std::string> rules;  // the rules of the oracle that found it (none for the other kinds)
  FuzzCase shrunk;
  int shrinkRuns = 0;     // engine runs spent shrinking
  std::string regressionFile;  // "" when not written
};

struct FuzzSummary {
  long run = 0, pass = 0, fail = 0, notApplicable = 0, engineFailure = 0, skipped = 0;
  long expectedFailures = 0, unexpectedPasses = 0;  // with expectations (fail, engineFailure: the others)
  double seconds = 0;
  std::vector<FuzzFailure> failures;  // one per failing case, shrunk
  MetamorphicTally metamorphic;       // with --metamorphic: the relations' counts (not the shrinker's runs)
  bool clean() const { return fail == 0 && engineFailure == 0; }
};

std::uint64_t fuzzCaseSeed(std::uint64_t runSeed, long index);
std::string caseSeedTag(std::uint64_t caseSeed);  // 16 hex digits: names the case's results and files

// The case a case seed generates (its RapidCheck shrink tree's root), drawing from `formats` and `cycles`.
FuzzCase generateFuzzCase(std::uint64_t caseSeed, const CycleFormats& formats = kDefaultCycleFormats,
                          const FuzzCycles& cycles = kDefaultFuzzCycles);

// One generated case through `engine` (and `vs`): pass, fail (the case's expected alarm not met —
// kind "expected-alarm" —, an oracle finding, or a divergence), not-applicable or engine-failure;
// `kind` names what failed. When the oracles refuse to judge the case (NotSupported: G73 today) it
// is not applicable — after the comparison with `vs`, which still judges it — unless its expected
// alarm was met, which makes it pass.
struct FuzzVerdict {
  std::string verdict, kind, detail;
  std::vector<Finding> findings;
  double seconds = 0;
  std::optional<MetamorphicViolation> violation;  // a metamorphic kind's: both paths, for the plot
};
FuzzVerdict judgeFuzzCase(Engine& engine, Engine* vs, const SpecCase& c, double tolerance);
// The same for a result the engine already gave (a batch's; moved in, its toolpath is not copied).
FuzzVerdict judgeFuzzResult(EngineResult r, const Engine& engine, Engine* vs, const SpecCase& c, double tolerance);

// Cases per engine batch: one rs274 start serves this many.
inline constexpr std::size_t kFuzzBatch = 64;

// Runs the campaign; progress (cases/s, failures so far) goes to `progress` every few seconds,
// and each failure as it is found, with its seed and the command that reproduces it.
// With options.jobs workers, each with the engines makeEngines makes (harness/run/parallel_run.h): the
// results, their order in results.jsonl and the failures kept are those of one worker.
FuzzSummary runFuzz(const EnginesMaker& makeEngines, const FuzzOptions& options, std::ostream& progress);
// On one worker with these engines (options.jobs is not used).
FuzzSummary runFuzz(Engine& engine, Engine* vs, const FuzzOptions& options, std::ostream& progress);

}  // namespace cyclecert
