// convexHullOf (oracles/material/tool_shape.h) follows Boost's Graham–Andrew hull step by step on
// buffers of its own: its rings must be Boost's point for point (the unions of a sweep's hulls
// after it then see the same input), also for the degenerate clouds a sweep makes — repeated
// points, collinear points, a blade's corners along a chord parallel to one of its sides. A sweep
// passes each chord's hull only the points that can lie on it: the swept region must be the one
// made from every point, ring for ring.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "oracles/groove/groove_nose.h"
#include "oracles/material/boost_geometry.h"
#include "oracles/material/tool_shape.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

// The hull as bg::convex_hull makes it (what convexHullOf did before).
BgRegion boostHullOf(const std::vector<Point>& points) {
  bg::model::multi_point<BgPoint> cloud;
  for (Point p : points) cloud.push_back(toBg(p));
  BgPolygon hull;
  bg::convex_hull(cloud, hull);
  BgRegion out;
  if (bg::area(hull) != 0) out.push_back(hull);
  bg::correct(out);
  return out;
}

void expectSameRings(const std::vector<Point>& points) {
  const BgRegion ours = convexHullOf(points), boost = boostHullOf(points);
  ASSERT_EQ(ours.size(), boost.size());
  for (std::size_t k = 0; k < ours.size(); ++k) {
    const auto& a = ours[k].outer();
    const auto& b = boost[k].outer();
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].x(), b[i].x());
      EXPECT_EQ(a[i].y(), b[i].y());
    }
  }
}

TEST(ConvexHull, ABladeAlongAChordIsBoostsHexagon) {
  const std::vector<Point> shape{{0, 0}, {0, -0.5}, {-30, -0.5}, {-30, 0}};
  for (Point to : {Point{2, 1}, Point{2, 0}, Point{0, 1}, Point{-2, 1}, Point{0, 0}}) {
    std::vector<Point> points;
    for (Point c : shape) {
      points.push_back(Point{1, 1} + c);
      points.push_back(Point{1, 1} + to + c);
    }
    expectSameRings(points);
  }
}

TEST(ConvexHull, DegenerateCloudsAreBoosts) {
  expectSameRings({});
  expectSameRings({{1, 2}});
  expectSameRings({{1, 2}, {1, 2}, {1, 2}});
  expectSameRings({{0, 0}, {1, 1}, {2, 2}, {3, 3}});
  expectSameRings({{0, 0}, {0, 1}, {0, 2}, {1, 0}, {1, 1}, {1, 2}});
  expectSameRings({{0, 0}, {1e-13, 1}, {0, 2}, {2, 1}, {2, 1}});
}

TEST(ConvexHull, RandomCloudsOnAGridAreBoosts) {
  std::mt19937 random(17);
  std::uniform_int_distribution<int> coordinate(-3, 3), count(1, 16);
  for (int trial = 0; trial < 5000; ++trial) {
    std::vector<Point> points(static_cast<std::size_t>(count(random)));
    for (Point& p : points) p = {0.25 * coordinate(random), 0.5 * coordinate(random)};
    expectSameRings(points);
  }
}

TEST(ConvexHull, RandomCloudsAreBoosts) {
  std::mt19937 random(5);
  std::uniform_real_distribution<double> coordinate(-10, 10);
  std::uniform_int_distribution<int> count(3, 40);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<Point> points(static_cast<std::size_t>(count(random)));
    for (Point& p : points) p = {coordinate(random), coordinate(random)};
    expectSameRings(points);
  }
}

void expectSameRegions(const BgRegion& ours, const BgRegion& theirs) {
  ASSERT_EQ(ours.size(), theirs.size());
  for (std::size_t k = 0; k < ours.size(); ++k) {
    ASSERT_EQ(ours[k].outer().size(), theirs[k].outer().size());
    for (std::size_t i = 0; i < ours[k].outer().size(); ++i) {
      ASSERT_EQ(ours[k].outer()[i].x(), theirs[k].outer()[i].x());
      ASSERT_EQ(ours[k].outer()[i].y(), theirs[k].outer()[i].y());
    }
    ASSERT_EQ(ours[k].inners().size(), theirs[k].inners().size());
  }
}

// The sweep as it was made from every point of the shape at both ends of each chord.
BgRegion sweepFromEveryPoint(const Segment& move, const std::vector<Point>& shape, double chord) {
  const std::vector<Point> chords = flatten(move, chord);
  BgRegion swept;
  for (std::size_t k = 0; k + 1 < chords.size(); ++k) {
    std::vector<Point> points;
    for (Point c : shape) {
      points.push_back(chords[k] + c);
      points.push_back(chords[k + 1] + c);
    }
    BgRegion piece = convexHullOf(points);
    if (swept.empty()) {
      swept = std::move(piece);
    } else if (!piece.empty()) {
      BgRegion merged;
      bg::union_(swept, piece, merged);
      swept = std::move(merged);
    }
  }
  tidy(swept);
  return swept;
}

TEST(ConvexHull, ANoseSweptWithOnlyItsHullsCandidatesIsTheSameRegion) {
  std::mt19937 random(23);
  std::uniform_real_distribution<double> coordinate(-5, 5), radius(0.2, 1.6), angle(0, 6.283185307179586);
  for (int trial = 0; trial < 300; ++trial) {
    const double r = radius(random), chord = trial % 2 ? 1e-3 : 1e-2;
    std::vector<Point> shape = noseDisc(r, chord);
    if (trial % 3 != 0) {  // with its shadow along ±u (the replay's feeds), of the band's length
      const std::size_t n = shape.size();
      const Point along = trial % 3 == 1 ? Point{0, 12} : Point{0, -12};
      for (std::size_t i = 0; i < n; ++i) shape.push_back(shape[i] + along);
    }
    const Point from{coordinate(random), coordinate(random)};
    Segment move{SegmentKind::Line, from, {coordinate(random), coordinate(random)}, {}, 0};
    if (trial % 4 == 0) move.to = {from.z, from.x + 3};  // along u
    if (trial % 4 == 1) {                                 // an arc about a centre 2 away
      const Point centre = from + Point{2 * std::cos(angle(random)), 2 * std::sin(angle(random))};
      const double a0 = std::atan2(from.x - centre.x, from.z - centre.z), a1 = a0 + angle(random) / 3;
      move = {trial % 8 == 1 ? SegmentKind::ArcCCW : SegmentKind::ArcCW, from,
              centre + Point{2 * std::cos(a1), 2 * std::sin(a1)}, centre, 0};
      move.from = centre + Point{2 * std::cos(a0), 2 * std::sin(a0)};
    }
    expectSameRegions(sweptConvexShape(move, shape, chord), sweepFromEveryPoint(move, shape, chord));
  }
}

}  // namespace
}  // namespace cyclecert
