// Planning cost of the reference G71 type II on contours with 1, 10 and 100 pockets: each pocket
// is a rectangular groove 3 levels deep between collars, so the cut tree grows with the pockets.
#include <benchmark/benchmark.h>

#include <sstream>
#include <string>

#include "bench/plan_loop.h"

namespace {

using namespace cyclecert;

std::string pocketsProgram(int pockets) {
  std::ostringstream p;
  p << "G00 X44 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X40 W0;\n";
  double z = 0;
  for (int i = 0; i < pockets; ++i) {
    const double wallNear = z - 5, wallFar = z - 10;
    p << "G01 Z" << wallNear << ";\nX28;\nZ" << wallFar << ";\nX40;\n";
    z = wallFar;
  }
  p << "N20 G01 Z" << (z - 5) << ";\n";
  return p.str();
}

void BM_G71Type2Pockets(benchmark::State& state) {
  const int pockets = static_cast<int>(state.range(0));
  planRepeatedly(state, pocketsProgram(pockets));
  state.SetComplexityN(pockets);
}

BENCHMARK(BM_G71Type2Pockets)->Arg(1)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond)->Complexity();

}  // namespace
