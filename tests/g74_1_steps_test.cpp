// G74.1's ten steps (reference/cycles/g74_1_steps.cpp) on small grooves whose moves are worked out
// by hand in the comments (docs/g74_1.md §6 states the rules used), and seed 002's example O0008.
// Plane points are (z, x radius). Unless a test says otherwise P and Q are in mm (--param 182#7=1).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

Toolpath planGsk(const std::string& program, std::vector<std::pair<std::string, double>> params = {{"182#7", 1}}) {
  return planWithReference({program, "test.nc", "gsk", std::move(params), {}});
}

struct Expected {
  char kind;  // 'r' rapid, 'f' feed
  double z, x;
  const char* rule;
};

void expectMoves(const Toolpath& t, std::size_t from, const std::vector<Expected>& expected) {
  ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
  ASSERT_GE(t.moves.size(), from + expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const Move& m = t.moves[from + i];
    const Expected& e = expected[i];
    SCOPED_TRACE("move " + std::to_string(from + i));
    EXPECT_EQ(m.kind == MoveKind::Rapid ? 'r' : 'f', e.kind);
    EXPECT_NEAR(m.to.z, e.z, 1e-6);
    EXPECT_NEAR(m.to.x, e.x, 1e-6);
    ASSERT_FALSE(m.rules.empty());
    EXPECT_EQ(m.rules.front(), e.rule);
  }
}

const char* kO0008 =
    "O0008;\nG00 X70 Z10 M3 S500;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5;\nM30;\n";

TEST(G74_1Steps, O0008AsWritten) {
  // docs/g74_1.md §8(a): pointed tool (no I), Δi 3 mm (30000 × 0.0001), Δk 5 mm, e 0.5; x = 33 − u,
  // z = −w. Cycle 1 (u 0, the 45° flank's top) makes no move; cycle 2 at u 1.5 (x 31.5) ends at
  // depth 1.5; cycle 5 at u 6 (x 27): 5, back 0.5, then to Bmn 6.
  const Toolpath t = planGsk(kO0008, {});
  EXPECT_EQ(t.moves.size(), 83u);
  expectMoves(t, 0,
              {{'r', 0, 33, "G74_1.STEP1"},
               {'r', 0, 31.5, "G74_1.STEP7"},
               {'f', -1.5, 31.5, "G74_1.STEP3"},
               {'r', 0, 31.5, "G74_1.STEP6"},
               {'r', 0, 30, "G74_1.STEP7"},
               {'f', -3, 30, "G74_1.STEP3"},
               {'r', 0, 30, "G74_1.STEP6"},
               {'r', 0, 28.5, "G74_1.STEP7"},
               {'f', -4.5, 28.5, "G74_1.STEP3"},
               {'r', 0, 28.5, "G74_1.STEP6"},
               {'r', 0, 27, "G74_1.STEP7"},
               {'f', -5, 27, "G74_1.STEP3"},
               {'r', -4.5, 27, "G74_1.STEP4"},
               {'f', -6, 27, "G74_1.STEP5"},
               {'r', 0, 27, "G74_1.STEP6"}});
  // The end: cycle 18 at u 25.5 (x 7.5) to √3·0.273503 = 0.473721; Amf u 25.773503 makes no move;
  // back to A11; the rough profile X46 Z−10, X26 Z−10, X14.452995 Z0; A11; the start X70 Z10.
  expectMoves(t, 83 - 10,
              {{'r', 0, 7.5, "G74_1.STEP7"},
               {'f', -0.473721, 7.5, "G74_1.STEP3"},
               {'r', 0, 7.5, "G74_1.STEP6"},
               {'r', 0, 7.2264973, "G74_1.STEP7"},
               {'r', 0, 33, "G74_1.STEP8"},
               {'f', -10, 23, "G74_1.STEP9"},
               {'f', -10, 13, "G74_1.STEP9"},
               {'f', 0, 7.2264973, "G74_1.STEP9"},
               {'r', 0, 33, "G74_1.STEP9"},
               {'r', 10, 35, "G74_1.STEP10"}});
  EXPECT_EQ(t.moves.back().phase, MovePhase::Return);
}

