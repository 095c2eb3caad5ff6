// convexHullOf (oracles/material/tool_shape.h) follows Boost's Graham–Andrew hull step by step on
// buffers of its own: its rings must be Boost's point for point (the unions of a sweep's hulls
// after it then see the same input), also for the degenerate clouds a sweep makes — repeated
// points, collinear points, a blade's corners along a chord parallel to one of its sides.
#include <gtest/gtest.h>

#include <random>
#include <vector>

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

}  // namespace
}  // namespace cyclecert
