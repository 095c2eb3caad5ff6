// A parallelogram (a blade with its shank, a point's shadow) swept along a move
// (oracles/material/tool_shape.h): along an arc, runs of chords in one open cone between the sides
// are built directly rather than united chord by chord; the region must stay the union of the
// chords' hulls (sweptConvexShape of the same parallelogram).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/tool_shape.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

constexpr double kPi = 3.14159265358979323846;
constexpr double kChord = 1e-3;

Segment arc(Point centre, double radius, double fromAngle, double toAngle, SegmentKind kind) {
  const auto at = [&](double a) { return centre + Point{radius * std::cos(a), radius * std::sin(a)}; };
  return {kind, at(fromAngle), at(toAngle), centre};
}

double areaOf(const BgRegion& r) { return bg::area(r); }

double symmetricDifferenceArea(const BgRegion& a, const BgRegion& b) {
  BgRegion ab, ba;
  bg::difference(a, b, ab);
  bg::difference(b, a, ba);
  return bg::area(ab) + bg::area(ba);
}

// The Minkowski sum of an a × b rectangle and a path monotone in both coordinates has the area
// ab + a·|Δx| + b·|Δz| whatever the path's shape (the band between the path moved by the two side
// corners): the quarter arc from (1, 0) to (0, 1), a = 0.5 along z and b = 2 along x, gives
// 1 + 0.5·1 + 2·1 = 3.5 — its chords have the same ends, so the flattened sweep has it exactly.
TEST(BladeSweep, AQuarterArcSweepsTheBandBetweenItsSideCorners) {
  const Segment quarter = arc({0, 0}, 1, 0, kPi / 2, SegmentKind::ArcCCW);
  const BgRegion swept = sweptRegion(quarter, {1, 0}, 0.5, {0, 1}, 2, kChord);
  ASSERT_EQ(swept.size(), 1u);
  EXPECT_TRUE(swept.front().inners().empty());
  EXPECT_NEAR(areaOf(swept), 3.5, 1e-9);
}

// Arcs of every quadrant, both senses, short and long, small and large against the blade, the
// blade's frame turned too: the region is the union of the chords' hulls (a wrong corner, a run across
// two cones or a missed cap would be off by a share of the blade's area, 1e-2 and more).
TEST(BladeSweep, AlongAnyArcItIsTheUnionOfTheChordsHulls) {
  struct Frame {
    Point da, db;
    double a, b;
  };
  const std::vector<Frame> frames = {
      {{0, -1}, {-1, 0}, 0.8, 12},  // a G74.1 blade: across −u, its shank back along −w
      {{1, 0}, {0, 1}, 0.5, 2},
      {{0.6, 0.8}, {-0.8, 0.6}, 1.5, 0.3},
      {{1, 0}, {0.6, 0.8}, 1, 1},  // a slanted parallelogram
  };
  int checked = 0;
  for (const Frame& f : frames) {
    for (double radius : {0.2, 1.0, 4.0}) {
      for (int sixth = 0; sixth < 6; ++sixth) {
        const double start = sixth * kPi / 3;
        for (double sweep : {kPi / 5, kPi / 2, 1.1 * kPi, 1.7 * kPi}) {
          for (SegmentKind kind : {SegmentKind::ArcCCW, SegmentKind::ArcCW}) {
            const double end = kind == SegmentKind::ArcCCW ? start + sweep : start - sweep;
            const Segment move = arc({3, -2}, radius, start, end, kind);
            const std::vector<Point> shape{{0, 0}, f.a * f.da, f.a * f.da + f.b * f.db, f.b * f.db};
            const BgRegion fast = sweptRegion(move, f.da, f.a, f.db, f.b, kChord);
            const BgRegion united = sweptConvexShape(move, shape, kChord);
            SCOPED_TRACE("radius " + std::to_string(radius) + " start " + std::to_string(start) + " sweep " +
                         std::to_string(sweep) + (kind == SegmentKind::ArcCW ? " CW" : " CCW"));
            std::string reason;
            EXPECT_TRUE(bg::is_valid(fast, reason)) << reason;
            // Within the booleans' resolution (region.h): the union's crossings round, the run's do not.
            EXPECT_NEAR(areaOf(fast), areaOf(united), kBooleanResolution * areaOf(united));
            EXPECT_LT(symmetricDifferenceArea(fast, united), kBooleanResolution * areaOf(united));
            ++checked;
          }
        }
      }
    }
  }
  EXPECT_EQ(checked, 4 * 3 * 6 * 4 * 2);
}

}  // namespace
}  // namespace cyclecert
