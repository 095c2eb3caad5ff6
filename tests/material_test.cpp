// The oracles' material model (oracles/material): flattening arcs, shadows of feed moves, stocks,
// replaying moves, crossings of rapids, the part region and its erosion, thickness above a profile.
// Every expected number is worked out by hand in the comment beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/material.h"
#include "oracles/material_replay.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;
using std::numbers::pi;

Segment line(Point a, Point b) { return {SegmentKind::Line, a, b, {}, 0}; }
Segment arc(SegmentKind k, Point a, Point b, Point c) { return {k, a, b, c, 0}; }

double areaOf(const BgRegion& r) { return bg::area(r); }
bool inside(const BgRegion& r, Point p) { return bg::within(toBg(p), r); }

constexpr Point kOuter{0, 1};   // G71 outer turning: away from the part is +x
constexpr Point kBoring{0, -1};  // G71 boring: away is −x
constexpr Point kFacing{1, 0};   // G72 facing towards −z: away is +z

// Shoelace sum: negative for a clockwise ring in the plot (z right, x up).
double signedArea(const std::vector<Point>& ring) {
  double twice = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    twice += a.z * b.x - b.z * a.x;
  }
  return twice / 2;
}

// ---------------------------------------------------------------------------------------------
// flatten

TEST(Material, FlattenGivesALineItsTwoEndPoints) {
  const auto points = flatten(line({0, 10}, {-20, 15}), 0.01);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0], (Point{0, 10}));
  EXPECT_EQ(points[1], (Point{-20, 15}));
}

TEST(Material, FlattenKeepsEverySagittaWithinTheTolerance) {
  // Quarter circle r = 10 about the origin, (10, 0) → (0, 10), counter-clockwise. A chord of angle
  // φ has sagitta r(1 − cos(φ/2)); with tol = 0.01 the largest φ is 4·asin(√(tol/2r)) = 0.0894502,
  // so (π/2)/0.0894502 = 17.56 → 18 chords (19 points) of π/36 each, sagitta
  // 10(1 − cos(2.5°)) = 0.0095178; 17 chords would give 10(1 − cos(π/68)) = 0.01067 > tol.
  const Segment quarter = arc(SegmentKind::ArcCCW, {10, 0}, {0, 10}, {0, 0});
  const auto points = flatten(quarter, 0.01);
  ASSERT_EQ(points.size(), 19u);
  EXPECT_EQ(points.front(), quarter.from);  // ends exact, not recomputed
  EXPECT_EQ(points.back(), quarter.to);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(std::hypot(points[i].z, points[i].x), 10, 1e-12);  // every point on the arc
    if (i == 0) continue;
    const Point mid = 0.5 * (points[i - 1] + points[i]);
    const double sagitta = 10 - std::hypot(mid.z, mid.x);  // chord inside the arc
    EXPECT_NEAR(sagitta, 0.0095178, 1e-6);
    EXPECT_LE(sagitta, 0.01);
  }
}

TEST(Material, FlattenFollowsTheArcDirection) {
  // G02 from (−20, 5) to (−25, 10) about (−20, 10): clockwise from angle −90° through −135° to
  // −180°. r = 5, tol 0.001: φ ≤ 4·asin(0.01) = 0.0400007, (π/2)/0.0400007 = 39.27 → 40 chords; the
  // middle point (the 20th) is at −135°: (−20 − 5/√2, 10 − 5/√2) = (−23.5355, 6.4645).
  const auto points = flatten(arc(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10}), 0.001);
  ASSERT_EQ(points.size(), 41u);
  EXPECT_NEAR(points[20].z, -23.535534, 1e-6);
  EXPECT_NEAR(points[20].x, 6.464466, 1e-6);
}

TEST(Material, FlattenStaysOnTheArcOverThousandsOfChords) {
  // r = 100, tol 1e-6: φ ≤ 4·asin(√(1e-6/200)) = 2.828e-4, (π/2)/φ = 5,554 chords. Each point is
  // the one before turned by φ; the last interior point still stands where its angle says.
  const Segment quarter = arc(SegmentKind::ArcCCW, {100, 0}, {0, 100}, {0, 0});
  const auto points = flatten(quarter, 1e-6);
  ASSERT_EQ(points.size(), 5555u);
  const double step = (std::numbers::pi / 2) / 5554;
  for (std::size_t k = 0; k + 1 < points.size(); k += 500) {
    EXPECT_NEAR(points[k].z, 100 * std::cos(k * step), 1e-9);
    EXPECT_NEAR(points[k].x, 100 * std::sin(k * step), 1e-9);
  }
  EXPECT_NEAR(points[5553].z, 100 * std::cos(5553 * step), 1e-9);
  EXPECT_NEAR(points[5553].x, 100 * std::sin(5553 * step), 1e-9);
}

