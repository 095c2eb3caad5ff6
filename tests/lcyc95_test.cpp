// LCYC95 (SINUMERIK 802S/C, seed 004 §2; reference/siemens/lcyc95.cpp and siemens_roughing_*):
// the machining-type table, the roughing and finishing sequences on hand-derivable contours, the
// seed's L42, face and internal machining, complete machining, and the alarms. Every expectation is
// derived by hand in the comments from the documented steps (LCYC95.ROUGH/FINISH/COMPLETE) and the
// interpretations written in specs/rules.json (LCYC95.START, LCYC95.DEPTH).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "reference/model/alarms.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_parser.h"
#include "reference/siemens/siemens_roughing_contour.h"
#include "reference/siemens/siemens_roughing_steps.h"
#include "tests/siemens_contours.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

MachiningType typeOf(double r105) { return machiningTypeOf(r105).value(); }

// R106=0, R108=4, R109=0, R110=1, R111=0.2, R112=0.1 unless a test says otherwise.
Lcyc95Parameters params(double r105) {
  Lcyc95Parameters p;
  p.type = typeOf(r105);
  p.allowance = 0;
  p.maxInfeed = 4;
  p.infeedAngle = 0;
  p.retract = 1;
  p.roughingFeed = 0.2;
  p.finishingFeed = 0.1;
  return p;
}

SiemensCycleCall callAt(Point position, const SiemensContour& contour, ToolOffset tool = {}) {
  SiemensCycleCall c;
  c.line = 7;
  c.position = position;
  c.contour = &contour;
  c.tool = tool;
  return c;
}

std::string alarmCodeOf(const SiemensCycleCall& call, const Lcyc95Parameters& p) {
  try {
    planLcyc95(call, p);
  } catch (const CycleAlarm& a) {
    EXPECT_EQ(a.alarm().line, call.line);
    return a.alarm().code;
  }
  return "no alarm";
}

// --- LCYC95.PARAMS: the table of R105 ---

TEST(Lcyc95Types, TheTableOfR105) {
  using C = SiemensCut;
  using S = SiemensSide;
  using T = SiemensTechnology;
  const MachiningType table[] = {
      {C::Longitudinal, S::External, T::Roughing},  {C::Face, S::External, T::Roughing},
      {C::Longitudinal, S::Internal, T::Roughing},  {C::Face, S::Internal, T::Roughing},
      {C::Longitudinal, S::External, T::Finishing}, {C::Face, S::External, T::Finishing},
      {C::Longitudinal, S::Internal, T::Finishing}, {C::Face, S::Internal, T::Finishing},
      {C::Longitudinal, S::External, T::Complete},  {C::Face, S::External, T::Complete},
      {C::Longitudinal, S::Internal, T::Complete},  {C::Face, S::Internal, T::Complete},
  };
  for (int v = 1; v <= 12; ++v) EXPECT_EQ(machiningTypeOf(v), table[v - 1]) << "R105=" << v;
}

TEST(Lcyc95Types, ValuesOutsideTheTableAreNone) {
  for (double v : {0.0, 13.0, -1.0, 1.5, 12.0001}) EXPECT_FALSE(machiningTypeOf(v)) << v;
  EXPECT_FALSE(machiningTypeOf(std::nan("")));
}

// --- LCYC95.DEPTH: the fewest equal steps not above R108 ---

TEST(Lcyc95Depth, TheTotalDepthInTheFewestEqualSteps) {
  // 9 / 4 = 2.25 → 3 steps of 3; 8 / 4 = 2 exactly → 2 steps of 4; 21.3 / 2 = 10.65 → 11 of 1.93636.
  EXPECT_EQ(equalInfeedSteps(9, 4).count, 3);
  EXPECT_DOUBLE_EQ(equalInfeedSteps(9, 4).depth, 3);
  EXPECT_EQ(equalInfeedSteps(8, 4).count, 2);
  EXPECT_DOUBLE_EQ(equalInfeedSteps(8, 4).depth, 4);
  EXPECT_EQ(equalInfeedSteps(21.3, 2).count, 11);
  EXPECT_NEAR(equalInfeedSteps(21.3, 2).depth, 1.9363636, 1e-6);
  EXPECT_EQ(equalInfeedSteps(0, 2).count, 0);
}

