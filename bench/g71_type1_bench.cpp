// Planning cost of the reference G71 type I on long monotone contours: near-linear in
// segments × passes is the requirement (10,000 segments, 1,000 passes well under 50 ms).
#include <benchmark/benchmark.h>

#include <sstream>
#include <string>

#include "bench/plan_loop.h"
#include "reference/cycles/type1_roughing.h"

namespace {

using namespace cyclecert;

// An outer staircase-with-tapers contour from X0 to X(2·depth) over `segments` blocks, so that the
// number of passes is depth / Δd whatever the number of segments.
std::string staircaseProgram(int segments, double depthRadius, double dd) {
  std::ostringstream p;
  p.precision(10);
  const double startX = 2 * depthRadius + 2;
  p << "G00 X" << startX << " Z2;\nG71 U" << dd << " R0.2;\nG71 P1 Q2 U0.4 W0.1 F0.2;\nN1 G00 X0;\n";
  const double rise = 2 * depthRadius / segments;  // diameter per segment
  for (int i = 1; i <= segments; ++i) {
    if (i % 2) p << "G01 U" << rise << " W-0.5;\n";
    else p << "G01 W-0.5;\n";
  }
  p << "N2 G01 W-1;\n";
  return p.str();
}

void BM_G71Type1(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const int passes = static_cast<int>(state.range(1));
  const double dd = 1.0;
  planRepeatedly(state, staircaseProgram(segments, passes * dd, dd));
  state.counters["segments"] = segments;
}

// Contour sizes (segments × passes) every benchmark here runs.
void segmentsByPasses(benchmark::internal::Benchmark* b) {
  for (const auto& [segments, passes] : {std::pair{10, 10}, {100, 100}, {1000, 100}, {10000, 100}, {10000, 1000}}) {
    b->Args({segments, passes});
  }
  b->Unit(benchmark::kMicrosecond);
}

// The eight steps alone, on the same staircase already in the cycle frame: the share of the
// program interpretation (modal walk, shape reading, checks) is the difference to BM_G71Type1.
void BM_Type1StepsOnly(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const int passes = static_cast<int>(state.range(1));
  Type1Cycle c;
  c.family = CycleFamily::G71;
  c.start = {2, passes + 1.0};
  c.headEnd = {2, 0};
  const double rise = static_cast<double>(passes) / segments;
  Point at = c.headEnd;
  for (int i = 1; i <= segments; ++i) {
    const Point next = at + Point{-0.5, i % 2 ? rise * 2 : 0.0};
    c.body.push_back({SegmentKind::Line, at, next, {}, 0});
    at = next;
  }
  c.allowance = {0.1, 0.2};
  c.depthOfCut = 1;
  c.retract = 0.2;
  c.feed = 0.2;
  std::size_t moves = 0;
  for (auto _ : state) {
    moves = planType1(c).size();
    benchmark::DoNotOptimize(moves);
  }
  state.counters["moves"] = static_cast<double>(moves);
}

BENCHMARK(BM_Type1StepsOnly)->Apply(segmentsByPasses);

BENCHMARK(BM_G71Type1)->Apply(segmentsByPasses);

}  // namespace

BENCHMARK_MAIN();
