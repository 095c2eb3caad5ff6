// --jobs (issue 18): fuzz throughput of runFuzz — the whole campaign as `cyclecert fuzz` runs it:
// generating, planning, judging, recording every result in results.jsonl — over the same 400
// cases with one worker and with two, in one run. The figure is items_per_second (cases/s, wall
// time: the workers are threads), and the ratio of /2 to /1 is the speed-up (target ≥ 1.8 on two
// cores). The CPU column is the whole process's (every thread): /2's against /1's is what the
// workers cost beyond the work itself. On a shared machine the wall time only shows the speed-up
// when a second core is free: Linux shares the CPU between sessions (autogroup), not threads.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <filesystem>
#include <sstream>

#include "harness/fuzz/fuzz_run.h"

namespace {

using namespace cyclecert;

constexpr long kCases = 400;

void BM_FuzzJobs(benchmark::State& state) {
  FuzzOptions options;
  options.seed = 20261121;
  options.cases = kCases;
  options.jobs = static_cast<int>(state.range(0));
  options.outDir = (std::filesystem::temp_directory_path() / ("cyclecert-bench-jobs-" + std::to_string(::getpid()))).string();
  options.regressionsDir.clear();
  const EnginesMaker reference = namedEngines("reference", "", {});
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove_all(options.outDir);
    state.ResumeTiming();
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(reference, options, progress);
    if (s.run != kCases) state.SkipWithError("not every case ran");
  }
  std::filesystem::remove_all(options.outDir);
  state.SetItemsProcessed(state.iterations() * kCases);
}
BENCHMARK(BM_FuzzJobs)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime()->UseRealTime();

}  // namespace
