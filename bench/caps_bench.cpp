// Issue 19, item 2: the resource caps (README "Limits") cost nothing on ordinary programs. The
// checks cannot be switched off, so each benchmark measures, in one run, the plan of an ordinary
// program from its text (planWithReference: parse, plan, with every check) and the checks that
// plan makes, alone, as many times as it makes them: one block count per block (PROG.CAP.BLOCKS),
// the pass, move and passes × segments counts per cycle (PROG.CAP.PASSES, PROG.CAP.WORK) and the
// program's move count per cycle (PROG.CAP.MOVES). The counter `checks_share` is the checks' time
// over the plan's.
#include <benchmark/benchmark.h>

#include <chrono>
#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/toolpath.h"

namespace {

using namespace cyclecert;
using Clock = std::chrono::steady_clock;

struct Ordinary {
  PlanRequest request;
  std::size_t blocks;    // blocks read
  std::size_t cycles;    // cycles planned
  double passes;         // per cycle
  std::size_t segments;  // of each cycle's shape
};

Ordinary ordinaryProgram(int which) {
  switch (which) {
    case 0:  // G71 type I: a stepped shaft, 12 passes
      return {{"G21;\nG00 X42 Z2;\nG71 U1.5 R0.5;\nG71 P10 Q50 U0.4 W0.1 F0.2;\nN10 G00 X10;\nG01 Z-10;\nX20 Z-20;\n"
               "G02 X30 Z-25 R5;\nN50 G01 X40;\nG70 P10 Q50;\nM30;\n",
               "bench.nc", "fanuc-0i-f", {}, {}},
              11, 2, 12, 5};
    case 1:  // G73: the seed's example, 3 divisions
      return {{"G21;\nG00 X60 Z3;\nG73 U4 W2 R3;\nG73 P10 Q20 U0.4 W0.2 F0.2;\nN10 G01 X20 Z0;\nG03 X30 Z-5 I0 K-5;\n"
               "G01 Z-15;\nG02 X40 Z-20 R5;\nG01 Z-30;\nN20 X56;\nM30;\n",
               "bench.nc", "fanuc-0i-f", {}, {}},
              11, 1, 3, 6};
    default: {  // CYCLE95 on a contour of four elements
      PlanRequest r{"G0 X50 Z2\nCYCLE95(\"L4\", 3, 0, 0, 0, 0.3, 0.15, 0.1, 9, 0, 0, 1)\nM02\n", "bench.mpf",
                    "sinumerik-802d", {}, {}};
      r.subprograms = {{"L4", "G1 X20 Z0\nG3 X36 Z-16 I0 K-10\nG1 Z-25\nX40\nRET\n", "L4.spf"}};
      return {r, 8, 1, 4, 4};
    }
  }
}

// The checks one plan of `o` makes, alone.
void capChecks(const Ordinary& o) {
  for (std::size_t b = 1; b <= o.blocks; ++b) requireBlockWithinTheCap(b, "bench.nc", static_cast<int>(b));
  for (std::size_t c = 0; c < o.cycles; ++c) {
    const double passes = o.passes;
    benchmark::DoNotOptimize(passes <= kMostRoughingPasses && passes * (static_cast<double>(o.segments) + 8) <= kMostCycleMoves);
    requireWorkWithinTheCap("G71", passes, o.segments, [] { return std::string(); }, 3);
    benchmark::DoNotOptimize(c * 100 <= kMostMovesPerToolpath);
  }
}

void BM_CapsOnOrdinaryPlans(benchmark::State& state) {
  Ordinary o = ordinaryProgram(static_cast<int>(state.range(0)));
  const std::string text = o.request.programText;
  const bool siemens = o.request.profile.rfind("sinumerik", 0) == 0;  // ';' comments
  Clock::duration planning{}, checking{};
  constexpr int kChecksPerPlan = 1000;  // the checks alone are too quick to time one at a time
  long n = 0;
  for (auto _ : state) {
    // A comment makes each text new, so that the parsed-program cache does not hide the reading.
    const std::string comment = std::to_string(n++);
    o.request.programText = (siemens ? ";" + comment : "(" + comment + ")") + "\n" + text;
    const auto t0 = Clock::now();
    const Toolpath t = planWithReference(o.request);
    const auto t1 = Clock::now();
    for (int k = 0; k < kChecksPerPlan; ++k) capChecks(o);
    const auto t2 = Clock::now();
    benchmark::DoNotOptimize(t.moves.size());
    planning += t1 - t0;
    checking += (t2 - t1) / kChecksPerPlan;
  }
  state.counters["plan_us"] = std::chrono::duration<double, std::micro>(planning).count() / static_cast<double>(n);
  state.counters["checks_ns"] = std::chrono::duration<double, std::nano>(checking).count() / static_cast<double>(n);
  state.counters["checks_share"] = std::chrono::duration<double>(checking) / std::chrono::duration<double>(planning);
}
// 0: G71 type I and G70, 1: G73, 2: CYCLE95.
BENCHMARK(BM_CapsOnOrdinaryPlans)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

}  // namespace
