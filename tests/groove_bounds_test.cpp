// oracles/groove/groove_bounds.h: the staircase of cleared material against the exact regions it
// spares, and the part's top against the part region (random rectangles, Boost as the judge).
#include <gtest/gtest.h>

#include <random>

#include "oracles/groove/groove_bounds.h"
#include "oracles/material/boost_geometry.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

BgRegion rectangle(double u0, double u1, double w0, double w1) {
  return regionFrom({grooveUW(u0, w0), grooveUW(u1, w0), grooveUW(u1, w1), grooveUW(u0, w1)});
}

BgRegion stepsOf(const ClearedStaircase& c, double top) {
  BgRegion steps;
  for (const auto& ring : c.outlines(top)) {
    const BgRegion one = regionFrom(ring);
    steps.insert(steps.end(), one.begin(), one.end());
  }
  return steps;
}

TEST(ClearedStaircase, TwoPecksAndAStepBetweenThem) {
  const BandFrame band{-1, 11, 0};
  ClearedStaircase c(band);
  c.clearDownTo(0, 2, 5);
  c.clearDownTo(4, 6, 3);
  c.clearDownTo(1, 5, 1);
  // depths: [0,1) 5, [1,2) 5, [2,4) 1, [4,5) 3, [5,6) 3
  EXPECT_TRUE(c.goneAbove(0, 2, 5));
  EXPECT_FALSE(c.goneAbove(0, 2.5, 5));
  EXPECT_TRUE(c.goneAbove(0, 6, 1));
  EXPECT_FALSE(c.goneAbove(-0.5, 6, 1)) << "left of the first peck nothing is cleared";
  EXPECT_TRUE(c.goneAbove(-0.5, 6, 0)) << "above the mouth is air";
  EXPECT_TRUE(c.goneAbove(20, 30, 100)) << "beyond the band there is no material";
  EXPECT_TRUE(c.goneAbove(2, 2, 1));
  EXPECT_FALSE(c.goneAbove(2, 2, 3)) << "a point on a step's edge sees both sides";
  const BgRegion left = without(rectangle(-1, 11, 0, 10), stepsOf(c, -2));
  EXPECT_NEAR(bg::area(left), 12 * 10 - (2 * 5 + 2 * 1 + 2 * 3), 1e-9);
}

TEST(ClearedStaircase, NeighbouringPecksWhoseEdgesDifferInTheLastBitsMakeOneStaircase) {
  // Blade pecks as a planner computes them: one ends at its u, the next begins at its own u − r,
  // a few 1e-15 off either way (the G74.1 replay's cases that failed: a sliver "not cleared"
  // between two pecks split the staircase into two touching rings, and Boost's difference with
  // them left the material standing; a retract's span starting in the neighbour's step).
  const double u1 = 1.2989316740918, gap = 4e-15;
  ClearedStaircase c(BandFrame{-2, 44, 0});
  c.clearDownTo(u1 - 1.16, u1, 0.144);
  c.clearDownTo(u1 + gap, u1 + gap + 1.16, 1.345);
  c.clearDownTo(u1 + 1.16 - gap, u1 + 2 * 1.16, 1.36);
  EXPECT_EQ(c.outlines(-2).size(), 1u) << "no sliver of uncleared material between them";
  EXPECT_TRUE(c.goneAbove(u1 - 1.16, u1 + 2 * 1.16, 0.144)) << "across all three";
  EXPECT_TRUE(c.goneAbove(u1 + 1.16 - 2 * gap, u1 + 2 * 1.16, 1.36)) << "the retract after the third";
}

TEST(ClearedStaircase, MatchesTheDifferenceOfItsRectanglesOnRandomPecks) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-2, 22), width(0.1, 4), depth(0.1, 9);
  for (int trial = 0; trial < 200; ++trial) {
    const double slope = trial % 3 == 0 ? 0.2 : 0;
    const BandFrame band{0, 20, slope};
    const BgRegion stock = regionFrom({grooveUW(0, 0), grooveUW(20, 20 * slope), grooveUW(20, 15), grooveUW(0, 15)});
    ClearedStaircase c(band);
    BgRegion exact = stock;
    for (int k = 0; k < 12; ++k) {
      const double a = u(random), b = a + width(random), w = depth(random);
      c.clearDownTo(a, b, w);
      exact = without(exact, rectangle(a, b, -10, w));
    }
    const BgRegion fast = without(stock, stepsOf(c, -10));
    ASSERT_NEAR(bg::area(fast), bg::area(exact), 1e-4) << "trial " << trial;
    // Where goneAbove says gone, no exact material lies above w over the span.
    for (int q = 0; q < 20; ++q) {
      const double a = u(random), b = a + width(random) * (q % 4 == 0 ? 0 : 1), w = depth(random);
      if (!c.goneAbove(a, b, w)) continue;
      const BgRegion probe = rectangle(a, std::max(b, a + 1e-6), -10, w);
      ASSERT_LT(bg::area(checkedIntersection(probe, exact)), 1e-6) << "trial " << trial << " query " << q;
    }
  }
}