// --- LCYC95.ROUGH on the step shaft ---
//
// Contour (radius): (z 0, x 0) → (0, 4) → (−10, 4) → (−10, 9) → (−20, 9); R106 = 0, so the profile is
// the contour. Start (LCYC95.START): R110 = 1 beyond the highest z (0) and the highest x (9): (1, 10).
// Depth 9 − 0 = 9, R108 = 4: 3 passes of 3 at x 6, 3, 0. Each pass: infeed straight (R109 = 0) at
// R111 to the level at z 1; G1 to where the level meets the profile; along the profile up to the
// previous level; retract 1 in each axis; G0 back to z 1.
TEST(Lcyc95Rough, TheStepShaftMoveByMove) {
  const SiemensContour shaft = stepShaft();
  const auto out = planLcyc95(callAt({5, 15}, shaft), params(1));
  expectMoves(out.moves, {
                             {G0, {1, 10}, "approach"},
                             // pass 1, level 6 (previous: the top, 9): meets the face z −10 at x 6.
                             {G1, {1, 6}, "pass", 1},
                             {G1, {-10, 6}, "pass", 1},
                             {G1, {-10, 9}, "pass", 1},
                             {G0, {-9, 10}, "pass", 1},
                             {G0, {1, 10}, "pass", 1},
                             // pass 2, level 3: meets the face z 0 at x 3; up to x 6 along the contour.
                             {G1, {1, 3}, "pass", 2},
                             {G1, {0, 3}, "pass", 2},
                             {G1, {0, 4}, "pass", 2},
                             {G1, {-10, 4}, "pass", 2},
                             {G1, {-10, 6}, "pass", 2},
                             {G0, {-9, 7}, "pass", 2},
                             {G0, {1, 7}, "pass", 2},
                             // pass 3, level 0: meets the contour at its start; up to x 3.
                             {G1, {1, 0}, "pass", 3},
                             {G1, {0, 0}, "pass", 3},
                             {G1, {0, 3}, "pass", 3},
                             {G0, {1, 4}, "pass", 3},
                             // roughing only: G0 back to the computed start, both axes together.
                             {G0, {1, 10}, "return"},
                         });
  EXPECT_EQ(out.end, (Point{1, 10}));
  for (const Move& m : out.moves) {
    if (m.kind == MoveKind::Feed) {
      EXPECT_EQ(m.feed, 0.2);
    }
    EXPECT_EQ(m.rules.front(), "LCYC95.ROUGH");
  }
  EXPECT_EQ(out.moves[0].rules, (std::vector<std::string>{"LCYC95.ROUGH", "LCYC95.START"}));
  EXPECT_EQ(out.moves[1].rules, (std::vector<std::string>{"LCYC95.ROUGH", "LCYC95.DEPTH"}));
}

// R109 = 45°: the infeed runs as far along −z as it goes down. Pass 1 from (1, 10) down 4 to x 6:
// z 1 − 4·tan 45° = −3.
TEST(Lcyc95Rough, TheInfeedRunsAtTheAngleR109) {
  const SiemensContour shaft = stepShaft();
  Lcyc95Parameters p = params(1);
  p.infeedAngle = 45;
  const auto out = planLcyc95(callAt({5, 15}, shaft), p);
  EXPECT_NEAR(out.moves[1].to.z, -3, 1e-9);
  EXPECT_NEAR(out.moves[1].to.x, 6, 1e-9);
  EXPECT_EQ(out.moves[1].kind, MoveKind::Feed);
}

// --- LCYC95.FINISH ---
//
// R105 = 5 from (5, 15): G0 to the start (1, 10) axis by axis, X (the infeed axis) first: (5, 10),
// then (1, 10); G0 to the contour start (0, 0); the contour at R112; G0 back to (1, 10).
TEST(Lcyc95Finish, AxisByAxisThenTheContourAndBack) {
  const SiemensContour shaft = stepShaft();
  const auto out = planLcyc95(callAt({5, 15}, shaft), params(5));
  expectMoves(out.moves, {
                             {G0, {5, 10}, "approach"},
                             {G0, {1, 10}, "approach"},
                             {G0, {0, 0}, "finish"},
                             {G1, {0, 4}, "finish"},
                             {G1, {-10, 4}, "finish"},
                             {G1, {-10, 9}, "finish"},
                             {G1, {-20, 9}, "finish"},
                             {G0, {1, 10}, "return"},
                         });
  EXPECT_EQ(out.moves[3].feed, 0.1);
  EXPECT_EQ(out.moves[3].rules, (std::vector<std::string>{"LCYC95.FINISH"}));
}

// Nose radius 0.4, tip 3: finishing runs the tool's control point as G42 would (stock on the right
// of travel towards −z). The nose centre runs 0.4 off the contour (face z 0.4, shoulder x 4.4, face
// z −9.6, x 9.4; round corners of 0.4 about (0, 4) and (−10, 9); the inner corner (−10, 4) meets at
// (−9.6, 4.4)); the tip point is the centre + 0.4·(−1, −1): the face at z 0 from x −0.4 to 3.6,
// the arc about (−0.4, 3.6) to (−0.4, 4), x 4 to z −10, the face z −10 to x 8.6, the arc about
// (−10.4, 8.6) to (−10.4, 9), x 9 to z −20.4.
TEST(Lcyc95Finish, NoseRadiusCompensationIsSwitchedOnAutomatically) {
  const SiemensContour shaft = stepShaft();
  const auto out = planLcyc95(callAt({5, 15}, shaft, {0.4, 3}), params(5));
  expectMoves(out.moves, {
                             {G0, {5, 10}, "approach"},
                             {G0, {1, 10}, "approach"},
                             {G0, {0, -0.4}, "finish"},
                             {G1, {0, 3.6}, "finish"},
                             {G1, {-0.4, 4}, "finish"},
                             {G1, {-10, 4}, "finish"},
                             {G1, {-10, 8.6}, "finish"},
                             {G1, {-10.4, 9}, "finish"},
                             {G1, {-20.4, 9}, "finish"},
                             {G0, {1, 10}, "return"},
                         });
  EXPECT_EQ(out.moves[4].shape, SegmentKind::ArcCCW);
  EXPECT_NEAR(out.moves[4].center->z, -0.4, 1e-9);
  EXPECT_NEAR(out.moves[4].center->x, 3.6, 1e-9);
}

