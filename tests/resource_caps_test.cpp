// Issue 19, item 2: every bound of README "Limits" is hit by a program and refused with a clear
// error naming where, what was given and the limit — quickly, from the counts, before the work.
// planner_bound_test.cpp holds the first G71/G72 cases (issue 13); these add every other cycle
// family, the work of passes × segments, and the blocks of a program.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "oracles/material/region.h"
#include "reference/gcode/parser.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/alarms.h"
#include "reference/siemens/siemens_parser.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {
namespace {

using Clock = std::chrono::steady_clock;

// A request refused as NotSupported: its message ("(no NotSupported)" when it was planned or
// refused otherwise) and how long the refusal took.
struct Refusal {
  std::string message;
  Clock::duration took{};
};

Refusal refusalOf(PlanRequest request) {
  const auto begin = Clock::now();
  Refusal r{"(no NotSupported)", {}};
  try {
    const Toolpath t = planWithReference(request);
    if (t.alarm) r.message = "(alarm " + t.alarm->code + ": " + t.alarm->message + ")";
  } catch (const NotSupported& e) {
    r.message = e.what();
  } catch (const std::exception& e) {
    r.message = std::string("(other error: ") + e.what() + ")";
  }
  r.took = Clock::now() - begin;
  return r;
}

struct HugeCycle {
  std::string name;
  PlanRequest request;
  std::string says;  // a part of the message: the count and the limit
  int line;          // the cycle's block (its second block, P and Q)
};

// Δd (or its like) of 0.001 mm over a profile 1 m across: a million passes in every family.
std::vector<HugeCycle> aMillionPassesInEveryFamily() {
  const std::string shaft = "N10 G00 X2;\nN20 G01 Z-10;\nM30;\n";  // type I: 1000 mm deep from X2002
  const std::vector<GivenSubprogram> contour{{"R1", "G1 X20 Z0\nZ-10\nX2020\nRET\n", "case.json#/subprograms/R1"}};
  return {
      {"G71 type I", {"G00 X2002 Z2;\nG71 U0.001 R0.5;\nG71 P10 Q20 U0 W0 F0.2;\n" + shaft, "a.nc", "fanuc-0i-f", {}, {}},
       "G71 would make 1,000,000 roughing passes", 3},
      {"G71 type II",
       {"G00 X2002 Z2;\nG71 U0.001 R0.5;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2 W0;\nG01 Z-10;\nN20 X2000 Z-20;\nM30;\n",
        "a.nc", "fanuc-0i-f", {}, {}},
       "G71 would make 1,000,000 roughing passes", 3},
      {"G72 type I", {"G00 X42 Z2;\nG72 W0.001 R0.5;\nG72 P10 Q20 U0 W0 F0.2;\nN10 G00 Z-998;\nN20 G01 X2;\nM30;\n", "a.nc",
                      "fanuc-0i-f", {}, {}},
       "G72 would make 1,000,000 roughing passes", 3},
      {"G73 divisions", {"G00 X60 Z3;\nG73 U4 W2 R50000;\nG73 P10 Q20 U0.4 W0.2 F0.2;\nN10 G01 X20 Z0;\nN20 X56;\nM30;\n",
                         "a.nc", "fanuc-0i-f", {}, {}},
       "at most 10,000 passes", 3},
      {"Huazhong G71", {"G00 X2002 Z2;\nG71 U0.001 R0.5 P10 Q20 X0 Z0 F0.2;\n" + shaft, "a.nc", "hnc", {}, {}},
       "G71 would make 1,000,000 roughing passes", 2},
      {"Haas G71", {"G21;\nG00 X2002 Z2;\nG71 P10 Q20 D0.001 U0 W0 F0.2;\n" + shaft, "a.nc", "haas", {}, {}},
       "G71 would make 1,000,000 roughing passes", 3},
      {"Series 10/11 G71", {"G00 X2002 Z2;\nG71 P10 Q20 U0 W0 D1 F0.2;\n" + shaft, "a.nc", "fanuc-0i-f", {{"FCV", 1}}, {}},
       "G71 would make 1,000,000 roughing passes", 2},
      {"G74.1 pecks", {"G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P0.01 Q0.001 H-4 D-4;\nG74.1 R0.5;\n", "a.nc", "gsk", {{"182#7", 1}}, {}},
       "moves per cycle", 3},
      {"LCYC95", {"G0 X2050 Z2\n_CNAME=\"R1\"\nR105=1 R106=0 R108=0.001 R109=0\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n",
                  "a.mpf", "sinumerik-802s", {}, {}, contour},
       "the stock-removal cycle would make 1,000,000 passes", 5},
      {"CYCLE95", {"G0 X2050 Z2\nCYCLE95(\"R1\", 0.001, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)\nM02\n", "a.mpf", "sinumerik-802d",
                   {}, {}, contour},
       "the stock-removal cycle would make 1,000,000 passes", 2},
  };
}

TEST(ResourceCaps, AMillionPassesAreRefusedAtOnceInEveryCycleFamily) {
  for (const HugeCycle& c : aMillionPassesInEveryFamily()) {
    const Refusal r = refusalOf(c.request);
    EXPECT_NE(r.message.find(c.says), std::string::npos) << c.name << ": " << r.message;
    EXPECT_EQ(r.message.rfind("line " + std::to_string(c.line) + ":", 0), 0u) << c.name << " names the cycle's line: " << r.message;
    EXPECT_LT(r.took, std::chrono::seconds(2)) << c.name;
  }
}

// A staircase of `steps` segments from (x0, z0), rising `rise` (diameter) and falling `fall` in z:
// monotonic in both axes, so a type I shape and a LCYC95 contour.
std::string staircase(int steps, double x0, double rise, double fall, const std::string& g) {
  std::string blocks;
  for (int i = 1; i <= steps; ++i) {
    blocks += g + " X" + std::to_string(x0 + rise * i / steps) + " Z" + std::to_string(-fall * i / steps) + "\n";
  }
  return blocks;
}

TEST(ResourceCaps, TypeIPassesTimesSegmentsAreBounded) {
  // 2,000 passes (200 mm deep, Δd 0.1: under the pass cap, 8,000 moves: under the move cap) over a
  // shape of 5,003 segments: 10 million meetings of a pass with the shape. 10,000 passes over
  // 200,000 segments took 22 s and 1 GB before PROG.CAP.WORK.
  const std::string program = "G00 X402 Z2;\nG71 U0.1 R0.05;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2;\nG01 Z0;\n" +
                              staircase(5000, 2, 398, 50, "G01") + "N20 G01 Z-60;\nM30;\n";
  const Refusal r = refusalOf({program, "a.nc", "fanuc-0i-f", {}, {}});
  EXPECT_NE(r.message.find("G71 would cut 2,000 passes across a shape of 5,003 segments"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("at most 10,000,000 passes × segments per cycle"), std::string::npos) << r.message;
  EXPECT_LT(r.took, std::chrono::seconds(5));
}

TEST(ResourceCaps, TheStockRemovalCyclesPassesTimesSegmentsAreBounded) {
  // CYCLE95 with MID 0.1 over 500 mm (radius) of depth: 5,000 passes, under the pass cap; a contour
  // of 2,002 segments makes it over 10 million.
  const std::string contour = "G1 X20 Z0\n" + staircase(2000, 20, 1000, 250, "G1") + "Z-300\nRET\n";
  PlanRequest request{"G0 X1050 Z2\nCYCLE95(\"L4\", 0.1, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)\nM02\n", "a.mpf",
                      "sinumerik-802d", {}, {}};
  request.subprograms = {{"L4", contour, "L4.spf"}};
  const Refusal r = refusalOf(request);
  EXPECT_NE(r.message.find("line 2: the stock-removal cycle would cut 5,000 passes across a shape of"), std::string::npos)
      << r.message;
  EXPECT_NE(r.message.find("(infeed of at most 0.1 mm)"), std::string::npos) << r.message;
  EXPECT_LT(r.took, std::chrono::seconds(5));
}

std::string blocks(std::size_t n, const std::string& block) {
  std::string text;
  text.reserve(n * block.size());
  for (std::size_t i = 0; i < n; ++i) text += block;
  return text;
}

TEST(ResourceCaps, AProgramOfMoreBlocksThanTheCapIsAParseErrorAtTheFirstBlockBeyond) {
  const std::string atTheCap = blocks(kMostBlocksPerProgram, "X1\n");
  EXPECT_EQ(parseProgram(atTheCap, "big.nc").blocks.size(), kMostBlocksPerProgram);
  try {
    // Blank lines and comments are no blocks: the first block beyond is on line cap + 3.
    parseProgram("(big)\n\n" + atTheCap + "Z1\n", "big.nc");
    FAIL() << "a program of cap + 1 blocks was read";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.loc().file, "big.nc");
    EXPECT_EQ(e.loc().line, static_cast<int>(kMostBlocksPerProgram) + 3);
    EXPECT_EQ(e.loc().column, 1);
    EXPECT_NE(std::string(e.what()).find("at most 250,000 blocks"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("block 250,001"), std::string::npos) << e.what();
  }
}

TEST(ResourceCaps, ASinumerikProgramCountsItsPrintedSubprogramsBlocksTowardsTheCap) {
  const std::size_t half = kMostBlocksPerProgram / 2;
  const std::string text = blocks(half, "G1 X1\n") + "M02\nL42.spf\n" + blocks(half, "G1 X2\n") + "RET\n";
  try {
    parseSiemensProgram(text, "big.mpf");
    FAIL() << "a program of cap + 2 blocks was read";
  } catch (const ParseError& e) {
    // Block cap + 1 is the subprogram's last G1 (the heading is no block): line cap + 2.
    EXPECT_EQ(e.loc().line, static_cast<int>(kMostBlocksPerProgram) + 2);
    EXPECT_EQ(e.loc().column, 1);
    EXPECT_NE(std::string(e.what()).find("at most 250,000 blocks"), std::string::npos) << e.what();
  }
}

TEST(ResourceCaps, AnArcIsFlattenedIntoAtMostAMillionChords) {
  // A full circle of the largest radius the dimension words allow: some 70,000 chords at the
  // default chord tolerance of 1 µm; one a million times finer would take 70 million.
  Segment circle;
  circle.kind = SegmentKind::ArcCCW;
  circle.center = {0, 0};
  circle.from = circle.to = {999999.999, 0};
  const std::size_t points = flatten(circle, 1e-3).size();
  EXPECT_GT(points, 50'000u);
  EXPECT_LT(points, 100'000u);
  try {
    flatten(circle, 1e-9);
    FAIL() << "a circle of 2 million chords was flattened";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("more than 1,000,000 chords"), std::string::npos) << e.what();
  }
}

TEST(ResourceCaps, TheChordBoundWithoutAnglesBoundsTheChordsOfEveryArc) {
  // PROG.CAP's check looks at mostChordsToFlatten first and counts exactly only beyond it: it must
  // never say fewer chords than flattening takes — full circles, sweeps just short of one, tiny and
  // huge radii, tolerances coarser than the radius.
  for (const double radius : {1e-9, 1e-3, 0.5, 1.0, 37.7, 1000.0, 999999.999}) {
    for (const double tolerance : {1e-9, 1e-6, 1e-4, 1e-3, 0.1, 10.0}) {
      for (const double sweep : {0.01, 1.0, 3.14159, 6.28318, 2 * std::numbers::pi}) {
        for (const SegmentKind kind : {SegmentKind::ArcCCW, SegmentKind::ArcCW}) {
          Segment arc;
          arc.kind = kind;
          arc.center = {3, -2};
          arc.from = {3 + radius, -2};
          const double end = kind == SegmentKind::ArcCCW ? sweep : -sweep;
          arc.to = sweep == 2 * std::numbers::pi ? arc.from
                                                 : Point{3 + radius * std::cos(end), -2 + radius * std::sin(end)};
          EXPECT_GE(mostChordsToFlatten(arc, tolerance), chordsToFlatten(arc, tolerance))
              << "radius " << radius << ", tolerance " << tolerance << ", sweep " << sweep;
        }
      }
    }
  }
}

std::size_t occurrences(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(ResourceCaps, AnSvgDrawsTheFirstMovesAndFindingsAndSaysHowManyMore) {
  // 60,000 feeds (a zigzag) and 70 findings: 50,000 and 50 drawn, the rest counted.
  PlotInput in;
  in.title = "huge";
  for (int i = 0; i < 60'000; ++i) {
    Move m;
    m.kind = MoveKind::Feed;
    m.to = {-0.001 * i, i % 2 == 0 ? 10.0 : 11.0};
    in.path.moves.push_back(m);
  }
  for (int i = 0; i < 70; ++i) in.highlights.push_back({"finding " + std::to_string(i), {}, {}, {{-1.0 * i, 10}}, false});
  const std::string svg = renderToolpathSvg(in);
  EXPECT_EQ(occurrences(svg, "<path class=\"feed\""), 50'000u);
  EXPECT_EQ(occurrences(svg, "<g class=\"finding\">"), 50u);
  EXPECT_NE(svg.find("the first 50000 moves drawn, and 10000 more"), std::string::npos);
  EXPECT_NE(svg.find("the first 50 findings drawn, and 20 more"), std::string::npos);
  EXPECT_LT(svg.size(), 10u << 20);
}

TEST(ResourceCaps, AnOrdinarySvgHasNoNoteOfMovesLeftOut) {
  PlotInput in;
  in.title = "small";
  for (int i = 0; i < 100; ++i) {
    Move m;
    m.kind = MoveKind::Feed;
    m.to = {-0.1 * i, 10};
    in.path.moves.push_back(m);
  }
  const std::string svg = renderToolpathSvg(in);
  EXPECT_EQ(occurrences(svg, "<path class=\"feed\""), 100u);
  EXPECT_EQ(svg.find("not-drawn"), std::string::npos);
}

}  // namespace
}  // namespace cyclecert
