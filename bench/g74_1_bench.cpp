// Planning cost of the reference G74.1 (GSK axial trapezoid groove): a straight groove of L layers
// (Δv 1 mm) with C axial cycles in each (Δi/2 1 mm across a floor C − 1 mm wide), one feed per
// cycle and layer (Δk = Δv); the work is layers × cycles, and near-linear in that product is what
// Complexity(oN) checks (bench/README.md). The `per move` counter stays flat when it is.
#include <benchmark/benchmark.h>

#include <string>

#include "bench/plan_loop.h"

namespace {

using namespace cyclecert;

// O0008's form with n layers × n cycles: S at radius n + 10, steps towards −X, feeds towards −Z.
std::string grooveProgram(int n) {
  const std::string x = std::to_string(2 * (n + 10));
  return "G00 X" + x + " Z5 F0.1;\nG74.1 X" + x + " Z0 P20000 Q10000 H-" + std::to_string(n) + " D-" +
         std::to_string(2 * (n - 1)) + ";\nG74.1 R0.1 V1;\nM30;\n";
}

void BM_G74_1(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  planRepeatedly(state, grooveProgram(n), "gsk");
  state.SetComplexityN(static_cast<benchmark::IterationCount>(n) * n);
  state.counters["layers x cycles"] = static_cast<double>(n) * n;
  state.counters["per move"] = benchmark::Counter(state.counters["moves"] * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// 10 × 10 … 280 × 280 (the cycle's plan cap, PROG.CAP.PASSES: at most 250,000 moves a cycle).
BENCHMARK(BM_G74_1)->Arg(10)->Arg(30)->Arg(100)->Arg(200)->Arg(280)->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);

}  // namespace
