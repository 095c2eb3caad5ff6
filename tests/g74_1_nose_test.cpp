// G74.1 with a pointed tool under G41/G42 (docs/g74_1.md I26, I27; reference/cycles/g74_1_nose.cpp):
// the cycle planned for the nose centre in the groove eroded by R, every move the imaginary tip. The
// coordinates are worked out by hand in the comments. Plane points are (z, x radius); P and Q in mm.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "reference/cycles/g74_1_nose.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

Toolpath planWithNose(const std::string& program, double noseRadius, int tip) {
  RunOptions options;
  options.tool = {noseRadius, tip};
  return planWithReference({program, "test.nc", "gsk", {{"182#7", 1}}, options});
}

struct Expected {
  char kind;  // 'r' rapid, 'f' feed
  double z, x;
};

void expectMoves(const Toolpath& t, const std::vector<Expected>& expected) {
  ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
  ASSERT_EQ(t.moves.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i) {
    SCOPED_TRACE("move " + std::to_string(i));
    EXPECT_EQ(t.moves[i].kind == MoveKind::Rapid ? 'r' : 'f', expected[i].kind);
    EXPECT_NEAR(t.moves[i].to.z, expected[i].z, 1e-9);
    EXPECT_NEAR(t.moves[i].to.x, expected[i].x, 1e-9);
  }
}

// S = X40 Z0 (radius 20), 4 deep (h < 0), floor 3 wide (radius), Δi 2 (steps of 1), Δk 3, e 0.5; the
// tool stands over the groove (X36 Z5).
constexpr const char* kGrooveG41 = "G00 X36 Z5 F0.1;\nG41;\nG74.1 X40 Z0 P2 Q3 H-4 D-6;\nG74.1 R0.5;\n";

TEST(G74_1Nose, AStraightGrooveUnderG41IsCutByTheNoseMovedToTheTip) {
  // u = 20 − x, w = −z. The steps plan the nose's lowest point (its centre + R along h) on the groove
  // eroded by R 0.5: near flank u 0.5, far flank u 2.5, the floor w 4, the start level w 0. Cycles at
  // u 0.5, 1.5, 2.5, each: feed w 3, retract 2.5, feed 4 (Bmn), back 0. The centre is (u, w − 0.5);
  // tip 3: the control point = centre + 0.5·(−z, −x): z = −w, x = 20 − u − 0.5.
  std::vector<Expected> e{{'r', 0, 19}};
  for (double x : {19.0, 18.0, 17.0}) {
    if (x != 19.0) e.push_back({'r', 0, x});
    e.insert(e.end(), {{'f', -3, x}, {'r', -2.5, x}, {'f', -4, x}, {'r', 0, x}});
  }
  e.insert(e.end(), {{'r', 0, 19}, {'f', -4, 19}, {'f', -4, 17}, {'f', 0, 17}, {'r', 0, 19}, {'r', 5, 18}});
  expectMoves(planWithNose(kGrooveG41, 0.5, 3), e);
}

TEST(G74_1Nose, AGrooveStepsTowardsPlusXUnderG42) {
  // h < 0, d > 0: the frame mirrors, the inside lies right of the passes (I26): G42. u = x − 20;
  // tip 2 = (−z, +x): z = −w, x = 20 + u + 0.5.
  const Toolpath t = planWithNose("G00 X44 Z5 F0.1;\nG42;\nG74.1 X40 Z0 P2 Q3 H-4 D6;\nG74.1 R0.5;\n", 0.5, 2);
  std::vector<Expected> e{{'r', 0, 21}};
  for (double x : {21.0, 22.0, 23.0}) {
    if (x != 21.0) e.push_back({'r', 0, x});
    e.insert(e.end(), {{'f', -3, x}, {'r', -2.5, x}, {'f', -4, x}, {'r', 0, x}});
  }
  e.insert(e.end(), {{'r', 0, 21}, {'f', -4, 21}, {'f', -4, 23}, {'f', 0, 23}, {'r', 0, 21}, {'r', 5, 22}});
  expectMoves(t, e);
}

