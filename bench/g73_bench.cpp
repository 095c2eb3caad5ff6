// Planning cost of the reference G73: every pass follows the whole shape, so the work is segments ×
// divisions; near-linear in that product is the requirement (issue 15). The `per move` counter
// (time per move made) stays flat across the sizes when it is.
#include <benchmark/benchmark.h>

#include <sstream>
#include <string>

#include "bench/plan_loop.h"

namespace {

using namespace cyclecert;

// An outer shape of `segments` blocks that is not monotone along X (a zigzag of shallow grooves:
// what G73 is for), from B (X20, Z0) towards −Z, with d divisions of a 3 mm relief.
std::string zigzagProgram(int segments, int divisions) {
  std::ostringstream p;
  p << "G00 X40 Z2;\nG73 U3 W0 R" << divisions << ";\nG73 P1 Q2 U0.4 W0.1 F0.2;\nN1 G01 X20 Z0;\n";
  for (int i = 1; i <= segments; ++i) p << (i % 2 ? "G01 U-1 W-0.5;\n" : "G01 U1 W-0.5;\n");
  p << "N2 G01 X36;\n";
  return p.str();
}

void BM_G73(benchmark::State& state) {
  const int segments = static_cast<int>(state.range(0));
  const int divisions = static_cast<int>(state.range(1));
  planRepeatedly(state, zigzagProgram(segments, divisions));
  state.counters["segments x d"] = static_cast<double>(segments) * divisions;
  state.counters["per move"] = benchmark::Counter(state.counters["moves"] * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// Segments × divisions up to 1,000,000 moves' worth (the toolpath's cap, PROG.CAP.MOVES, is 1,000,000 moves).
BENCHMARK(BM_G73)
    ->Args({10, 10})
    ->Args({100, 10})
    ->Args({1000, 10})
    ->Args({10000, 10})
    ->Args({100, 100})
    ->Args({1000, 100})
    ->Args({100, 1000})
    ->Unit(benchmark::kMicrosecond);

}  // namespace