TEST(G74_1Steps, O0008WithTheExamplesFourMillimetreTool) {
  // §8(b): I4: A11 u 4 (x 29, X58); cycle u 4 makes no move; u 5.5 (x 27.5) to min(depth(1.5),
  // depth(5.5)) = 1.5. The rough pass: near flank shifted by 4: (−10, 33 − 14 = 19), floor to
  // (−10, 13), far flank to (0, 7.2264973); back to A11; the start.
  const std::string program =
      "O0008;\nG00 X70 Z10 M3 S500;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5 I4;\nM30;\n";
  const Toolpath t = planGsk(program, {});
  expectMoves(t, 0,
              {{'r', 0, 29, "G74_1.STEP1"},
               {'r', 0, 27.5, "G74_1.STEP7"},
               {'f', -1.5, 27.5, "G74_1.STEP3"},
               {'r', 0, 27.5, "G74_1.STEP6"}});
  expectMoves(t, t.moves.size() - 5,
              {{'f', -10, 19, "G74_1.STEP9"},
               {'f', -10, 13, "G74_1.STEP9"},
               {'f', 0, 7.2264973, "G74_1.STEP9"},
               {'r', 0, 29, "G74_1.STEP9"},
               {'r', 10, 35, "G74_1.STEP10"}});
}

// A straight groove 4 deep and 2 wide (radius) from X40 Z0: Δi/2 0.5, Δk 2, e 0.5, one layer.
// In the frame: cycles at u 0, 0.5, 1, 1.5, 2, each: feed to w 2, retract to 1.5, (Δk + e) = 2.5
// ends at 4 = Bmn: feed to 4, back to 0. Then back to A11, the profile, A11, the start (z 5, x 25).
struct UW {
  char kind;
  double u, w;
  const char* rule;
};
const std::vector<UW> kStraightGroove = [] {
  std::vector<UW> v{{'r', 0, 0, "G74_1.STEP1"}};
  for (double u : {0.0, 0.5, 1.0, 1.5, 2.0}) {
    if (u > 0) v.push_back({'r', u, 0, "G74_1.STEP7"});
    v.push_back({'f', u, 2, "G74_1.STEP3"});
    v.push_back({'r', u, 1.5, "G74_1.STEP4"});
    v.push_back({'f', u, 4, "G74_1.STEP5"});
    v.push_back({'r', u, 0, "G74_1.STEP6"});
  }
  v.push_back({'r', 0, 0, "G74_1.STEP8"});
  v.push_back({'f', 0, 4, "G74_1.STEP9"});
  v.push_back({'f', 2, 4, "G74_1.STEP9"});
  v.push_back({'f', 2, 0, "G74_1.STEP9"});
  v.push_back({'r', 0, 0, "G74_1.STEP9"});
  return v;
}();

TEST(G74_1Steps, EveryStepOfAStraightGrooveInAllFourDirections) {
  // x = 20 + sd·u, z = sh·w (I: the frame); the last move returns to (5, 25).
  for (int sh : {-1, 1}) {
    for (int sd : {-1, 1}) {
      SCOPED_TRACE("h sign " + std::to_string(sh) + ", d sign " + std::to_string(sd));
      const std::string program = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H" + std::to_string(4 * sh) + " D" +
                                  std::to_string(4 * sd) + ";\nG74.1 R0.5;\n";
      const Toolpath t = planGsk(program);
      std::vector<Expected> expected;
      for (const UW& m : kStraightGroove) expected.push_back({m.kind, sh * m.w, 20 + sd * m.u, m.rule});
      expected.push_back({'r', 5, 25, "G74_1.STEP10"});
      EXPECT_EQ(t.moves.size(), expected.size());
      expectMoves(t, 0, expected);
    }
  }
}

