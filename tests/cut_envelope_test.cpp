// The feeds' envelope (oracles/material/cut_envelope.h) and the material model built on it: the
// envelope is the lower envelope of the feeds' paths, worked out by hand below; and the model's
// material equals the stock minus the union of the feeds' shadows taken with Boost's booleans, the
// definition it replaces, on random feeds (RapidCheck).
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/material.h"
#include "oracles/material_replay.h"
#include "reference/model/offset.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

constexpr Point kOuter{0, 1};  // G71 outer turning: depth = x, cut = z

Segment line(Point a, Point b) { return {SegmentKind::Line, a, b, {}, 0}; }

double distanceToBoundary(const BgRegion& region, Point p) {
  double nearest = INFINITY;
  for (const auto& ring : outlinesOf(region)) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      nearest = std::min(nearest, distanceToSegment(p, line(ring[i], ring[(i + 1) % ring.size()])));
    }
  }
  return nearest;
}

TEST(CutEnvelope, TheLowerOfTwoFeedsWinsAndTheyCrossWhereTheirLinesMeet) {
  const DepthFrame frame(kOuter);
  CutEnvelope e;
  // A flat feed at x 10 over z ∈ [−20, 0], then a taper from x 12 at z 0 down to x 8 at z −20:
  // x = 12 + 0.2·z is lower than 10 for z < −10. Pieces run along z: the taper on [−20, −10]
  // (8 to 10), then the flat feed on [−10, 0].
  EXPECT_TRUE(e.lower({{0, 10}, {-20, 10}}, frame));
  EXPECT_TRUE(e.lower({{0, 12}, {-20, 8}}, frame));
  ASSERT_EQ(e.pieces().size(), 2u);
  EXPECT_NEAR(e.pieces()[0].c0, -20, 1e-12);
  EXPECT_NEAR(e.pieces()[0].d0, 8, 1e-12);
  EXPECT_NEAR(e.pieces()[0].c1, -10, 1e-12);
  EXPECT_NEAR(e.pieces()[0].d1, 10, 1e-12);
  EXPECT_NEAR(e.pieces()[1].c1, 0, 1e-12);
  EXPECT_NEAR(e.pieces()[1].d1, 10, 1e-12);
  // Retracing the flat feed lowers nothing; a feed along the depth axis removes nothing.
  EXPECT_FALSE(e.lower({{0, 10}, {-10, 10}}, frame));
  EXPECT_FALSE(e.lower({{-5, 30}, {-5, 0}}, frame));
}

TEST(CutEnvelope, AWalkMeetsEachPieceOverTheSpanAndEachStretchNoFeedCovers) {
  const DepthFrame frame(kOuter);
  CutEnvelope e;
  e.lower({{0, 10}, {-10, 10}}, frame);   // z [−10, 0] at 10
  e.lower({{-10, 9}, {-20, 11}}, frame);  // z [−20, −10] from 11 (at −20) to 9 (at −10)
  std::vector<CutEnvelope::Piece> pieces;
  std::vector<std::pair<double, double>> gaps;
  const auto walk = [&](double c0, double c1) {
    pieces.clear();
    gaps.clear();
    e.walk(c0, c1, [&](const CutEnvelope::Piece& p) { pieces.push_back(p); },
           [&](double g0, double g1) { gaps.push_back({g0, g1}); });
  };
  walk(-20, 0);
  EXPECT_TRUE(gaps.empty());
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_NEAR(pieces[0].d0, 11, 1e-12);  // the deepest over the span
  EXPECT_NEAR(pieces[1].d1, 10, 1e-12);
  walk(-15, 0);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_NEAR(pieces[0].c0, -15, 1e-12);  // cut to the span: 10 at z −15
  EXPECT_NEAR(pieces[0].d0, 10, 1e-12);
  walk(-25, -15);  // beyond z −20 no feed has been
  ASSERT_EQ(gaps.size(), 1u);
  EXPECT_NEAR(gaps[0].first, -25, 1e-12);
  EXPECT_NEAR(gaps[0].second, -20, 1e-12);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_NEAR(pieces[0].d1, 10, 1e-12);
}

TEST(CutEnvelope, BelowIsTheBoxUnderTheEnvelope) {
  const DepthFrame frame(kOuter);
  CutEnvelope e;
  e.lower({{-5, 10}, {-15, 10}}, frame);  // z [−15, −5] at depth 10
  // Box z [−20, 0] × depth [0, 20]: 400, less the 10 × 10 above the feed.
  const BgRegion below = e.below(frame, -20, 0, 0, 20);
  EXPECT_NEAR(bg::area(below), 300, 1e-9);
  EXPECT_TRUE(bg::within(toBg({-10, 9}), below));
  EXPECT_FALSE(bg::within(toBg({-10, 11}), below));
  EXPECT_TRUE(bg::within(toBg({-2, 19}), below));  // beside the feed the box stands full
}