TEST(Material, FlattenCopesWithDegenerateArcs) {
  // No radius: the arc is a point; nothing to flatten but its two ends.
  const auto point = flatten(arc(SegmentKind::ArcCW, {1, 1}, {1, 1}, {1, 1}), 0.01);
  ASSERT_EQ(point.size(), 2u);
  EXPECT_EQ(point[0], (Point{1, 1}));
  // from == to with a radius is a full circle (geometry.h): r = 1, tol 0.01: φ ≤ 4·asin(√0.005)
  // = 0.282901, 2π/0.282901 = 22.2 → 23 chords, back to the start.
  const auto circle = flatten(arc(SegmentKind::ArcCCW, {1, 0}, {1, 0}, {0, 0}), 0.01);
  ASSERT_EQ(circle.size(), 24u);
  EXPECT_EQ(circle.front(), circle.back());
  // A tolerance above the diameter: one chord whatever the sweep.
  EXPECT_EQ(flatten(arc(SegmentKind::ArcCCW, {1, 0}, {-1, 0}, {0, 0}), 5).size(), 2u);
  EXPECT_THROW(flatten(arc(SegmentKind::ArcCCW, {1, 0}, {0, 1}, {0, 0}), 0), std::invalid_argument);
  EXPECT_THROW(flatten(line({NAN, 0}, {0, 1}), 0.01), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// regions

TEST(Material, RegionFromClosesAndOrientsClockwise) {
  // Counter-clockwise input, a repeated point and a collinear one: a 4 × 2 rectangle, area 8,
  // returned clockwise with the four corners only.
  const BgRegion r = regionFrom({{0, 0}, {4, 0}, {4, 0}, {4, 1}, {4, 2}, {0, 2}});
  EXPECT_DOUBLE_EQ(areaOf(r), 8);
  const auto outlines = outlinesOf(r);
  ASSERT_EQ(outlines.size(), 1u);
  EXPECT_EQ(outlines[0].size(), 4u);
  EXPECT_DOUBLE_EQ(signedArea(outlines[0]), -8);
}

TEST(Material, RegionFromRejectsASelfIntersectingOutline) {
  // A bow tie crosses itself at (1, 1).
  try {
    regionFrom({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not a simple polygon"), std::string::npos) << e.what();
  }
  EXPECT_THROW(regionFrom({{0, 0}, {1, NAN}, {1, 1}}), std::invalid_argument);
}

TEST(Material, RegionFromAnOutlineWithoutAreaIsEmpty) {
  EXPECT_TRUE(regionFrom({}).empty());
  EXPECT_TRUE(regionFrom({{0, 0}, {1, 1}}).empty());
  EXPECT_TRUE(regionFrom({{0, 0}, {1, 1}, {2, 2}}).empty());  // collinear
}

// ---------------------------------------------------------------------------------------------
// shadows

TEST(Material, ShadowOfACutAlongZIsARectangle) {
  // Outer turning: (0, 10) → (−20, 10) with reach 5 sweeps z ∈ [−20, 0], x ∈ [10, 15]: area 100.
  const BgRegion outer = shadowOf(line({0, 10}, {-20, 10}), kOuter, 5, 0.001);
  EXPECT_TRUE(bg::equals(outer, regionFrom({{0, 10}, {-20, 10}, {-20, 15}, {0, 15}})));
  EXPECT_DOUBLE_EQ(areaOf(outer), 100);
  // Boring: the shadow hangs below, x ∈ [5, 10].
  const BgRegion boring = shadowOf(line({0, 10}, {-20, 10}), kBoring, 5, 0.001);
  EXPECT_TRUE(bg::equals(boring, regionFrom({{0, 10}, {-20, 10}, {-20, 5}, {0, 5}})));
}

TEST(Material, ShadowOfASlantedLineIsAParallelogram) {
  // (0, 10) → (−20, 15): base 20 along z times reach 5 = area 100 either way.
  const Segment slant = line({0, 10}, {-20, 15});
  const BgRegion outer = shadowOf(slant, kOuter, 5, 0.001);
  EXPECT_TRUE(bg::equals(outer, regionFrom({{0, 10}, {-20, 15}, {-20, 20}, {0, 15}})));
  EXPECT_DOUBLE_EQ(areaOf(outer), 100);
  const BgRegion boring = shadowOf(slant, kBoring, 5, 0.001);
  EXPECT_TRUE(bg::equals(boring, regionFrom({{0, 10}, {-20, 15}, {-20, 10}, {0, 5}})));
  // G72: cut along x, shadow along +z. (−2, 20) → (−5, 5): base 15 along x times reach 4 = 60.
  const BgRegion facing = shadowOf(line({-2, 20}, {-5, 5}), kFacing, 4, 0.001);
  EXPECT_TRUE(bg::equals(facing, regionFrom({{-2, 20}, {-5, 5}, {-1, 5}, {2, 20}})));
  EXPECT_DOUBLE_EQ(areaOf(facing), 60);
}

TEST(Material, ShadowOfAMoveAlongTheDepthAxisIsEmpty) {
  EXPECT_TRUE(shadowOf(line({0, 20}, {0, 10}), kOuter, 5, 0.001).empty());  // an infeed
  EXPECT_TRUE(shadowOf(line({3, 3}, {3, 3}), kOuter, 5, 0.001).empty());    // no length
}

TEST(Material, ShadowOfAnArcTurningBackIsTheUnionOfItsPieces) {
  // Half circle r = 5 about (0, 15) on the −z side, (0, 10) → (−5, 15) → (0, 20), clockwise; it
  // turns back along z at (−5, 15). Over z ∈ [−5, 0] the rays cover from the lower half up to the
  // upper half + 100: area = half disk 25π/2 = 39.27 + 5 × 100 = 539.27, less the chords' error
  // (≤ arc length 15.7 × 0.001).
  const Segment half = arc(SegmentKind::ArcCW, {0, 10}, {0, 20}, {0, 15});
  const BgRegion shadow = shadowOf(half, kOuter, 100, 0.001);
  ASSERT_EQ(shadow.size(), 1u);
  EXPECT_NEAR(areaOf(shadow), 25 * pi / 2 + 500, 0.016);
  EXPECT_TRUE(inside(shadow, {-4.9, 15}));  // just inside the apex
  EXPECT_FALSE(inside(shadow, {-0.1, 9}));  // below the lower half
}

// ---------------------------------------------------------------------------------------------
// the model

// A bar Ø40 × 50 from z = 0: x ∈ [0, 20], z ∈ [−50, 0], area 1000.
MaterialModel barModel() { return MaterialModel(barStock(40, 50, 0), kOuter, 100, 0.001); }

TEST(Material, BarStockMinusOnePass) {
  MaterialModel model = barModel();
  EXPECT_DOUBLE_EQ(model.area(), 1000);
  // A pass at x = 18 from z = 2 to z = −30 removes z ∈ [−30, 0] × x ∈ [18, 20] = 30 × 2 = 60.
  model.apply(line({2, 18}, {-30, 18}), MoveKind::Feed);
  EXPECT_NEAR(model.area(), 940, 1e-5);
  // The same move as a rapid removes nothing (rapids are judged, not cut).
  model.apply(line({2, 16}, {-30, 16}), MoveKind::Rapid);
  EXPECT_NEAR(model.area(), 940, 1e-5);
}

TEST(Material, RemovedByAFirstPassIsPassLengthTimesDepth) {
  const MaterialModel model = barModel();
  // The pass runs 30 mm inside the bar (z from 0 to −30), 2 mm deep: 60; the model is unchanged.
  const BgRegion removed = model.removedBy(line({2, 18}, {-30, 18}));
  EXPECT_NEAR(areaOf(removed), 60, 1e-5);
  // The layer itself.
  EXPECT_NEAR(areaOf(without(removed, regionFrom({{0, 18}, {-30, 18}, {-30, 20}, {0, 20}}))), 0, 1e-9);
  EXPECT_DOUBLE_EQ(model.area(), 1000);
}

TEST(Material, ARapidThroughMaterialCrossesTheChordThroughIt) {
  const MaterialModel model = barModel();
  const double eps = 1e-3;
  // (4, 18) → (−16, 8): z = 4 − 20t, x = 18 − 10t enters the front face z = 0 at (0, 16) and ends
  // inside at (−16, 8): chord √(16² + 8²) = √320. The first ε along z lies within ε of the face:
  // ε·√(20² + 10²)/20 = ε·√5/2 of the move. Length √320 − ε√5/2 = 17.887236.
  const Crossing through = model.crossing(line({4, 18}, {-16, 8}), eps);
  EXPECT_NEAR(through.length, std::sqrt(320.0) - eps * std::sqrt(5.0) / 2, 1e-9);
  ASSERT_EQ(through.pieces.size(), 1u);
  EXPECT_NEAR(through.pieces[0].from.z, -eps, 1e-9);
  EXPECT_NEAR(through.pieces[0].from.x, 16 - eps / 2, 1e-9);
  EXPECT_EQ(through.pieces[0].to, (Point{-16, 8}));
  // Straight through the bar at z = −10, from x = 25 to x = −5: 20 mm inside, less ε at each face.
  EXPECT_NEAR(model.crossing(line({-10, 25}, {-10, -5}), eps).length, 20 - 2 * eps, 1e-9);
}

TEST(Material, ARapidGrazingOrAboveTheMaterialCrossesNothing) {
  const MaterialModel model = barModel();
  const double eps = 1e-3;
  EXPECT_EQ(model.crossing(line({5, 20 - eps / 2}, {-60, 20 - eps / 2}), eps).length, 0);  // ε/2 in
  EXPECT_EQ(model.crossing(line({5, 20}, {-60, 20}), eps).length, 0);                      // on it
  EXPECT_EQ(model.crossing(line({5, 21}, {-60, 21}), eps).length, 0);                      // above
  EXPECT_EQ(model.crossing(line({5, 25}, {0, 10}), eps).length, 0);  // ends on the front face
}

// ---------------------------------------------------------------------------------------------
// implied stock, part region

// G71 type I, outer turning: A = (2, 20), B = (2, 10), then (−10, 10), a taper to (−20, 15), and
// C = (−30, 15). The stock is z ∈ [−30, 2] × x ∈ [10, 20] = 320, less what lies under the shape
// above x = 10: the taper's triangle 10 × 5 / 2 = 25 and z ∈ [−30, −20] × [10, 15] = 50: 245.
const std::vector<Segment> kG71Shape = {line({2, 20}, {2, 10}), line({2, 10}, {-10, 10}),
                                        line({-10, 10}, {-20, 15}), line({-20, 15}, {-30, 15})};

TEST(Material, ImpliedStockOfATypeIG71Shape) {
  const BgRegion stock = impliedStock(kG71Shape, kOuter, 0.001);
  EXPECT_NEAR(areaOf(stock), 245, 1e-9);
  EXPECT_TRUE(inside(stock, {-25, 17}));
  EXPECT_FALSE(inside(stock, {-25, 14}));  // under the shape: the part
  EXPECT_FALSE(inside(stock, {3, 15}));    // beyond A along z
}

TEST(Material, ImpliedStockOfAShapeWithAnArc) {
  // As kG71Shape but a convex quarter round (−10, 10) → (−15, 15) about (−15, 10) (G03, r = 5)
  // and a flat (−15, 15) → (−30, 15). r = 5, tol 0.001: 40 chords of π/80 (FlattenFollows…). The
  // part under the round is their fan from the centre, 40 · r²/2 · sin(π/80) = 19.629908 (the
  // quarter disk: 19.634954; the chords lie inside the arc, so the stock is larger by 0.005 ≤ the
  // round's length 7.854 × tol). Stock = 320 − 75 − 19.629908 = 225.370092.
  const std::vector<Segment> shape = {line({2, 20}, {2, 10}), line({2, 10}, {-10, 10}),
                                      arc(SegmentKind::ArcCCW, {-10, 10}, {-15, 15}, {-15, 10}),
                                      line({-15, 15}, {-30, 15})};
  EXPECT_NEAR(areaOf(impliedStock(shape, kOuter, 0.001)), 320 - 75 - 500 * std::sin(pi / 80),
              1e-9);
}

TEST(Material, ImpliedStockOfAG72Shape) {
  // G72 facing: A = (2, 30), B = (−6, 30) (the infeed along z), then (−6, 20), a taper to (−2, 15),
  // C = (−2, 5); cut along x, away = +z. "Above C" is (2, 5). Rectangle z ∈ [−6, 2] × x ∈ [5, 30]
  // = 200, less z ∈ [−6, −2] × x ∈ [5, 15] = 40 and the taper's triangle 4 × 5 / 2 = 10: 150.
  const std::vector<Segment> shape = {line({2, 30}, {-6, 30}), line({-6, 30}, {-6, 20}),
                                      line({-6, 20}, {-2, 15}), line({-2, 15}, {-2, 5})};
  const BgRegion stock = impliedStock(shape, kFacing, 0.001);
  EXPECT_NEAR(areaOf(stock), 150, 1e-9);
  EXPECT_TRUE(inside(stock, {0, 10}));
  EXPECT_FALSE(inside(stock, {-4, 10}));
}

// The rough profile of kG71Shape with Δu/2 = 0.5, from B' = (2, 10.5) to C' = (−30, 15.5).
const std::vector<Segment> kRough = {line({2, 10.5}, {-10, 10.5}), line({-10, 10.5}, {-20, 15.5}),
                                     line({-20, 15.5}, {-30, 15.5})};

// The stock a cycle implies: between its start level and the shape, over the shape's span.
TEST(Material, ImpliedStockIsBetweenTheStartLevelAndTheShape) {
  // A at x 20; the shape (outer, cutting towards −z) down the wall at z 2 to x 10, along to z −10,
  // then a bump: the upper half of the circle of radius 5 about (−15, 10), to z −20, then along
  // x 10 to z −30. Under x 20 over z [−30, 2]: 32 × 10 = 320, less the bump's half disc, 25π/2.
  CycleSpec c;
  c.code = "G71";
  c.start = {2, 20};
  c.shape = {line({2, 20}, {2, 10}), line({2, 10}, {-10, 10}), arc(SegmentKind::ArcCCW, {-10, 10}, {-20, 10}, {-15, 10}),
             line({-20, 10}, {-30, 10})};
  ASSERT_NEAR(pointAt(c.shape[2], 0.5).x, 15, 1e-12);  // the upper half
  const BgRegion stock = impliedStockOf(c, kOuter, 100, 1e-4);
  EXPECT_NEAR(bg::area(stock), 320 - 12.5 * std::numbers::pi, 1e-2);
  EXPECT_TRUE(bg::within(toBg({-15, 16}), stock));
  EXPECT_FALSE(bg::within(toBg({-15, 14}), stock));
  // A start level of 14 leaves the bump's top (x 15) standing through it: the stock falls in two,
  // one each side of the bump — the arc's top counts, not only its ends (both at x 10). Each side:
  c.start = {2, 14};
  c.shape.front() = line({2, 14}, {2, 10});
  const BgRegion split = impliedStockOf(c, kOuter, 100, 1e-4);
  EXPECT_EQ(split.size(), 2u);
  EXPECT_FALSE(bg::within(toBg({-15, 14.5}), split));
  EXPECT_TRUE(bg::within(toBg({-25, 12}), split));
}

TEST(Material, PartRegionAndItsErosion) {
  // Reach 5 below the deepest profile point (10.5): bottom x = 5.5. Area over z ∈ [−30, 2]:
  // 32 × 5 = 160 up to x = 10.5, plus the taper's 25 and the flat's 10 × 5 = 50 above it: 235.
  const BgRegion part = partRegion(kRough, kOuter, 5, 0.001);
  EXPECT_NEAR(areaOf(part), 235, 1e-9);
  // Perimeter P = 12 + √125 + 10 + 10 + 32 + 5 = 80.180340. Eroding by ε = 0.1 leaves
  // A − Pε + ε²(Σ cot(θ/2) over convex corners − Σ α/2 over reflex ones): four right angles
  // (1 each), 153.43° at (−20, 15.5) (cot 76.72° = √5 − 2 = 0.236068), and the reflex corner at
  // (−10, 10.5) turning by α = atan(1/2) = 0.463648:
  // 235 − 8.018034 + 0.01 · (4.236068 − 0.231824) = 227.022008.
  const BgRegion core = eroded(part, 0.1);
  EXPECT_NEAR(areaOf(core), 227.022008, 1e-4);
  EXPECT_FALSE(inside(core, {-5, 10.45}));  // 0.05 below the profile: within ε
  EXPECT_TRUE(inside(core, {-5, 10.35}));
  EXPECT_TRUE(eroded(part, 10).empty());  // nothing is 10 mm inside a 5 mm band… and more
  // The same verdict without a buffer: a move along the profile does not enter the part, one
  // 0.2 below it from z = −2 to z = −8 does, by its whole 6 mm.
  EXPECT_EQ(crossingOf(part, line({2, 10.5}, {-10, 10.5}), 0.1, 0.001).length, 0);
  EXPECT_NEAR(crossingOf(part, line({-2, 10.3}, {-8, 10.3}), 0.1, 0.001).length, 6, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// thickness

TEST(Material, ThickestAboveASingleLeftoverStep) {
  // What a pass at x = 15.5 (to z = −20) and one at x = 13 (to z = −15) leave above the taper of
  // kRough between them: the triangle (−15, 13), (−15, 15.5), (−20, 15.5). Its top right corner
  // stands 15.5 − 13 = 2.5 above the taper (x = 13 at z = −15); the other corners lie on it.
  // thickestAbove takes the profile beneath a point at its highest within ± w = 2·tol (+ 2e-6,
  // the resolution for a region of size 5), and the taper rises 0.5 per mm away from the corner:
  // 2.5 − 0.5 · 0.002 = 2.499, measured against the taper at z = −15.002.
  const BgRegion step = regionFrom({{-15, 13}, {-15, 15.5}, {-20, 15.5}});
  const auto t = thickestAbove(step, kRough, kOuter, 0.001);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->thickness, 2.499, 1e-5);
  EXPECT_EQ(t->where, (Point{-15, 15.5}));
  EXPECT_NEAR(t->beneath.x, 13.001, 1e-5);
  // With a finer tolerance the window, and the difference, shrink: 2.5 − 0.5 · 2e-6.
  EXPECT_NEAR(thickestAbove(step, kRough, kOuter, 1e-6)->thickness, 2.5, 1e-5);
}

TEST(Material, ThickestAboveMeasuresAnArcExactly) {
  // A hollow in the profile: the lower half of the circle about (z 0, x 10) of radius 5, from
  // z −5 to z 5 through (0, 5). Material up to x 8 over it stands thickest where the hollow is
  // deepest, 8 − 5 = 3 at z 0 — inside the arc, not at either end of it (where the arc meets x 10
  // and the material stands beneath it): found where the arc's tangent is parallel to the top.
  const Segment hollow = arc(SegmentKind::ArcCCW, {-5, 10}, {5, 10}, {0, 10});
  ASSERT_NEAR(pointAt(hollow, 0.5).x, 5, 1e-12);
  const BgRegion block = regionFrom({{-5, 4}, {-5, 8}, {5, 8}, {5, 4}});
  const auto t = thickestAbove(block, {hollow}, kOuter, 1e-6);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->thickness, 3, 1e-9);
  EXPECT_NEAR(t->where.z, 0, 1e-9);
  EXPECT_NEAR(t->beneath.x, 5, 1e-9);
  // The same measured on the top alone (thickestBeneath), and on a top sloping 1 in 10: 8 − z/10
  // over the circle 10 − √(25 − z²) stands highest where the circle's slope is −1/10,
  // z = −5 / √101, at 8 + 0.5/√101 − 10 + 5·10/√101 = √101/2 − 2 = 3.0249… (less the window's
  // due: the circle there rises 0.1 per mm, and beneath is its highest within ± w ≈ 6e-6).
  const auto flat = thickestBeneath({{-5, 8, 5, 8}}, {hollow}, kOuter, 1e-6);
  ASSERT_TRUE(flat);
  EXPECT_NEAR(flat->thickness, 3, 1e-9);
  const auto sloped = thickestBeneath({{-5, 8.5, 5, 7.5}}, {hollow}, kOuter, 1e-6);
  ASSERT_TRUE(sloped);
  EXPECT_NEAR(sloped->thickness, std::sqrt(101.0) / 2 - 2, 1e-6);
  EXPECT_NEAR(sloped->where.z, -5 / std::sqrt(101.0), 1e-9);
}

TEST(Material, StandsThickerThanFindsWhatStandsOffTheStepsItSkips) {
  // A flat (x 10 from z −10 to −5) and a bump on it (the upper half of the circle about (z 0,
  // x 10) of radius 5). A top along their chords stands nowhere above them (a chord of the bump
  // lies inside the circle): the search skips its points from each step alone (thickness.cpp,
  // cannotBeatAt). A chord raised near the bump's apex, or a piece raised over the flat, stands
  // above its step there: measured as before.
  const Segment flat = line({-10, 10}, {-5, 10});
  const Segment bump = arc(SegmentKind::ArcCW, {-5, 10}, {5, 10}, {0, 10});
  ASSERT_NEAR(pointAt(bump, 0.5).x, 15, 1e-12);
  const std::vector<Segment> profile{flat, bump};
  std::vector<CutEnvelope::Piece> top;
  for (const Segment& s : profile) {
    const std::vector<Point> chords = flatten(s, 0.001);
    for (std::size_t i = 1; i < chords.size(); ++i) top.push_back({chords[i - 1].z, chords[i - 1].x, chords[i].z, chords[i].x});
  }
  EXPECT_FALSE(standsThickerThan(top, profile, kOuter, 1e-6, 0.01));
  std::vector<CutEnvelope::Piece> raisedAtTheApex = top;
  for (CutEnvelope::Piece& p : raisedAtTheApex) {
    if (p.c0 <= 0 && p.c1 > 0) {
      p.d0 += 0.05;
      p.d1 += 0.05;
    }
  }
  EXPECT_TRUE(standsThickerThan(raisedAtTheApex, profile, kOuter, 1e-6, 0.01));
  const auto atTheApex = thickestBeneath(raisedAtTheApex, profile, kOuter, 1e-6);
  ASSERT_TRUE(atTheApex);
  EXPECT_NEAR(atTheApex->thickness, 0.05, 1e-4);
  EXPECT_NEAR(atTheApex->where.z, 0, 0.2);
  std::vector<CutEnvelope::Piece> raisedOverTheFlat = top;
  raisedOverTheFlat.front() = {-10, 10, -8, 10};
  raisedOverTheFlat.insert(raisedOverTheFlat.begin() + 1, {{-8, 10.02, -7, 10.02}, {-7, 10, -5, 10}});
  EXPECT_TRUE(standsThickerThan(raisedOverTheFlat, profile, kOuter, 1e-6, 0.01));
  EXPECT_FALSE(standsThickerThan(raisedOverTheFlat, profile, kOuter, 1e-6, 0.03));
  const auto overTheFlat = thickestBeneath(raisedOverTheFlat, profile, kOuter, 1e-6);
  ASSERT_TRUE(overTheFlat);
  EXPECT_NEAR(overTheFlat->thickness, 0.02, 1e-9);
}

TEST(Material, ThickestAboveReplayedPassesIsTheDepthOfCut) {
  // The three passes of the type I test below (x = 18 to z = −30, 15.5 to −20, 13 to −15)
  // replayed on the implied stock of kG71Shape, without the semi-finish pass. Above the rough
  // profile there remain: the layer x ∈ [10.5, 13] over z ∈ [−10, 2] (12 × 2.5 = 30), the triangle
  // under x = 13 down to the taper (5 × 2.5 / 2 = 6.25), the triangle of the test above (6.25) and
  // the layer x ∈ [15.5, 18] over z ∈ [−30, −20] (10 × 2.5 = 25): 67.5, all 2.5 thick at most.
  MaterialModel model(impliedStock(kG71Shape, kOuter, 0.001), kOuter, 50, 0.001);
  model.apply(line({2, 18}, {-30, 18}), MoveKind::Feed);
  model.apply(line({2, 15.5}, {-20, 15.5}), MoveKind::Feed);
  model.apply(line({2, 13}, {-15, 13}), MoveKind::Feed);
  const BgRegion beyond = without(model.remaining(), partRegion(kRough, kOuter, 50, 0.001));
  EXPECT_NEAR(areaOf(beyond), 67.5, 1e-4);
  const auto t = thickestAbove(beyond, kRough, kOuter, 0.001);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->thickness, 2.5, 1e-6);
}

TEST(Material, ThicknessBesideAShoulderIsMeasuredFromTheStepBelow) {
  // Profile: x = 10 for z ∈ [−10, 0], a shoulder up to x = 15 at z = −10, x = 15 beyond.
  const std::vector<Segment> profile = {line({0, 10}, {-10, 10}), line({-10, 10}, {-10, 15}),
                                        line({-10, 15}, {-20, 15})};
  // A wedge left against the shoulder on the low step: its corner (−10, 12) is 2 above x = 10
  // (the shoulder wall is not "beneath" it).
  const BgRegion wedgeRegion = regionFrom({{-10, 10}, {-10, 12}, {-7, 10}});
  const auto wedge = thickestAbove(wedgeRegion, profile, kOuter, 0.001);
  ASSERT_TRUE(wedge);
  EXPECT_NEAR(wedge->thickness, 2, 1e-12);
  EXPECT_EQ(wedge->where, (Point{-10, 12}));
  // A block on the high step against the shoulder's top: 1 above x = 15, not 6 above x = 10.
  const BgRegion blockRegion = regionFrom({{-12, 15}, {-12, 16}, {-10, 16}, {-10, 15}});
  const auto block = thickestAbove(blockRegion, profile, kOuter, 0.001);
  ASSERT_TRUE(block);
  EXPECT_NEAR(block->thickness, 1, 1e-12);
}

TEST(Material, ThicknessOverANotchIsMeasuredAtItsBottom) {
  // A V notch (0, 10) → (−5, 8) → (−10, 10) under a layer up to x = 11: 11 − 8 = 3 at z = −5,
  // although every vertex of the layer is only 1 above the profile. (Less the window allowance:
  // slope 0.4 × w = 0.002 + 4e-6: 2.9992.)
  const std::vector<Segment> profile = {line({0, 10}, {-5, 8}), line({-5, 8}, {-10, 10})};
  const BgRegion layer = regionFrom({{0, 10}, {-5, 8}, {-10, 10}, {-10, 11}, {0, 11}});
  const auto t = thickestAbove(layer, profile, kOuter, 0.001);
  ASSERT_TRUE(t);
  EXPECT_NEAR(t->thickness, 2.9992, 1e-5);
  EXPECT_NEAR(t->where.z, -5, 1e-12);
  EXPECT_NEAR(t->where.x, 11, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// a whole type I cycle

TEST(Material, TypeIPassesAndSemiFinishLeaveOnlyTheAllowance) {
  // kG71Shape with Δu/2 = 0.5, Δw = 0, Δd = 2.5, e = 0.5, A = (2, 20), A' = (2, 20.5).
  // Levels 20.5 − 2.5k strictly between A' and B' (10.5): 18, 15.5, 13. Each cut ends where the
  // rough profile first reaches its level walking from B' — never for 18 (cut to C'.z = −30),
  // (−20, 15.5) for 15.5, and on the taper x = 10.5 + (−10 − z)/2 = 13 at z = −15 for 13 —
  // then a 45° retract by e, a rapid back to z = 2, an infeed of Δd + e; from 13.5 the next level
  // 10.5 is B' itself: infeed to B', the semi-finish pass along the rough profile, and the return.
  struct Step { MoveKind kind; Point to; };
  const std::vector<Step> path = {
      {MoveKind::Rapid, {2, 20.5}},     {MoveKind::Rapid, {2, 18}},    // A → A', infeed
      {MoveKind::Feed, {-30, 18}},      {MoveKind::Feed, {-29.5, 18.5}},
      {MoveKind::Rapid, {2, 18.5}},     {MoveKind::Rapid, {2, 15.5}},
      {MoveKind::Feed, {-20, 15.5}},    {MoveKind::Feed, {-19.5, 16}},
      {MoveKind::Rapid, {2, 16}},       {MoveKind::Rapid, {2, 13}},
      {MoveKind::Feed, {-15, 13}},      {MoveKind::Feed, {-14.5, 13.5}},
      {MoveKind::Rapid, {2, 13.5}},     {MoveKind::Rapid, {2, 10.5}},  // to B'
      {MoveKind::Feed, {-10, 10.5}},    {MoveKind::Feed, {-20, 15.5}},
      {MoveKind::Feed, {-30, 15.5}},                                   // semi-finish to C'
      {MoveKind::Rapid, {-30, 20}},     {MoveKind::Rapid, {2, 20}}};   // return to A
  MaterialModel model(impliedStock(kG71Shape, kOuter, 0.001), kOuter, 50, 0.001);
  Point at{2, 20};
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Segment move = line(at, path[i].to);
    // Every rapid runs in air or along the stock's edge (the infeeds at z = 2): no crossing.
    if (path[i].kind == MoveKind::Rapid) {
      EXPECT_EQ(model.crossing(move, 1e-3).length, 0) << "move " << i;
    }
    model.apply(move, path[i].kind);
    at = path[i].to;
  }
  // Left: the allowance band, 0.5 thick along x over z ∈ [−30, 2]: 32 × 0.5 = 16.
  EXPECT_NEAR(model.area(), 16, 1e-5);
  const BgRegion beyond = without(model.remaining(), partRegion(kRough, kOuter, 50, 0.001));
  const auto t = thickestAbove(beyond, kRough, kOuter, 0.001);
  EXPECT_LE(t ? t->thickness : 0.0, 1e-6);
  // The same measured on what remains, without subtracting the part region first.
  const auto direct = thickestAbove(model.remaining(), kRough, kOuter, 0.001);
  EXPECT_LE(direct ? direct->thickness : 0.0, 1e-6);
}

TEST(Material, TypeIAlongAFilletLeavesOnlyTheAllowance) {
  // As above with a concave fillet: B = (2, 10), (−5, 10), G02 to (−10, 15) about (−5, 15), then
  // C = (−30, 15). Rough profile (Δu/2 = 0.5): the fillet about (−5, 15.5) from (−5, 10.5) to
  // (−10, 15.5), where its tangent is parallel to x. Levels 18, 15.5, 13: 18 is never reached (cut
  // to −30); 15.5 first at the fillet's end (−10, 15.5); 13 on the fillet where
  // 15.5 − √(25 − (z + 5)²) = 13: z = −5 − √18.75 = −9.330127. The fillet is flattened alike in
  // the stock and the semi-finish pass (the same arc, translated), so what remains is the band 0.5
  // thick along x: 32 × 0.5 = 16 again. Above the exact rough profile stand only the slivers between
  // the fillet and the pass's chords: no thicker than their sagitta, the chord tolerance 0.001.
  const std::vector<Segment> shape = {line({2, 20}, {2, 10}), line({2, 10}, {-5, 10}),
                                      arc(SegmentKind::ArcCW, {-5, 10}, {-10, 15}, {-5, 15}),
                                      line({-10, 15}, {-30, 15})};
  const std::vector<Segment> rough = {line({2, 10.5}, {-5, 10.5}),
                                      arc(SegmentKind::ArcCW, {-5, 10.5}, {-10, 15.5}, {-5, 15.5}),
                                      line({-10, 15.5}, {-30, 15.5})};
  const double z13 = -5 - std::sqrt(18.75);
  struct Step { MoveKind kind; Segment move; };
  const std::vector<Step> path = {
      {MoveKind::Rapid, line({2, 20}, {2, 20.5})},
      {MoveKind::Rapid, line({2, 20.5}, {2, 18})},
      {MoveKind::Feed, line({2, 18}, {-30, 18})},
      {MoveKind::Feed, line({-30, 18}, {-29.5, 18.5})},
      {MoveKind::Rapid, line({-29.5, 18.5}, {2, 18.5})},
      {MoveKind::Rapid, line({2, 18.5}, {2, 15.5})},
      {MoveKind::Feed, line({2, 15.5}, {-10, 15.5})},
      {MoveKind::Feed, line({-10, 15.5}, {-9.5, 16})},
      {MoveKind::Rapid, line({-9.5, 16}, {2, 16})},
      {MoveKind::Rapid, line({2, 16}, {2, 13})},
      {MoveKind::Feed, line({2, 13}, {z13, 13})},
      {MoveKind::Feed, line({z13, 13}, {z13 + 0.5, 13.5})},
      {MoveKind::Rapid, line({z13 + 0.5, 13.5}, {2, 13.5})},
      {MoveKind::Rapid, line({2, 13.5}, {2, 10.5})},
      {MoveKind::Feed, rough[0]},                     {MoveKind::Feed, rough[1]},
      {MoveKind::Feed, rough[2]},
      {MoveKind::Rapid, line({-30, 15.5}, {-30, 20})}, {MoveKind::Rapid, line({-30, 20}, {2, 20})}};
  MaterialModel model(impliedStock(shape, kOuter, 0.001), kOuter, 50, 0.001);
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (path[i].kind == MoveKind::Rapid) {
      EXPECT_EQ(model.crossing(path[i].move, 1e-3 + 0.001).length, 0) << "move " << i;
    }
    model.apply(path[i].move, path[i].kind);
  }
  EXPECT_NEAR(model.area(), 16, 1e-5);
  const auto t = thickestAbove(model.remaining(), rough, kOuter, 0.001);
  EXPECT_LE(t ? t->thickness : 0.0, 0.001);
}

// ---------------------------------------------------------------------------------------------
// degenerate input

TEST(Material, DegenerateMovesAndStocksNeitherCrashNorProduceNaN) {
  MaterialModel model = barModel();
  const Segment still = line({-5, 10}, {-5, 10});
  const Segment dot = arc(SegmentKind::ArcCW, {-5, 10}, {-5, 10}, {-5, 10});
  for (const Segment& s : {still, dot}) {
    model.apply(s, MoveKind::Feed);
    EXPECT_EQ(model.crossing(s, 1e-3).length, 0);
    EXPECT_TRUE(model.removedBy(s).empty());
    EXPECT_TRUE(shadowOf(s, kOuter, 10, 0.001).empty());
  }
  EXPECT_DOUBLE_EQ(model.area(), 1000);

  MaterialModel empty(BgRegion{}, kOuter, 100, 0.001);
  empty.apply(line({0, 10}, {-10, 10}), MoveKind::Feed);
  EXPECT_EQ(empty.area(), 0);
  EXPECT_EQ(empty.crossing(line({0, 10}, {-10, 5}), 1e-3).length, 0);
  EXPECT_TRUE(empty.removedBy(line({0, 10}, {-10, 10})).empty());
  EXPECT_TRUE(barStock(0, 10, 0).empty());
  EXPECT_TRUE(impliedStock({}, kOuter, 0.001).empty());
  EXPECT_TRUE(partRegion({}, kOuter, 5, 0.001).empty());
  EXPECT_TRUE(eroded(BgRegion{}, 0.1).empty());
  EXPECT_FALSE(thickestAbove(BgRegion{}, kRough, kOuter, 0.001));
  EXPECT_THROW(MaterialModel(BgRegion{}, {0, 0}, 1, 0.001), std::invalid_argument);
}

}  // namespace
}  // namespace cyclecert
