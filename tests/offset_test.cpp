// Tool-nose radius compensation geometry: offset lines and arcs on both sides, convex corners
// (connecting arcs) and concave corners (trimmed), the imaginary tip chart, type A start-up, the
// interference errors, and the compensated path of seed 003 example 1.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>

#include "reference/model/offset.h"

namespace cyclecert {
namespace {

constexpr double kTol = 1e-9;
constexpr auto kRight = CompensationSide::Right;
constexpr auto kLeft = CompensationSide::Left;
const double kSqrt2 = std::numbers::sqrt2;
const double kSqrt5 = std::sqrt(5.0);

Segment line(Point a, Point b, int sourceLine = 0) {
  return {SegmentKind::Line, a, b, {}, sourceLine};
}
Segment arc(SegmentKind k, Point a, Point b, Point c, int sourceLine = 0) {
  return {k, a, b, c, sourceLine};
}

#define EXPECT_POINT(p, ez, ex)     \
  do {                              \
    EXPECT_NEAR((p).z, (ez), kTol); \
    EXPECT_NEAR((p).x, (ex), kTol); \
  } while (0)

// Each piece starts where the previous one ends.
void expectConnected(const std::vector<Segment>& path) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_TRUE(nearlyEqual(path[i - 1].to, path[i].from)) << "gap before piece " << i;
  }
}

// The smallest and largest distance from sampled points of `path` to `contour`. A correct
// nose-centre path touches the contour everywhere: both are r.
struct Clearance {
  double least = std::numeric_limits<double>::infinity();
  double most = 0;
};
Clearance clearance(const std::vector<Segment>& path, const std::vector<Segment>& contour) {
  Clearance c;
  for (const Segment& s : path) {
    for (int k = 0; k <= 50; ++k) {
      const double d = distanceToPath(pointAt(s, k / 50.0), contour);
      c.least = std::min(c.least, d);
      c.most = std::max(c.most, d);
    }
  }
  return c;
}

// ---- lines ------------------------------------------------------------------------------------

TEST(Offset, LinesMoveAlongTheirNormalOnEitherSide) {
  // Moving −z: the right normal is +x, the left one −x.
  const std::vector<Segment> along{line({0, 10}, {-20, 10}, 7)};
  const auto right = offsetPath(along, 0.4, kRight);
  ASSERT_EQ(right.size(), 1u);
  EXPECT_POINT(right[0].from, 0, 10.4);
  EXPECT_POINT(right[0].to, -20, 10.4);
  EXPECT_EQ(right[0].sourceLine, 7);
  const auto left = offsetPath(along, 0.4, kLeft);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_POINT(left[0].from, 0, 9.6);
  EXPECT_POINT(left[0].to, -20, 9.6);
  // Moving +x: the right normal is +z, the left one −z.
  const std::vector<Segment> up{line({-5, 0}, {-5, 10})};
  EXPECT_POINT(offsetPath(up, 0.4, kRight)[0].from, -4.6, 0);
  EXPECT_POINT(offsetPath(up, 0.4, kLeft)[0].to, -5.4, 10);
}

TEST(Offset, AxisParallelLinesAreTracedExactly) {
  // Outer turning towards the chuck on top of the part: tool above the contour = right of the
  // travel (−z) → G42; nose centre at x + r, tip 3 (−z,−x) brings the tip point back to x. The
  // tip point runs on the programmed line itself (its ends shifted along it by −r in z).
  const std::vector<Segment> outer{line({0, 10}, {-20, 10})};
  const auto tipPath = compensatedPath(outer, {0.4, 3}, kRight);
  ASSERT_EQ(tipPath.size(), 1u);
  EXPECT_POINT(tipPath[0].from, -0.4, 10);
  EXPECT_POINT(tipPath[0].to, -20.4, 10);
  // Boring towards the chuck: the tool is inside the hole, below the surface (−x) = left of the
  // travel (−z) → G41; nose centre at x − r, tip 2 (−z,+x) brings the tip point back to x.
  const std::vector<Segment> bore{line({0, 8}, {-30, 8})};
  const auto borePath = compensatedPath(bore, {0.4, 2}, kLeft);
  ASSERT_EQ(borePath.size(), 1u);
  EXPECT_POINT(borePath[0].from, -0.4, 8);
  EXPECT_POINT(borePath[0].to, -30.4, 8);
  // A face rising towards +x (a shoulder, G42): nose centre at z + r, tip 3 back to z = −20.
  const std::vector<Segment> face{line({-20, 10}, {-20, 15})};
  const auto facePath = compensatedPath(face, {0.4, 3}, kRight);
  EXPECT_POINT(facePath[0].from, -20, 9.6);
  EXPECT_POINT(facePath[0].to, -20, 14.6);
}