TEST(CutEnvelope, TheModelsTopBoundsTheLayerAFeedRemoves) {
  // A first pass 2 mm into a bar of radius 20: the layer it removes is 2 mm thick, and the top
  // (the stock's, before any feed) measured against the pass says so; a second pass 2 mm lower
  // stands 2 below the first pass's envelope. How the depth-per-pass oracle spares measuring the
  // material left (material_replay.cpp).
  MaterialModel model(barStock(40, 50, 0), kOuter, 100, 0.001);
  const auto layer = [&](const Segment& move) {
    const double c0 = std::min(move.from.z, move.to.z), c1 = std::max(move.from.z, move.to.z);
    return thickestBeneath(model.topWithin(c0, c1), {move}, kOuter, 1e-6);
  };
  const Segment first = line({2, 18}, {-30, 18});
  EXPECT_NEAR(layer(first)->thickness, 2, 1e-12);
  model.apply(first, MoveKind::Feed);
  EXPECT_NEAR(layer(line({2, 16}, {-30, 16}))->thickness, 2, 1e-12);
  // Where no feed has been beyond z −30, the stock's top: 20 − 16.
  EXPECT_NEAR(layer(line({2, 16}, {-40, 16}))->thickness, 4, 1e-12);
  // A move along the depth axis is beneath nothing.
  EXPECT_FALSE(layer(line({-35, 19}, {-35, 10})).has_value());
}

TEST(CutEnvelope, TheModelsTopIsTheEnvelopeCappedByTheStock) {
  // A bar of radius 20 over z [−50, 0]; a feed at x 18 over z [−30, −10], and one rising from x 15
  // at z −45 to x 25 at z −35 (above the bar from z −40 on). The top over z [−50, 0]: the bar's
  // 20 where no feed has been, the feeds' depths, and the rising feed capped at 20.
  MaterialModel model(barStock(40, 50, 0), kOuter, 100, 0.001);
  model.apply(line({-10, 18}, {-30, 18}), MoveKind::Feed);
  model.apply(line({-45, 15}, {-35, 25}), MoveKind::Feed);
  const auto top = model.topWithin(-50, 0);
  ASSERT_EQ(top.size(), 6u);
  const auto expectPiece = [](const CutEnvelope::Piece& p, double c0, double d0, double c1, double d1) {
    EXPECT_NEAR(p.c0, c0, 1e-9);
    EXPECT_NEAR(p.d0, d0, 1e-9);
    EXPECT_NEAR(p.c1, c1, 1e-9);
    EXPECT_NEAR(p.d1, d1, 1e-9);
  };
  expectPiece(top[0], -50, 20, -45, 20);  // no feed: the bar's top
  expectPiece(top[1], -45, 15, -40, 20);  // the rising feed, to where it meets the bar's top
  expectPiece(top[2], -40, 20, -35, 20);  // … and capped beyond
  expectPiece(top[3], -35, 20, -30, 20);
  expectPiece(top[4], -30, 18, -10, 18);
  expectPiece(top[5], -10, 20, 0, 20);
}

// A stock whose top slopes: x 20 at z −40 rising to x 24 at z 0 (1 in 10), down to the axis.
BgRegion slopedStock() { return polygonStock({{-40, 0}, {-40, 20}, {0, 24}, {0, 0}}); }

TEST(CutEnvelope, TheTopWithoutSkinsFollowsTheStocksOwnTop) {
  // No feed yet: topWithin takes the stock's highest point over the range (x 23 at z −10), the top
  // without skins the sloping top itself — and, without skins 1 mm wide, the lowest of it within
  // ± 1 mm: 0.1 lower.
  MaterialModel model(slopedStock(), kOuter, 100, 0.001);
  const auto flat = model.topWithin(-30, -10);
  ASSERT_EQ(flat.size(), 1u);
  EXPECT_NEAR(flat[0].d0, 23, 1e-9);
  EXPECT_NEAR(flat[0].d1, 23, 1e-9);
  const auto sloping = *model.topWithoutSkinsWithin(-30, -10, 0);
  ASSERT_EQ(sloping.size(), 1u);
  EXPECT_NEAR(sloping[0].c0, -30, 1e-9);
  EXPECT_NEAR(sloping[0].d0, 21, 1e-9);
  EXPECT_NEAR(sloping[0].c1, -10, 1e-9);
  EXPECT_NEAR(sloping[0].d1, 23, 1e-9);
  const auto solid = *model.topWithoutSkinsWithin(-30, -10, 1);
  ASSERT_EQ(solid.size(), 1u);
  EXPECT_NEAR(solid[0].d0, 20.9, 1e-9);
  EXPECT_NEAR(solid[0].d1, 22.9, 1e-9);
  // Beyond the stock's end nothing stands: the top stops at z 0.
  const auto end = *model.topWithoutSkinsWithin(-5, 5, 0);
  ASSERT_FALSE(end.empty());
  EXPECT_NEAR(end.back().c1, 0, 1e-9);
}