// --- LCYC95.COMPLETE, with R106 = 0.5 and R108 = 5 ---
//
// The profile is the contour offset 0.5 outwards: face z 0.5 from x 0 to 4; round corner about (0, 4)
// to (0, 4.5); x 4.5 to the inner corner (−9.5, 4.5); face z −9.5 to x 9; round corner about (−10, 9)
// to (−10, 9.5); x 9.5 to z −20. Start: (0.5 + 1, 9.5 + 1) = (1.5, 10.5). Depth 9.5 − 0 = 9.5,
// R108 = 5: 2 passes of 4.75, at x 4.75 and 0. After the last pass's retract the finishing starts
// (no return to the start first): axis by axis to (1.5, 10.5), then the contour (without allowance).
TEST(Lcyc95Complete, RoughingThenFinishingWithoutTheReturnBetween) {
  const SiemensContour shaft = stepShaft();
  Lcyc95Parameters p = params(9);
  p.allowance = 0.5;
  p.maxInfeed = 5;
  const auto out = planLcyc95(callAt({5, 15}, shaft), p);
  expectMoves(out.moves, {
                             {G0, {1.5, 10.5}, "approach"},
                             {G1, {1.5, 4.75}, "pass", 1},
                             {G1, {-9.5, 4.75}, "pass", 1},
                             {G1, {-9.5, 9}, "pass", 1},
                             {G1, {-10, 9.5}, "pass", 1},  // the round corner, G3 about (−10, 9)
                             {G0, {-9, 10.5}, "pass", 1},
                             {G0, {1.5, 10.5}, "pass", 1},
                             {G1, {1.5, 0}, "pass", 2},
                             {G1, {0.5, 0}, "pass", 2},
                             {G1, {0.5, 4}, "pass", 2},
                             {G1, {0, 4.5}, "pass", 2},  // G3 about (0, 4)
                             {G1, {-9.5, 4.5}, "pass", 2},
                             {G1, {-9.5, 4.75}, "pass", 2},
                             {G0, {-8.5, 5.75}, "pass", 2},
                             {G0, {-8.5, 10.5}, "approach"},
                             {G0, {1.5, 10.5}, "approach"},
                             {G0, {0, 0}, "finish"},
                             {G1, {0, 4}, "finish"},
                             {G1, {-10, 4}, "finish"},
                             {G1, {-10, 9}, "finish"},
                             {G1, {-20, 9}, "finish"},
                             {G0, {1.5, 10.5}, "return"},
                         });
  EXPECT_EQ(out.moves[4].shape, SegmentKind::ArcCCW);
  EXPECT_EQ(out.moves[10].shape, SegmentKind::ArcCCW);
  EXPECT_EQ(out.moves[14].rules, (std::vector<std::string>{"LCYC95.FINISH", "LCYC95.COMPLETE"}));
}

// --- Face machining (R105 = 2): the cut along X, the infeed along Z ---
//
// The step shaft with z and x exchanged and moved 20 along the cut axis: (z 0, x 20) → (4, 20) →
// (4, 10) → (9, 10) → (9, 0), programmed towards −X (the finishing direction). Every move is the step
// shaft's with (z, x) → (x, z + 20): start (10, 21); levels z 6, 3, 0.
TEST(Lcyc95Face, TheStepShaftAlongTheOtherAxis) {
  const SiemensContour face = polyline("FACE", {{0, 20}, {4, 20}, {4, 10}, {9, 10}, {9, 0}});
  const auto out = planLcyc95(callAt({15, 25}, face), params(2));
  expectMoves(out.moves, {
                             {G0, {10, 21}, "approach"},
                             {G1, {6, 21}, "pass", 1},
                             {G1, {6, 10}, "pass", 1},
                             {G1, {9, 10}, "pass", 1},
                             {G0, {10, 11}, "pass", 1},
                             {G0, {10, 21}, "pass", 1},
                             {G1, {3, 21}, "pass", 2},
                             {G1, {3, 20}, "pass", 2},
                             {G1, {4, 20}, "pass", 2},
                             {G1, {4, 10}, "pass", 2},
                             {G1, {6, 10}, "pass", 2},
                             {G0, {7, 11}, "pass", 2},
                             {G0, {7, 21}, "pass", 2},
                             {G1, {0, 21}, "pass", 3},
                             {G1, {0, 20}, "pass", 3},
                             {G1, {3, 20}, "pass", 3},
                             {G0, {4, 21}, "pass", 3},
                             {G0, {10, 21}, "return"},
                         });
}

// Face finishing: the infeed axis (Z) first. From (15, 25): (10, 25), then (10, 21).
TEST(Lcyc95Face, FinishingMovesTheInfeedAxisZFirst) {
  const SiemensContour face = polyline("FACE", {{0, 20}, {4, 20}, {4, 10}, {9, 10}, {9, 0}});
  const auto out = planLcyc95(callAt({15, 25}, face), params(6));
  ASSERT_GE(out.moves.size(), 3u);
  EXPECT_EQ(out.moves[0].to, (Point{10, 25}));
  EXPECT_EQ(out.moves[1].to, (Point{10, 21}));
  EXPECT_EQ(out.moves[2].to, (Point{0, 20}));
}