TEST(Offset, ChamferTipPathDeviates) {
  // Seed 003 N12: the C2 chamfer (3,0)→(−2,5), r = 0.4, tip 3, G42.
  //   direction t = (−5,5)/√50 = (−1,1)/√2, right normal (t.x, −t.z) = (1,1)/√2
  //   nose centre = contour + 0.4·(1,1)/√2 = contour + (0.282843, 0.282843)
  //   tip point   = centre + 0.4·(−1,−1)  = contour + 0.4·(1/√2 − 1)·(1,1)
  //               = contour − (0.117157, 0.117157)
  //   its distance across the chamfer: 0.117157·√2 = 0.4·(√2 − 1) = 0.165685, into the material.
  const std::vector<Segment> chamfer{line({3, 0}, {-2, 5}, 12)};
  const double k = 0.4 * (1 / kSqrt2 - 1);
  const auto tipPath = compensatedPath(chamfer, {0.4, 3}, kRight);
  ASSERT_EQ(tipPath.size(), 1u);
  EXPECT_POINT(tipPath[0].from, 3 + k, k);
  EXPECT_POINT(tipPath[0].to, -2 + k, 5 + k);
  EXPECT_NEAR(k, -0.117157287525, 1e-12);
  EXPECT_NEAR(distanceToSegment(pointAt(tipPath[0], 0.5), chamfer[0]), 0.4 * (kSqrt2 - 1), kTol);
  // The tip point lies on the material side: below the chamfer line x = 3 − z.
  EXPECT_LT(tipPath[0].from.x, 3 - tipPath[0].from.z);
}

// ---- corners ----------------------------------------------------------------------------------

TEST(Offset, ConvexCornerGetsAnArcAroundTheCorner) {
  // Up a shoulder face then along −z: a left turn, so with the tool on the right the offset
  // pieces leave a gap, bridged by a CCW arc of radius r centred on the corner (−20,10).
  const std::vector<Segment> path{line({-20, 5}, {-20, 10}, 1), line({-20, 10}, {-30, 10}, 2)};
  const auto out = offsetPath(path, 0.4, kRight);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_POINT(out[0].from, -19.6, 5);
  EXPECT_POINT(out[0].to, -19.6, 10);
  EXPECT_EQ(out[1].kind, SegmentKind::ArcCCW);
  EXPECT_POINT(out[1].center, -20, 10);
  EXPECT_POINT(out[1].from, -19.6, 10);
  EXPECT_POINT(out[1].to, -20, 10.4);
  EXPECT_NEAR(sweep(out[1]), std::numbers::pi / 2, kTol);
  EXPECT_EQ(out[1].sourceLine, 2);  // corner arcs belong to the segment after the corner
  EXPECT_POINT(out[2].from, -20, 10.4);
  EXPECT_POINT(out[2].to, -30, 10.4);
}

TEST(Offset, ConvexCornerOnTheLeftTurnsClockwise) {
  // Along −z then up (+x): a right turn (cross product of the tangents (−1,0)×(0,1) = −1 < 0),
  // convex for a tool on the left. Offsets x = 7.6 and z = −10.4; the arc runs CW around (−10,8).
  const std::vector<Segment> path{line({0, 8}, {-10, 8}), line({-10, 8}, {-10, 12})};
  const auto out = offsetPath(path, 0.4, kLeft);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].kind, SegmentKind::ArcCW);
  EXPECT_POINT(out[1].center, -10, 8);
  EXPECT_POINT(out[1].from, -10, 7.6);
  EXPECT_POINT(out[1].to, -10.4, 8);
  EXPECT_NEAR(sweep(out[1]), -std::numbers::pi / 2, kTol);
}