TEST(PartTop, IsTheMouthBesideTheGrooveAndTheChainInIt) {
  // A groove 4 wide at the mouth, 2 at its floor 3 deep (45° flanks), from u = 2.
  GrooveOutline o;
  const auto line = [](Point a, Point b) { return Segment{SegmentKind::Line, a, b, {}, 0}; };
  o.chain = {line(grooveUW(2, 0), grooveUW(3, 3)), line(grooveUW(3, 3), grooveUW(5, 3)), line(grooveUW(5, 3), grooveUW(6, 0))};
  const BandFrame band{0, 8, 0};
  const auto top = PartTop::of(o, band, 0.001);
  ASSERT_TRUE(top);
  EXPECT_DOUBLE_EQ(top->shallowestOver(3, 5), 3);
  EXPECT_DOUBLE_EQ(top->shallowestOver(3.5, 4), 3);
  EXPECT_NEAR(top->shallowestOver(2.5, 4), 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(top->shallowestOver(1, 4), 0) << "the mouth beside the groove";
  EXPECT_EQ(top->shallowestOver(9, 10), std::numeric_limits<double>::infinity()) << "no part beyond the band";
}

// The groove of the test above, for the part's top against polylines (a blade's deepest outline).
GrooveOutline slantedGroove() {
  GrooveOutline o;
  const auto line = [](Point a, Point b) { return Segment{SegmentKind::Line, a, b, {}, 0}; };
  o.chain = {line(grooveUW(2, 0), grooveUW(3, 3)), line(grooveUW(3, 3), grooveUW(5, 3)), line(grooveUW(5, 3), grooveUW(6, 0))};
  return o;
}

TEST(PartTop, APolylineAlongTheFlanksAndTheFloorLiesOnItsTop) {
  const auto top = PartTop::of(slantedGroove(), BandFrame{0, 8, 0}, 0.001);
  ASSERT_TRUE(top);
  // On the near flank w = 3(u − 2): its box reaches 2.4 deep over a span where the flank is 0.6 deep,
  // the polyline itself never goes below it.
  EXPECT_LT(top->shallowestOver(2.2, 2.8), 2.4);
  EXPECT_TRUE(top->liesBelow({grooveUW(2.2, 0.6), grooveUW(2.8, 2.4)}, 1e-9));
  EXPECT_FALSE(top->liesBelow({grooveUW(2.2, 0.61), grooveUW(2.8, 2.41)}, 1e-9)) << "0.01 into the flank";
  // Down the near flank, along the floor, up the far flank: the part's top itself.
  EXPECT_TRUE(top->liesBelow({grooveUW(2.5, 1.5), grooveUW(3, 3), grooveUW(5, 3), grooveUW(5.5, 1.5)}, 1e-9));
  EXPECT_FALSE(top->liesBelow({grooveUW(2.5, 1.5), grooveUW(3, 3.001), grooveUW(5, 3), grooveUW(5.5, 1.5)}, 1e-9))
      << "a vertex 0.001 below the floor's corner";
  // A straight cut across the floor's corner at (5, 3) stays inside; one across the mouth's corner at
  // (6, 0) into the band beside the groove does not.
  EXPECT_TRUE(top->liesBelow({grooveUW(4.5, 3), grooveUW(5.5, 1.5)}, 1e-9));
  EXPECT_FALSE(top->liesBelow({grooveUW(5.5, 1.5), grooveUW(6.5, 0.5)}, 1e-9));
  EXPECT_TRUE(top->liesBelow({grooveUW(9, 7), grooveUW(10, 7)}, 1e-9)) << "no part beyond the band";
  EXPECT_FALSE(top->liesBelow({grooveUW(4, 1), grooveUW(4, 2)}, 1e-9)) << "no graph over u: not proven";
}

// Random polylines: where liesBelow proves nothing of the part lies above them, the region above
// each holds none of the exact part (band without the groove's interior).
TEST(PartTop, WhereAPolylineLiesAboveItTheExactPartHasNothingAboveIt) {
  const BandFrame band{0, 8, 0};
  const auto top = PartTop::of(slantedGroove(), band, 0.001);
  ASSERT_TRUE(top);
  const BgRegion part = without(rectangle(0, 8, 0, 5), regionFrom({grooveUW(2, 0), grooveUW(3, 3), grooveUW(5, 3),
                                                                    grooveUW(6, 0), grooveUW(6, -1), grooveUW(2, -1)}));
  std::mt19937 random(17);
  std::uniform_real_distribution<double> u(-1, 9), step(0.05, 2), depth(-0.5, 4);
  int proven = 0;
  for (int trial = 0; trial < 400; ++trial) {
    std::vector<Point> outline{grooveUW(u(random), depth(random))};
    for (int k = 0; k < 2; ++k) outline.push_back(grooveUW(outline.back().x + step(random), depth(random)));
    if (!top->liesBelow(outline, 1e-9)) continue;
    ++proven;
    std::vector<Point> above = outline;
    above.push_back(grooveUW(outline.back().x, -10));
    above.push_back(grooveUW(outline.front().x, -10));
    ASSERT_LT(bg::area(checkedIntersection(regionFrom(above), part)), 1e-9) << "trial " << trial;
  }
  EXPECT_GT(proven, 40) << "the trials must prove some";
}

// Everything above the polyline (u increasing) down to it, from w = top: a blade's sweep reaching
// back out of the band, or what a rapid's blade would cross.
BgRegion aboveOutline(const std::vector<Point>& outline, double top) {
  std::vector<Point> ring{grooveUW(outline.front().x, top)};
  for (Point p : outline) ring.push_back(p);
  ring.push_back(grooveUW(outline.back().x, top));
  return regionFrom(ring);
}

TEST(ClearedOutline, ASlantedPassAndAPeckBoundWhatStands) {
  ClearedOutline c(BandFrame{0, 10, 0});
  c.clearDownTo({grooveUW(1, 2), grooveUW(3, 2)});              // a peck 2 deep over [1, 3]
  c.clearDownTo({grooveUW(2, 1), grooveUW(4, 3), grooveUW(5, 3)});  // a pass down a flank
  // D: 2 over [1, 3) but the flank's 1 + (u − 2) beyond u = 3, 3 over [4, 5].
  EXPECT_TRUE(c.covers({grooveUW(1, 2), grooveUW(3, 2)}, 1e-9));
  EXPECT_TRUE(c.covers({grooveUW(1.5, 1.9), grooveUW(3.5, 2), grooveUW(5, 3)}, 1e-9));
  EXPECT_FALSE(c.covers({grooveUW(2.5, 2.1), grooveUW(3, 2.1)}, 1e-9)) << "below the peck's floor";
  EXPECT_FALSE(c.covers({grooveUW(4.5, 3), grooveUW(5.5, 3)}, 1e-9)) << "beyond the pass";
  EXPECT_TRUE(c.covers({grooveUW(5.5, 0), grooveUW(7, 0)}, 1e-9)) << "at the mouth";
  EXPECT_TRUE(c.covers({grooveUW(11, 5), grooveUW(12, 5)}, 1e-9)) << "beyond the band";
  EXPECT_TRUE(c.covers({grooveUW(3, 2), grooveUW(3, 1), grooveUW(4, 3)}, 1e-9)) << "a wall is skipped";
  EXPECT_FALSE(c.covers({grooveUW(3, 2), grooveUW(3.5, 2.6)}, 1e-9)) << "0.1 below the flank's pass";
}

TEST(ClearedOutline, AgreesWithTheDifferenceOfTheSweepsOnRandomPasses) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-2, 22), width(0.1, 5), depth(0.1, 9);
  const double top = -10;
  for (int trial = 0; trial < 200; ++trial) {
    const double slope = trial % 3 == 0 ? 0.2 : 0;
    const BandFrame band{0, 20, slope};
    const BgRegion stock = regionFrom({grooveUW(0, 0), grooveUW(20, 20 * slope), grooveUW(20, 15), grooveUW(0, 15)});
    ClearedOutline c(band);
    BgRegion exact = stock;
    const auto outline = [&](double scale) {
      const double a = u(random), b = a + width(random), m = a + (b - a) * 0.5;
      return std::vector<Point>{grooveUW(a, scale * depth(random)), grooveUW(m, scale * depth(random)),
                                grooveUW(b, scale * depth(random))};
    };
    for (int k = 0; k < 12; ++k) {
      const std::vector<Point> o = outline(1);
      c.clearDownTo(o);
      ASSERT_TRUE(c.covers(o, 1e-9)) << "trial " << trial << ": an outline just cleared";
      exact = without(exact, aboveOutline(o, top));
    }
    // Shallower outlines, often covered: where the bound says so, nothing exact stands above them.
    for (int q = 0; q < 40; ++q) {
      const std::vector<Point> o = outline(0.4);
      if (!c.covers(o, 1e-9)) continue;
      ASSERT_LT(bg::area(checkedIntersection(aboveOutline(o, top), exact)), 1e-6) << "trial " << trial << " query " << q;
    }
  }
}