TEST(G74_1Steps, TheRefeedIsDeltaKPlusE) {
  // Δk 1.5, e 0.5, depth 4 at u 0 (x 20): feed 1.5; back to 1.0; (Δk + e) = 2 → 3.0 (< 4); back to
  // 2.5; 2.5 + 2 = 4.5 passes Bmn: feed to 4; back to 0.
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q1.5 H-4 D-4;\nG74.1 R0.5;\n");
  expectMoves(t, 1,
              {{'f', -1.5, 20, "G74_1.STEP3"},
               {'r', -1.0, 20, "G74_1.STEP4"},
               {'f', -3.0, 20, "G74_1.STEP5"},
               {'r', -2.5, 20, "G74_1.STEP4"},
               {'f', -4, 20, "G74_1.STEP5"},
               {'r', 0, 20, "G74_1.STEP6"},
               {'r', 0, 19.5, "G74_1.STEP7"}});
}

TEST(G74_1Steps, LayersByDeltaVAndTheStepToTheNextLayer) {
  // ∠a = ∠b = 45°, |h| 4, floor 2, V2, Δi/2 0.5, Δk 5: near flank w = u, far flank w = 10 − u.
  // Layer 1 (w 0…2): starts u 0 … 10 by 0.5 (slice at w 0); Bmn = min(2, depth). Its last cycle
  // (u 10) has depth 0. Step 8: x to Cmf (u 2, w 0) — layer 2's first start (slice at w 2: 2…8);
  // step 2 down to (u 2, w 2); cycle u 2 is the flank's top (no move); step 7 to u 2.5, feed to
  // Bmn 2.5 (Δk clamps), back to 2.
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q5 H-4 D-4 A45 B45;\nG74.1 R0.5 V2;\n");
  ASSERT_FALSE(t.alarm);
  std::size_t step8 = 0;
  while (step8 < t.moves.size() && t.moves[step8].rules.front() != "G74_1.STEP8") ++step8;
  ASSERT_LT(step8, t.moves.size());
  // Before it: layer 1's Amf u 10 (x 10) reached by step 7; its cycle (depth 0) made no move.
  expectMoves(t, step8 - 1, {{'r', 0, 10, "G74_1.STEP7"}});
  expectMoves(t, step8,
              {{'r', 0, 18, "G74_1.STEP8"},
               {'r', -2, 18, "G74_1.STEP2"},
               {'r', -2, 17.5, "G74_1.STEP7"},
               {'f', -2.5, 17.5, "G74_1.STEP3"},
               {'r', -2, 17.5, "G74_1.STEP6"}});
  EXPECT_EQ(t.moves[step8 + 1].pass, 2);  // layer 2
  // Layer 1's cycle at u 3 (x 17) goes to w 2 only (the layer's bottom), not to the flank's 3.
  bool sawLayerOneAtU3 = false;
  for (std::size_t i = 0; i < step8; ++i) {
    if (std::abs(t.moves[i].to.x - 17) < 1e-9 && t.moves[i].kind == MoveKind::Feed) {
      EXPECT_NEAR(t.moves[i].to.z, -2, 1e-9);
      sawLayerOneAtU3 = true;
    }
  }
  EXPECT_TRUE(sawLayerOneAtU3);
}

// Straight groove with U0.4 W0.2: the rough profile S' (0.2, 0), floor w 3.8 from u 0.2 to 1.8.
const char* kAllowanceGroove = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q5 H-4 D-4;\nG74.1 R0.5 U0.4 W0.2 J";

