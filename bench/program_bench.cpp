// A whole shop program of 2,000 blocks with two roughing cycles (issue 14: planning it stays under
// 5 ms): the program is written once, outside the timed loops, in the style of corpus/field/*.nc —
// safe-start lines, tool changes, G50 S clamp, G96, coolant, comments, N numbers, a G72 facing and
// a G71 turning cycle each finished by G70, some 1,900 positioning and feed blocks with arcs (a
// CAM-style profiling section), a part-off. Measured: parsing alone, planning the parsed program
// (program runner), parse + plan as `cyclecert plan` does (planWithReference), and the oracles
// judging the reference's path.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "bench/plan_loop.h"
#include "harness/judge/judging.h"

namespace {

using namespace cyclecert;

constexpr int kBlocks = 2000;

// A length in millimetres as a program writes it: "57.300".
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}

// The program text: kBlocks N-numbered blocks, and comments on lines of their own (not blocks).
// With `faceCycle` false the end face is cut by three plain facing passes instead of G72 + G70, so
// the G71 is the program's single roughing cycle and the oracles replay the material for it.
std::string generateShopProgram(bool faceCycle) {
  std::ostringstream text;
  int n = 0;
  int blocks = 0;
  auto block = [&](const std::string& words) {
    text << 'N' << (n += 10) << ' ' << words << ";\n";
    ++blocks;
  };
  auto comment = [&](const std::string& c) { text << '(' << c << ")\n"; };
  auto toolChangeTo = [&](const std::string& tool, int clamp, int speed) {
    block("G28 U0 W0");
    block(tool);
    block("G50 S" + std::to_string(clamp));
    block("G96 S" + std::to_string(speed) + " M03");
  };

  comment("MATL: C45 BAR D64 / STICKOUT 170");
  comment("T01 ROUGH CNMG 120408 / T03 FINISH VNMG 160404 / T07 PROFILE VBMT 110302 / T05 PARTING 3MM");
  block("G18 G21 G40 G80 G99");

  // --- OP 1: the end face, by G72 (its shape ns…nf finished by the G70 of OP 3) or by passes.
  int faceNs = 0, faceNf = 0;
  if (faceCycle) {
    comment("--- FACE ROUGH G72 ---");
    toolChangeTo("T0101", 2000, 180);
    block("G00 X68.0 Z2.0 M08");
    block("G72 W1.5 R0.5");
    faceNs = n + 20;
    faceNf = faceNs + 40;
    block("G72 P" + std::to_string(faceNs) + " Q" + std::to_string(faceNf) + " U0.3 W0.1 F0.22");
    block("G00 Z-2.0");  // ns: the face at Z-2
    block("G01 X64.0 F0.1");
    block("X6.0");
    block("G03 X2.0 Z0 R2.0");  // a centre boss for the tailstock
    block("G01 X0");  // nf
  } else {
    comment("--- FACE, THREE PASSES ---");
    toolChangeTo("T0101", 2000, 180);
    for (const char* z : {"-0.7", "-1.4", "-1.9"}) {  // W0.1 left on the face
      block("G00 X68.0 Z" + std::string(z) + " M08");
      block("G01 X-1.0 F0.2");
      block("G00 Z2.0");
    }
  }
  block("G00 X150.0 Z50.0 M09");

  // --- OP 2: outer diameter G71, a stepped shaft with fillets and a taper.
  comment("--- OD ROUGH G71 ---");
  toolChangeTo("T0101", 2200, 200);
  block("G00 X68.0 Z0 M08");
  block("G71 U2.0 R0.5");
  const int odNs = n + 20;
  const int odNf = odNs + 10 * 13;
  block("G71 P" + std::to_string(odNs) + " Q" + std::to_string(odNf) + " U0.4 W0.1 F0.25");
  block("G00 X18.0");                  // ns
  block("G01 Z-2.0 F0.1");
  block("X22.0 Z-4.0");
  block("Z-25.0");
  block("G02 X28.0 Z-28.0 R3.0");
  block("G01 X34.0");
  block("X38.0 Z-30.0");
  block("Z-60.0");
  block("G02 X44.0 Z-63.0 R3.0");
  block("G01 X48.0");
  block("X56.0 Z-90.0");
  block("Z-140.0");
  block("X62.0");
  block("X68.0 Z-143.0");              // nf
  block("G00 X150.0 Z50.0 M09");

  // --- OP 3: both shapes finished with another tool.
  comment("--- FACE AND OD FINISH G70 ---");
  toolChangeTo("T0303", 3000, 240);
  if (faceCycle) {
    block("G00 X68.0 Z2.0 M08");
    block("G70 P" + std::to_string(faceNs) + " Q" + std::to_string(faceNf));
  }
  block("G00 X68.0 Z0");
  block("G70 P" + std::to_string(odNs) + " Q" + std::to_string(odNf));
  block("G00 X150.0 Z50.0 M09");

  // --- OP 4: CAM-style profiling of the D56 section, over the finished surface: each pass a row
  // of shallow arcs (R10 over 4 mm: 0.2 mm rise) at a diameter clear of the part.
  comment("--- PROFILE D56 SECTION, CAM OUTPUT ---");
  toolChangeTo("T0707", 3000, 220);
  block("G00 X70.0 Z-92.0 M08");
  const int reserve = 9;  // part-off and end of program
  int pass = 0;
  while (blocks + 24 + reserve <= kBlocks) {  // a pass is 24 blocks
    const double x = 57.0 + 0.1 * (pass % 10);
    comment("PASS " + std::to_string(++pass));
    block("G00 X" + num(x) + " Z-92.0");
    block("G01 Z-94.0 F0.12");
    double z = -94.0;
    for (int k = 0; k < 10; ++k) {  // to Z-139, clear of the shoulder at Z-140
      block(std::string(k % 2 ? "G02" : "G03") + " Z" + num(z - 4.0) + " R10.0");
      z -= 4.0;
      block("G01 X" + num(x + 0.4) + " Z" + num(z - 0.5));
      z -= 0.5;
    }
    block("G00 X70.0");
    block("Z-92.0");
  }
  while (blocks + reserve < kBlocks) block("G04 X0.1");  // dwells at the end of the profiling: kBlocks in all
  block("G00 X150.0 Z50.0 M09");

  // --- OP 5: part-off.
  comment("--- PART OFF ---");
  block("G28 U0 W0");
  block("T0505");
  block("G97 S700 M03");
  block("G00 X68.0 Z-148.0 M08");
  block("G01 X-1.0 F0.05");
  block("G00 X68.0 M09");
  block("G28 U0 W0 M05");
  block("M30");
  return "%\nO2000 (BENCH - SHAFT D64 X 145, FACE + OD + PROFILE)\n" + text.str() + "%\n";
}

