// The crossing tests' index (oracles/material/crossing_region.h) against Boost on random regions:
// containment agrees with bg::within away from the boundary, and a query visits every edge whose
// box meets it, once.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <map>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/crossing_region.h"
#include "reference/model/offset.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

// A region of many edges: a comb of random teeth (short walls, tops, slopes) over a long, deep
// base, its last wall standing at the far right of the short edges — edges on every side of the
// index's box.
BgRegion randomComb() {
  const int teeth = *rc::gen::inRange(1, 40);
  std::vector<Point> outline{{-1, -100}, {0, 0}};
  double z = 0;
  for (int i = 0; i < teeth; ++i) {
    const double width = *rc::gen::inRange(1, 30) / 10.0, height = *rc::gen::inRange(1, 100) / 10.0;
    const double lean = *rc::gen::inRange(0, 2) * 0.5;  // a vertical wall, or a slope
    outline.push_back({z + lean, height});
    outline.push_back({z + lean + width, height});
    z += lean + width;
    if (i + 1 < teeth) z += *rc::gen::inRange(0, 20) / 10.0;
    outline.push_back({z, 0.0});
  }
  outline.push_back({z + 1, -100});
  return regionFrom(outline);
}

double distanceToBoundary(const BgRegion& region, Point p) {
  double nearest = INFINITY;
  for (const auto& ring : outlinesOf(region)) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      nearest = std::min(nearest, distanceToSegment(p, {SegmentKind::Line, ring[i], ring[(i + 1) % ring.size()], {}, 0}));
    }
  }
  return nearest;
}

RC_GTEST_PROP(CrossingRegion, ContainsAgreesWithBoostAwayFromTheBoundary, ()) {
  const BgRegion region = randomComb();
  const CrossingRegion index(region);
  for (int k = 0; k < 200; ++k) {
    const Point p{*rc::gen::inRange(-50, 1500) / 10.0, *rc::gen::inRange(-1100, 150) / 10.0};
    if (distanceToBoundary(region, p) < 1e-6) continue;
    RC_ASSERT(index.contains(p) == bg::within(toBg(p), region));
  }
}

RC_GTEST_PROP(CrossingRegion, AQueryVisitsEveryEdgeItsBoxMeetsOnce, ()) {
  const BgRegion region = randomComb();
  const CrossingRegion index(region);
  for (int query = 0; query < 20; ++query) {
    // Boxes of every size anywhere, points and lines among them.
    const double z0 = *rc::gen::inRange(-50, 1500) / 10.0, x0 = *rc::gen::inRange(-1100, 150) / 10.0;
    const double z1 = z0 + *rc::gen::element(0, 0, 1, 30, 300, 3000) / 10.0;
    const double x1 = x0 + *rc::gen::element(0, 0, 1, 30, 300, 3000) / 10.0;
    std::map<std::pair<std::pair<double, double>, std::pair<double, double>>, int> visits;
    index.forEachEdgeNear(z0, z1, x0, x1, [&](Point a, Point b) { ++visits[{{a.z, a.x}, {b.z, b.x}}]; });
    for (const auto& [edge, count] : visits) RC_ASSERT(count == 1);
    for (const auto& ring : outlinesOf(region)) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Point a = ring[i], b = ring[(i + 1) % ring.size()];
        const bool meets = std::max(a.z, b.z) >= z0 && std::min(a.z, b.z) <= z1 && std::max(a.x, b.x) >= x0 &&
                           std::min(a.x, b.x) <= x1;
        if (meets) RC_ASSERT(visits.count({{a.z, a.x}, {b.z, b.x}}) == 1u);
      }
    }
  }
}

// The part of a type II cycle with a pocket, where a wall at the far end of the index's box was
// once left out of it (its cell lay one past the last): the ray from a point beside the pocket
// must cross that wall.
TEST(CrossingRegion, AWallOnTheFarSideOfTheIndexCounts) {
  const CrossingRegion index(
      std::vector<std::vector<Point>>{{{2, 15}, {2, -77}, {-11, -77}, {-11, 16}, {-7, 16}, {-4, 19}, {-4, 15}}});
  EXPECT_FALSE(index.contains({-8, 18}));
  EXPECT_TRUE(index.contains({-5, 17}));
}

}  // namespace
}  // namespace cyclecert