// The groove of slantedGroove (near flank u = 2 + w/3, far flank u = 6 − w/3, floor 3 deep) and a
// point's feeds with their shadows 20 long (beyond the band's side).
std::vector<Point> slantedChain() {
  const auto top = PartTop::of(slantedGroove(), BandFrame{0, 8, 0}, 0.001);
  return top->chain();
}

TEST(ShadowedRows, APassDownTheFarFlankShadowingTowardsTheStartClearsTheTarget) {
  ShadowedRows rows(BandFrame{0, 8, 0});
  rows.clearBehind(grooveUW(5.5, 1.5), grooveUW(5, 3), -1, 20);
  EXPECT_FALSE(rows.coversTarget(slantedChain(), 1e-9)) << "the rows above 1.5 stand";
  rows.clearBehind(grooveUW(6, 0), grooveUW(5.5, 1.5), -1, 20);
  EXPECT_TRUE(rows.coversTarget(slantedChain(), 1e-9));
}

TEST(ShadowedRows, ShadowsFromBothSidesMeet) {
  ShadowedRows rows(BandFrame{0, 8, 0});
  rows.clearBehind(grooveUW(4, -1), grooveUW(4, 2.5), -1, 20);  // a peck at u = 4, behind it towards −u
  rows.clearBehind(grooveUW(4, -1), grooveUW(4, 3), 1, 20);     // and towards +u
  EXPECT_FALSE(rows.coversTarget(slantedChain(), 1e-9)) << "below 2.5 only the +u side is cleared";
  rows.clearBehind(grooveUW(4, 2), grooveUW(4, 3), -1, 20);
  EXPECT_TRUE(rows.coversTarget(slantedChain(), 1e-9));
  ShadowedRows near(BandFrame{0, 8, 0});
  near.clearBehind(grooveUW(2, 0), grooveUW(3, 3), 1, 20);  // down the near flank, towards +u
  EXPECT_TRUE(near.coversTarget(slantedChain(), 1e-9));
  ShadowedRows shortShadow(BandFrame{0, 8, 0});
  shortShadow.clearBehind(grooveUW(2, 0), grooveUW(3, 3), 1, 4);
  EXPECT_FALSE(shortShadow.coversTarget(slantedChain(), 1e-9)) << "a shadow short of the band's side: no bound";
}

