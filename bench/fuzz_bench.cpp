// Fuzz throughput (issue 5's targets: ≥ 10,000 cases/s per core against `reference`, ≥ 500 cases/s
// against `linuxcnc`): the same generated cases, split into their stages so that the ratios show
// where the time goes — generating a case, the engine planning it, the oracles judging it, and the
// whole of `fuzz`'s per-case work (judgeFuzzCase). One core: the benchmarks run single-threaded.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/engines/linuxcnc/linuxcnc_engine.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/judge/judging.h"
#include "oracles/material_replay.h"

namespace {

using namespace cyclecert;

constexpr std::uint64_t kSeed = 20261121;

// A fixed sample of generated cases, as `fuzz --seed 20261121` draws them.
std::vector<SpecCase> casesOf(const CycleFormats& formats, const FuzzCycles& cycles = kDefaultFuzzCycles) {
  std::vector<SpecCase> out;
  for (long i = 0; i < 200; ++i) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i);
    out.push_back(fuzzSpecCase(generateFuzzCase(seed, formats, cycles), std::to_string(seed)));
  }
  return out;
}

const std::vector<SpecCase>& sampleCases() {
  static const std::vector<SpecCase> cases = casesOf(kDefaultCycleFormats);
  return cases;
}

void BM_FuzzGenerate(benchmark::State& state) {
  long i = 0;
  for (auto _ : state) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i++);
    benchmark::DoNotOptimize(fuzzSpecCase(generateFuzzCase(seed), "bench"));
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzGenerate)->Unit(benchmark::kMicrosecond);

// The same with every cycle format drawn (`fuzz --formats all`): the format is one more draw.
void BM_FuzzGenerateAllFormats(benchmark::State& state) {
  const CycleFormats formats = parseCycleFormats("all");
  long i = 0;
  for (auto _ : state) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i++);
    benchmark::DoNotOptimize(fuzzSpecCase(generateFuzzCase(seed, formats), "bench"));
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzGenerateAllFormats)->Unit(benchmark::kMicrosecond);

void BM_FuzzReferencePlanOnly(benchmark::State& state) {
  const auto engine = makeEngine("reference");
  const auto& cases = sampleCases();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(engine->run(cases[i++ % cases.size()]));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzReferencePlanOnly)->Unit(benchmark::kMicrosecond);

void BM_FuzzOraclesOnly(benchmark::State& state) {
  const auto engine = makeEngine("reference");
  const auto& cases = sampleCases();
  std::vector<JudgeInput> inputs;
  for (const SpecCase& c : cases) inputs.push_back(judgeInputFor(judgeRequestFor(c), engine->run(c).path));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(judge(inputs[i++ % inputs.size()]));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzOraclesOnly)->Unit(benchmark::kMicrosecond);

// The whole per-case work of `cyclecert fuzz --engine reference`.
void BM_FuzzCaseReference(benchmark::State& state) {
  const auto engine = makeEngine("reference");
  const auto& cases = sampleCases();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(judgeFuzzCase(*engine, nullptr, cases[i++ % cases.size()], 1e-3));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzCaseReference)->Unit(benchmark::kMicrosecond);

// The same on the Haas block and the programs in G code systems B and C (`--formats haas,gsys-b,gsys-c`).
void BM_FuzzCaseReferenceHaasAndGCodeSystems(benchmark::State& state) {
  const auto engine = makeEngine("reference");
  static const std::vector<SpecCase> cases = casesOf(parseCycleFormats("haas,gsys-b,gsys-c"));
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(judgeFuzzCase(*engine, nullptr, cases[i++ % cases.size()], 1e-3));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzCaseReferenceHaasAndGCodeSystems)->Unit(benchmark::kMicrosecond);

// Cases of the given cycle families generated, planned and judged in the loop, as `fuzz` does.
void judgeGeneratedCases(benchmark::State& state, const FuzzCycles& cycles) {
  const auto engine = makeEngine("reference");
  long i = 0;
  for (auto _ : state) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i++);
    const SpecCase c = fuzzSpecCase(generateFuzzCase(seed, kDefaultCycleFormats, cycles), "bench");
    benchmark::DoNotOptimize(judgeFuzzCase(*engine, nullptr, c, 1e-3));
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}

// `fuzz --engine reference --cycles g73` end to end: each case generated, planned and judged by
// every oracle (the material replayed on the near-net blank, in the relief's frame). Its time per
// case over BM_FuzzG71CaseReferenceGenerated's (G71/G72, generated the same way, the same run) is
// the figure issue 15 asks for; target ≥ 10,000/s (bench/README.md).
void BM_FuzzG73CaseReference(benchmark::State& state) { judgeGeneratedCases(state, {FuzzCycle::G73}); }
BENCHMARK(BM_FuzzG73CaseReference)->Unit(benchmark::kMicrosecond);

// The same for G71/G72 cases, generated in the loop too, so that the two lines compare like with like.
void BM_FuzzG71CaseReferenceGenerated(benchmark::State& state) { judgeGeneratedCases(state, kDefaultFuzzCycles); }
BENCHMARK(BM_FuzzG71CaseReferenceGenerated)->Unit(benchmark::kMicrosecond);

// `fuzz --engine reference --cycles g74.1` end to end: each G74.1 groove case generated, planned
// and judged — judgeFuzzCase, so once the groove oracles judge these cases they are in this figure
// with nothing changed here. Report it as a ratio to BM_FuzzG71CaseReferenceGenerated of the same
// run (bench/README.md).
void BM_FuzzG74_1CaseReference(benchmark::State& state) { judgeGeneratedCases(state, {FuzzCycle::G74_1}); }
BENCHMARK(BM_FuzzG74_1CaseReference)->Unit(benchmark::kMicrosecond);

