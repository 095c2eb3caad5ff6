// The crossing tests' index (oracles/material/crossing_region.h) against Boost on random regions:
// containment agrees with bg::within away from the boundary, and a query visits every edge whose
// box meets it, once.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <map>
#include <set>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/crossing_region.h"
#include "oracles/material/cut_envelope.h"
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

// The region below the feeds' envelope, as the rapids' crossing test sees it, against the same
// region as Boost has it (CutEnvelope::below), in both a G71 and a G72 frame.
RC_GTEST_PROP(CrossingRegion, TheRegionBelowTheEnvelopeAgreesWithBoost, ()) {
  const Point away = *rc::gen::element(Point{0, 1}, Point{0, -1}, Point{1, 0}, Point{-1, 0});
  const DepthFrame frame(away);
  CutEnvelope envelope;
  const int feeds = *rc::gen::inRange(0, 60);  // up to some 120 edges: several blocks of the index
  for (int i = 0; i < feeds; ++i) {
    const double c0 = *rc::gen::inRange(-400, 400) / 10.0, c1 = *rc::gen::inRange(-400, 400) / 10.0;
    const double d0 = *rc::gen::inRange(-200, 200) / 10.0, d1 = *rc::gen::inRange(-200, 200) / 10.0;
    envelope.lower({c0 * frame.along() + d0 * frame.away(), c1 * frame.along() + d1 * frame.away()}, frame);
  }
  const BgRegion below = envelope.below(frame, -30, 30, -25, 25);
  const RegionBelowGraph index(frame, envelope.belowTop(-30, 30, -25, 25), -25);
  for (int k = 0; k < 200; ++k) {
    const Point p{*rc::gen::inRange(-400, 400) / 10.0 + 0.013, *rc::gen::inRange(-400, 400) / 10.0 + 0.007};
    if (distanceToBoundary(below, p) < 1e-6) continue;
    RC_ASSERT(index.contains(p) == bg::within(toBg(p), below));
  }
  // A segment the index finds no more than a slack inside has no point inside more than the slack
  // deep: segments along either axis (along the depth axis on the walls' cut coordinates, the grid
  // being the feeds'), and any other.
  const double slack = *rc::gen::element(0.0, 0.5);
  for (int k = 0; k < 50; ++k) {
    const Point a{*rc::gen::inRange(-400, 400) / 10.0, *rc::gen::inRange(-400, 400) / 10.0};
    const int direction = *rc::gen::inRange(0, 3);
    const Point b = direction == 0   ? a + Point{*rc::gen::inRange(-300, 300) / 10.0, 0}
                    : direction == 1 ? a + Point{0, *rc::gen::inRange(-300, 300) / 10.0}
                                     : Point{*rc::gen::inRange(-400, 400) / 10.0, *rc::gen::inRange(-400, 400) / 10.0};
    if (!index.staysWithin(a, b, slack)) continue;
    for (int t = 0; t <= 100; ++t) {
      const Point p = a + (t / 100.0) * (b - a);
      RC_ASSERT(!bg::within(toBg(p), below) || distanceToBoundary(below, p) < slack + 1e-9);
    }
  }
  // Every point of the boundary within a query's box lies on an edge the query visits (the index
  // may visit more; Boost merges collinear edges the index keeps apart, so points decide).
  const double z0 = *rc::gen::inRange(-400, 400) / 10.0, x0 = *rc::gen::inRange(-400, 400) / 10.0;
  const double z1 = z0 + *rc::gen::element(0, 1, 30, 300) / 10.0, x1 = x0 + *rc::gen::element(0, 1, 30, 300) / 10.0;
  std::vector<Segment> visited;
  index.forEachEdgeNear(z0, z1, x0, x1, [&](Point a, Point b) { visited.push_back({SegmentKind::Line, a, b, {}, 0}); });
  for (const auto& ring : outlinesOf(below)) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i], b = ring[(i + 1) % ring.size()];
      for (int k = 0; k <= 20; ++k) {
        const Point p = a + (k / 20.0) * (b - a);
        if (p.z < z0 || p.z > z1 || p.x < x0 || p.x > x1) continue;
        RC_ASSERT(std::any_of(visited.begin(), visited.end(), [&](const Segment& e) { return distanceToSegment(p, e) < 1e-9; }));
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

// A wall in the top (from depth 2 up to 5 at cut 10): a segment at depth 3 leaving the wall
// towards the high side runs inside; one reaching the wall from the low side stays outside, as
// does a move down the wall itself or beside it within the slack — but not farther off.
TEST(CrossingRegion, TheTopOnEachSideOfAWall) {
  const DepthFrame frame(Point{0, 1});
  const RegionBelowGraph index(frame, {{0, 2}, {10, 2}, {10, 5}, {20, 5}}, -10);
  const auto at = [&](double c, double d) { return frame.point(c, d); };
  EXPECT_FALSE(index.staysWithin(at(10, 3), at(15, 3), 0.5));
  EXPECT_FALSE(index.staysWithin(at(15, 3), at(10, 3), 0.5));
  EXPECT_TRUE(index.staysWithin(at(5, 3), at(10, 3), 0.5));
  EXPECT_TRUE(index.staysWithin(at(10, 3), at(5, 3), 0.5));
  EXPECT_TRUE(index.staysWithin(at(10, 5), at(10, 2.2), 0.5));
  EXPECT_TRUE(index.staysWithin(at(10.3, 5), at(10.3, 2.2), 0.5));
  EXPECT_FALSE(index.staysWithin(at(11, 5), at(11, 2.2), 0.5));
  EXPECT_TRUE(index.contains(at(12, 3)));
  EXPECT_FALSE(index.contains(at(8, 3)));
}

}  // namespace
}  // namespace cyclecert