TEST(CutEnvelope, TheTopWithoutSkinsTakesTheLowestWithinTheSkinOfAFeed) {
  // A feed at x 21 over z [−25, −15] under the sloping top: the top is the feed there, the stock
  // beside it; without skins 1 mm wide the feed's depth reaches 1 mm further each way.
  MaterialModel model(slopedStock(), kOuter, 100, 0.001);
  model.apply(line({-15, 21}, {-25, 21}), MoveKind::Feed);
  const auto depthAt = [](const std::vector<CutEnvelope::Piece>& top, double c) -> double {
    for (const CutEnvelope::Piece& p : top) {
      if (c >= p.c0 && c <= p.c1) return p.depthAt(c);
    }
    return -INFINITY;
  };
  const auto top = *model.topWithoutSkinsWithin(-35, -5, 0);
  EXPECT_NEAR(depthAt(top, -30), 21, 1e-9);
  EXPECT_NEAR(depthAt(top, -25.5), 21.45, 1e-9);
  EXPECT_NEAR(depthAt(top, -20), 21, 1e-9);
  EXPECT_NEAR(depthAt(top, -10), 23, 1e-9);
  const auto solid = *model.topWithoutSkinsWithin(-35, -5, 1);
  EXPECT_NEAR(depthAt(solid, -30), 20.9, 1e-9);   // the stock 1 mm to the left
  EXPECT_NEAR(depthAt(solid, -25.5), 21, 1e-9);   // the feed, 0.5 mm to the right
  EXPECT_NEAR(depthAt(solid, -14.5), 21, 1e-9);   // the feed, 0.5 mm to the left
  EXPECT_NEAR(depthAt(solid, -13.5), 22.55, 1e-9);  // the stock 1 mm to the left
}

// The top without skins bounds the material left without skins (withoutSkins, Boost) above a
// profile that is a graph over the cut axis, on random feeds over a stock whose top slopes: the
// material measures no thicker than the top but for the booleans' noise (µm), so that
// mayStandThickerWithoutSkins (which spares the oracles that measure) never hides a layer.
RC_GTEST_PROP(CutEnvelope, TheTopWithoutSkinsBoundsTheMaterialWithoutSkins, ()) {
  const std::vector<Segment> profile = {line({0, 12}, {-10, 12}), line({-10, 12}, {-10, 14}),
                                        {SegmentKind::ArcCW, {-10, 14}, {-20, 14}, {-15, 14}, 0},
                                        line({-20, 14}, {-40, 16})};
  MaterialModel model(slopedStock(), kOuter, 100, 0.001);
  const int feeds = *rc::gen::inRange(0, 8);
  for (int i = 0; i < feeds; ++i) {
    const Point a{-*rc::gen::inRange(0, 400) / 10.0, *rc::gen::inRange(90, 250) / 10.0};
    const Point b{-*rc::gen::inRange(0, 400) / 10.0, *rc::gen::inRange(90, 250) / 10.0};
    model.apply(line(a, b), MoveKind::Feed);
  }
  const double skin = *rc::gen::inRange(1, 30) / 10.0;
  const double c0 = -*rc::gen::inRange(200, 400) / 10.0, c1 = -*rc::gen::inRange(0, 200) / 10.0;
  const BgRegion band = regionFrom({{c0, -100}, {c0, 100}, {c1, 100}, {c1, -100}});
  // The skins come off the material left before it is clipped to the band: clipped first, the band's
  // edge moved by the skin can meet an edge of the material moved the same way and leave a sliver
  // that is no material (a steep feed near c0; found by this property, RC seed 17870914112940817977:
  // 10.7952 measured against a bound of 10.7919). `complete` still clips first, where such a sliver
  // could only add a finding, never hide one (the session note of 2026-11-26).
  const BgRegion left = without(model.remaining(), partRegionOf(profile, kOuter, 100, 0.001));
  const auto region = thickestAbove(checkedIntersection(withoutSkins(left, kOuter, skin), band), profile, kOuter, 1e-6);
  const auto top = thickestBeneath(*model.topWithoutSkinsWithin(c0, c1, skin), profile, kOuter, 1e-6);
  if (!region) return;
  RC_ASSERT(top.has_value());
  RC_ASSERT(region->thickness <= top->thickness + 1e-4);
  // And the question the oracles ask: not thicker than a limit the top stays below.
  RC_ASSERT(mayStandThickerWithoutSkins(model, c0, c1, profile, skin, region->thickness));
}

