// Geometry of contours: arcs (direction convention, centres from R), intersections with lines
// parallel to an axis, extents and apexes, translation and transposition.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "reference/model/geometry.h"

namespace cyclecert {
namespace {

Segment line(Point a, Point b) { return {SegmentKind::Line, a, b, {}, 0}; }
Segment arc(SegmentKind k, Point a, Point b, Point c) { return {k, a, b, c, 0}; }

// Seed 003 example 1, N14 G02 U10 W-5 R5: from (z -20, r 5) to (z -25, r 10) — a concave fillet.
const Segment kFillet = arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10});

TEST(Geometry, ClockwiseArcSweepsNegativeQuarter) {
  EXPECT_NEAR(sweep(kFillet), -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(kFillet.length(), 5 * std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(sweep(kFillet.reversed()), std::numbers::pi / 2, 1e-12);
}

TEST(Geometry, CentreFromRadiusFollowsTheG02G03Convention) {
  // G02 R5 (clockwise, Z right, X up) from (-20,5) to (-25,10): centre (-20,10).
  const auto cw = arcCenterFromRadius({-20, 5}, {-25, 10}, 5, SegmentKind::ArcCW);
  ASSERT_TRUE(cw);
  EXPECT_NEAR(cw->z, -20, 1e-12);
  EXPECT_NEAR(cw->x, 10, 1e-12);
  // N16 G03 U14 W-7 R7 from (-35,10) to (-42,17): centre (-42,10) — a convex round.
  const auto ccw = arcCenterFromRadius({-35, 10}, {-42, 17}, 7, SegmentKind::ArcCCW);
  ASSERT_TRUE(ccw);
  EXPECT_NEAR(ccw->z, -42, 1e-12);
  EXPECT_NEAR(ccw->x, 10, 1e-12);
  // R < 0 asks for the arc of more than 180°: the centre moves to the other side.
  const auto major = arcCenterFromRadius({-20, 5}, {-25, 10}, -5, SegmentKind::ArcCW);
  ASSERT_TRUE(major);
  EXPECT_NEAR(major->z, -25, 1e-12);
  EXPECT_NEAR(major->x, 5, 1e-12);
}

TEST(Geometry, CentreFromRadiusRejectsImpossibleArcs) {
  EXPECT_FALSE(arcCenterFromRadius({0, 0}, {10, 0}, 4.9, SegmentKind::ArcCW));
  EXPECT_FALSE(arcCenterFromRadius({0, 0}, {0, 0}, 5, SegmentKind::ArcCW));
  EXPECT_FALSE(arcCenterFromRadius({0, 0}, {1, 0}, std::nan(""), SegmentKind::ArcCW));
  EXPECT_TRUE(arcCenterFromRadius({0, 0}, {10, 0}, 5, SegmentKind::ArcCW));  // half circle
}

TEST(Geometry, LineMeetsLevel) {
  const auto hits = intersectWithLevelX(line({-51.9, 17.3}, {-61.9, 22.3}), 21.3);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].z, -59.9, 1e-12);
  EXPECT_EQ(hits[0].x, 21.3);
  EXPECT_TRUE(intersectWithLevelX(line({0, 0}, {-10, 5}), 5.1).empty());
  // A line lying on the level: both end points, in order.
  const auto on = intersectWithLevelX(line({0, 3}, {-10, 3}), 3);
  ASSERT_EQ(on.size(), 2u);
  EXPECT_EQ(on[0].z, 0);
  EXPECT_EQ(on[1].z, -10);
  EXPECT_TRUE(intersectWithLevelX(line({0, 3}, {-10, 3}), 3.5).empty());
}

TEST(Geometry, ArcMeetsLevelOnlyWithinItsSpan) {
  // Rough copy of N16 (G03 R7 centre (-41.9, 10.3)) at level 12.3: z = -41.9 + sqrt(45).
  const Segment round = arc(SegmentKind::ArcCCW, {-34.9, 10.3}, {-41.9, 17.3}, {-41.9, 10.3});
  const auto hits = intersectWithLevelX(round, 12.3);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_NEAR(hits[0].z, -41.9 + std::sqrt(45.0), 1e-12);
  EXPECT_TRUE(intersectWithLevelX(round, 9.0).empty());   // below the span
  EXPECT_TRUE(intersectWithLevelX(round, 17.4).empty());  // above the circle
  // A half circle over its apex is met twice, in order along the arc.
  const Segment dome = arc(SegmentKind::ArcCCW, {10, 0}, {-10, 0}, {0, 0});  // over the top
  const auto two = intersectWithLevelX(dome, 6);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_NEAR(two[0].z, 8, 1e-12);
  EXPECT_NEAR(two[1].z, -8, 1e-12);
}

TEST(Geometry, ExtentIncludesArcApexes) {
  const Segment dome = arc(SegmentKind::ArcCCW, {10, 0}, {-10, 0}, {0, 0});  // over the top
  const Extent e = extent(dome);
  EXPECT_NEAR(e.xMax, 10, 1e-12);
  EXPECT_NEAR(e.xMin, 0, 1e-12);
  ASSERT_EQ(apexesAlong(dome).size(), 1u);
  EXPECT_NEAR(apexesAlong(dome)[0].x, 10, 1e-12);
  EXPECT_TRUE(apexesAlong(kFillet).empty());  // a quarter between apexes has none inside
}

TEST(Geometry, ShiftAndTransposeKeepArcsConsistent) {
  const Segment moved = kFillet.shifted({0.1, 0.3});
  EXPECT_NEAR(moved.center.z, -19.9, 1e-12);
  EXPECT_NEAR(moved.radius(), 5, 1e-12);
  const Segment t = transposed(kFillet);
  EXPECT_EQ(t.kind, SegmentKind::ArcCCW);  // exchanging the axes mirrors the plane
  EXPECT_NEAR(sweep(t), std::numbers::pi / 2, 1e-12);
  EXPECT_EQ(transposed(t).kind, SegmentKind::ArcCW);
  EXPECT_TRUE(nearlyEqual(transposed(pointAt(kFillet, 0.5)), pointAt(t, 0.5), 1e-12));
}

TEST(Geometry, FullCircleWhenEndsCoincide) {
  const Segment circle = arc(SegmentKind::ArcCCW, {5, 0}, {5, 0}, {0, 0});
  EXPECT_NEAR(sweep(circle), 2 * std::numbers::pi, 1e-12);
}

}  // namespace
}  // namespace cyclecert