TEST(G74_1Nose, TheOtherSideIsTheInterferenceAlarmNamingTheCodeToCommand) {
  const Toolpath t = planWithNose("G00 X36 Z5 F0.1;\nG42;\nG74.1 X40 Z0 P2 Q3 H-4 D-6;\nG74.1 R0.5;\n", 0.5, 3);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, alarm::kInterference);
  EXPECT_EQ(t.alarm->line, 4);
  EXPECT_NE(t.alarm->message.find("command G41"), std::string::npos) << t.alarm->message;
}

TEST(G74_1Nose, ANoseWiderThanHalfTheFloorIsTheInterferenceAlarmWithTheNumbers) {
  // Floor 3 wide: a nose of 2 (4 across) has no centre path (I27); one of 1.4 fits.
  const Toolpath t = planWithNose(kGrooveG41, 2, 3);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, alarm::kInterference);
  EXPECT_EQ(t.alarm->line, 4);
  EXPECT_NE(t.alarm->message.find("R 2"), std::string::npos) << t.alarm->message;
  EXPECT_NE(t.alarm->message.find("floor 3 mm wide"), std::string::npos) << t.alarm->message;
  EXPECT_FALSE(planWithNose(kGrooveG41, 1.4, 3).alarm);
}

TEST(G74_1Nose, AFloorRoundLargerThanTheNoseShrinksOneSmallerBecomesSharp) {
  // r3 a round of 1 (centre u 1, w 3): the centre's arc of 0.5 from (u 0.5, w 3) to (u 1, w 3.5);
  // r4 a round of 0.3 < R: sharp — the floor runs to u 2.5. Tip 0: the control point is the centre,
  // x = 20 − u, z = −w (the centre's w). The first cycle (u 0.5) ends on the round: centre w 3.
  const Toolpath t =
      planWithNose("G00 X36 Z5 F0.1;\nG41;\nG74.1 X40 Z0 P2 Q3 H-4 D-6;\nG74.1 R0.5 D1 E0.3 P0011;\n", 0.5, 0);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.moves.size(), 22u);
  EXPECT_NEAR(t.moves[0].to.z, 0.5, 1e-9);  // A11: the nose on the start level, its centre 0.5 above
  EXPECT_NEAR(t.moves[3].to.z, -3, 1e-9);
  const Move& arc = t.moves[17];
  EXPECT_EQ(arc.shape, SegmentKind::ArcCCW);
  EXPECT_NEAR(arc.to.z, -3.5, 1e-9);
  EXPECT_NEAR(arc.to.x, 19, 1e-9);
  ASSERT_TRUE(arc.center);
  EXPECT_NEAR(arc.center->z, -3, 1e-9);
  EXPECT_NEAR(arc.center->x, 19, 1e-9);
  EXPECT_NEAR(t.moves[18].to.x, 17.5, 1e-9);  // the floor to the sharp far corner
  EXPECT_NEAR(t.moves[18].to.z, -3.5, 1e-9);
}

TEST(G74_1Nose, AFloorChamferTheNoseCannotReachLeavesTheCornerSharp) {
  // 90° corner, R 1: the nose stands 1/sin45° − 1 = 0.414 from the vertex along the bisector; a
  // chamfer of legs c reaches c·cos45°: 0.5 does not (0.354), 1 does (0.707).
  GrooveShape g;
  g.depth = 4;
  g.floorWidth = 4;
  g.corners[kCornerR3] = {0.5, GrooveCornerKind::Chamfer};
  const GrooveProfile untouched = noseCentreProfile(g, 0, 0, 1);
  EXPECT_NEAR(untouched.floorFrom, 1, 1e-9);
  g.corners[kCornerR3].size = 1;
  const GrooveProfile touched = noseCentreProfile(g, 0, 0, 1);
  EXPECT_GT(touched.floorFrom, 1 + 1e-6);
}