TEST(ShadowedRows, RowsAboveASlantedMouthAreAir) {
  // The mouth w = 0.1u: the chain from (2, 0.2) on it down to the floor 3 deep and up to (6, 0.6).
  const std::vector<Point> chain{grooveUW(2, 0.2), grooveUW(3, 3), grooveUW(5, 3), grooveUW(6, 0.6)};
  ShadowedRows rows(BandFrame{0, 8, 0.1});
  rows.clearBehind(grooveUW(6, 0.6), grooveUW(5, 3), -1, 20);  // down the far flank, towards −u
  EXPECT_FALSE(rows.coversTarget(chain, 1e-9)) << "the rows from 0.2 to 0.6 hold material up to u = 10w";
  rows.clearBehind(grooveUW(6, 0.2), grooveUW(6, 0.6), -1, 20);
  EXPECT_TRUE(rows.coversTarget(chain, 1e-9)) << "above 0.2 the target's rows are air";
}

TEST(ShadowedRows, ARapidAlongThePecksBottomsOrBackUpAPeckCrossesNothing) {
  ShadowedRows rows(BandFrame{0, 8, 0});
  rows.clearBehind(grooveUW(1, 0), grooveUW(1, 2), -1, 20);
  rows.clearBehind(grooveUW(2, 0), grooveUW(2, 2), -1, 20);
  rows.clearBehind(grooveUW(1, 2), grooveUW(1, 4), -1, 20);  // the next layer's first peck
  EXPECT_TRUE(rows.clears(grooveUW(1, 2), grooveUW(2, 2), 1e-9)) << "along the first layer's bottom";
  EXPECT_FALSE(rows.clears(grooveUW(1, 2.5), grooveUW(2, 2.5), 1e-9)) << "half a millimetre below it";
  EXPECT_TRUE(rows.clears(grooveUW(1, 4), grooveUW(1, -1), 1e-9)) << "back up the peck and out";
  EXPECT_FALSE(rows.clears(grooveUW(1, 4), grooveUW(2, 0), 1e-9)) << "across the second peck's material";
}

}  // namespace
}  // namespace cyclecert