TEST(Offset, ReversalGetsAHalfCircle) {
  const std::vector<Segment> path{line({0, 5}, {-10, 5}), line({-10, 5}, {0, 5})};
  const auto out = offsetPath(path, 0.4, kRight);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[1].kind, SegmentKind::ArcCCW);
  EXPECT_POINT(out[1].from, -10, 5.4);
  EXPECT_POINT(out[1].to, -10, 4.6);
  EXPECT_POINT(pointAt(out[1], 0.5), -10.4, 5);
}

TEST(Offset, ConcaveCornerIsTrimmedAtTheIntersection) {
  // Along −z then up a shoulder: a right turn, concave for a tool on the right. The offset lines
  // x = 5.4 and z = −20 + 0.4 meet at (−19.6, 5.4).
  const std::vector<Segment> square{line({0, 5}, {-20, 5}), line({-20, 5}, {-20, 10})};
  const auto out = offsetPath(square, 0.4, kRight);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_POINT(out[0].to, -19.6, 5.4);
  EXPECT_POINT(out[1].from, -19.6, 5.4);
  EXPECT_POINT(out[1].to, -19.6, 10);
  // The shoulder of ConvexCornerGetsAnArcAroundTheCorner, seen from the left, is concave: the
  // offsets z = −20.4 and x = 9.6 meet at (−20.4, 9.6).
  const std::vector<Segment> shoulder{line({-20, 5}, {-20, 10}), line({-20, 10}, {-30, 10})};
  const auto left = offsetPath(shoulder, 0.4, kLeft);
  ASSERT_EQ(left.size(), 2u);
  EXPECT_POINT(left[0].to, -20.4, 9.6);
}

TEST(Offset, ConcaveTaperCornerIsTrimmedAtTheBisector) {
  // Along −z at x = 5, then a 45° taper up to (−15,10). Normals n1 = (0,1), n2 = (1,1)/√2; two
  // lines offset by r meet at P + r·(n1 + n2)/(1 + n1·n2) = P + 0.4·(tan 22.5°, 1), with
  // tan 22.5° = √2 − 1: (−10 + 0.4·0.414214, 5.4) = (−9.834315, 5.4).
  const std::vector<Segment> path{line({0, 5}, {-10, 5}), line({-10, 5}, {-15, 10})};
  const auto out = offsetPath(path, 0.4, kRight);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_POINT(out[0].to, -10 + 0.4 * (kSqrt2 - 1), 5.4);
  EXPECT_POINT(out[1].from, -10 + 0.4 * (kSqrt2 - 1), 5.4);
  EXPECT_POINT(out[1].to, -15 + 0.4 / kSqrt2, 10 + 0.4 / kSqrt2);
}

TEST(Offset, StepAsHighAsTheRadiusLeavesNoVerticalPiece) {
  // A 0.2 step with r = 0.2: the trimmed offset of the step has zero length and is dropped.
  const std::vector<Segment> path{line({0, 5}, {-20, 5}), line({-20, 5}, {-20, 5.2}),
                                  line({-20, 5.2}, {-30, 5.2})};
  const auto out = offsetPath(path, 0.2, kRight);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_POINT(out[0].to, -19.8, 5.2);
  EXPECT_EQ(out[1].kind, SegmentKind::ArcCCW);
  EXPECT_POINT(out[1].center, -20, 5.2);
  EXPECT_POINT(out[2].from, -20, 5.4);
  expectConnected(out);
}

