// G74.1's groove geometry in its own frame (reference/cycles/g74_1_groove.h, docs/g74_1.md §3, §5):
// u along d (radius), w the depth; a local Point is {z = w, x = u}. Every expected value is worked
// out by hand in the comment above it.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/cycles/g74_1_groove.h"

namespace cyclecert {
namespace {

GrooveShape shape(double depth, double floorWidth, double a = 90, double b = 90, double p = 0) {
  GrooveShape g;
  g.depth = depth;
  g.floorWidth = floorWidth;
  g.angleA = a;
  g.angleB = b;
  g.slope = p;
  return g;
}

void expectPoint(Point got, double u, double w) {
  EXPECT_NEAR(got.x, u, 1e-6) << "u";
  EXPECT_NEAR(got.z, w, 1e-6) << "w";
}

TEST(G74_1Groove, O0008sTrapezoid) {
  // h = −10, d = −20, ∠a 45°, ∠b 60°: S (0, 0); N (10·cot45 = 10, 10); F (10 + 10, 10);
  // M2: u = 20 + 10·cot60 = 25.773503, w 0. No corners: three lines.
  const GrooveProfile p = buildGrooveProfile(shape(10, 10, 45, 60), 0, 0);
  ASSERT_EQ(p.chain.size(), 3u);
  expectPoint(p.chain[0].from, 0, 0);
  expectPoint(p.chain[0].to, 10, 10);
  expectPoint(p.chain[1].to, 20, 10);
  expectPoint(p.chain[2].to, 25.773503, 0);
  EXPECT_EQ(p.parts[1], GroovePart::Floor);
}

TEST(G74_1Groove, TheRoughProfileMovesEachSideIn) {
  // |h| 4, floor 2 (radius), ∠a = ∠b = 45°, Δu/2 = 0.2, Δw = 0.2 (I15): near flank u = 0.2 + w;
  // floor w = 3.8: N' (4.0, 3.8); the finish far flank (6, 4)…(10, 0) moved by −0.2: u = 5.8 + (4 − w),
  // F' (6.0, 3.8), M2' (9.8, 0); S' (0.2, 0).
  const GrooveProfile p = buildGrooveProfile(shape(4, 2, 45, 45), 0.2, 0.2);
  expectPoint(p.start, 0.2, 0);
  expectPoint(p.chain.front().to, 4.0, 3.8);
  expectPoint(p.chain[1].to, 6.0, 3.8);
  expectPoint(p.chain.back().to, 9.8, 0);
  EXPECT_NEAR(p.floorDepth, 3.8, 1e-9);
}

TEST(G74_1Groove, TheSlopeApproachesTheFloorOnTheFarSide) {
  // ∠p 45° (I7): the mouth w = u. Straight flanks, |h| 4, floor 2: the far flank u = 2 meets the
  // mouth at w = 2: M2 (2, 2).
  const GrooveProfile p = buildGrooveProfile(shape(4, 2, 90, 90, 45), 0, 0);
  expectPoint(p.chain.back().to, 2, 2);
}

TEST(G74_1Groove, ASlopeThatReachesTheFloorOrStandsAboveTheNearFlankIsNoGroove) {
  // ∠p 70°: tan 70° · 2 = 5.49 > 4: the slope meets the floor before the far flank (I9).
  EXPECT_THROW(buildGrooveProfile(shape(4, 2, 90, 90, 70), 0, 0), GrooveDoesNotFit);
  // ∠a 30°, ∠p 40°: tan 40°·cot 30° = 1.45 ≥ 1: the near flank never goes below the slope.
  EXPECT_THROW(buildGrooveProfile(shape(4, 2, 30, 90, 40), 0, 0), GrooveDoesNotFit);
  // Δw ≥ |h|: nothing left.
  EXPECT_THROW(buildGrooveProfile(shape(4, 2), 0, 4), GrooveDoesNotFit);
}

TEST(G74_1Groove, AChamferCutsEqualLegsOffTheCorner) {
  // Straight groove |h| 4, floor 2, r3 = 0.5 chamfer (I10): the near flank ends 0.5 above N (0, 4),
  // the chamfer runs to 0.5 along the floor: (0, 3.5) → (0.5, 4); the floor from 0.5 to 2.
  GrooveShape g = shape(4, 2);
  g.corners[kCornerR3] = {0.5, GrooveCornerKind::Chamfer};
  const GrooveProfile p = buildGrooveProfile(g, 0, 0);
  ASSERT_EQ(p.chain.size(), 4u);
  EXPECT_EQ(p.parts[1], GroovePart::CornerR3);
  expectPoint(p.chain[1].from, 0, 3.5);
  expectPoint(p.chain[1].to, 0.5, 4);
  EXPECT_NEAR(p.floorFrom, 0.5, 1e-9);
  EXPECT_NEAR(p.floorTo, 2, 1e-9);
}

TEST(G74_1Groove, ARoundIsTangentToBothEdges) {
  // r4 = 1 round at F (2, 4), a right angle: tangent points 1 from F: (1, 4) on the floor, (2, 3) on
  // the far flank; centre (1, 3). In (z = w, x = u) the chain turns from +u to −w: counter-clockwise.
  GrooveShape g = shape(4, 2);
  g.corners[kCornerR4] = {1, GrooveCornerKind::Round};
  const GrooveProfile p = buildGrooveProfile(g, 0, 0);
  ASSERT_EQ(p.chain.size(), 4u);
  const Segment& arc = p.chain[2];
  EXPECT_EQ(arc.kind, SegmentKind::ArcCCW);
  expectPoint(arc.from, 1, 4);
  expectPoint(arc.to, 2, 3);
  expectPoint(arc.center, 1, 3);
}

TEST(G74_1Groove, CornersThatDoNotFitTheirEdgeAreRefused) {
  // Near flank 4 long; chamfers r1 = 2 and r3 = 3 need 5 of it (I11).
  GrooveShape g = shape(4, 2);
  g.corners[kCornerR1] = {2, GrooveCornerKind::Chamfer};
  g.corners[kCornerR3] = {3, GrooveCornerKind::Chamfer};
  EXPECT_THROW(buildGrooveProfile(g, 0, 0), GrooveDoesNotFit);
}

TEST(G74_1Groove, TheMouthCornerStartsOnTheMouthBeforeTheStart) {
  // r1 = 1 chamfer, ∠p 0: from (−1, 0) on the mouth to (0, 1) on the near flank.
  GrooveShape g = shape(4, 2);
  g.corners[kCornerR1] = {1, GrooveCornerKind::Chamfer};
  const GrooveProfile p = buildGrooveProfile(g, 0, 0);
  EXPECT_EQ(p.parts[0], GroovePart::CornerR1);
  expectPoint(p.chain[0].from, -1, 0);
  expectPoint(p.chain[0].to, 0, 1);
}

TEST(G74_1Groove, SliceAndDepthUnderTheBlade) {
  // ∠a = ∠b = 45°, |h| 4, floor 2: near flank w = u, far flank w = 10 − u.
  const GrooveProfile p = buildGrooveProfile(shape(4, 2, 45, 45), 0, 0);
  const GrooveSlice at2 = sliceAt(p, 2);
  EXPECT_NEAR(at2.nearU, 2, 1e-9);
  EXPECT_NEAR(at2.farU, 8, 1e-9);
  // A point at u = 3: depth 3; a blade of width 2 at u = 3 spans [1, 3]: min(1, 3) = 1.
  EXPECT_NEAR(deepestUnderTheBlade(p, 3, 0), 3, 1e-9);
  EXPECT_NEAR(deepestUnderTheBlade(p, 3, 2), 1, 1e-9);
  EXPECT_NEAR(deepestUnderTheBlade(p, 5, 0), 4, 1e-9);
  EXPECT_NEAR(deepestUnderTheBlade(p, 11, 0), 0, 1e-9);  // outside the groove
}

TEST(G74_1Groove, TheBladesPathShiftsTheStartSide) {
  // Straight groove |h| 4, floor 2, r = 0.5 (§7): near flank (0.5, 0) → (0.5, 4); the floor from
  // its start N (0, 4) + r = (0.5, 4) to F (2, 4); far flank unshifted (2, 4) → (2, 0).
  const GrooveProfile p = buildGrooveProfile(shape(4, 2), 0, 0);
  const std::vector<Segment> path = bladePath(p, 0.5);
  ASSERT_EQ(path.size(), 3u);
  expectPoint(path[0].from, 0.5, 0);
  expectPoint(path[0].to, 0.5, 4);
  expectPoint(path[1].from, 0.5, 4);
  expectPoint(path[1].to, 2, 4);
  expectPoint(path[2].to, 2, 0);
  EXPECT_THROW(bladePath(p, 2.5), GrooveDoesNotFit);  // wider than the floor
}

TEST(G74_1Groove, WhereTheFarMouthRoundFallsTheBladesStartSideTakesOver) {
  // I23: h 4, floor 2 wide, flanks 90°, slope ∠p 45° (the mouth w = u), r2 a round of 0.5. M2 = (u 2,
  // w 2); the flank runs up (direction w −1), the mouth on along (1, 1)/√2: a turn of 135°, so the
  // round touches both 0.5·tan 67.5° = 1.207107 from M2: on the flank at (2, 3.207107), on the mouth
  // at (2.853553, 2.853553), centre (2.5, 3.207107). Its highest point (least w) is below the
  // centre, (2.5, 2.707107); beyond it the round falls again. A 0.5 blade whose far corner rode on
  // past it would cut 0.146 under the round at u 2.5; instead: the round to its top, level by r to
  // (3, 2.707107), the rest of the round shifted by r to (3.353553, 2.853553) about (3, 3.207107).
  GrooveShape g = shape(4, 2, 90, 90, 45);
  g.corners[kCornerR2] = {0.5, GrooveCornerKind::Round};
  const GrooveProfile p = buildGrooveProfile(g, 0, 0);
  const std::vector<Segment> path = bladePath(p, 0.5);
  ASSERT_GE(path.size(), 3u);
  const Segment& level = path[path.size() - 2];
  const Segment& rest = path.back();
  const Segment& up = path[path.size() - 3];
  EXPECT_TRUE(up.isArc());
  expectPoint(up.from, 2, 3.207107);
  expectPoint(up.to, 2.5, 2.707107);
  EXPECT_FALSE(level.isArc());
  expectPoint(level.to, 3, 2.707107);
  EXPECT_TRUE(rest.isArc());
  expectPoint(rest.to, 3.353553, 2.853553);
  expectPoint(rest.center, 3, 3.207107);
  // Without a slope the round ends level on the mouth: the far corner rides it to its end.
  GrooveShape flat = shape(4, 2);
  flat.corners[kCornerR2] = {0.5, GrooveCornerKind::Round};
  const std::vector<Segment> flatPath = bladePath(buildGrooveProfile(flat, 0, 0), 0.5);
  expectPoint(flatPath.back().to, 2.5, 0);
}

TEST(G74_1Groove, TheFrameMapsTheFourDirectionsAndMirrorsArcs) {
  // S (z 0, x 20). Local (u 1, w 3): h<0,d<0 → (−3, 19); h>0,d<0 → (3, 19); h<0,d>0 → (−3, 21);
  // h>0,d>0 → (3, 21). An arc keeps its direction when h·d > 0, turns when h·d < 0.
  Segment arc;
  arc.kind = SegmentKind::ArcCCW;
  arc.from = grooveLocal(1, 4);
  arc.to = grooveLocal(2, 3);
  arc.center = grooveLocal(1, 3);
  const struct { int h, d; double z, x; SegmentKind kind; } cases[] = {
      {-1, -1, -3, 19, SegmentKind::ArcCCW}, {1, -1, 3, 19, SegmentKind::ArcCW},
      {-1, 1, -3, 21, SegmentKind::ArcCW}, {1, 1, 3, 21, SegmentKind::ArcCCW}};
  for (const auto& c : cases) {
    const GrooveFrame f{{0, 20}, c.h, c.d};
    const Point p = f.toPlane(grooveLocal(1, 3));
    EXPECT_NEAR(p.z, c.z, 1e-12);
    EXPECT_NEAR(p.x, c.x, 1e-12);
    EXPECT_EQ(f.toPlane(arc).kind, c.kind) << c.h << " " << c.d;
  }
}

}  // namespace
}  // namespace cyclecert