// The material the model leaves equals stock ∖ ∪ shadows (Boost), for random line feeds over a bar.
RC_GTEST_PROP(CutEnvelope, TheMaterialIsTheStockMinusEveryShadow, ()) {
  const BgRegion stock = barStock(40, 50, 0);
  MaterialModel model(stock, kOuter, 100, 0.001);
  BgRegion expected = stock;
  const int feeds = *rc::gen::inRange(1, 8);
  for (int i = 0; i < feeds; ++i) {
    const Point a{-*rc::gen::inRange(0, 500) / 10.0, *rc::gen::inRange(0, 220) / 10.0};
    const Point b{-*rc::gen::inRange(0, 500) / 10.0, *rc::gen::inRange(0, 220) / 10.0};
    const Segment feed = line(a, b);
    model.apply(feed, MoveKind::Feed);
    expected = without(expected, shadowOf(feed, kOuter, 100, 0.001));
  }
  // Within the booleans' resolution: Boost rounds to about 1e-5 mm on a picture 150 mm across
  // (region.h), which over a 20 mm edge is 2e-4 mm².
  RC_ASSERT(std::abs(bg::area(model.remaining()) - bg::area(expected)) < 1e-3);
  // And the same places: a point in one and not in the other lies on their boundaries (booleans
  // between two so nearly equal regions are what Boost gets wrong, so points decide).
  for (int z = 0; z <= 100; ++z) {
    for (int x = 0; x <= 44; ++x) {
      const Point p{-z * 0.5 - 0.013, x * 0.5 - 0.007};
      if (bg::within(toBg(p), model.remaining()) == bg::within(toBg(p), expected)) continue;
      RC_ASSERT(distanceToBoundary(expected, p) < 1e-3);
    }
  }
}

// The material's top bounds the material left above a profile that is a graph over the cut axis
// (thickestBeneath, which spares the completeness oracle its booleans): on random feeds over a bar
// and a profile with a wall, a hollow (an arc) and a taper, the region left beyond the part
// measures no thicker than the top, but for the region's noise (chords of the part's arc,
// points the booleans round: µm).
RC_GTEST_PROP(CutEnvelope, TheTopBoundsTheMaterialLeftAboveAGraphProfile, ()) {
  const std::vector<Segment> profile = {line({0, 12}, {-10, 12}), line({-10, 12}, {-10, 14}),
                                        {SegmentKind::ArcCW, {-10, 14}, {-20, 14}, {-15, 14}, 0},
                                        line({-20, 14}, {-40, 16})};
  MaterialModel model(barStock(40, 50, 0), kOuter, 100, 0.001);
  const int feeds = *rc::gen::inRange(0, 8);
  for (int i = 0; i < feeds; ++i) {
    const Point a{-*rc::gen::inRange(0, 450) / 10.0, *rc::gen::inRange(90, 220) / 10.0};
    const Point b{-*rc::gen::inRange(0, 450) / 10.0, *rc::gen::inRange(90, 220) / 10.0};
    model.apply(line(a, b), MoveKind::Feed);
  }
  const BgRegion band = regionFrom({{-40, -100}, {-40, 100}, {0, 100}, {0, -100}});
  const BgRegion left = checkedIntersection(without(model.remaining(), partRegionOf(profile, kOuter, 100, 0.001)), band);
  const auto region = thickestAbove(left, profile, kOuter, 1e-6);
  const auto top = thickestBeneath(model.topWithin(-40, 0), profile, kOuter, 1e-6);
  // The oracles' question, answered without measuring what cannot exceed the limit: the same
  // answer as the measure (limits within a millimetre of it either way).
  const double limit = (top ? top->thickness : 5.0) + *rc::gen::inRange(-10, 11) / 10.0;
  RC_ASSERT(standsThickerThan(model.topWithin(-40, 0), profile, kOuter, 1e-6, limit) == (top && top->thickness > limit));
  if (!region) return;
  RC_ASSERT(top.has_value());
  RC_ASSERT(region->thickness <= top->thickness + 0.005);
}

}  // namespace
}  // namespace cyclecert