TEST(Offset, ConcaveCornerWithTooLargeARadiusThrows) {
  // The same 0.2 step with r = 0.4: x = 5.4 never reaches the step's offset (x in [5, 5.2]).
  const std::vector<Segment> path{line({0, 5}, {-20, 5}, 10), line({-20, 5}, {-20, 5.2}, 11),
                                  line({-20, 5.2}, {-30, 5.2}, 12)};
  try {
    offsetPath(path, 0.4, kRight);
    FAIL() << "expected OffsetError";
  } catch (const OffsetError& e) {
    EXPECT_EQ(e.problem, OffsetProblem::Interference);
    EXPECT_EQ(e.segmentIndex, 1);
    EXPECT_EQ(e.sourceLine, 11);
  }
}

// ---- arcs -------------------------------------------------------------------------------------

TEST(Offset, ArcsGrowOrShrinkWithTheSide) {
  // Seed 003 N14 G02 R5 (centre on its right): shrinks on the right, grows on the left.
  const std::vector<Segment> cw{arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10}, 14)};
  const auto cwRight = offsetPath(cw, 0.4, kRight);
  ASSERT_EQ(cwRight.size(), 1u);
  EXPECT_EQ(cwRight[0].kind, SegmentKind::ArcCW);
  EXPECT_POINT(cwRight[0].center, -20, 10);
  EXPECT_NEAR(cwRight[0].radius(), 4.6, kTol);
  EXPECT_POINT(cwRight[0].from, -20, 5.4);
  EXPECT_POINT(cwRight[0].to, -24.6, 10);
  EXPECT_EQ(cwRight[0].sourceLine, 14);
  const auto cwLeft = offsetPath(cw, 0.4, kLeft);
  EXPECT_NEAR(cwLeft[0].radius(), 5.4, kTol);
  EXPECT_POINT(cwLeft[0].to, -25.4, 10);
  // Seed 003 N16 G03 R7 (centre on its left): grows on the right, shrinks on the left.
  const std::vector<Segment> ccw{arc(SegmentKind::ArcCCW, {-35, 10}, {-42, 17}, {-42, 10})};
  const auto ccwRight = offsetPath(ccw, 0.4, kRight);
  EXPECT_NEAR(ccwRight[0].radius(), 7.4, kTol);
  EXPECT_POINT(ccwRight[0].from, -34.6, 10);
  EXPECT_POINT(ccwRight[0].to, -42, 17.4);
  const auto ccwLeft = offsetPath(ccw, 0.4, kLeft);
  EXPECT_NEAR(ccwLeft[0].radius(), 6.6, kTol);
  EXPECT_POINT(ccwLeft[0].from, -35.4, 10);
}

TEST(Offset, ArcShrinkingToNothingThrows) {
  for (double radius : {0.3, 0.4}) {  // radius below r, and equal to r
    const std::vector<Segment> path{
        line({0, 5}, {-20, 5}, 13),
        arc(SegmentKind::ArcCW, {-20, 5}, {-20 - radius, 5 + radius}, {-20, 5 + radius}, 14)};
    try {
      offsetPath(path, 0.4, kRight);
      FAIL() << "expected OffsetError for R" << radius;
    } catch (const OffsetError& e) {
      EXPECT_EQ(e.problem, OffsetProblem::ArcVanishes);
      EXPECT_EQ(e.segmentIndex, 1);
      EXPECT_EQ(e.sourceLine, 14);
      EXPECT_NE(std::string(e.what()).find("segment 1"), std::string::npos);
    }
  }
}

TEST(Offset, TangentJoinsAddNoPiece) {
  // N13 → N14 (line into a tangent G02) and N16 → N17 (G03 into a tangent line).
  const std::vector<Segment> lineToArc{line({0, 5}, {-20, 5}),
                                       arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10})};
  const auto a = offsetPath(lineToArc, 0.4, kRight);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_TRUE(a[1].isArc());
  expectConnected(a);
  const std::vector<Segment> arcToLine{arc(SegmentKind::ArcCCW, {-35, 10}, {-42, 17}, {-42, 10}),
                                       line({-42, 17}, {-52, 17})};
  const auto b = offsetPath(arcToLine, 0.4, kLeft);
  ASSERT_EQ(b.size(), 2u);
  EXPECT_POINT(b[1].from, -42, 16.6);
  expectConnected(b);
}

