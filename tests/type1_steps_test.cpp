// The eight type I steps one by one (G72.STEP1…8; G71.T1.STEP1…8), on small cycles in the cycle
// frame: cut along z, step along x. Expected values are worked out in the comments.
#include <gtest/gtest.h>

#include <algorithm>

#include "reference/cycles/type1_roughing.h"

namespace cyclecert {
namespace {

Segment line(Point a, Point b) { return {SegmentKind::Line, a, b, {}, 0}; }

// Outer shaft: A (z 2, x 20); ns rapid to B (2, 10); taper to (-8, 15); then straight to (-20, 15).
// Allowance (0.1, 0.5): A' (2.1, 20.5), B' (2.1, 10.5), rough taper (-7.9, 15.5) → C' (-19.9, 15.5).
Type1Cycle shaft() {
  Type1Cycle c;
  c.family = CycleFamily::G71;
  c.start = {2, 20};
  c.headEnd = {2, 10};
  c.body = {line({2, 10}, {-8, 15}), line({-8, 15}, {-20, 15})};
  c.allowance = {0.1, 0.5};
  c.depthOfCut = 2;
  c.retract = 0.5;
  c.feed = 0.25;
  return c;
}

std::vector<Move> withRule(const std::vector<Move>& moves, const std::string& rule) {
  std::vector<Move> out;
  std::copy_if(moves.begin(), moves.end(), std::back_inserter(out),
               [&](const Move& m) { return std::find(m.rules.begin(), m.rules.end(), rule) != m.rules.end(); });
  return out;
}

TEST(Type1Steps, Step1RapidsToTheShiftedStart) {
  const auto moves = planType1(shaft());
  ASSERT_FALSE(moves.empty());
  EXPECT_EQ(moves[0].kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(moves[0].to, {2.1, 20.5}));
  EXPECT_EQ(moves[0].rules.front(), "G71.T1.STEP1");
}

TEST(Type1Steps, Step1IsOmittedWithoutAllowance) {
  Type1Cycle c = shaft();
  c.allowance = {0, 0};
  const auto moves = planType1(c);
  EXPECT_EQ(moves[0].rules.front(), "G71.T1.STEP2");  // no zero-length move
}

TEST(Type1Steps, Step2InfeedIsRapidForG00AndFeedForG01) {
  Type1Cycle c = shaft();
  auto infeed = withRule(planType1(c), "G71.T1.STEP2");
  ASSERT_EQ(infeed.size(), 1u);
  EXPECT_EQ(infeed[0].kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(infeed[0].to, {2.1, 18.5}));  // 20.5 − Δd
  c.headIsRapid = false;
  infeed = withRule(planType1(c), "G71.T1.STEP2");
  EXPECT_EQ(infeed[0].kind, MoveKind::Feed);
  EXPECT_EQ(infeed[0].feed, 0.25);
  for (const Move& m : withRule(planType1(c), "G71.T1.STEP6")) EXPECT_EQ(m.kind, MoveKind::Feed);
}

TEST(Type1Steps, Step3CutsToTheFirstCrossingOfTheRoughProfile) {
  const auto cuts = withRule(planType1(shaft()), "G71.T1.STEP3");
  // Levels 18.5, 16.5 lie above C' (15.5): the cut ends at C'.z = -19.9 (interpretation).
  // Levels 14.5 and 12.5 meet the rough taper x = 10.5 + (2.1 − z)/2: z = 2.1 − 2(x − 10.5).
  ASSERT_EQ(cuts.size(), 4u);
  EXPECT_TRUE(nearlyEqual(cuts[0].to, {-19.9, 18.5}, 1e-9));
  EXPECT_TRUE(nearlyEqual(cuts[1].to, {-19.9, 16.5}, 1e-9));
  EXPECT_TRUE(nearlyEqual(cuts[2].to, {-5.9, 14.5}, 1e-9));
  EXPECT_TRUE(nearlyEqual(cuts[3].to, {-1.9, 12.5}, 1e-9));
  for (const Move& m : cuts) EXPECT_EQ(m.kind, MoveKind::Feed);
}

TEST(Type1Steps, Step4Retracts45DegreesAgainstCutAndInfeed) {
  const auto retracts = withRule(planType1(shaft()), "G71.T1.STEP4");
  ASSERT_EQ(retracts.size(), 4u);
  // From (-5.9, 14.5): +e in z (against the −z cut), +e in x (against the −x infeed).
  EXPECT_TRUE(nearlyEqual(retracts[2].to, {-5.4, 15.0}, 1e-9));
  EXPECT_EQ(retracts[2].kind, MoveKind::Feed);
  EXPECT_NE(std::find(retracts[2].rules.begin(), retracts[2].rules.end(), "G71.T1.RETRACT45"), retracts[2].rules.end());
}

TEST(Type1Steps, Step4DirectionFollowsTheQuadrant) {
  // Inner bore towards +z: A (-2, 5), B (-2, 15) (infeed +x), shape rising... retreat is −x,
  // cut +z. Retract must be −e in z and −e in x.
  Type1Cycle c;
  c.family = CycleFamily::G71;
  c.start = {-2, 5};
  c.headEnd = {-2, 15};
  c.body = {line({-2, 15}, {20, 8})};
  c.depthOfCut = 3;
  c.retract = 1;
  c.feed = 1;
  const auto moves = planType1(c);
  const auto cuts = withRule(moves, "G71.T1.STEP3");
  const auto retracts = withRule(moves, "G71.T1.STEP4");
  ASSERT_FALSE(cuts.empty());
  ASSERT_EQ(cuts.size(), retracts.size());
  EXPECT_TRUE(nearlyEqual(retracts[0].to, cuts[0].to + Point{-1, -1}, 1e-9));
}

TEST(Type1Steps, Step5RapidsBackToTheZOfAPrime) {
  const auto backs = withRule(planType1(shaft()), "G71.T1.STEP5");
  ASSERT_EQ(backs.size(), 4u);
  for (const Move& m : backs) {
    EXPECT_EQ(m.kind, MoveKind::Rapid);
    EXPECT_NEAR(m.to.z, 2.1, 1e-12);
  }
  EXPECT_NEAR(backs[0].to.x, 19.0, 1e-12);  // level 18.5 + e
}

TEST(Type1Steps, Step6InfeedsDdPlusEAndStopsBeforeBPrime) {
  const auto moves = planType1(shaft());
  const auto infeeds = withRule(moves, "G71.T1.STEP6");
  // Levels 16.5, 14.5, 12.5 by Δd + e = 2.5 from the retracted height; 10.5 reaches B' exactly,
  // so the last infeed goes to B' and the semi-finish pass follows.
  ASSERT_EQ(infeeds.size(), 4u);
  EXPECT_NEAR(infeeds[0].to.x, 16.5, 1e-12);
  EXPECT_NEAR(infeeds[2].to.x, 12.5, 1e-12);
  EXPECT_TRUE(nearlyEqual(infeeds[3].to, {2.1, 10.5}, 1e-12));
  EXPECT_EQ(infeeds[3].phase, MovePhase::SemiFinish);
}

TEST(Type1Steps, FirstInfeedReachingBPrimeGoesStraightToTheSemiFinish) {
  Type1Cycle c = shaft();
  c.depthOfCut = 12;  // 20.5 − 12 = 8.5 is past B' (10.5)
  const auto moves = planType1(c);
  EXPECT_TRUE(withRule(moves, "G71.T1.STEP3").empty());
  ASSERT_GE(moves.size(), 2u);
  EXPECT_TRUE(nearlyEqual(moves[1].to, {2.1, 10.5}, 1e-12));
}

TEST(Type1Steps, Step7FollowsTheRoughProfileKeepingArcs) {
  Type1Cycle c = shaft();
  c.body = {line({2, 10}, {-3, 10}), {SegmentKind::ArcCCW, {-3, 10}, {-8, 15}, {-8, 10}, 0}};
  const auto semi = withRule(planType1(c), "G71.T1.STEP7");
  ASSERT_EQ(semi.size(), 2u);
  EXPECT_TRUE(nearlyEqual(semi[0].to, {-2.9, 10.5}, 1e-12));
  EXPECT_EQ(semi[1].shape, SegmentKind::ArcCCW);
  ASSERT_TRUE(semi[1].center.has_value());
  EXPECT_TRUE(nearlyEqual(*semi[1].center, {-7.9, 10.5}, 1e-12));
  EXPECT_TRUE(nearlyEqual(semi[1].to, {-7.9, 15.5}, 1e-12));
}

TEST(Type1Steps, RF1SkipsTheSemiFinishAndTheInfeedToBPrime) {
  Type1Cycle c = shaft();
  c.semiFinish = false;
  const auto moves = planType1(c);
  EXPECT_TRUE(withRule(moves, "G71.T1.STEP7").empty());
  for (const Move& m : moves) EXPECT_NE(m.phase, MovePhase::SemiFinish);
  EXPECT_TRUE(nearlyEqual(moves.back().to, c.start));
}

TEST(Type1Steps, Step8ReturnsConventionallyOrDirectly) {
  Type1Cycle c = shaft();
  auto ret = withRule(planType1(c), "G71.T1.STEP8");
  // DTP = 0: from C' (-19.9, 15.5) along x to A.x = 20, then along z to A.
  ASSERT_EQ(ret.size(), 2u);
  EXPECT_TRUE(nearlyEqual(ret[0].to, {-19.9, 20}, 1e-12));
  EXPECT_TRUE(nearlyEqual(ret[1].to, {2, 20}, 1e-12));
  c.directReturn = true;
  ret = withRule(planType1(c), "G71.T1.STEP8");
  ASSERT_EQ(ret.size(), 1u);
  EXPECT_TRUE(nearlyEqual(ret[0].to, {2, 20}, 1e-12));
  EXPECT_NE(std::find(ret[0].rules.begin(), ret[0].rules.end(), "G71.DTP"), ret[0].rules.end());
}

TEST(Type1Steps, G72CitesItsOwnSteps) {
  Type1Cycle c = shaft();
  c.family = CycleFamily::G72;
  const auto moves = planType1(c);
  EXPECT_EQ(moves[0].rules.front(), "G72.STEP1");
  EXPECT_FALSE(withRule(moves, "G72.STEP8").empty());
  EXPECT_FALSE(withRule(moves, "G72.RETRACT").empty());
}

TEST(Type1Steps, NoZeroLengthMoves) {
  Type1Cycle c = shaft();
  c.allowance = {0, 0};
  c.retract = 0;
  Point at = c.start;
  for (const Move& m : planType1(c)) {
    EXPECT_GT(distance(at, m.to), 1e-9);
    at = m.to;
  }
}

}  // namespace
}  // namespace cyclecert