TEST(G74_1Steps, J0RoughsOnly) {
  // Cycles at u 0.2, 0.7, 1.2, 1.7, 1.8 (x 19.8 … 18.2) to w 3.8; the rough pass (−3.8, 19.8),
  // (−3.8, 18.2), (0, 18.2), back to A11 (0, 19.8); no finish pass.
  const Toolpath t = planGsk(std::string(kAllowanceGroove) + "0;\n");
  expectMoves(t, 0, {{'r', 0, 19.8, "G74_1.STEP1"}, {'f', -3.8, 19.8, "G74_1.STEP3"}, {'r', 0, 19.8, "G74_1.STEP6"}});
  expectMoves(t, t.moves.size() - 5,
              {{'f', -3.8, 19.8, "G74_1.STEP9"},
               {'f', -3.8, 18.2, "G74_1.STEP9"},
               {'f', 0, 18.2, "G74_1.STEP9"},
               {'r', 0, 19.8, "G74_1.STEP9"},
               {'r', 5, 25, "G74_1.STEP10"}});
  for (const Move& m : t.moves) EXPECT_NE(m.phase, MovePhase::Finish);
}

TEST(G74_1Steps, J1RoughsThenFinishes) {
  // After the rough pass back at A11 (0, 19.8): to the finish start (0, 20), the finish profile
  // (−4, 20), (−4, 18), (0, 18), back to (0, 20), then the start.
  const Toolpath t = planGsk(std::string(kAllowanceGroove) + "1;\n");
  expectMoves(t, t.moves.size() - 7,
              {{'r', 0, 19.8, "G74_1.STEP9"},
               {'r', 0, 20, "G74_1.STEP10"},
               {'f', -4, 20, "G74_1.STEP10"},
               {'f', -4, 18, "G74_1.STEP10"},
               {'f', 0, 18, "G74_1.STEP10"},
               {'r', 0, 20, "G74_1.STEP10"},
               {'r', 5, 25, "G74_1.STEP10"}});
  EXPECT_EQ(t.moves[t.moves.size() - 3].phase, MovePhase::Finish);
}

TEST(G74_1Steps, J2FinishesOnly) {
  // Step 1 to A11 (0, 19.8), then step 10 at once: (0, 20), the profile, (0, 20), the start.
  const Toolpath t = planGsk(std::string(kAllowanceGroove) + "2;\n");
  EXPECT_EQ(t.moves.size(), 7u);
  expectMoves(t, 0,
              {{'r', 0, 19.8, "G74_1.STEP1"},
               {'r', 0, 20, "G74_1.STEP10"},
               {'f', -4, 20, "G74_1.STEP10"},
               {'f', -4, 18, "G74_1.STEP10"},
               {'f', 0, 18, "G74_1.STEP10"},
               {'r', 0, 20, "G74_1.STEP10"},
               {'r', 5, 25, "G74_1.STEP10"}});
}

TEST(G74_1Steps, AChamferedFloorCorner) {
  // D0.5 (r3, P's third digit 0: a chamfer): the profile (−3.5, 20) → (−4, 19.5) → (−4, 18) → (0, 18).
  // The first cycle (u 0) stops on the chamfer's top: depth 3.5; the next (u 0.5) reaches 4.
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q5 H-4 D-4;\nG74.1 R0.5 D0.5;\n");
  expectMoves(t, 1, {{'f', -3.5, 20, "G74_1.STEP3"}, {'r', 0, 20, "G74_1.STEP6"}, {'r', 0, 19.5, "G74_1.STEP7"},
                     {'f', -4, 19.5, "G74_1.STEP3"}});
  expectMoves(t, t.moves.size() - 6,
              {{'f', -3.5, 20, "G74_1.STEP9"},
               {'f', -4, 19.5, "G74_1.STEP9"},
               {'f', -4, 18, "G74_1.STEP9"},
               {'f', 0, 18, "G74_1.STEP9"},
               {'r', 0, 20, "G74_1.STEP9"},
               {'r', 5, 25, "G74_1.STEP10"}});
}