TEST(Offset, ZeroLengthSegmentsAreDropped) {
  const std::vector<Segment> path{line({0, 5}, {-10, 5}), line({-10, 5}, {-10, 5}),
                                  line({-10, 5}, {-20, 5})};
  const auto out = offsetPath(path, 0.4, kRight);
  ASSERT_EQ(out.size(), 2u);
  expectConnected(out);
}

TEST(Offset, DistanceToSegments) {
  const Segment l = line({0, 0}, {-10, 0});
  EXPECT_NEAR(distanceToSegment({-5, 3}, l), 3, kTol);
  EXPECT_NEAR(distanceToSegment({4, 3}, l), 5, kTol);  // beyond the start: to the end point
  // Quarter G02 from (−20,5) to (−25,10) around (−20,10): inside its span the radial distance,
  // outside it the distance to the nearer end.
  const Segment a = arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10});
  EXPECT_NEAR(distanceToSegment({-23, 6}, a), 0, kTol);
  EXPECT_NEAR(distanceToSegment({-22, 8}, a), 5 - std::hypot(2, 2), kTol);
  EXPECT_NEAR(distanceToSegment({-15, 10}, a), std::hypot(5, 5), kTol);  // nearest: the start
  EXPECT_NEAR(distanceToPath({-15, 10}, {l, a}), std::hypot(5, 5), kTol);
}

TEST(Offset, NearAPathIsDistanceToPathWithinATolerance) {
  const Segment l = line({0, 0}, {-10, 0});
  const Segment a = arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10});
  EXPECT_TRUE(nearPath({-5, 0.3}, {l, a}, 0.4));
  EXPECT_FALSE(nearPath({-5, 0.5}, {l, a}, 0.4));
  // Within the arc's circle's box but 5 − √8 from the arc; and from its start, √50.
  EXPECT_FALSE(nearPath({-22, 8}, {l, a}, 2));
  EXPECT_TRUE(nearPath({-22, 8}, {l, a}, 2.2));
  EXPECT_FALSE(nearPath({-15, 10}, {l, a}, 7));
  EXPECT_TRUE(nearPath({-15, 10}, {l, a}, 7.1));
  EXPECT_FALSE(nearPath({0, 0}, {}, 1));
}

// ---- imaginary tip, start-up ------------------------------------------------------------------

TEST(Offset, ImaginaryTipChart) {
  const Point expected[10] = {{0, 0}, {1, 1}, {-1, 1}, {-1, -1}, {1, -1},
                              {1, 0}, {0, 1}, {-1, 0}, {0, -1},  {0, 0}};
  for (int tip = 0; tip <= 9; ++tip) {
    EXPECT_EQ(imaginaryTipDirection(tip), expected[tip]) << "tip " << tip;
  }
  EXPECT_THROW(imaginaryTipDirection(10), std::out_of_range);
  EXPECT_THROW(imaginaryTipDirection(-1), std::out_of_range);
}

TEST(Offset, StartUpPointTypeA) {
  // Seed 003 N11→N12: arriving at A' (3,0) before the chamfer, G42, r = 0.4, tip 3:
  //   (3,0) + 0.4·(1,1)/√2 + 0.4·(−1,−1) = (3 − 0.117157, −0.117157).
  const Segment chamfer = line({3, 0}, {-2, 5});
  const double k = 0.4 * (1 / kSqrt2 - 1);
  EXPECT_POINT(startUpPoint({3, 0}, chamfer, {0.4, 3}, kRight), 3 + k, k);
  // Tip 0 gives the nose centre; before a line along −z, tip 3 keeps the point on that line.
  EXPECT_POINT(startUpPoint({3, 0}, chamfer, {0.4, 0}, kRight), 3 + 0.4 / kSqrt2, 0.4 / kSqrt2);
  EXPECT_POINT(startUpPoint({-2, 5}, line({-2, 5}, {-20, 5}), {0.4, 3}, kRight), -2.4, 5);
  // Before an arc, the normal at its start: N16 G03 starts moving +x, its right normal is +z.
  const Segment round = arc(SegmentKind::ArcCCW, {-35, 10}, {-42, 17}, {-42, 10});
  EXPECT_POINT(startUpPoint({-35, 10}, round, {0.4, 9}, kRight), -34.6, 10);
}