// The program with both cycles (G72 and G71), or with the G71 alone.
const std::string& shopProgram(bool twoCycles = true) {
  static const std::string both = generateShopProgram(true), one = generateShopProgram(false);
  return twoCycles ? both : one;
}

void BM_ShopProgramParse(benchmark::State& state) {
  std::size_t blocks = 0;
  for (auto _ : state) {
    blocks = parseProgram(shopProgram(), "shop.nc").blocks.size();
    benchmark::DoNotOptimize(blocks);
  }
  state.counters["blocks"] = static_cast<double>(blocks);
}
BENCHMARK(BM_ShopProgramParse)->Unit(benchmark::kMicrosecond);

// The parsed program planned (the program runner alone, as every planning benchmark here).
void BM_ShopProgramPlan(benchmark::State& state) { planRepeatedly(state, shopProgram()); }
BENCHMARK(BM_ShopProgramPlan)->Unit(benchmark::kMicrosecond);

// Parse + plan from the text, as `cyclecert plan` does (readRequest keeps the last programs it
// parsed, so the text is made unique per iteration to measure the parsing too).
void BM_ShopProgramParseAndPlan(benchmark::State& state) {
  std::size_t moves = 0;
  long iteration = 0;
  const std::string base = shopProgram();
  for (auto _ : state) {
    state.PauseTiming();
    std::string text = base + "(RUN " + std::to_string(++iteration) + ")\n";
    state.ResumeTiming();
    const Toolpath t = planWithReference({std::move(text), "shop.nc", "fanuc-0i-f", {}, {}});
    moves = t.moves.size();
    benchmark::DoNotOptimize(moves);
  }
  state.counters["moves"] = static_cast<double>(moves);
}
BENCHMARK(BM_ShopProgramParseAndPlan)->Unit(benchmark::kMicrosecond);

// Every oracle on the reference's path of the program (their input built once). Argument 2: the
// program with two cycles, where the geometric oracles (no-gouge, rapids-in-air, complete) do not
// replay the material (oracles/material_replay.h: a single roughing cycle only); it must be judged
// clean. 1: the G71 alone, where they replay it: the cost is measured, and the findings counted
// (the oracles judge the facing passes before the cycle and the profiling after it against the
// G71's part and passes: bench/README.md).
void BM_ShopProgramOracles(benchmark::State& state) {
  JudgeRequest request;
  request.program = {shopProgram(state.range(0) == 2), "shop.nc", "fanuc-0i-f", {}, {}};
  const Toolpath path = planWithReference(request.program);
  if (path.alarm) {
    state.SkipWithError(("the reference alarms: " + path.alarm->message).c_str());
    return;
  }
  const JudgeInput in = judgeInputFor(request, path);
  std::vector<Finding> findings;
  for (auto _ : state) {
    findings = judge(in);
    benchmark::DoNotOptimize(findings.data());
  }
  state.counters["moves"] = static_cast<double>(in.path.moves.size());
  state.counters["cycles"] = static_cast<double>(in.program.cycles.size());
  state.counters["findings"] = static_cast<double>(findings.size());
  if (state.range(0) == 2 && !findings.empty()) {
    state.SkipWithError(("the oracles found: " + findingsText(findings)).c_str());
  }
}
BENCHMARK(BM_ShopProgramOracles)->Arg(2)->Arg(1)->Unit(benchmark::kMicrosecond);

}  // namespace