// `fuzz --engine reference --cycles siemens` end to end: each SINUMERIK case (LCYC95 or CYCLE95, a
// main program and its contour subprogram) generated, planned and judged — judgeFuzzCase, so once the
// Siemens oracles judge these cases they are in this figure with nothing changed here (until then the
// judge refuses the case after the reference planned it). Report it as a ratio to
// BM_FuzzG71CaseReferenceGenerated of the same run; target ≥ 10,000/s (bench/README.md).
void BM_FuzzSiemensCaseReference(benchmark::State& state) {
  judgeGeneratedCases(state, {FuzzCycle::Lcyc95, FuzzCycle::Cycle95});
}
BENCHMARK(BM_FuzzSiemensCaseReference)->Unit(benchmark::kMicrosecond);

// The SINUMERIK cases generated and planned only (no judging): what the reference's part costs.
void BM_FuzzSiemensCasePlanOnly(benchmark::State& state) {
  const auto engine = makeEngine("reference");
  long i = 0;
  for (auto _ : state) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i++);
    const SpecCase c = fuzzSpecCase(generateFuzzCase(seed, kDefaultCycleFormats, {FuzzCycle::Lcyc95, FuzzCycle::Cycle95}), "bench");
    benchmark::DoNotOptimize(engine->run(c));
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzSiemensCasePlanOnly)->Unit(benchmark::kMicrosecond);

// A fixed sample of generated SINUMERIK cases and the reference's paths for them, planned once:
// 64 cases, as `fuzz` plans a batch (kFuzzBatch) before it judges it, so that the texts the engine
// parsed are kept for the oracles' reading (harness/engines/reference_plan.h keeps the last 128) as in `fuzz`.
struct PlannedCase {
  SpecCase spec;
  Toolpath path;
};
const std::vector<PlannedCase>& plannedSiemensCases() {
  static const std::vector<PlannedCase> planned = [] {
    const auto engine = makeEngine("reference");
    std::vector<PlannedCase> out;
    std::vector<SpecCase> cases = casesOf(kDefaultCycleFormats, {FuzzCycle::Lcyc95, FuzzCycle::Cycle95});
    cases.resize(64);
    for (SpecCase& c : cases) {
      Toolpath path = engine->run(c).path;
      out.push_back({std::move(c), std::move(path)});
    }
    return out;
  }();
  return planned;
}

// Those cases read as the oracles read them (the inputs of the oracles' and the replay's benches).
std::vector<JudgeInput> readSiemensCases() {
  std::vector<JudgeInput> inputs;
  for (const PlannedCase& c : plannedSiemensCases()) inputs.push_back(judgeInputFor(judgeRequestFor(c.spec), c.path));
  return inputs;
}

// The oracles' reading of a planned SINUMERIK case alone (judgeInputFor: the program read again
// with recording planners, readSiemensProgramSpec): what a case pays, after the engine, before any
// oracle judges. The parsed texts are kept per thread (harness/engines/reference_plan.h), as in `fuzz`.
void BM_FuzzSiemensReadingOnly(benchmark::State& state) {
  const auto& cases = plannedSiemensCases();
  std::size_t i = 0;
  for (auto _ : state) {
    const PlannedCase& c = cases[i++ % cases.size()];
    benchmark::DoNotOptimize(judgeInputFor(judgeRequestFor(c.spec), c.path));
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzSiemensReadingOnly)->Unit(benchmark::kMicrosecond);

// Every oracle on a planned and read SINUMERIK case (judge: the material replay, completeness,
// no-gouge, the Siemens oracles).
void BM_FuzzSiemensOraclesOnly(benchmark::State& state) {
  const std::vector<JudgeInput> inputs = readSiemensCases();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(judge(inputs[i++ % inputs.size()]));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzSiemensOraclesOnly)->Unit(benchmark::kMicrosecond);

// The material replay alone on the same cases (replayMaterial: the implied stock, the part, the
// moves replayed), the oracles' largest share.
void BM_FuzzSiemensReplayOnly(benchmark::State& state) {
  const std::vector<JudgeInput> inputs = readSiemensCases();
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(replayMaterial(inputs[i++ % inputs.size()]));
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(i), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_FuzzSiemensReplayOnly)->Unit(benchmark::kMicrosecond);

// LinuxCNC's rs274 on the same cases, one process per case and batched (when rs274 was fetched:
// `make rs274`; otherwise the benchmark says so and is skipped).
void linuxCncPlans(benchmark::State& state, bool batched) {
  const auto made = makeEngine("linuxcnc");
  auto& engine = dynamic_cast<LinuxCncEngine&>(*made);
  if (!engine.available()) {
    state.SkipWithError("rs274 is not fetched (make rs274)");
    return;
  }
  const auto& cases = sampleCases();
  const std::size_t batch = batched ? 50 : 1;
  std::size_t done = 0;
  for (auto _ : state) {
    const std::vector<SpecCase> some(cases.begin() + static_cast<long>(done % cases.size()),
                                     cases.begin() + static_cast<long>(done % cases.size() + batch));
    benchmark::DoNotOptimize(batched ? engine.runBatch(some) : std::vector<EngineResult>{engine.run(some.front())});
    done += batch;
  }
  state.counters["cases/s"] = benchmark::Counter(static_cast<double>(done), benchmark::Counter::kIsRate);
}
void BM_FuzzLinuxCncOnePerProcess(benchmark::State& state) { linuxCncPlans(state, false); }
void BM_FuzzLinuxCncBatched(benchmark::State& state) { linuxCncPlans(state, true); }
BENCHMARK(BM_FuzzLinuxCncOnePerProcess)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FuzzLinuxCncBatched)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