// ---- seed 003 example 1 -----------------------------------------------------------------------

// N12…N20 of seed 003 example 1 in radius (z, x); N11 G00 X0 at Z3 puts A' at (3,0).
std::vector<Segment> seed003Contour() {
  return {
      line({3, 0}, {-2, 5}, 12),                                      // C2 chamfer (extended)
      line({-2, 5}, {-20, 5}, 13),                                    // Ø10
      arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10}, 14),    // G02 R5
      line({-25, 10}, {-35, 10}, 15),                                 // Ø20
      arc(SegmentKind::ArcCCW, {-35, 10}, {-42, 17}, {-42, 10}, 16),  // G03 R7
      line({-42, 17}, {-52, 17}, 17),                                 // Ø34
      line({-52, 17}, {-62, 22}, 18),                                 // taper U10 W−10
      line({-62, 22}, {-87, 22}, 19),                                 // Ø44
      line({-87, 22}, {-87, 26}, 20),                                 // X52
  };
}

TEST(Offset, Seed003NoseCentrePath) {
  const auto contour = seed003Contour();
  const auto centre = offsetPath(contour, 0.4, kRight);
  // Corners: N12→N13 convex (arc), N13→N14 tangent, N14→N15 convex (arc), N15→N16 concave,
  // N16→N17 tangent, N17→N18 concave, N18→N19 convex (arc), N19→N20 concave.
  ASSERT_EQ(centre.size(), 12u);
  const int lines[12] = {12, 13, 13, 14, 15, 15, 16, 17, 18, 19, 19, 20};
  for (int i = 0; i < 12; ++i) EXPECT_EQ(centre[i].sourceLine, lines[i]) << "piece " << i;
  const double c = 0.4 / kSqrt2;  // 0.282843
  EXPECT_POINT(centre[0].from, 3 + c, c);
  EXPECT_POINT(centre[1].center, -2, 5);  // corner arc around the chamfer's end
  EXPECT_POINT(centre[1].to, -2, 5.4);
  EXPECT_POINT(centre[3].from, -20, 5.4);  // G02 R5 → R4.6
  EXPECT_NEAR(centre[3].radius(), 4.6, kTol);
  EXPECT_POINT(centre[4].center, -25, 10);  // corner arc at the top of the fillet
  EXPECT_POINT(centre[4].from, -24.6, 10);
  // N15→N16 concave: x = 10.4 meets the R7.4 circle around (−42,10) at z = −42 + √(7.4² − 0.4²)
  // = −42 + √54.6 = −34.610819.
  EXPECT_POINT(centre[5].to, -42 + std::sqrt(54.6), 10.4);
  EXPECT_NEAR(centre[6].radius(), 7.4, kTol);
  // N17→N18 concave: taper normal n2 = (1,2)/√5, n1 = (0,1); P + r·(n1 + n2)/(1 + n1·n2)
  // = (−52,17) + 0.4·(√5 − 2, 1) = (−51.905573, 17.4).
  EXPECT_POINT(centre[7].to, -52 + 0.4 * (kSqrt5 - 2), 17.4);
  EXPECT_POINT(centre[8].to, -62 + 0.4 / kSqrt5, 22 + 0.8 / kSqrt5);
  EXPECT_NEAR(distanceToSegment(pointAt(centre[8], 0.5), contour[6]), 0.4, kTol);
  EXPECT_POINT(centre[9].center, -62, 22);
  EXPECT_POINT(centre[10].to, -86.6, 22.4);  // N19→N20 concave
  EXPECT_POINT(centre[11].to, -86.6, 26);
  expectConnected(centre);
  const Clearance gap = clearance(centre, contour);
  EXPECT_GE(gap.least, 0.4 - 1e-9);
  EXPECT_LE(gap.most, 0.4 + 1e-9);
}