// --- Internal machining (R105 = 3): the depth direction mirrored ---
//
// A bore: (z 0, x 30) → (0, 26) → (−10, 26) → (−10, 21) → (−20, 21), the step shaft with x → 30 − x.
// Start (1, 30 − 10) = (1, 20); levels x 24, 27, 30 (infeed towards +X).
TEST(Lcyc95Internal, TheStepShaftMirrored) {
  const SiemensContour bore = polyline("BORE", {{0, 30}, {0, 26}, {-10, 26}, {-10, 21}, {-20, 21}});
  const auto out = planLcyc95(callAt({5, 15}, bore), params(3));
  expectMoves(out.moves, {
                             {G0, {1, 20}, "approach"},
                             {G1, {1, 24}, "pass", 1},
                             {G1, {-10, 24}, "pass", 1},
                             {G1, {-10, 21}, "pass", 1},
                             {G0, {-9, 20}, "pass", 1},
                             {G0, {1, 20}, "pass", 1},
                             {G1, {1, 27}, "pass", 2},
                             {G1, {0, 27}, "pass", 2},
                             {G1, {0, 26}, "pass", 2},
                             {G1, {-10, 26}, "pass", 2},
                             {G1, {-10, 24}, "pass", 2},
                             {G0, {-9, 23}, "pass", 2},
                             {G0, {1, 23}, "pass", 2},
                             {G1, {1, 30}, "pass", 3},
                             {G1, {0, 30}, "pass", 3},
                             {G1, {0, 27}, "pass", 3},
                             {G0, {1, 26}, "pass", 3},
                             {G0, {1, 20}, "return"},
                         });
}

// Internal finishing compensates on the left (G41): the bore's face z 0 is traced by the nose centre
// at z 0.4 as outside, the shoulder x 26 at x 25.6 (below it, inside the hole). Tip 2 (−1, +1) puts the
// control point back on x 26: the second feed runs along x 26 to z −10.
TEST(Lcyc95Internal, FinishingCompensatesOnTheLeft) {
  const SiemensContour bore = polyline("BORE", {{0, 30}, {0, 26}, {-10, 26}, {-10, 21}, {-20, 21}});
  const auto out = planLcyc95(callAt({5, 15}, bore, {0.4, 2}), params(7));
  ASSERT_GE(out.moves.size(), 6u);
  // Moves: approach X, approach Z, G0 to the start, the face, the round corner, the shoulder.
  EXPECT_NEAR(out.moves[5].to.x, 26, 1e-9);
  EXPECT_NEAR(out.moves[5].to.z, -10, 1e-9);
}

// --- The seed's L42 (SEED004.EX.L42), built by hand in radius ---
//
// G1X0Z0: (0, 0). G3X20.8Z-25.8K-15I0: centre (−15, 0), radius 15, to (−25.8, 10.4) — which lies
// 14.9933 from that centre: the printed end is 0.007 off the circle. Here the end is put on the circle
// in the same direction from the centre: (−15, 0) + 15·(−10.8, 10.4)/14.9933 (kL42ArcEnd), which keeps
// the arc's start tangent along +x. The arc runs from the start over the top (−15, 15) to about 136° —
// more than a quarter circle, so here it is split at its top into two arcs that describe the same part
// (the seed's own text raises the alarm: Lcyc95Alarms.L42AsPrintedHasAnArcOverAQuarterCircle).
// G2X31.6Z-39.5CR=8: to (−39.5, 15.8), radius 8 clockwise: 134°, split at its bottom likewise. Then
// the lines to (−45, 15.8), (−45, 17.5), (−46.5, 19), (−58.5, 19), (−60, 17.5), (−65, 17.5), (−65, 19.5),
// (−66.5, 21), (−75, 21).
const Point kL42Centre{-15, 0};
const Point kL42Top{-15, 15};
const Point kL42ArcEnd = kL42Centre + (15 / std::hypot(10.8, 10.4)) * Point{-10.8, 10.4};

SiemensContour l42() {
  SiemensContour c{"L42", "L42.spf", {}};
  c.segments.push_back(arc(SegmentKind::ArcCCW, {0, 0}, kL42Top, kL42Centre, 2));
  c.segments.push_back(arc(SegmentKind::ArcCCW, kL42Top, kL42ArcEnd, kL42Centre, 2));
  const Point g2Centre = arcCenterFromRadius(kL42ArcEnd, {-39.5, 15.8}, 8, SegmentKind::ArcCW).value();
  const Point bottom{g2Centre.z, g2Centre.x - 8};
  c.segments.push_back(arc(SegmentKind::ArcCW, kL42ArcEnd, bottom, g2Centre, 3));
  c.segments.push_back(arc(SegmentKind::ArcCW, bottom, {-39.5, 15.8}, g2Centre, 3));
  const std::vector<Point> rest = {{-39.5, 15.8}, {-45, 15.8}, {-45, 17.5}, {-46.5, 19}, {-58.5, 19},
                                   {-60, 17.5},   {-65, 17.5}, {-65, 19.5}, {-66.5, 21}, {-75, 21}};
  for (std::size_t i = 1; i < rest.size(); ++i) c.segments.push_back(line(rest[i - 1], rest[i], int(i) + 3));
  return c;
}

