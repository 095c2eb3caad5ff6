// The oracles' cost: the full set on type I paths of 10, 100 and 1,000 passes, and the throughput
// of reference + every oracle on random type I cases of at most 30 segments (the fuzzing budget:
// the target is 20,000 cases per second on one core).
#include <benchmark/benchmark.h>

#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "harness/judge/judging.h"

namespace {

using namespace cyclecert;

// One step down (a shoulder) per segment pair, `passes` levels of Δd = 1 over the whole depth.
std::string shaftWithPasses(int passes) {
  std::ostringstream p;
  const double depth = passes;  // radius, Δd = 1
  p << "G00 X" << 2 * (depth + 1) << " Z2;\nG71 U1 R0.3;\nG71 P1 Q2 U0.4 W0.1 F0.2;\nN1 G00 X2;\n";
  p << "G01 Z-10;\nX" << depth << " Z-20;\nZ-30;\nN2 X" << 2 * depth << ";\n";
  return p.str();
}

JudgeInput inputFor(const std::string& program) {
  JudgeRequest request;
  request.program = {program, "bench.nc", "fanuc-0i-f", {}, {}};
  return judgeInputFor(request, planWithReference(request.program));
}

void BM_AllOracles(benchmark::State& state) {
  const JudgeInput in = inputFor(shaftWithPasses(static_cast<int>(state.range(0))));
  std::size_t findings = 0;
  for (auto _ : state) {
    findings += judge(in).size();
    benchmark::DoNotOptimize(findings);
  }
  state.counters["moves"] = static_cast<double>(in.path.moves.size());
  if (findings) state.SkipWithError("the oracles found something on the reference");
}
BENCHMARK(BM_AllOracles)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

// Random monotone outer type I contours of 2–30 lines (fixed seed, so every run judges the same).
std::vector<std::string> randomTypeIPrograms(int count) {
  std::mt19937 rng(20261121);
  std::uniform_int_distribution<int> segments(2, 30), step(1, 400);
  std::vector<std::string> programs;
  for (int k = 0; k < count; ++k) {
    std::ostringstream p;
    const int n = segments(rng);
    std::vector<std::pair<int, int>> pts;  // hundredths (z, x radius)
    int z = 0, x = 200;
    for (int i = 0; i < n; ++i) {
      z -= step(rng);
      if (i % 2) x += step(rng) / 2;
      pts.push_back({z, x});
    }
    p << "G00 X" << 2 * (x + 100) / 100.0 << " Z1;\nG71 U1.5 R0.5;\nG71 P1 Q2 U0.4 W0.1 F0.2;\nN1 G00 X4;\n";
    for (int i = 0; i < n; ++i) {
      p << (i + 1 == n ? "N2 " : "") << "G01 X" << 2 * pts[i].second / 100.0 << " Z" << pts[i].first / 100.0 << ";\n";
    }
    programs.push_back(p.str());
  }
  return programs;
}

void BM_ReferencePlusOraclesPerCase(benchmark::State& state) {
  const std::vector<std::string> programs = randomTypeIPrograms(256);
  std::size_t i = 0, findings = 0;
  for (auto _ : state) {
    const JudgeInput in = inputFor(programs[i++ % programs.size()]);
    findings += judge(in).size();
    benchmark::DoNotOptimize(findings);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));  // cases per second
  if (findings) state.SkipWithError("the oracles found something on the reference");
}
BENCHMARK(BM_ReferencePlusOraclesPerCase)->Unit(benchmark::kMicrosecond);

// The reference alone on the same cases, to see what dominates.
void BM_ReferenceOnlyPerCase(benchmark::State& state) {
  const std::vector<std::string> programs = randomTypeIPrograms(256);
  std::size_t i = 0;
  for (auto _ : state) {
    JudgeRequest request;
    request.program = {programs[i++ % programs.size()], "bench.nc", "fanuc-0i-f", {}, {}};
    benchmark::DoNotOptimize(planWithReference(request.program).moves.size());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()));
}
BENCHMARK(BM_ReferenceOnlyPerCase)->Unit(benchmark::kMicrosecond);

}  // namespace