// A mouth rising behind S (∠p 30°) with an r1 chamfer of 1 (found by fuzz --cycles g74.1 --seed 1 as
// 0.003 mm left at the chamfer's top). u = 20 − x, w = −z, R 0.2, tip 0 (the control point is the
// centre). The chamfer (I10: 1 along each edge from S): P0 = S − (cos 30°, sin 30°) = (−0.866025,
// −0.5) on the mouth, above the start level, to E = (0, 1) on the 90° near flank; its direction
// (0.5, 0.866025), the groove's side (0.866025, −0.5). The nose's edge follows the whole chamfer as
// the point's path does from P0 (I26): its centre starts at P0 + 0.2·(0.866025, −0.5) = (−0.692820,
// −0.6) — z 0.6, x 20.692820 — not where the chamfer's offset crosses the start level (the lowest
// point on w 0: centre (−0.461880, −0.2), x 20.461880 z 0.2, which left the chamfer's top above
// w −0.4 standing); then to E + 0.2·(0.866025, −0.5) = (0.173205, 0.9) — z −0.9, x 19.826795 — and
// round E (an arc of R: the part's corner there is convex) to the flank's offset (0.2, 1): z −1, x 19.8.
TEST(G74_1Nose, TheNoseFollowsAnR1ChamferRisingAboveTheStartLevelWhole) {
  const Toolpath t = planWithNose("G00 X42 Z3 F0.1;\nG41;\nG74.1 X40 Z0 P2 Q5 H-4 D-8 L30;\nG74.1 R0.5 A1;\n", 0.2, 0);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  std::size_t pass = 0;
  while (pass < t.moves.size() && t.moves[pass].phase != MovePhase::SemiFinish) ++pass;
  ASSERT_LT(pass + 2, t.moves.size());
  EXPECT_EQ(t.moves[pass].kind, MoveKind::Feed);
  EXPECT_NEAR(t.moves[pass].to.z, 0.6, 1e-6);
  EXPECT_NEAR(t.moves[pass].to.x, 20.692820, 1e-6);
  EXPECT_NEAR(t.moves[pass + 1].to.z, -0.9, 1e-6);
  EXPECT_NEAR(t.moves[pass + 1].to.x, 19.826795, 1e-6);
  EXPECT_NE(t.moves[pass + 2].shape, SegmentKind::Line);
  EXPECT_NEAR(t.moves[pass + 2].to.z, -1, 1e-6);
  EXPECT_NEAR(t.moves[pass + 2].to.x, 19.8, 1e-6);
}

// I22 with a nose: no layer below one whose cycles all stopped on the flanks (the class `fuzz --cycles
// g74.1` found as rapids-in-air of about 0.01 mm beside a slanted flank: layer 2 plunged at its
// slice's near boundary through what layer 1 had not cut). u = 20 − x, w = −z; R 0.2, tip 0 (the
// control point is the centre, 0.2 above the lowest point: z = 0.2 − w). The groove: flanks at 45°
// from S (0, 0) to N (2, 2) and from F (3, 2) to M2 (5, 0). For the lowest point (I26) the near flank
// moves in to u = w + q with q = 0.2·√2 − 0.2 = 0.082843, the far one to u = 5.2 − 0.2·√2 − w, the floor
// stays at w 2. A11 = (q, 0). Layer 1 (w 0 … 1, V1): cycles at u q (depth 0: no move), q + Δi/2 =
// q + 4 (the far flank allows 5.2 − 0.2·√2 − 4 − q = 1.4 − 0.4·√2 = 0.834315 < 1: one feed, Δk 5),
// Amf u 5.2 − 0.2·√2 (depth 0). None reached 1: no layer 2; ⑧ back to A11; ⑨ N' (2 + q, 2), F'
// (3.2 − 0.2·√2, 2), the far flank to the start level; back to A11; the return to X38 Z3.
TEST(G74_1Nose, NoLayerBelowOneWhoseCyclesAllStoppedOnTheFlanks) {
  const double q = 0.2 * std::sqrt(2.0) - 0.2, far = 5.2 - 0.2 * std::sqrt(2.0);
  const Toolpath t = planWithNose("G00 X38 Z3 F0.1;\nG41;\nG74.1 X40 Z0 P8 Q5 H-2 D-2 A45 B45;\nG74.1 R0.5 V1;\n", 0.2, 0);
  expectMoves(t, {{'r', 0.2, 20 - q},
                  {'r', 0.2, 16 - q},
                  {'f', 0.2 - (1.4 - 0.4 * std::sqrt(2.0)), 16 - q},
                  {'r', 0.2, 16 - q},
                  {'r', 0.2, 20 - far},
                  {'r', 0.2, 20 - q},
                  {'f', -1.8, 18 - q},
                  {'f', -1.8, 20 - (far - 2)},
                  {'f', 0.2, 20 - far},
                  {'r', 0.2, 20 - q},
                  {'r', 3, 19}});
}

}  // namespace
}  // namespace cyclecert