TEST(G74_1Steps, ARoundedFloorCornerIsAnArcMove) {
  // E1 with P1 (digits 0001: r4 round): tangent points (u 1, w 4) and (u 2, w 3), centre (1, 3).
  // h < 0, d < 0: from (−4, 19) to (−3, 18) about (−3, 19), counter-clockwise. H4 (h > 0) mirrors z:
  // (4, 19) to (3, 18) about (3, 19), clockwise. The cycle at u 1.5 (x 18.5) ends on the arc at
  // w = 3 + √(1 − 0.25) = 3.866025.
  for (int sh : {-1, 1}) {
    const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q5 H" + std::to_string(4 * sh) +
                               " D-4;\nG74.1 R0.5 E1 P1;\n");
    ASSERT_FALSE(t.alarm);
    const Move* arc = nullptr;
    for (const Move& m : t.moves) {
      if (m.shape != SegmentKind::Line) arc = &m;
      if (m.kind == MoveKind::Feed && std::abs(m.to.x - 18.5) < 1e-9 && m.phase == MovePhase::Pass) {
        EXPECT_NEAR(m.to.z, sh * 3.866025, 1e-6);
      }
    }
    ASSERT_NE(arc, nullptr);
    EXPECT_EQ(arc->shape, sh < 0 ? SegmentKind::ArcCCW : SegmentKind::ArcCW);
    EXPECT_NEAR(arc->to.z, sh * 3, 1e-9);
    EXPECT_NEAR(arc->to.x, 18, 1e-9);
    ASSERT_TRUE(arc->center);
    EXPECT_NEAR(arc->center->z, sh * 3, 1e-9);
    EXPECT_NEAR(arc->center->x, 19, 1e-9);
  }
}

TEST(G74_1Steps, AToolWiderThanTheFloorIsAlarmed) {
  // I3 on a floor 2 wide (radius): PS0062 at the second block, before any move.
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q5 H-4 D-4;\nG74.1 R0.5 I3;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0062");
  EXPECT_EQ(t.alarm->line, 3);
  EXPECT_EQ(t.alarm->when, "cycle block");
  EXPECT_NE(t.alarm->message.find("tool width"), std::string::npos) << t.alarm->message;
}

TEST(G74_1Steps, TheToolMustFitTheFloorsOfTheProfilesTheCycleCuts) {
  // I24. h −2, d −2: a finish floor 1 wide (radius); ∠a 45 and W0.5 raise the rough floor to z −1.5
  // and widen it by 0.5·cot 45° = 0.5 on the near flank's side (∠b 90: none on the far one): 1.5
  // wide. A 1.2 mm blade fits the rough floor and not the finish one: J0 (rough only) plans, J1 and
  // J2 (which cut the finish profile) alarm PS0062 naming the finish floor.
  const std::string groove = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P0.5 Q1 H-2 D-2 A45;\n";
  const Toolpath rough = planGsk(groove + "G74.1 R0.2 W0.5 I1.2 J0;\n");
  EXPECT_FALSE(rough.alarm) << rough.alarm->message;
  EXPECT_FALSE(rough.moves.empty());
  for (const char* j : {"J1", "J2"}) {
    const Toolpath t = planGsk(groove + "G74.1 R0.2 W0.5 I1.2 " + j + ";\n");
    ASSERT_TRUE(t.alarm) << j;
    EXPECT_EQ(t.alarm->code, "PS0062") << j;
    EXPECT_NE(t.alarm->message.find("finish groove's floor"), std::string::npos) << t.alarm->message;
  }
}

