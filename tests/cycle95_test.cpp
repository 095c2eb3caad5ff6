// CYCLE95 (SINUMERIK 802D, seed 004 §3; reference/siemens/cycle95_planner.cpp and
// siemens_roughing_*): the roughing with its own parameters (MID, FALZ/FALX/FAL, FF1, _VRT, the G0
// infeed, the axes returning one after the other), DAM, undercuts at FF2, the seed's L18, the
// alarms. Expectations derived by hand in the comments from CYCLE95.ROUGH/UNDERCUT and the
// interpretations in specs/rules.json (CYCLE95.*).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "reference/model/alarms.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_parser.h"
#include "tests/siemens_contours.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

// MID 4, no allowances, FF1 0.2, FF2 0.05, FF3 0.1, DT 0, DAM 0, _VRT 1 unless a test says otherwise.
Cycle95Parameters params(double vari) {
  Cycle95Parameters p;
  p.contourName = "C";
  p.infeed = 4;
  p.roughingFeed = 0.2;
  p.undercutFeed = 0.05;
  p.finishingFeed = 0.1;
  p.type = machiningTypeOf(vari).value();
  p.retract = 1;
  return p;
}

SiemensCycleCall callAt(Point position, const SiemensContour& contour) {
  SiemensCycleCall c;
  c.line = 4;
  c.position = position;
  c.contour = &contour;
  return c;
}

// FALZ 0.5, FALX 0.25, each on the stock side of its element (CYCLE95.PARAMS note): the face at z 0
// (stock in front) moves to z 0.5 and up by 0.25 with the rectangle's corner on its stock side
// (+0.5, +0.25) — the profile begins at the contour's first point so moved, (0.5, 0.25); the
// diameters move up by 0.25, the shoulder at z −10 (stock in front) to −9.5; the convex corners close
// along the 0.5 × 0.25 rectangle. The profile: (0.5, 0.25) → (0.5, 4.25) → (−9.5, 4.25) → (−9.5, 9.25)
// → (−20, 9.25). Start: (0.5 + 1, 9.25 + 1) = (1.5, 10.25). Depth 9.25 − 0.25 = 9, MID 4: 3 passes of
// 3, levels 6.25, 3.25, 0.25. The infeed is a G0 (CYCLE95.ROUGH).
TEST(Cycle95Rough, AxisAllowancesAndTheG0Infeed) {
  const SiemensContour shaft = stepShaft();
  Cycle95Parameters p = params(1);
  p.allowanceZ = 0.5;
  p.allowanceX = 0.25;
  const auto out = planCycle95(callAt({5, 15}, shaft), p);
  ASSERT_GE(out.moves.size(), 6u);
  const std::vector<Move> first(out.moves.begin(), out.moves.begin() + 6);
  expectMoves(first, {
                         {G0, {1.5, 10.25}, "approach"},
                         {G0, {1.5, 6.25}, "pass", 1},
                         {G1, {-9.5, 6.25}, "pass", 1},
                         {G1, {-9.5, 9.25}, "pass", 1},
                         {G0, {-8.5, 10.25}, "pass", 1},
                         {G0, {1.5, 10.25}, "pass", 1},
                     });
  EXPECT_EQ(passCount(out.moves), 3);
  EXPECT_EQ(first[2].feed, 0.2);
  EXPECT_EQ(first[2].rules, (std::vector<std::string>{"CYCLE95.ROUGH"}));
}

// DAM 4: pass 1's cut from (1, 6) to (−10, 6), 11 long, is interrupted after 4 and 8: (−3, 6), (−7, 6),
// then the rest to (−10, 6). DT 0.5 is no move: the tool dwells 0.5 s at each interruption, the end
// of (−3, 6) and (−7, 6), not at the roughing intersection (CYCLE95.DAM note).
TEST(Cycle95Rough, DamInterruptsTheCut) {
  const SiemensContour shaft = stepShaft();
  Cycle95Parameters p = params(1);
  p.interruptLength = 4;
  p.dwell = 0.5;
  const auto out = planCycle95(callAt({5, 15}, shaft), p);
  ASSERT_GE(out.moves.size(), 6u);
  EXPECT_EQ(out.moves[1].to, (Point{1, 6}));
  EXPECT_EQ(out.moves[2].to, (Point{-3, 6}));
  EXPECT_EQ(out.moves[3].to, (Point{-7, 6}));
  EXPECT_EQ(out.moves[4].to, (Point{-10, 6}));
  EXPECT_EQ(out.moves[2].rules, (std::vector<std::string>{"CYCLE95.ROUGH", "CYCLE95.DAM"}));
  EXPECT_EQ(out.moves[4].rules, (std::vector<std::string>{"CYCLE95.ROUGH"}));
  EXPECT_EQ(out.moves[2].dwell.value_or(0), 0.5);
  EXPECT_EQ(out.moves[3].dwell.value_or(0), 0.5);
  EXPECT_FALSE(out.moves[4].dwell.has_value());
  EXPECT_FALSE(out.moves[1].dwell.has_value());
}

