#pragma once
// The measured loop every planning benchmark shares: parse once, plan with the reference on the
// profile (fanuc-0i-f unless named: G74.1 is gsk's) as often as Google Benchmark asks, report the
// number of moves.
#include <benchmark/benchmark.h>

#include <string>

#include "reference/gcode/parser.h"
#include "reference/engine/program_runner.h"
#include "reference/model/profile.h"

namespace cyclecert {

inline void planRepeatedly(benchmark::State& state, const std::string& programText,
                           const std::string& profileName = "fanuc-0i-f") {
  const Program program = parseProgram(programText, "bench.nc");
  const Profile& profile = *findProfile(profileName);
  std::size_t moves = 0;
  for (auto _ : state) {
    const Toolpath t = planProgram(program, profile, profile.defaults);
    moves = t.moves.size();
    benchmark::DoNotOptimize(moves);
  }
  state.counters["moves"] = static_cast<double>(moves);
}

}  // namespace cyclecert