// R105=1 R106=0.3 R108=2 R109=7 R110=1.5 R111=0.4 R112=0.25, from G0X50Z2: (2, 25).
Lcyc95Parameters l42Roughing() {
  Lcyc95Parameters p;
  p.type = typeOf(1);
  p.allowance = 0.3;
  p.maxInfeed = 2;
  p.infeedAngle = 7;
  p.retract = 1.5;
  p.roughingFeed = 0.4;
  p.finishingFeed = 0.25;
  return p;
}

// The profile (contour + 0.3): its highest point the last diameter, x 21 + 0.3 = 21.3; its lowest the
// start of the first arc moved 0.3 along its normal (+z): (0.3, 0); its largest z that same 0.3.
// Start: (0.3 + 1.5, 21.3 + 1.5) = (1.8, 22.8). Depth 21.3, R108 = 2: 21.3 / 2 = 10.65 → 11 passes
// of 21.3 / 11 = 1.936364.
TEST(Lcyc95Seed, L42RoughingMakesElevenPassesOf1p936) {
  const SiemensContour contour = l42();
  const auto out = planLcyc95(callAt({2, 25}, contour), l42Roughing());
  EXPECT_EQ(passCount(out.moves), 11);
  EXPECT_TRUE(nearlyEqual(out.moves.front().to, {1.8, 22.8}, 1e-9));
  // Every pass's infeed ends on its level 21.3 − k·1.936364 (the last on 0).
  int k = 0;
  for (std::size_t i = 0; i < out.moves.size(); ++i) {
    const Move& m = out.moves[i];
    if (m.phase != MovePhase::Pass || m.pass == k) continue;
    k = m.pass;
    EXPECT_NEAR(m.to.x, 21.3 - k * 21.3 / 11, 1e-9) << "pass " << k;
  }
  EXPECT_TRUE(nearlyEqual(out.end, {1.8, 22.8}, 1e-9));
}

// Pass 1 on level 21.3 − 1.936364 = 19.363636: infeed from (1.8, 22.8) at 7°: down 3.436364, along −z
// 3.436364·tan 7° = 0.421933 → (1.378067, 19.363636). The level first meets the profile on the face
// z −65 moved 0.3 towards +z: (−64.7, 19.363636) (everything before it lies lower: the flat at
// x 19 + 0.3 = 19.3 is below the level). Cleanup: up that face to (−64.7, 19.5); the round corner of
// 0.3 about (−65, 19.5) to the chamfer's offset start (−65 + 0.3·sin45°, 19.5 + 0.3·cos45°) =
// (−64.787868, 19.712132); the chamfer to (−66.5 + 0.212132, 21 + 0.212132) = (−66.287868, 21.212132);
// the round corner about (−66.5, 21) to (−66.5, 21.3), the previous level (the top). Retract 1.5 in
// each axis: (−65, 22.8); G0 back to z 1.8.
TEST(Lcyc95Seed, L42FirstPassMoveByMove) {
  const SiemensContour contour = l42();
  const auto out = planLcyc95(callAt({2, 25}, contour), l42Roughing());
  ASSERT_GE(out.moves.size(), 9u);
  const std::vector<Move> first(out.moves.begin(), out.moves.begin() + 9);
  expectMoves(first, {
                         {G0, {1.8, 22.8}, "approach"},
                         {G1, {1.378067, 19.363636}, "pass", 1},
                         {G1, {-64.7, 19.363636}, "pass", 1},
                         {G1, {-64.7, 19.5}, "pass", 1},
                         {G1, {-64.787868, 19.712132}, "pass", 1},
                         {G1, {-66.287868, 21.212132}, "pass", 1},
                         {G1, {-66.5, 21.3}, "pass", 1},
                         {G0, {-65, 22.8}, "pass", 1},
                         {G0, {1.8, 22.8}, "pass", 1},
                     },
              1e-5);
  EXPECT_EQ(first[4].shape, SegmentKind::ArcCCW);
  EXPECT_EQ(first[6].shape, SegmentKind::ArcCCW);
  EXPECT_EQ(first[2].feed, 0.4);
}

// R105=5 R106=0 after the roughing call (the tool at its start (1.8, 22.8)): the start is now
// (0 + 1.5, 21 + 1.5) = (1.5, 22.5); X first: (1.8, 22.5), then (1.5, 22.5); G0 to (0, 0); the 13
// contour segments at R112 = 0.25; G0 back to (1.5, 22.5).
TEST(Lcyc95Seed, L42FinishingWithR105Five) {
  const SiemensContour contour = l42();
  Lcyc95Parameters p = l42Roughing();
  p.type = typeOf(5);
  p.allowance = 0;
  const auto out = planLcyc95(callAt({1.8, 22.8}, contour), p);
  ASSERT_EQ(out.moves.size(), 3 + contour.segments.size() + 1);
  EXPECT_EQ(out.moves[0].to, (Point{1.8, 22.5}));
  EXPECT_EQ(out.moves[1].to, (Point{1.5, 22.5}));
  EXPECT_EQ(out.moves[2].to, (Point{0, 0}));
  for (std::size_t i = 0; i < contour.segments.size(); ++i) {
    const Move& m = out.moves[3 + i];
    const Segment& s = contour.segments[i];
    EXPECT_EQ(m.kind, MoveKind::Feed);
    EXPECT_EQ(m.shape, s.kind) << i;
    EXPECT_EQ(m.to, s.to) << i;
    if (s.isArc()) {
      EXPECT_EQ(*m.center, s.center) << i;
    }
    EXPECT_EQ(m.feed, 0.25);
    EXPECT_EQ(m.phase, MovePhase::Finish);
  }
  EXPECT_EQ(out.moves.back().to, (Point{1.5, 22.5}));
  EXPECT_EQ(out.moves.back().kind, MoveKind::Rapid);
}