// The cycle record's rough profile (drawn dashed in every plot) is the groove moved in by the
// allowances (docs/g74_1.md I15), not the finish shape shifted. S = (0, 20), h −4 (towards −Z),
// d −4 (width 2 towards −X), flanks at 90°: the finish profile (0, 20) → (−4, 20) → (−4, 18) →
// (0, 18); U0.4 W0.2 move the near flank to x 19.8, the far one to 18.2 and the floor to z −3.8.
TEST(G74_1Record, TheRoughProfileIsTheGrooveMovedInByTheAllowances) {
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q3 H-4 D-4;\nG74.1 R0.5 U0.4 W0.2 J1;\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.cycles.size(), 1u);
  const std::vector<Segment> rough = t.cycles.front().roughProfile();
  const std::vector<Point> corners{{0, 19.8}, {-3.8, 19.8}, {-3.8, 18.2}, {0, 18.2}};
  ASSERT_EQ(rough.size(), corners.size() - 1);
  for (std::size_t i = 0; i < rough.size(); ++i) {
    EXPECT_TRUE(nearlyEqual(rough[i].from, corners[i], 1e-9)) << i;
    EXPECT_TRUE(nearlyEqual(rough[i].to, corners[i + 1], 1e-9)) << i;
  }
  const PlotInput plot = plotInputFor(t, "allowances");
  ASSERT_EQ(plot.rough.segments.size(), rough.size());
  EXPECT_TRUE(nearlyEqual(plot.rough.segments[1].from, {-3.8, 19.8}, 1e-9));
}

// I22: the second layer runs over the cycles of the first that reached its bottom. S = (0, 20), h −4,
// d −8 (floor 4 wide), ∠a 45 (near flank u = w), ∠b 90 (far flank u = 8), Δi/2 0.75, Δk 5 (one
// peck), V2 (layers 0…2, 2…4), a 1 mm blade. Layer 1 (slice at w 0: u 0…8): cycles u 1, 1.75, 2.5,
// 3.25, … 7.75, 8; under the blade's near corner u − 1 the flank allows w = u − 1: 0, 0.75, 1.5 (short
// of the bottom 2), then 2 from u 3.25 on. Layer 2 starts at u 3.25 (x 16.75), not at its slice's
// near boundary + r = 3 (x 17): a plunge there would cross the flank's staircase [2, 2.25] × [1.5, 2]
// that layer 1 left (rapids-in-air, found by fuzz --cycles g74.1). The far flank is straight down:
// both layers end at u 8 (x 12).
TEST(G74_1Layers, ALayerRunsOverTheCyclesOfTheLayerAboveThatReachedItsBottom) {
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1.5 Q5 H-4 D-8 A45;\nG74.1 R0.5 V2 I1;\n");
  ASSERT_FALSE(t.alarm);
  std::vector<Point> layerStarts, layerEnds;
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    const Move& m = t.moves[i];
    if (m.rules.front() == "G74_1.STEP2") layerStarts.push_back(m.to);
    if (m.rules.front() == "G74_1.STEP8") layerEnds.push_back(t.from(i));
  }
  ASSERT_FALSE(layerStarts.empty());
  EXPECT_NEAR(layerStarts.back().z, -2, 1e-9);
  EXPECT_NEAR(layerStarts.back().x, 16.75, 1e-9);
  ASSERT_FALSE(layerEnds.empty());
  EXPECT_NEAR(layerEnds.front().x, 12, 1e-9);  // layer 1's Amf: u 8
  EXPECT_NEAR(layerEnds.back().x, 12, 1e-9);   // layer 2's
}

