// A failure's plot on a G74.1 cycle cut with a grooving tool draws, at each finding's move, the
// region the blade's end face sweeps there (harness/results/failure_plot.h): the tool width I and the side
// the blade stands on (towards the groove's start, against d) come from the program.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/results/failure_plot.h"
#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

SpecCase grooveCase(const std::string& program) {
  return specCaseFrom(nlohmann::json{{"id", "gsk/g74_1/plot"},
                                     {"title", "plot"},
                                     {"rules", {"G74_1.FMT"}},
                                     {"profile", "gsk"},
                                     {"program", program},
                                     {"expect", {{"oracles", "pass"}}},
                                     {"derivation", "a plot test"}},
                      "plot");
}

// Seed 002's O0008 with the example's 4 mm grooving tool (docs/g74_1.md §8 (b)).
const char* kO0008WithTool = "G00 X70 Z10 M3 S500;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5 I4;\nM30;\n";

void expectRegion(const std::vector<Point>& got, const std::vector<Point>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t k = 0; k < want.size(); ++k) {
    EXPECT_NEAR(got[k].z, want[k].z, 1e-9) << k;
    EXPECT_NEAR(got[k].x, want[k].x, 1e-9) << k;
  }
}

// The oracles' reading of a gsk program (what failurePlot reads the grooving tools from).
ProgramSpec programSpecOf(const std::string& program) {
  return judgeInputFor(judgeRequestFor(grooveCase(program)), Toolpath{}).program;
}

TEST(G74_1FailurePlot, TheGroovingToolComesFromTheProgram) {
  const auto tools = groovingToolsOf(programSpecOf(kO0008WithTool));
  ASSERT_EQ(tools.size(), 1u);
  EXPECT_EQ(tools.front().first, 3);  // the second block's line, which the cycle record carries
  EXPECT_DOUBLE_EQ(tools.front().second.width, 4);
  EXPECT_EQ(tools.front().second.widthSign, -1);  // D-20
  const auto plusD = groovingToolsOf(programSpecOf("G00 X36 Z1;\nG74.1 X36 Z0 P2 Q3 H4 D4;\nG74.1 R0.5 I-1.5;\n"));
  ASSERT_EQ(plusD.size(), 1u);
  EXPECT_EQ(plusD.front().second.widthSign, 1);
  EXPECT_DOUBLE_EQ(plusD.front().second.width, 1.5);
  EXPECT_TRUE(groovingToolsOf(programSpecOf("G00 X70 Z10;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20;\nG74.1 R0.5;\n")).empty())
      << "a pointed tool (no I) has no blade";
  EXPECT_TRUE(groovingToolsOf(programSpecOf("G00 X40 Z2;\nG71 U1 R0.5;\nG71 P1 Q2 U0.4 W0.1 F0.2;\nN1 G00 X20;\nN2 G01 X40 Z-20;\n")).empty());
  // A program the oracles cannot read (a SINUMERIK text under gsk): its plot draws no blade.
  const SpecCase unreadable = grooveCase("_CNAME=\"L1\"\nLCYC95\nM02\n");
  Toolpath path;
  path.moves.resize(2);
  Finding f;
  f.oracle = "no-gouge";
  f.move = 1;
  const auto plot = failurePlot(unreadable, EngineResult::planned(path), "reference", {f}, 1e-3, std::nullopt);
  ASSERT_TRUE(plot);
  for (const Highlight& h : plot->highlights) EXPECT_EQ(h.label.find("swept blade"), std::string::npos) << h.label;
}