// --- The alarms (LCYC95.CONTOUR, LCYC95.PARAMS) ---

// The seed's first arc as printed: 136° (see l42()).
TEST(Lcyc95Alarms, L42AsPrintedHasAnArcOverAQuarterCircle) {
  SiemensContour printed = l42();
  printed.segments.erase(printed.segments.begin(), printed.segments.begin() + 2);
  printed.segments.insert(printed.segments.begin(), arc(SegmentKind::ArcCCW, {0, 0}, kL42ArcEnd, kL42Centre, 2));
  const auto call = callAt({2, 25}, printed);
  EXPECT_EQ(alarmCodeOf(call, l42Roughing()), "10931");
  try {
    planLcyc95(call, l42Roughing());
  } catch (const CycleAlarm& a) {
    EXPECT_NE(std::string(a.what()).find("L42.spf line 2"), std::string::npos) << a.what();
  }
}

TEST(Lcyc95Alarms, AQuarterCircleExactlyIsAccepted) {
  const SiemensContour c{"Q", "Q.spf", {arc(SegmentKind::ArcCCW, {0, 0}, {-10, 10}, {-10, 0}, 1),
                                        line({-10, 10}, {-20, 10}, 2)}};
  EXPECT_NO_THROW(planLcyc95(callAt({5, 15}, c), params(1)));
}

TEST(Lcyc95Alarms, AContourAgainstTheFinishingDirection) {
  const SiemensContour reversed = polyline("REV", {{-20, 9}, {-10, 9}, {-10, 4}, {0, 4}, {0, 0}});
  EXPECT_EQ(alarmCodeOf(callAt({5, 15}, reversed), params(1)), "10931");
  EXPECT_EQ(alarmCodeOf(callAt({5, 15}, reversed), params(5)), "10931");
}

TEST(Lcyc95Alarms, AnEmptyContour) {
  const SiemensContour empty{"E", "E.spf", {}};
  EXPECT_EQ(alarmCodeOf(callAt({5, 15}, empty), params(1)), "10931");
  const SiemensContour standingStill{"S", "S.spf", {line({0, 5}, {0, 5}, 1)}};  // a block that does not move
  EXPECT_EQ(alarmCodeOf(callAt({5, 15}, standingStill), params(5)), "10931");
  try {
    planLcyc95(callAt({5, 15}, standingStill), params(5));
  } catch (const CycleAlarm& a) {
    EXPECT_NE(std::string(a.what()).find("has no moves"), std::string::npos) << a.what();
  }
}

TEST(Lcyc95Alarms, NoInfeedDepthForRoughing) {
  const SiemensContour shaft = stepShaft();
  for (double r108 : {0.0, -1.0}) {
    Lcyc95Parameters p = params(1);
    p.maxInfeed = r108;
    EXPECT_EQ(alarmCodeOf(callAt({5, 15}, shaft), p), "61610") << r108;
    p.type = typeOf(9);
    EXPECT_EQ(alarmCodeOf(callAt({5, 15}, shaft), p), "61610") << r108;
    p.type = typeOf(5);  // finishing does not infeed: R108 is not read
    EXPECT_EQ(alarmCodeOf(callAt({5, 15}, shaft), p), "no alarm") << r108;
  }
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

using namespace siemens_test;

Lcyc95Parameters shaftRoughing() {
  Lcyc95Parameters p;
  p.type = machiningTypeOf(1).value();
  p.maxInfeed = 4;
  p.retract = 1;
  p.roughingFeed = 0.2;
  p.finishingFeed = 0.1;
  return p;
}

SiemensCycleCall shaftCall(const SiemensContour& c) {
  SiemensCycleCall call;
  call.line = 12;
  call.position = {5, 15};
  call.contour = &c;
  return call;
}

// Values no program should give the planner are a clear NotSupported naming the call's line, never
// NaN moves or a crash: a non-finite angle, an infeed so small the passes would exceed PROG.CAP.PASSES
// (9 / 1e-9 = 9e9, far beyond what an int holds), a tool tip outside 0…9.
TEST(Lcyc95Limits, UnplannableValuesAreNotSupported) {
  const SiemensContour shaft = stepShaft();
  Lcyc95Parameters p = shaftRoughing();
  p.infeedAngle = std::nan("");
  EXPECT_THROW(planLcyc95(shaftCall(shaft), p), NotSupported);
  p = shaftRoughing();
  p.maxInfeed = 1e-9;
  try {
    planLcyc95(shaftCall(shaft), p);
    FAIL() << "no NotSupported";
  } catch (const NotSupported& e) {
    EXPECT_EQ(e.line(), 12);
  }
  SiemensCycleCall call = shaftCall(shaft);
  call.tool = {0.4, 11};
  p = shaftRoughing();
  p.type = machiningTypeOf(5).value();
  EXPECT_THROW(planLcyc95(call, p), NotSupported);
}

// R108 = 100 covers the depth 9: one step, level 0 straight away.
TEST(Lcyc95Limits, OneStepWhenR108CoversTheDepth) {
  const SiemensContour shaft = stepShaft();
  Lcyc95Parameters p = shaftRoughing();
  p.maxInfeed = 100;
  const auto out = planLcyc95(shaftCall(shaft), p);
  EXPECT_EQ(passCount(out.moves), 1);
  EXPECT_EQ(out.moves[1].to, (Point{1, 0}));
}

// R106 and R110 are unsigned (entered without sign): −0.5 is taken as 0.5 (interpretation), as in
// Lcyc95Complete: the start (1.5, 10.5).
TEST(Lcyc95Limits, UnsignedParametersAreTakenBySize) {
  const SiemensContour shaft = stepShaft();
  Lcyc95Parameters p = shaftRoughing();
  p.allowance = -0.5;
  p.retract = -1;
  const auto out = planLcyc95(shaftCall(shaft), p);
  EXPECT_EQ(out.moves[0].to, (Point{1.5, 10.5}));
}

}  // namespace
}  // namespace cyclecert