// I22 when no cycle of a layer reaches its bottom (found by fuzz --cycles g74.1 --seed 7, shrunk): a
// pointed tool (no I) stepping Δi/2 = P38800 × 0.0001 / 2 = 1.94 across a groove 1.97 wide at the
// start level, Δk = Q2000 × 0.0001 = 0.2, e = 1.53, V0.5. u = 16.51 − x (radius), w = 13.77 − z.
// The groove: near flank w = u·tan 48° (N: u = cot 48° = 0.900404, w 1), floor to F (1.900404, 1),
// far flank at 86° to M2: u = 1.900404 + cot 86° = 1.970331. Layer 1 (w 0 … 0.5): the cycle at u 0
// stands on the near flank's top (no move); at u 1.94 the far flank allows (1.970331 − 1.94)·tan 86°
// = 0.433751: feeds to w 0.2, retract to −1.33, feed to 0.4, retract to −1.13, feed to Bmn 0.433751
// (0.6 passes it), back to w 0; Amf u 1.970331 is on the far flank's top (no move). No cycle reached
// 0.5, so there is no layer 2 (it plunged at the slice's u 0.5·cot 48° = 0.450202 through 0.063 mm of
// material and crossed 1.49 mm along w 0.5 with rapids only). ⑧ back to A11, ⑨ N, F, M2, A11, return.
TEST(G74_1Layers, NoLayerBelowOneWhoseCyclesAllStoppedOnAFlank) {
  const Toolpath t = planGsk("G00 X29.46 Z16.1 F0.1;\nG74.1 X33.02 Z13.77 P38800 Q2000 H-1 D-2 A48 B86;\nG74.1 R1.53 V0.5;\n", {});
  const double n = 16.51 - 0.900404, f = 16.51 - 1.900404, m2 = 16.51 - 1.970331;
  ASSERT_EQ(t.moves.size(), 15u);
  expectMoves(t, 0,
              {{'r', 13.77, 16.51, "G74_1.STEP1"},
               {'r', 13.77, 14.57, "G74_1.STEP7"},
               {'f', 13.57, 14.57, "G74_1.STEP3"},
               {'r', 15.1, 14.57, "G74_1.STEP4"},
               {'f', 13.37, 14.57, "G74_1.STEP5"},
               {'r', 14.9, 14.57, "G74_1.STEP4"}});
  EXPECT_NEAR(t.moves[6].to.z, 13.77 - 0.433751, 1e-6);  // Bmn
  expectMoves(t, 7, {{'r', 13.77, 14.57, "G74_1.STEP6"}});
  EXPECT_NEAR(t.moves[8].to.x, m2, 1e-6);  // ⑦ to Amf
  expectMoves(t, 9, {{'r', 13.77, 16.51, "G74_1.STEP8"}});
  EXPECT_NEAR(t.moves[10].to.x, n, 1e-6);
  EXPECT_NEAR(t.moves[10].to.z, 12.77, 1e-9);
  EXPECT_NEAR(t.moves[11].to.x, f, 1e-6);
  EXPECT_NEAR(t.moves[12].to.x, m2, 1e-6);
  EXPECT_NEAR(t.moves[12].to.z, 13.77, 1e-9);
  expectMoves(t, 13, {{'r', 13.77, 16.51, "G74_1.STEP9"}, {'r', 16.1, 14.73, "G74_1.STEP10"}});
}

// Found by the metamorphic relation scale-k on a fuzzer's case: the groove below (∠a 20°, rounded
// corners, Δk 1.875, e 0.025) has the far flank's last axial cycle 7.5 deep — computed through the
// round r4 as 7.500000024 — and the pecks land on 7.5 by (Δk + e) exactly: 1.875, 3.75, 5.625, 7.5.
// The last one reaches Bmn (STEP5); the plan went on with a retract and a feed of 2.4e-8 mm, one peck
// more than the same part 2.5 times smaller plans. The last cycle (x 5.001) feeds four times.
TEST(G74_1Steps, APeckLandingOnBmnWithinARoundingErrorReachesIt) {
  const Toolpath t = planGsk(
      "G00 X62.2 Z-73.75 F0.1;\nG74.1 X62.2 Z-75 P21000 Q18750 H-7.825 D-9.2 A20;\nG74.1 R0.025 E0.325 P0111;\n",
      {});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  int pecksOfTheLastCycle = 0;
  for (const Move& m : t.moves) {
    if (m.phase != MovePhase::Pass || m.kind != MoveKind::Feed) continue;
    if (std::abs(m.to.x - t.moves.back().to.x) > 1e-9 && std::abs(m.to.x - 5.001) < 0.001) ++pecksOfTheLastCycle;
  }
  EXPECT_EQ(pecksOfTheLastCycle, 4);  // 1.875, 3.75, 5.625, 7.5
}

}  // namespace
}  // namespace cyclecert