// §8 (b): move 0 is ① to A11 (X58 Z0), cycle 1 (u 4) makes no move, move 1 is ⑦ to X55, move 2 the
// first peck ③ G01 Z-1.5 at radius 27.5. The blade spans r = 4 towards the start (d < 0: +X), so it
// sweeps the rectangle z 0…−1.5, x 27.5…31.5.
TEST(G74_1FailurePlot, AFindingAtAGroovingMoveDrawsTheSweptBlade) {
  const SpecCase c = grooveCase(kO0008WithTool);
  const Toolpath path = planSpecCase(c);
  ASSERT_FALSE(path.alarm);
  ASSERT_GT(path.moves.size(), 3u);
  ASSERT_EQ(path.moves[2].rules, std::vector<std::string>{"G74_1.STEP3"});
  expectRegion(sweptBlade(path, 2, {4, -1}), {{0, 27.5}, {-1.5, 27.5}, {-1.5, 31.5}, {0, 31.5}});

  Finding f;
  f.oracle = "no-gouge";
  f.move = 2;
  f.message = "a test finding";
  const auto plot = failurePlot(c, EngineResult::planned(path), "reference", {f}, 1e-3, std::nullopt);
  ASSERT_TRUE(plot);
  const auto blade = std::find_if(plot->highlights.begin(), plot->highlights.end(), [](const Highlight& h) {
    return h.label.find("swept blade (I 4): move 2") != std::string::npos;
  });
  ASSERT_NE(blade, plot->highlights.end());
  ASSERT_EQ(blade->regions.size(), 1u);
  expectRegion(blade->regions.front(), {{0, 27.5}, {-1.5, 27.5}, {-1.5, 31.5}, {0, 31.5}});

  // No finding, no blade; a pointed tool, no blade.
  const auto clean = failurePlot(c, EngineResult::planned(path), "reference", {}, 1e-3, std::nullopt);
  EXPECT_TRUE(clean->highlights.empty());
  const SpecCase pointed = grooveCase("G00 X70 Z10;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5;\nM30;\n");
  const auto none = failurePlot(pointed, EngineResult::planned(planSpecCase(pointed)), "reference", {f}, 1e-3, std::nullopt);
  for (const Highlight& h : none->highlights) EXPECT_EQ(h.label.find("swept blade"), std::string::npos) << h.label;
}

// A divergence from another path is a witness too: the blade is drawn at the engine's diverging move.
TEST(G74_1FailurePlot, TheFirstDivergenceDrawsTheSweptBlade) {
  const SpecCase c = grooveCase(kO0008WithTool);
  const Toolpath path = planSpecCase(c);
  const auto plot = failurePlot(c, EngineResult::planned(path), "mutant", {}, 1e-3, PlotComparison{"reference", path, 2});
  ASSERT_TRUE(plot);
  const auto blade = std::find_if(plot->highlights.begin(), plot->highlights.end(), [](const Highlight& h) {
    return h.label.find("swept blade (I 4): move 2") != std::string::npos;
  });
  ASSERT_NE(blade, plot->highlights.end());
  expectRegion(blade->regions.front(), {{0, 27.5}, {-1.5, 27.5}, {-1.5, 31.5}, {0, 31.5}});
}

// An arc of a profile pass (a round r3 of 1 mm) is followed along its length, the blade moved by its
// width: the region's first half lies on the arc, its second half on the arc moved by r.
TEST(G74_1FailurePlot, AnArcSweepsAlongItsLength) {
  const SpecCase c = grooveCase("G00 X70 Z10 F0.1;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20;\nG74.1 R0.5 I4 D1 P0010;\nM30;\n");
  const Toolpath path = planSpecCase(c);
  ASSERT_FALSE(path.alarm) << path.alarm->message;
  std::size_t arc = path.moves.size();
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    if (path.moves[i].shape != SegmentKind::Line) {
      arc = i;
      break;
    }
  }
  ASSERT_LT(arc, path.moves.size()) << "the round r3 makes an arc move";
  const std::vector<Point> region = sweptBlade(path, arc, {4, -1});
  ASSERT_EQ(region.size(), 34u);  // 17 points along the arc, 17 back along the moved arc
  const Segment s = path.segment(arc);
  const Point centre = s.center;
  const double radius = distance(s.from, centre);
  for (std::size_t k = 0; k < 17; ++k) {
    EXPECT_NEAR(distance(region[k], centre), radius, 1e-9) << k;
    EXPECT_NEAR(distance(region[33 - k], centre + Point{0, 4}), radius, 1e-9) << k;
  }
}

}  // namespace
}  // namespace cyclecert