TEST(Offset, Seed003ImaginaryTipPath) {
  const auto contour = seed003Contour();
  const auto tip = compensatedPath(contour, {0.4, 3}, kRight);
  ASSERT_EQ(tip.size(), 12u);
  expectConnected(tip);
  // On the cylinders and the final face the tip point runs on the contour's own lines (Ø10 at
  // x = 5, Ø34 at x = 17, Ø44 at x = 22, the face at z = −87), each piece moved along its line.
  EXPECT_POINT(tip[2].from, -2.4, 5);
  EXPECT_POINT(tip[2].to, -20.4, 5);
  EXPECT_POINT(tip[7].from, -42.4, 17);
  EXPECT_POINT(tip[10].from, -62.4, 22);
  EXPECT_POINT(tip[10].to, -87, 22);  // the concave corner N19→N20 lands on the contour corner
  EXPECT_POINT(tip[11].from, -87, 22);
  EXPECT_POINT(tip[11].to, -87, 25.6);
  // On the chamfer it is shifted by 0.4·(1/√2 − 1) on both axes (Offset.ChamferTipPathDeviates).
  const double k = 0.4 * (1 / kSqrt2 - 1);
  EXPECT_POINT(tip[0].from, 3 + k, k);
  // At the concave corner N15→N16 the tip point is the nose centre minus (0.4, 0.4).
  EXPECT_POINT(tip[5].to, -42.4 + std::sqrt(54.6), 10);
}

// ---- property ---------------------------------------------------------------------------------

// A random monotone staircase/taper polyline from (0,0): z decreasing (or constant on a face),
// x non-decreasing, steps on a 0.01 mm grid, no zero-length segment.
std::vector<Segment> polylineFrom(const std::vector<std::tuple<int, int, int>>& steps) {
  std::vector<Segment> path;
  Point at{0, 0};
  for (const auto& [kind, a, b] : steps) {
    const double dz = kind == 1 ? 0.0 : -a / 100.0;  // 0 along −z, 1 face up, 2 taper
    const double dx = kind == 0 ? 0.0 : b / 100.0;
    const Point next{at.z + dz, at.x + dx};
    path.push_back(line(at, next, static_cast<int>(path.size()) + 1));
    at = next;
  }
  return path;
}

RC_GTEST_PROP(OffsetProperties, MonotonePolylinesStayClearOrThrow, ()) {
  // Half of the steps shorter than 1 mm, so that radii up to 1 mm often do not fit.
  const auto length = rc::gen::oneOf(rc::gen::inRange(1, 100), rc::gen::inRange(1, 1001));
  const int count = *rc::gen::inRange(1, 9);
  const auto steps = *rc::gen::container<std::vector<std::tuple<int, int, int>>>(
      count, rc::gen::tuple(rc::gen::inRange(0, 3), length, length));
  const double r = *rc::gen::inRange(1, 1001) / 1000.0;  // (0, 1]
  const auto path = polylineFrom(steps);
  std::vector<Segment> out;
  try {
    out = offsetPath(path, r, kRight);
  } catch (const OffsetError&) {
    RC_CLASSIFY(true, "interference");
    return;
  }
  RC_CLASSIFY(out.size() > path.size(), "with corner arcs");
  RC_ASSERT(!out.empty());
  for (std::size_t i = 1; i < out.size(); ++i) RC_ASSERT(nearlyEqual(out[i - 1].to, out[i].from));
  const Clearance c = clearance(out, path);
  RC_ASSERT(c.least >= r - 1e-6);
  RC_ASSERT(c.most <= r + 1e-6);  // and touches it everywhere
  RC_ASSERT(std::abs(distance(out.front().from, path.front().from) - r) <= kTol);
  RC_ASSERT(std::abs(distance(out.back().to, path.back().to) - r) <= kTol);
}

}  // namespace
}  // namespace cyclecert