// --- CYCLE95.UNDERCUT: a V-shaped pocket ---
//
// Contour: (0, 0) → (0, 6) → (−5, 6) → (−10, 2) → (−15, 6) → (−15, 8) → (−25, 8). Start (1, 9); depth 8,
// MID 4: levels 4 and 0.
//  pass 1 (level 4): G0 in to (1, 4); G1 to the face z 0; along it to (0, 6) and the flat to (−5, 6),
//    where the profile turns down (the pocket): stop; retract (−4, 7); G0 back (1, 7).
//  pass 2 (level 0): G0 (1, 0); G1 (0, 0); up the face to the previous level (0, 4); retract (1, 5).
//  The pocket: its rim (−5, 6) is below level 8 (the top: the lowest level strictly above it), so its
//  stock lies under 8, down to its lowest point x 2: depth 6, MID 4: 2 steps of 3, levels 5 and 2, at
//  FF2. G0 up to the start's height: (1, 9).
//  pass 3 (level 5): the previous level 8 stands above the rim, so the descent starts at the rim:
//    G0 (−5, 9), G1 down to (−5, 6), along the falling side (−5, 6)→(−10, 2) to x 5 at z −6.25;
//    across to the rising side (−10, 2)→(−15, 6) at x 5: z −13.75; along it to (−15, 6) and up the
//    face to the previous level 8: (−15, 8); retract (−14, 9).
//  pass 4 (level 2, the lowest point (−10, 2)): G0 along at x 9 to above where level 5 met the
//    falling side, (−6.25, 9); G1 down to (−6.25, 5); along the falling side to (−10, 2); along the
//    rising side to the previous level 5: (−13.75, 5); retract (−12.75, 6).
//  The axes return one after the other, X first: (−12.75, 9), then (1, 9).
TEST(Cycle95Undercut, AVPocketIsRoughedAtFF2) {
  const SiemensContour v = polyline("V", {{0, 0}, {0, 6}, {-5, 6}, {-10, 2}, {-15, 6}, {-15, 8}, {-25, 8}});
  const auto out = planCycle95(callAt({5, 15}, v), params(1));
  EXPECT_TRUE(out.warnings.empty());
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 4}, "pass", 1},
                             {G1, {0, 4}, "pass", 1},
                             {G1, {0, 6}, "pass", 1},
                             {G1, {-5, 6}, "pass", 1},
                             {G0, {-4, 7}, "pass", 1},
                             {G0, {1, 7}, "pass", 1},
                             {G0, {1, 0}, "pass", 2},
                             {G1, {0, 0}, "pass", 2},
                             {G1, {0, 4}, "pass", 2},
                             {G0, {1, 5}, "pass", 2},
                             {G0, {1, 9}, "pass", 3},
                             {G0, {-5, 9}, "pass", 3},
                             {G1, {-5, 6}, "pass", 3},
                             {G1, {-6.25, 5}, "pass", 3},
                             {G1, {-13.75, 5}, "pass", 3},
                             {G1, {-15, 6}, "pass", 3},
                             {G1, {-15, 8}, "pass", 3},
                             {G0, {-14, 9}, "pass", 3},
                             {G0, {-6.25, 9}, "pass", 4},
                             {G1, {-6.25, 5}, "pass", 4},
                             {G1, {-10, 2}, "pass", 4},
                             {G1, {-13.75, 5}, "pass", 4},
                             {G0, {-12.75, 6}, "pass", 4},
                             {G0, {-12.75, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
  for (std::size_t i = 11; i < 24; ++i) {
    EXPECT_EQ(out.moves[i].rules, (std::vector<std::string>{"CYCLE95.UNDERCUT"})) << i;
    if (out.moves[i].kind == MoveKind::Feed) {
      EXPECT_EQ(out.moves[i].feed, 0.05) << i;
    }
  }
}

// LCYC95 on the same contour leaves the pocket to finishing: its passes stop at the rim and no pass
// goes below level 4 between z −5 and −15.
TEST(Cycle95Undercut, Lcyc95DoesNotRoughThePocket) {
  const SiemensContour v = polyline("V", {{0, 0}, {0, 6}, {-5, 6}, {-10, 2}, {-15, 6}, {-15, 8}, {-25, 8}});
  Lcyc95Parameters p;
  p.type = machiningTypeOf(1).value();
  p.maxInfeed = 4;
  p.retract = 1;
  p.roughingFeed = 0.2;
  const auto out = planLcyc95(callAt({5, 15}, v), p);
  EXPECT_EQ(passCount(out.moves), 2);
  // It says so: the pocket begins on the contour's third block, (−5, 6) → (−10, 2), at Z −5.
  ASSERT_EQ(out.warnings.size(), 1u);
  EXPECT_NE(out.warnings[0].message.find("V.spf line 3"), std::string::npos) << out.warnings[0].message;
  EXPECT_NE(out.warnings[0].message.find("Z-5.0"), std::string::npos) << out.warnings[0].message;
  EXPECT_EQ(out.warnings[0].line, 4);
  for (const Move& m : out.moves) EXPECT_FALSE(m.to.z < -5 && m.to.z > -15 && m.to.x < 6) << m.to.z << " " << m.to.x;
}

// --- The seed's L18 (SEED004.EX.L18): CYCLE95("L18", 1.5, 0.3, 0.3, 0.2, 0.2, 0.2, 0.2, 9, 0, 0, 1)
// from G0X0Z2: (2, 0) ---
//
// L18 in radius: (0, 0); G03 to (−10, 10) CR=10: a quarter circle about (−10, 0); (−16, 10); (−16, 13.5);
// (−17.5, 15); (−30.5, 15); (−30.5, 20); (−35.5, 20); G02 to (−50, 20) CR=20: the centre above the
// chord, (−42.75, 20 + √(400 − 7.25²)) = (−42.75, 38.63968), 42.5°; (−58, 25); (−70, 25).
// The profile: offset 0.2 (FAL), then FALZ 0.3 / FALX 0.3 on each element's stock side: top 25 + 0.2 +
// 0.3 = 25.5; the start (a quarter circle leaving the axis straight up, on the face) moved 0.2 along
// +z, then FALZ in front of the face and FALX above its rising arc: the profile begins at (0.5, 0.3);
// largest z 0.5. Start (0.5 + 1, 25.5 + 1) = (1.5, 26.5). Depth 25.2, MID 1.5: 16.8 → 17 passes of
// 1.482353. The G02 is an undercut: the profile turns down at the offset flat x 20.5, under level 3
// (25.5 − 3·1.482353 = 21.052941) and over level 4 (19.570588). Its offset circle (radius 19.8) is
// moved by (−0.3, +0.3) where it falls and by (+0.3, +0.3) where it rises: the two halves cross below
// the centre's z −42.75 at x 38.63968 + 0.3 − √(19.8² − 0.3²) = 38.93968 − 19.797727 = 19.141953, the
// lowest point; depth 21.052941 − 19.141953 = 1.910988, MID 1.5: 2 more passes at FF2.
SiemensContour l18() {
  SiemensContour c{"L18", "L18.spf", {}};
  c.segments.push_back(arc(SegmentKind::ArcCCW, {0, 0}, {-10, 10}, {-10, 0}, 2));
  const std::vector<Point> a = {{-10, 10}, {-16, 10}, {-16, 13.5}, {-17.5, 15}, {-30.5, 15}, {-30.5, 20}, {-35.5, 20}};
  for (std::size_t i = 1; i < a.size(); ++i) c.segments.push_back(line(a[i - 1], a[i], int(i) + 2));
  c.segments.push_back(arc(SegmentKind::ArcCW, {-35.5, 20}, {-50, 20}, {-42.75, 20 + std::sqrt(400 - 7.25 * 7.25)}, 9));
  c.segments.push_back(line({-50, 20}, {-58, 25}, 10));
  c.segments.push_back(line({-58, 25}, {-70, 25}, 11));
  return c;
}

Cycle95Parameters l18Call() {
  Cycle95Parameters p;
  p.contourName = "L18";
  p.infeed = 1.5;
  p.allowanceZ = 0.3;
  p.allowanceX = 0.3;
  p.allowance = 0.2;
  p.roughingFeed = 0.2;
  p.undercutFeed = 0.2;
  p.finishingFeed = 0.2;
  p.type = machiningTypeOf(9).value();
  p.retract = 1;
  return p;
}

TEST(Cycle95Seed, L18SeventeenPassesThenTwoInTheUndercutThenFinishing) {
  const SiemensContour contour = l18();
  const auto out = planCycle95(callAt({2, 0}, contour), l18Call());
  EXPECT_TRUE(nearlyEqual(out.moves.front().to, {1.5, 26.5}, 1e-9));
  EXPECT_EQ(passCount(out.moves), 19);
  int k = 0;
  for (const Move& m : out.moves) {
    if (m.phase != MovePhase::Pass || m.pass == k || m.pass > 17) continue;
    k = m.pass;  // the infeed of an axis-parallel pass ends on its level
    EXPECT_NEAR(m.to.x, k == 17 ? 0.3 : 25.5 - k * 25.2 / 17, 1e-9) << "pass " << k;
  }
  // The undercut's two levels: 21.052941 − 1.910988/2 = 20.097447 and its lowest point 19.141953 —
  // each pocket pass's lowest feed (it runs down the falling side to its level, across, and back up).
  std::vector<double> undercutLevels;
  for (const Move& m : out.moves) {
    if (m.pass <= 17 || m.kind != MoveKind::Feed) continue;
    if (undercutLevels.size() < std::size_t(m.pass - 17)) undercutLevels.push_back(m.to.x);
    undercutLevels[m.pass - 18] = std::min(undercutLevels[m.pass - 18], m.to.x);
  }
  ASSERT_EQ(undercutLevels.size(), 2u);
  EXPECT_NEAR(undercutLevels[0], 20.097447, 1e-5);
  EXPECT_NEAR(undercutLevels[1], 19.141953, 1e-5);
  // Complete machining: the finishing ends the cycle at the start.
  EXPECT_EQ(out.moves.back().phase, MovePhase::Return);
  EXPECT_TRUE(nearlyEqual(out.end, {1.5, 26.5}, 1e-9));
  EXPECT_TRUE(std::any_of(out.moves.begin(), out.moves.end(), [](const Move& m) { return m.phase == MovePhase::Finish; }));
}

// --- Alarms ---

TEST(Cycle95Alarms, NoMidForRoughing) {
  const SiemensContour shaft = stepShaft();
  Cycle95Parameters p = params(1);
  p.infeed = 0;
  try {
    planCycle95(callAt({5, 15}, shaft), p);
    FAIL() << "no alarm";
  } catch (const CycleAlarm& a) {
    EXPECT_EQ(a.alarm().code, "61610");
    EXPECT_EQ(a.alarm().line, 4);
    EXPECT_NE(std::string(a.what()).find("MID"), std::string::npos) << a.what();
  }
  p.type = machiningTypeOf(5).value();
  EXPECT_NO_THROW(planCycle95(callAt({5, 15}, shaft), p));
}

TEST(Cycle95Alarms, AContourAgainstTheFinishingDirection) {
  const SiemensContour reversed = polyline("REV", {{-20, 9}, {-10, 9}, {-10, 4}, {0, 4}, {0, 0}});
  try {
    planCycle95(callAt({5, 15}, reversed), params(9));
    FAIL() << "no alarm";
  } catch (const CycleAlarm& a) {
    EXPECT_EQ(a.alarm().code, "10931");
  }
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

using namespace siemens_test;

// Random contours (lines and quarter-or-less arcs running towards −z, falling and rising: pockets,
// touching levels) in all twelve types of both cycles: every call plans finite moves or raises a
// clear alarm — no crash, hang or NaN. 300 contours, fixed seed.
TEST(Cycle95Robustness, RandomContoursPlanOrAlarm) {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> step(0.5, 6), height(0, 20), pick(0, 1);
  int planned = 0, undercutMoves = 0;
  for (int n = 0; n < 300; ++n) {
    SiemensContour c{"R", "R.spf", {}};
    Point at{0, std::round(height(rng))};
    const int count = 2 + n % 7;
    for (int i = 0; i < count; ++i) {
      Point to{at.z - std::round(step(rng) * 2) / 2, std::round(height(rng))};
      if (pick(rng) < 0.3 && std::abs(to.x - at.x) > 0.5) {  // a quarter circle between the two
        const Point centre = pick(rng) < 0.5 ? Point{at.z, to.x} : Point{to.z, at.x};
        const double r1 = distance(at, centre), r2 = distance(to, centre);
        if (std::abs(r1 - r2) < 1e-9) {
          // the arc whose sweep from `at` to `to` about `centre` is +90° is CCW
          const double a1 = std::atan2(at.x - centre.x, at.z - centre.z);
          const double a2 = std::atan2(to.x - centre.x, to.z - centre.z);
          const double d = std::remainder(a2 - a1, 2 * std::numbers::pi);
          c.segments.push_back(arc(d > 0 ? SegmentKind::ArcCCW : SegmentKind::ArcCW, at, to, centre, i + 1));
          at = to;
          continue;
        }
      }
      c.segments.push_back(line(at, to, i + 1));
      at = to;
    }
    for (int type = 1; type <= 12; ++type) {
      SCOPED_TRACE("contour " + std::to_string(n) + " type " + std::to_string(type));
      SiemensCycleCall call;
      call.line = 1;
      call.position = {50, 50};
      call.contour = &c;
      call.tool = {n % 3 == 0 ? 0.4 : 0.0, 3};
      Cycle95Parameters p;
      p.infeed = 1 + n % 4;
      p.allowance = 0.2 * (n % 2);
      p.allowanceZ = 0.1;
      p.allowanceX = 0.1;
      p.roughingFeed = 0.2;
      p.undercutFeed = 0.1;
      p.finishingFeed = 0.1;
      p.type = machiningTypeOf(type).value();
      p.retract = 1;
      Lcyc95Parameters q;
      q.type = p.type;
      q.allowance = p.allowance;
      q.maxInfeed = p.infeed;
      q.infeedAngle = 7;
      q.retract = 1;
      q.roughingFeed = 0.2;
      q.finishingFeed = 0.1;
      for (int cycle = 0; cycle < 2; ++cycle) {
        try {
          const auto out = cycle == 0 ? planCycle95(call, p) : planLcyc95(call, q);
          for (const Move& m : out.moves) {
            ASSERT_TRUE(std::isfinite(m.to.z) && std::isfinite(m.to.x));
            undercutMoves += std::count(m.rules.begin(), m.rules.end(), "CYCLE95.UNDERCUT");
          }
          ASSERT_LT(out.moves.size(), 100000u);
          ++planned;
        } catch (const CycleAlarm&) {
        }
      }
    }
  }
  // The sample is not all alarms: the longitudinal types (6 of 12) plan every contour that runs
  // towards −z with arcs of at most 90° (all of them), so at least 300 × 6 × 2 = 3,600 calls plan.
  EXPECT_GE(planned, 3600);
  EXPECT_GT(undercutMoves, 0);
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

// A DAM of 1e-6 on the step shaft's 11 mm cut would make 11 million moves: NotSupported at the
// bound (PROG.CAP.MOVES), naming the call's line.
TEST(Cycle95Limits, ATinyDamIsBounded) {
  const SiemensContour shaft = siemens_test::stepShaft();
  Cycle95Parameters p = params(1);
  p.interruptLength = 1e-6;
  SiemensCycleCall call;
  call.line = 9;
  call.position = {5, 15};
  call.contour = &shaft;
  try {
    planCycle95(call, p);
    FAIL() << "no NotSupported";
  } catch (const NotSupported& e) {
    EXPECT_EQ(e.line(), 9);
  }
}

}  // namespace
}  // namespace cyclecert

// --- A level through an element's end (issue 16) ---

namespace cyclecert {
namespace {

using namespace siemens_test;

// Contour L9 (radius): (0, 10) → (−5, 10); G2 to (−10, 15) CR=5 about (−5, 15), a quarter-circle
// fillet; the face (−10, 15) → (−10, 20); (−20, 20). MID 5, _VRT 1: start (1, 21); depth 10, levels
// 15 and 10. Level 15 first meets the profile at (−10, 15), the fillet's end: the pass goes on along
// the next element, the face, to the previous level (−10, 20) — not along the fillet's circle beyond
// its end (LCYC95.ROUGH / CYCLE95.ROUGH). Level 10: from the contour's start along the flat and the
// fillet up to (−10, 15). The axes return X first.
TEST(Cycle95Rough, ALevelThroughAnArcsEndGoesOnAlongTheNextElement) {
  SiemensContour c{"L9", "L9.spf", {}};
  c.segments.push_back(line({0, 10}, {-5, 10}, 2));
  c.segments.push_back(arc(SegmentKind::ArcCW, {-5, 10}, {-10, 15}, {-5, 15}, 3));
  c.segments.push_back(line({-10, 15}, {-10, 20}, 4));
  c.segments.push_back(line({-10, 20}, {-20, 20}, 5));
  Cycle95Parameters p = params(1);
  p.infeed = 5;
  const auto out = planCycle95(callAt({2, 25}, c), p);
  expectMoves(out.moves, {
                             {G0, {1, 21}, "approach"},
                             {G0, {1, 15}, "pass", 1},
                             {G1, {-10, 15}, "pass", 1},
                             {G1, {-10, 20}, "pass", 1},
                             {G0, {-9, 21}, "pass", 1},
                             {G0, {1, 21}, "pass", 1},
                             {G0, {1, 10}, "pass", 2},
                             {G1, {0, 10}, "pass", 2},
                             {G1, {-5, 10}, "pass", 2},
                             {G1, {-10, 15}, "pass", 2},
                             {G0, {-9, 16}, "pass", 2},
                             {G0, {-9, 21}, "return"},
                             {G0, {1, 21}, "return"},
                         });
  EXPECT_EQ(out.moves[3].shape, SegmentKind::Line);
  EXPECT_EQ(out.moves[9].shape, SegmentKind::ArcCW);
  EXPECT_EQ(out.moves[9].center, (std::optional<Point>{Point{-5, 15}}));
}

// --- An undercut whose rim is an arc's top (issue 16; CYCLE95.UNDERCUT) ---
//
// Contour L7 (radius): (0, 10) → (−5, 10) → (−5, 16) → (−10, 16); G3 X28 Z-12 CR=2 to (−12, 14) about
// (−10, 14): an arc starting at its top (tangent along −z) and falling, a quarter circle; → (−12, 12)
// → (−15, 12) → (−15, 16) → (−20, 16) → (−20, 20). MID 3, _VRT 1: start (1, 21); depth 10, 4 steps of
// 2.5: levels 17.5, 15, 12.5, 10. The rim is the arc's start (−10, 16) (CYCLE95.UNDERCUT: "the top of
// an arc"): pass 2 stops there, not after the falling arc. The pocket: from the level above the rim,
// 17.5, met again at (−20, 17.5), down to x 12: 5.5 in 2 steps of 2.75 (levels 14.75, 12) at FF2. Level
// 14.75 meets the arc at z = −10 − √(4 − 0.75²) = −11.854050 and the rising side at (−15, 14.75);
// level 12 is the pocket's lowest point, (−12, 12) where the falling side ends. Each pocket level runs
// down the falling side from where the previous one met it: pass 5 from the rim (below 17.5), G1
// down to (−10, 16), then G3 along the arc (centre (−10, 14)) to (−11.854050, 14.75); pass 6 G1 down
// to (−11.854050, 14.75), G3 on along the arc to its end (−12, 14), G1 down the line to (−12, 12).
TEST(Cycle95Undercut, ARimAtAnArcsTopStopsThePasses) {
  SiemensContour c = polyline("L7", {{0, 10}, {-5, 10}, {-5, 16}, {-10, 16}});
  c.segments.push_back(arc(SegmentKind::ArcCCW, {-10, 16}, {-12, 14}, {-10, 14}, 5));
  const std::vector<Point> rest = {{-12, 14}, {-12, 12}, {-15, 12}, {-15, 16}, {-20, 16}, {-20, 20}};
  for (std::size_t i = 1; i < rest.size(); ++i) c.segments.push_back(line(rest[i - 1], rest[i], int(i) + 5));
  Cycle95Parameters p = params(1);
  p.infeed = 3;
  const double z1475 = -10 - std::sqrt(4 - 0.75 * 0.75);
  const auto out = planCycle95(callAt({2, 25}, c), p);
  expectMoves(out.moves, {
                             {G0, {1, 21}, "approach"},
                             {G0, {1, 17.5}, "pass", 1},
                             {G1, {-20, 17.5}, "pass", 1},
                             {G1, {-20, 20}, "pass", 1},
                             {G0, {-19, 21}, "pass", 1},
                             {G0, {1, 21}, "pass", 1},
                             {G0, {1, 15}, "pass", 2},
                             {G1, {-5, 15}, "pass", 2},
                             {G1, {-5, 16}, "pass", 2},
                             {G1, {-10, 16}, "pass", 2},
                             {G0, {-9, 17}, "pass", 2},
                             {G0, {1, 17}, "pass", 2},
                             {G0, {1, 12.5}, "pass", 3},
                             {G1, {-5, 12.5}, "pass", 3},
                             {G1, {-5, 15}, "pass", 3},
                             {G0, {-4, 16}, "pass", 3},
                             {G0, {1, 16}, "pass", 3},
                             {G0, {1, 10}, "pass", 4},
                             {G1, {0, 10}, "pass", 4},
                             {G1, {-5, 10}, "pass", 4},
                             {G1, {-5, 12.5}, "pass", 4},
                             {G0, {-4, 13.5}, "pass", 4},
                             {G0, {-4, 21}, "pass", 5},
                             {G0, {-10, 21}, "pass", 5},
                             {G1, {-10, 16}, "pass", 5},
                             {G1, {z1475, 14.75}, "pass", 5},
                             {G1, {-15, 14.75}, "pass", 5},
                             {G1, {-15, 16}, "pass", 5},
                             {G1, {-20, 16}, "pass", 5},
                             {G1, {-20, 17.5}, "pass", 5},
                             {G0, {-19, 18.5}, "pass", 5},
                             {G0, {z1475, 18.5}, "pass", 6},
                             {G1, {z1475, 14.75}, "pass", 6},
                             {G1, {-12, 14}, "pass", 6},
                             {G1, {-12, 12}, "pass", 6},
                             {G1, {-15, 12}, "pass", 6},
                             {G1, {-15, 14.75}, "pass", 6},
                             {G0, {-14, 15.75}, "pass", 6},
                             {G0, {-14, 21}, "return"},
                             {G0, {1, 21}, "return"},
                         });
  // The two pieces along the falling arc keep its centre and sense (G3).
  for (std::size_t i : {25u, 33u}) {
    EXPECT_EQ(out.moves[i].shape, SegmentKind::ArcCCW) << i;
    EXPECT_EQ(out.moves[i].center, (std::optional<Point>{Point{-10, 14}})) << i;
  }
}

// --- A contour subprogram without elements (issue 16; LCYC95.ALARMS) ---
//
// A subprogram holding only RET, or only its first point, is a program the controller reads; the
// cycle refuses the contour when called: alarm 10931 at the call's line (4 here), naming the contour.
TEST(Cycle95Alarms, ASubprogramWithoutElementsIsAlarm10931) {
  for (const char* text : {"RET\n", "G1 X20 Z0\nRET\n"}) {
    SCOPED_TRACE(text);
    SiemensModal modal;
    modal.motion = 1;
    const SiemensContour c = readSiemensContour("L6", parseSiemensSubprogram(text, "L6.spf"), modal);
    EXPECT_TRUE(c.segments.empty());
    try {
      planCycle95(callAt({2, 25}, c), params(1));
      ADD_FAILURE() << "no alarm";
    } catch (const CycleAlarm& a) {
      EXPECT_EQ(a.alarm().code, "10931");
      EXPECT_EQ(a.alarm().line, 4);
      EXPECT_NE(std::string(a.what()).find("L6"), std::string::npos) << a.what();
    }
  }
}

}  // namespace
}  // namespace cyclecert