// --- Pieces of the profile without length (issue 16) ---

namespace cyclecert {
namespace {

using namespace siemens_test;

// Every arc move starts where the move before it ended; none ends where it starts (a controller
// reads an arc whose ends coincide as a full circle).
void expectNoArcWithoutLength(const std::vector<Move>& moves, Point position) {
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const Point from = i == 0 ? position : moves[i - 1].to;
    if (moves[i].shape != SegmentKind::Line) {
      EXPECT_GT(distance(from, moves[i].to), 1e-6) << "move " << i << " is an arc without length";
    }
  }
}

// Contour S1 (radius): (0, 0) → taper to (−4, 8) → (−10, 8); G2 to (−18, 0) CR=8 about (−18, 8): the
// start lies 8 towards +z from the centre, so the arc leaves the flat straight down (tangent −x), a
// quarter circle; → (−25, 0) → (−25, 12) → (−35, 12). R105=1, R106=0, R108=4, R110=1: start (1, 13);
// depth 12, 3 steps of 4: levels 8, 4, 0. Pass 1 meets the profile at the taper's end (−4, 8) and
// runs along the flat to (−10, 8), where the G2 turns down (an undercut, left to finishing): the pass
// ends there with no move on the arc (LCYC95.ROUGH). Pass 2 meets the taper x = −2z at (−2, 4), up to
// the previous level (−4, 8). Pass 3 starts at the contour's start (0, 0), up the taper to (−2, 4).
SiemensContour shoulderArcDown() {
  SiemensContour c{"S1", "S1.spf", {}};
  c.segments.push_back(line({0, 0}, {-4, 8}, 2));
  c.segments.push_back(line({-4, 8}, {-10, 8}, 3));
  c.segments.push_back(arc(SegmentKind::ArcCW, {-10, 8}, {-18, 0}, {-18, 8}, 4));
  c.segments.push_back(line({-18, 0}, {-25, 0}, 5));
  c.segments.push_back(line({-25, 0}, {-25, 12}, 6));
  c.segments.push_back(line({-25, 12}, {-35, 12}, 7));
  return c;
}

TEST(Lcyc95Rough, APassStoppingAtAnArcThatLeavesDownwardsMakesNoMoveOnIt) {
  const SiemensContour contour = shoulderArcDown();
  const auto out = planLcyc95(callAt({2, 25}, contour), params(1));
  expectNoArcWithoutLength(out.moves, {2, 25});
  expectMoves(out.moves, {
                             {G0, {1, 13}, "approach"},
                             {G1, {1, 8}, "pass", 1},
                             {G1, {-4, 8}, "pass", 1},
                             {G1, {-10, 8}, "pass", 1},
                             {G0, {-9, 9}, "pass", 1},
                             {G0, {1, 9}, "pass", 1},
                             {G1, {1, 4}, "pass", 2},
                             {G1, {-2, 4}, "pass", 2},
                             {G1, {-4, 8}, "pass", 2},
                             {G0, {-3, 9}, "pass", 2},
                             {G0, {1, 9}, "pass", 2},
                             {G1, {1, 0}, "pass", 3},
                             {G1, {0, 0}, "pass", 3},
                             {G1, {-2, 4}, "pass", 3},
                             {G0, {-1, 5}, "pass", 3},
                             {G0, {1, 13}, "return"},
                         });
}

// --- Undercuts beginning at an arc's top (issue 16; CYCLE95.UNDERCUT, LCYC95.ROUGH's undercut note) ---
//
// Contour D1 (radius): (0, 0); G3 to its apex (−10, 10) about (−10, 0), a quarter circle; G3 down to
// (−20, 0) about the same centre (the dome split at its apex: the second arc starts at its top);
// → (−25, 0) → (−25, 12) → (−35, 12). R105=1, R108=4, R110=1: start (1, 13); levels 8, 4, 0. The dome
// meets level L at z = −10 + √(100 − L²). Pass 1 (8): meets the dome at z −4; G3 to the apex, where the
// profile turns back down (an undercut, left to finishing): the pass ends there. Pass 2 (4): meets the
// dome at −10 + √84; G3 up to the previous level (−4, 8). Pass 3 (0): from the contour's start along
// the dome to (−10 + √84, 4). The pocket behind the apex is named in a warning (its line 3).
TEST(Lcyc95Rough, ADomeSplitAtItsApexStopsThePassesAtTheApex) {
  SiemensContour c{"D1", "D1.spf", {}};
  c.segments.push_back(arc(SegmentKind::ArcCCW, {0, 0}, {-10, 10}, {-10, 0}, 2));
  c.segments.push_back(arc(SegmentKind::ArcCCW, {-10, 10}, {-20, 0}, {-10, 0}, 3));
  c.segments.push_back(line({-20, 0}, {-25, 0}, 4));
  c.segments.push_back(line({-25, 0}, {-25, 12}, 5));
  c.segments.push_back(line({-25, 12}, {-35, 12}, 6));
  const double at4 = -10 + std::sqrt(84.0);
  const auto out = planLcyc95(callAt({2, 25}, c), params(1));
  expectMoves(out.moves, {
                             {G0, {1, 13}, "approach"},
                             {G1, {1, 8}, "pass", 1},
                             {G1, {-4, 8}, "pass", 1},
                             {G1, {-10, 10}, "pass", 1},
                             {G0, {-9, 11}, "pass", 1},
                             {G0, {1, 11}, "pass", 1},
                             {G1, {1, 4}, "pass", 2},
                             {G1, {at4, 4}, "pass", 2},
                             {G1, {-4, 8}, "pass", 2},
                             {G0, {-3, 9}, "pass", 2},
                             {G0, {1, 9}, "pass", 2},
                             {G1, {1, 0}, "pass", 3},
                             {G1, {0, 0}, "pass", 3},
                             {G1, {at4, 4}, "pass", 3},
                             {G0, {at4 + 1, 5}, "pass", 3},
                             {G0, {1, 13}, "return"},
                         });
  EXPECT_EQ(out.moves[3].shape, SegmentKind::ArcCCW);
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_NE(out.warnings[0].message.find("D1.spf line 3"), std::string::npos) << out.warnings[0].message;
}

// --- An I/K arc whose end lies slightly off its circle (issue 16; SIEMENS.ARC) ---
//
// Contour Q2: G1 X0 Z0; G3 X19.99 Z-10 K-10 I0: centre (−10, 0) as programmed, radius 10 at the
// start; the end (−10, 9.995) lies 9.995 from it, 0.005 off (accepted: at most 0.01). The controller
// keeps the end and moves the centre onto the chord's perpendicular bisector, 10 (the start's radius)
// from both ends, on the programmed centre's side: z² + x² = 100 and (z + 10)² + (x − 9.995)² = 100
// give 20z − 19.99x = −199.900025, so x = −0.005 and z = −√(100 − 0.005²) = −9.99999875. The arc
// then turns 89.97° (the chord, 14.13860, is shorter than a quarter circle's 14.14214; an end 0.005
// beyond the circle instead would turn it past 90°: alarm 10931). Then the taper G1 X24 Z-20 to
// (−20, 12): a corner after the arc. R105=5 R106=0 finishes it (before: alarm 10931, the allowance 0
// "not fitting" because the profile put the arc's end on the programmed circle, 0.005 from the
// taper's start). Start (LCYC95.START): (0 + 1, 12 + 1) = (1, 13).
TEST(Lcyc95Contour, AnIKArcEndingOffItsCircleIsOneCircle) {
  SiemensModal modal;
  modal.motion = 1;
  const SiemensContour c =
      readSiemensContour("Q2", parseSiemensSubprogram("G1 X0 Z0\nG3 X19.99 Z-10 K-10 I0\nG1 X24 Z-20\nRET\n", "Q2.spf"), modal);
  ASSERT_EQ(c.segments.size(), 2u);
  const Segment& a = c.segments[0];
  EXPECT_NEAR(a.to.z, -10, 1e-12);
  EXPECT_NEAR(a.to.x, 9.995, 1e-12);
  EXPECT_NEAR(a.center.z, -9.99999875, 1e-8);
  EXPECT_NEAR(a.center.x, -0.005, 1e-9);
  EXPECT_NEAR(distance(a.from, a.center), 10, 1e-9);
  EXPECT_NEAR(distance(a.to, a.center), 10, 1e-9);
  const auto out = planLcyc95(callAt({2, 25}, c), params(5));
  expectMoves(out.moves, {
                             {G0, {2, 13}, "approach"},
                             {G0, {1, 13}, "approach"},
                             {G0, {0, 0}, "finish"},
                             {G1, {-10, 9.995}, "finish"},
                             {G1, {-20, 12}, "finish"},
                             {G0, {1, 13}, "return"},
                         });
  ASSERT_TRUE(out.moves[3].center);
  EXPECT_TRUE(nearlyEqual(*out.moves[3].center, a.center, 1e-12));
  EXPECT_EQ(alarmCodeOf(callAt({2, 25}, c), params(9)), "no alarm");  // roughing the same contour too
}

}  // namespace
}  // namespace cyclecert
