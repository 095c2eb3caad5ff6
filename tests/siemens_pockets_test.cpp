// SINUMERIK stock-removal pockets (issue 16's fuzz classes; the shared steps in
// reference/siemens/siemens_roughing_steps.cpp): the axis-parallel allowances FALZ / FALX on each
// element's stock side (reference/siemens/siemens_axis_allowance.*), a wall falling down the part's
// face, the front stretch — where the profile falls from its first point, up to where it rises back
// to the level above that point — which the main passes reach along their levels, and a pocket inside
// a pocket (CYCLE95.PARAMS, CYCLE95.ROUGH, LCYC95.ROUGH and CYCLE95.UNDERCUT notes in
// specs/rules.json). Expectations derived by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "reference/siemens/siemens_axis_allowance.h"
#include "reference/siemens/siemens_cycles.h"
#include "tests/siemens_contours.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

// CYCLE95 VARI 1 (longitudinal external roughing), FF1 0.2, FF2 0.05; no allowances and _VRT 1
// unless given.
// Every feed move of pass `firstPass` and after at `feed` (0: every feed move; moves outside the
// passes have pass 0).
void expectEveryFeedFrom(const std::vector<Move>& moves, int firstPass, double feed) {
  for (const Move& m : moves) {
    if (m.kind == MoveKind::Feed && m.pass >= firstPass) {
      EXPECT_EQ(m.feed, feed) << "pass " << m.pass;
    }
  }
}

SiemensCycleOutcome roughWithCycle95(const SiemensContour& contour, double mid, double fal = 0, double vrt = 1) {
  Cycle95Parameters p;
  p.contourName = contour.name;
  p.infeed = mid;
  p.allowance = fal;
  p.roughingFeed = 0.2;
  p.undercutFeed = 0.05;
  p.finishingFeed = 0.1;
  p.type = machiningTypeOf(1).value();
  p.retract = vrt;
  SiemensCycleCall call;
  call.line = 4;
  call.position = {5, 15};
  call.contour = &contour;
  return planCycle95(call, p);
}

// The contour begins with a wall falling down its face: (0, 6) → (0, 4), then (−3, 4) → (−3, 8) →
// (−10, 8). The part's face stands at z 0 up to x 4 (the wall's foot); the wall has stock on both
// sides. Top 8, bottom 4, MID 1.5: 3 levels of 4/3: 6.666667, 5.333333, 4; start (1, 9).
//  pass 1 (6.666667, above the wall): to the rising wall at −3, up it to the top 8; retract (−2, 9);
//    back to z 1.
//  pass 2 (5.333333, through the falling wall — it is no roughing intersection): to (−3, 5.333333), up
//    the wall to the previous level; retract (−2, 6.333333); back.
//  pass 3 (4, the foot): the level meets the profile at the foot (0, 4), along the bottom to (−3, 4), up
//    to 5.333333; retract (−2, 6.333333).
//  The axes return one after the other, X first: (−2, 9), (1, 9).
// (Before: pass 2 stopped where its level crossed the falling wall, at z 0, leaving the band between
// 5.333333 and 6.666667 in front of the wall at −3.)
TEST(SiemensFrontPockets, ALevelRunsThroughAWallFallingDownTheFace) {
  const SiemensContour c = polyline("F", {{0, 6}, {0, 4}, {-3, 4}, {-3, 8}, {-10, 8}});
  const double l1 = 8 - 4.0 / 3, l2 = 8 - 8.0 / 3;
  expectMoves(roughWithCycle95(c, 1.5).moves, {
                                                   {G0, {1, 9}, "approach"},
                                                   {G0, {1, l1}, "pass", 1},
                                                   {G1, {-3, l1}, "pass", 1},
                                                   {G1, {-3, 8}, "pass", 1},
                                                   {G0, {-2, 9}, "pass", 1},
                                                   {G0, {1, 9}, "pass", 1},
                                                   {G0, {1, l2}, "pass", 2},
                                                   {G1, {-3, l2}, "pass", 2},
                                                   {G1, {-3, l1}, "pass", 2},
                                                   {G0, {-2, l1 + 1}, "pass", 2},
                                                   {G0, {1, l1 + 1}, "pass", 2},
                                                   {G0, {1, 4}, "pass", 3},
                                                   {G1, {0, 4}, "pass", 3},
                                                   {G1, {-3, 4}, "pass", 3},
                                                   {G1, {-3, l2}, "pass", 3},
                                                   {G0, {-2, l2 + 1}, "pass", 3},
                                                   {G0, {-2, 9}, "return"},
                                                   {G0, {1, 9}, "return"},
                                               });
}

// A groove inside the front stretch: the contour falls down its face (0, 6) → (0, 4), runs to
// (−2, 4), up to (−2, 5.5), along to (−3, 5.5), down into a groove to (−3, 4.5), along to (−5, 4.5),
// up to (−5, 8), along to (−10, 8). Top 8, bottom 4, MID 1.5: levels 6.666667, 5.333333, 4; start
// (1, 9). The front stretch runs from (0, 6) to where the profile rises back to the lowest level
// above x 6, 6.666667 (on the wall at −5): no undercut, the main passes reach it.
//  pass 1 (6.666667): to the wall at −5, up to 8; retract (−4, 9); back to z 1.
//  pass 2 (5.333333): through the falling wall to (−2, 5.333333), up to 5.5, along to (−3, 5.5), and
//    on through the stretch's descent: down to (−3, 4.5), along to (−5, 4.5), up to the previous level
//    6.666667; retract (−4, 7.666667); back.
//  pass 3 (4): from the wall's foot (0, 4) along to (−2, 4), up to 5.333333; retract (−1, 6.333333).
//  Return, X first: (−1, 9), (1, 9). Every feed at FF1.
// (Before: pass 2 stopped at the groove's rim (−3, 5.5), and the groove's stock below 6.666667 stayed:
// no undercut pass takes a pocket of the front stretch — 'complete' in the fuzz.)
TEST(SiemensFrontPockets, AGrooveInTheFrontStretchIsCleanedUpByTheMainPass) {
  const SiemensContour c =
      polyline("S", {{0, 6}, {0, 4}, {-2, 4}, {-2, 5.5}, {-3, 5.5}, {-3, 4.5}, {-5, 4.5}, {-5, 8}, {-10, 8}});
  const double l1 = 8 - 4.0 / 3, l2 = 8 - 8.0 / 3;
  const auto out = roughWithCycle95(c, 1.5);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, l1}, "pass", 1},
                             {G1, {-5, l1}, "pass", 1},
                             {G1, {-5, 8}, "pass", 1},
                             {G0, {-4, 9}, "pass", 1},
                             {G0, {1, 9}, "pass", 1},
                             {G0, {1, l2}, "pass", 2},
                             {G1, {-2, l2}, "pass", 2},
                             {G1, {-2, 5.5}, "pass", 2},
                             {G1, {-3, 5.5}, "pass", 2},
                             {G1, {-3, 4.5}, "pass", 2},
                             {G1, {-5, 4.5}, "pass", 2},
                             {G1, {-5, l1}, "pass", 2},
                             {G0, {-4, l1 + 1}, "pass", 2},
                             {G0, {1, l1 + 1}, "pass", 2},
                             {G0, {1, 4}, "pass", 3},
                             {G1, {0, 4}, "pass", 3},
                             {G1, {-2, 4}, "pass", 3},
                             {G1, {-2, l2}, "pass", 3},
                             {G0, {-1, l2 + 1}, "pass", 3},
                             {G0, {-1, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
  expectEveryFeedFrom(out.moves, 0, 0.2);
}

// A pocket whose rising side steps back down before the profile is back at the pocket's top (a
// wall returning along itself, then a second, shallower groove): (0, 6) → (−2, 6), down the rim's
// wall to (−2, 3), along to (−4, 3), up to (−4, 5), back down the same line to (−4, 4), along to
// (−6, 4), up to (−6, 8), along to (−10, 8). Top 8, bottom 3, MID 2.5: main levels 5.5 and 3; start
// (1, 9). Both main levels lie below the face's top 6.
//  pass 1 (5.5): to the face at z 0, up it to (0, 6), along to the rim (−2, 6); retract (−1, 7); back.
//  pass 2 (3): to the face; the face's top stands above the previous level; retract (1, 4).
//  The pocket (CYCLE95.UNDERCUT): from the rim (−2, 6) to where the profile is back at its top 8,
//  (−6, 8); bottom 3; its levels 5.5 and 3. G0 up to the start's height (1, 9).
//  pass 3 (5.5): G0 along to above the rim, G1 down the wall to (−2, 5.5), across to the rising side
//    at (−6, 5.5), up to 8; retract (−5, 9).
//  pass 4 (3, the lowest): G0 to above the rim, G1 down to (−2, 3), along the bottom to (−4, 3), up to
//    (−4, 5), and on through the rising side's own descent: down to (−4, 4), along to (−6, 4), up to
//    the previous level 5.5; retract (−5, 6.5).
//  Return, X first: (−5, 9), (1, 9).
// (Before: pass 4 stopped at (−4, 5), where the rising side turns back down, and the second groove's
// stock between 4 and 5.5 stayed: 'complete' in the fuzz.)
TEST(SiemensPockets, ARisingSideThatStepsBackIsFollowedToThePreviousLevel) {
  const SiemensContour c =
      polyline("P", {{0, 6}, {-2, 6}, {-2, 3}, {-4, 3}, {-4, 5}, {-4, 4}, {-6, 4}, {-6, 8}, {-10, 8}});
  const auto out = roughWithCycle95(c, 2.5);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 5.5}, "pass", 1},
                             {G1, {0, 5.5}, "pass", 1},
                             {G1, {0, 6}, "pass", 1},
                             {G1, {-2, 6}, "pass", 1},
                             {G0, {-1, 7}, "pass", 1},
                             {G0, {1, 7}, "pass", 1},
                             {G0, {1, 3}, "pass", 2},
                             {G1, {0, 3}, "pass", 2},
                             {G0, {1, 4}, "pass", 2},
                             {G0, {1, 9}, "pass", 3},
                             {G0, {-2, 9}, "pass", 3},
                             {G1, {-2, 5.5}, "pass", 3},
                             {G1, {-6, 5.5}, "pass", 3},
                             {G1, {-6, 8}, "pass", 3},
                             {G0, {-5, 9}, "pass", 3},
                             {G0, {-2, 9}, "pass", 4},
                             {G1, {-2, 3}, "pass", 4},
                             {G1, {-4, 3}, "pass", 4},
                             {G1, {-4, 5}, "pass", 4},
                             {G1, {-4, 4}, "pass", 4},
                             {G1, {-6, 4}, "pass", 4},
                             {G1, {-6, 5.5}, "pass", 4},
                             {G0, {-5, 6.5}, "pass", 4},
                             {G0, {-5, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
  for (std::size_t i = 10; i < 24; ++i) {
    if (out.moves[i].kind == MoveKind::Feed) {
      EXPECT_EQ(out.moves[i].feed, 0.05) << i;
    }
  }
}

// A pocket open to the contour's end whose last element falls steeply (3 down over 1 along):
// (0, 4) up the face to (0, 6), along to the rim (−4, 6), down to the end (−5, 3). Top 6, bottom 3,
// MID 2: main levels 4.5 and 3; start (1, 7). A retract by _VRT in each axis from the end's z below the
// rim would run back into the part across the steep fall (from (−5, 4.5) to (−4, 5.5), under the rim
// at 6): the pass first climbs along X at the end's z — beyond the contour — to the pocket's top 6.
//  pass 1 (4.5): meets the face wall at (0, 4.5), up it to 6; retract (1, 7) (the start: no G0 back).
//  pass 2 (3, below the face's top 4): to the face at z 0; retract (1, 4).
//  The pocket: rim (−4, 6), open to the end, top 6, bottom 3, levels 4.5 and 3; G0 up to (1, 7).
//  pass 3 (4.5): G0 to above the rim, G1 down to it, along the falling side to (−4.5, 4.5), across at
//    4.5 to the end's z −5, climb to (−5, 6); retract (−4, 7).
//  pass 4 (3, the lowest): G0 to above (−4.5, 4.5), G1 down to it, along the falling side to the end
//    (−5, 3), climb to (−5, 6); retract (−4, 7).
//  Return: X already at the start's height; Z: (1, 7).
TEST(SiemensPockets, APassEndingUnderASteepLastFallClimbsBeforeItsRetract) {
  const SiemensContour c = polyline("E", {{0, 4}, {0, 6}, {-4, 6}, {-5, 3}});
  expectMoves(roughWithCycle95(c, 2).moves, {
                                                 {G0, {1, 7}, "approach"},
                                                 {G0, {1, 4.5}, "pass", 1},
                                                 {G1, {0, 4.5}, "pass", 1},
                                                 {G1, {0, 6}, "pass", 1},
                                                 {G0, {1, 7}, "pass", 1},
                                                 {G0, {1, 3}, "pass", 2},
                                                 {G1, {0, 3}, "pass", 2},
                                                 {G0, {1, 4}, "pass", 2},
                                                 {G0, {1, 7}, "pass", 3},
                                                 {G0, {-4, 7}, "pass", 3},
                                                 {G1, {-4, 6}, "pass", 3},
                                                 {G1, {-4.5, 4.5}, "pass", 3},
                                                 {G1, {-5, 4.5}, "pass", 3},
                                                 {G1, {-5, 6}, "pass", 3},
                                                 {G0, {-4, 7}, "pass", 3},
                                                 {G0, {-4.5, 7}, "pass", 4},
                                                 {G1, {-4.5, 4.5}, "pass", 4},
                                                 {G1, {-5, 3}, "pass", 4},
                                                 {G1, {-5, 6}, "pass", 4},
                                                 {G0, {-4, 7}, "pass", 4},
                                                 {G0, {1, 7}, "return"},
                                             });
}

// A bump inside a pocket: (0, 6) → (−2, 6), down the rim's wall to (−2, 2), along to (−3, 2), up the
// bump to (−3, 4), along to (−4, 4), down to (−4, 1), along to (−6, 1), up to (−6, 8), along to
// (−10, 8). Top 8, bottom 1, MID 2.5: main levels 5.666667, 3.333333, 1 (all below the face's top 6);
// start (1, 9). The pocket runs from the rim (−2, 6) to (−6, 8), its top 8, bottom 1 (after the bump),
// its levels the same three.
//  pass 1 (5.666667): to the face, up to (0, 6), along to the rim; retract (−1, 7); back.
//  pass 2 (3.333333), pass 3 (1): to the face; retract.
//  pass 4 (5.666667): G0 up to (1, 9), along to above the rim, G1 down the wall to (−2, 5.666667),
//    across to the rising wall at −6, up to 8; retract (−5, 9).
//  pass 5 (3.333333): down the wall to (−2, 3.333333), across only to where the level meets the bump,
//    (−3, 3.333333), then along the profile over the bump — up to 4, along, down to 1 — along the bottom
//    and up the rising wall to the previous level 5.666667; retract (−5, 6.666667).
//  pass 6 (1, the lowest): down the falling side — the rim's wall to 2, along, over the bump, down to
//    (−4, 1) —, along the bottom to (−6, 1), up to 3.333333; retract (−5, 4.333333).
//  Return, X first: (−5, 9), (1, 9).
// (Before: pass 5 crossed at its level straight to the rising wall, through the bump standing to 4:
// no-gouge in the fuzz.)
TEST(SiemensPockets, APocketPassDoesNotCrossABumpInsideThePocket) {
  const SiemensContour c = polyline(
      "B", {{0, 6}, {-2, 6}, {-2, 2}, {-3, 2}, {-3, 4}, {-4, 4}, {-4, 1}, {-6, 1}, {-6, 8}, {-10, 8}});
  const double l1 = 8 - 7.0 / 3, l2 = 8 - 14.0 / 3;
  expectMoves(roughWithCycle95(c, 2.5).moves, {
                                                   {G0, {1, 9}, "approach"},
                                                   {G0, {1, l1}, "pass", 1},
                                                   {G1, {0, l1}, "pass", 1},
                                                   {G1, {0, 6}, "pass", 1},
                                                   {G1, {-2, 6}, "pass", 1},
                                                   {G0, {-1, 7}, "pass", 1},
                                                   {G0, {1, 7}, "pass", 1},
                                                   {G0, {1, l2}, "pass", 2},
                                                   {G1, {0, l2}, "pass", 2},
                                                   {G0, {1, l2 + 1}, "pass", 2},
                                                   {G0, {1, 1}, "pass", 3},
                                                   {G1, {0, 1}, "pass", 3},
                                                   {G0, {1, 2}, "pass", 3},
                                                   {G0, {1, 9}, "pass", 4},
                                                   {G0, {-2, 9}, "pass", 4},
                                                   {G1, {-2, l1}, "pass", 4},
                                                   {G1, {-6, l1}, "pass", 4},
                                                   {G1, {-6, 8}, "pass", 4},
                                                   {G0, {-5, 9}, "pass", 4},
                                                   {G0, {-2, 9}, "pass", 5},
                                                   {G1, {-2, l2}, "pass", 5},
                                                   {G1, {-3, l2}, "pass", 5},
                                                   {G1, {-3, 4}, "pass", 5},
                                                   {G1, {-4, 4}, "pass", 5},
                                                   {G1, {-4, 1}, "pass", 5},
                                                   {G1, {-6, 1}, "pass", 5},
                                                   {G1, {-6, l1}, "pass", 5},
                                                   {G0, {-5, l1 + 1}, "pass", 5},
                                                   {G0, {-2, l1 + 1}, "pass", 6},
                                                   {G1, {-2, l2}, "pass", 6},
                                                   {G1, {-2, 2}, "pass", 6},
                                                   {G1, {-3, 2}, "pass", 6},
                                                   {G1, {-3, 4}, "pass", 6},
                                                   {G1, {-4, 4}, "pass", 6},
                                                   {G1, {-4, 1}, "pass", 6},
                                                   {G1, {-6, 1}, "pass", 6},
                                                   {G1, {-6, l2}, "pass", 6},
                                                   {G0, {-5, l2 + 1}, "pass", 6},
                                                   {G0, {-5, 9}, "return"},
                                                   {G0, {1, 9}, "return"},
                                               });
}

// The profile falls from its first point along a slope: (0, 5) → (−2, 3) → (−4, 3) → (−4, 8) →
// (−10, 8). The face stands at z 0 up to x 5 (the first point). Top 8, bottom 3, MID 2: 3 levels of
// 5/3: 6.333333, 4.666667, 3; start (1, 9). The front stretch runs from (0, 5) to where the profile
// rises back to the lowest level above x 5, 6.333333 (on the wall at −4): no undercut.
//  pass 1 (6.333333, above the first point): to the wall at −4, up it to 8; retract (−3, 9); back.
//  pass 2 (4.666667, below the face's top): G1 to the face at z 0, up the face to the first point
//    (0, 5), then along the profile through the stretch's descent: down the slope to (−2, 3), along to
//    (−4, 3), up the wall to the previous level 6.333333; retract (−3, 7.333333); back.
//  pass 3 (3): to the face at z 0; the face's top stands above the previous level; retract (1, 4).
//  Return, X first: (1, 9) (then Z: no move). Every feed at FF1.
// (Before: pass 2 stopped at the first point, where the slope turns down, and the band between 5 and
// 6.333333 above the slope stayed, no pass reaching it: 'complete' in the fuzz.)
TEST(SiemensFrontPockets, APassMeetingTheFaceFollowsTheFrontStretchDown) {
  const SiemensContour c = polyline("S", {{0, 5}, {-2, 3}, {-4, 3}, {-4, 8}, {-10, 8}});
  const double l1 = 8 - 5.0 / 3, l2 = 8 - 10.0 / 3;
  const auto out = roughWithCycle95(c, 2);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, l1}, "pass", 1},
                             {G1, {-4, l1}, "pass", 1},
                             {G1, {-4, 8}, "pass", 1},
                             {G0, {-3, 9}, "pass", 1},
                             {G0, {1, 9}, "pass", 1},
                             {G0, {1, l2}, "pass", 2},
                             {G1, {0, l2}, "pass", 2},
                             {G1, {0, 5}, "pass", 2},
                             {G1, {-2, 3}, "pass", 2},
                             {G1, {-4, 3}, "pass", 2},
                             {G1, {-4, l1}, "pass", 2},
                             {G0, {-3, l1 + 1}, "pass", 2},
                             {G0, {1, l1 + 1}, "pass", 2},
                             {G0, {1, 3}, "pass", 3},
                             {G1, {0, 3}, "pass", 3},
                             {G0, {1, 4}, "pass", 3},
                             {G0, {1, 9}, "return"},
                         });
  expectEveryFeedFrom(out.moves, 0, 0.2);
}

// The contour begins with a wall rising at its first point's z, then falls behind its top: (0, 4) →
// (0, 8) → (−4, 4) → (−6, 4). The wall only rises: the part's own front, which the levels meet as
// they meet the profile (the face below the first point stands up to x 4). Behind the wall's top the
// slope falls away: a pocket the wall stands before, roughed as an undercut at FF2 (CYCLE95.UNDERCUT
// note). Top 8, bottom 4, MID 2.5: 2 levels of 2: 6, 4; start (1, 9).
//  pass 1 (6): G0 in to (1, 6), G1 to the wall (0, 6), up it to the previous level 8 (where the
//    profile turns down: the pocket's rim); retract (1, 9); back along z: already there.
//  pass 2 (4): G0 in to (1, 4), G1 to the wall's foot (0, 4), up to 6; retract (1, 7).
//  The pocket: rim (0, 8), down the slope to (−4, 4), open along the flat to the end (−6, 4); its
//  top 8 (no level above the rim), steps of 2: 6, 4. G0 up to the start's height (1, 9).
//  pass 3 (6): G0 to (0, 9), G1 down to the rim (0, 8), down the slope to (−2, 6); no profile ahead
//    at 6: G1 along to the end's z (−6, 6); retract (−5, 7).
//  pass 4 (4, the lowest): G0 to (−2, 7), G1 to (−2, 6), down the slope to (−4, 4), along the flat
//    to (−6, 4); retract (−5, 5).
//  Return, X first: (−5, 9), (1, 9).
// (Before: the descent from the wall's top counted as the contour's front — no undercut — and the
// passes stopped at the wall's top: the stock above the slope stayed, 'complete' in the fuzz, seed
// 14762804858427687941.)
TEST(SiemensFrontPockets, AWallRisingAtTheFrontStandsBeforeThePocketBehindIt) {
  const SiemensContour c = polyline("W", {{0, 4}, {0, 8}, {-4, 4}, {-6, 4}});
  const auto out = roughWithCycle95(c, 2.5);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 6}, "pass", 1},
                             {G1, {0, 6}, "pass", 1},
                             {G1, {0, 8}, "pass", 1},
                             {G0, {1, 9}, "pass", 1},
                             {G0, {1, 4}, "pass", 2},
                             {G1, {0, 4}, "pass", 2},
                             {G1, {0, 6}, "pass", 2},
                             {G0, {1, 7}, "pass", 2},
                             {G0, {1, 9}, "pass", 3},
                             {G0, {0, 9}, "pass", 3},
                             {G1, {0, 8}, "pass", 3},
                             {G1, {-2, 6}, "pass", 3},
                             {G1, {-6, 6}, "pass", 3},
                             {G0, {-5, 7}, "pass", 3},
                             {G0, {-2, 7}, "pass", 4},
                             {G1, {-2, 6}, "pass", 4},
                             {G1, {-4, 4}, "pass", 4},
                             {G1, {-6, 4}, "pass", 4},
                             {G0, {-5, 5}, "pass", 4},
                             {G0, {-5, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
  expectEveryFeedFrom(out.moves, 3, 0.05);
}

// A spike of no width at the front: the wall rises from the first point (0, 4) to (0, 8) and falls
// back along itself to (0, 5), then the profile runs to (−3, 5), up to (−3, 8), along to (−6, 8). The
// part's face stands at z 0 up to x 5 (where the profile leaves z 0); above 5 the walls have stock on
// both sides. Top 8, bottom 4, MID 2.5: levels 6, 4; start (1, 9). The descent down the face from
// the spike's top is no undercut.
//  pass 1 (6, above the face): through the spike to the wall at −3, up it to 8; retract (−2, 9); back
//    to z 1.
//  pass 2 (4, below the face's top): G1 to the face at z 0, up it to its top (0, 5), along to (−3, 5),
//    up to the previous level 6; retract (−2, 7).
//  Return, X first: (−2, 9), (1, 9). Every feed at FF1.
// (Before: the face's top was the walls' lowest point, 4, and pass 1 met the rising wall at (0, 6),
// went up it to 8 and stopped: the band between 6 and 8 over the groove stayed, 'complete' in the
// fuzz, seed 12927597250111814412.)
TEST(SiemensFrontPockets, ALevelRunsThroughASpikeOfNoWidthAtTheFront) {
  const SiemensContour c = polyline("P", {{0, 4}, {0, 8}, {0, 5}, {-3, 5}, {-3, 8}, {-6, 8}});
  const auto out = roughWithCycle95(c, 2.5);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 6}, "pass", 1},
                             {G1, {-3, 6}, "pass", 1},
                             {G1, {-3, 8}, "pass", 1},
                             {G0, {-2, 9}, "pass", 1},
                             {G0, {1, 9}, "pass", 1},
                             {G0, {1, 4}, "pass", 2},
                             {G1, {0, 4}, "pass", 2},
                             {G1, {0, 5}, "pass", 2},
                             {G1, {-3, 5}, "pass", 2},
                             {G1, {-3, 6}, "pass", 2},
                             {G0, {-2, 7}, "pass", 2},
                             {G0, {-2, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
  expectEveryFeedFrom(out.moves, 0, 0.2);
}

// A spike of no width at the front, and a pocket behind a lower spike further on: (0, 4) → (0, 8) →
// (0, 5) → (−3, 5) → (−3, 7) → back down to (−3, 5) → (−6, 5) → (−6, 8) → (−8, 8). The wall falling
// down the face from the first spike's top is no undercut, and only that wall; the descent at −3
// from (−3, 7) is a pocket (−3 … −6, down to 5) the main passes do not reach. Top 8, bottom 4, MID
// 2.5: levels 6, 4; start (1, 9). The face stands up to x 5 (where the profile leaves z 0).
//  pass 1 (6): through the first spike to the second at −3, up it to its top 7, where the profile
//    turns down; retract (−2, 8); back (1, 8).
//  pass 2 (4, below the face's top): to the face (0, 4), up to (0, 5), along to (−3, 5), up to 6;
//    retract (−2, 7).
//  The pocket: top 8 (the lowest level above its rim 7: the top), bottom 5: steps of 1.5, 6.5 and 5,
//  at FF2. G0 up to the start's height (−2, 9).
//  pass 3 (6.5): G0 to (−3, 9), G1 down the wall to (−3, 6.5), across to the rising side (−6, 6.5), up
//    to the previous level 8; retract (−5, 9).
//  pass 4 (5, the lowest): G0 to (−3, 9), G1 down to (−3, 5), along the bottom to (−6, 5), up to 6.5;
//    retract (−5, 7.5).
//  Return, X first: (−5, 9), (1, 9).
// (Before: the walk from the first spike's descent ran on to where the profile is back at the top 8,
// at −6, and took the second pocket with it as no undercut: its stock stayed, 'complete' in the fuzz,
// seed 6552314345380442963.)
TEST(SiemensFrontPockets, APocketBehindASpikeAfterTheFrontIsAnUndercut) {
  const SiemensContour c =
      polyline("Q", {{0, 4}, {0, 8}, {0, 5}, {-3, 5}, {-3, 7}, {-3, 5}, {-6, 5}, {-6, 8}, {-8, 8}});
  const auto out = roughWithCycle95(c, 2.5);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 6}, "pass", 1},
                             {G1, {-3, 6}, "pass", 1},
                             {G1, {-3, 7}, "pass", 1},
                             {G0, {-2, 8}, "pass", 1},
                             {G0, {1, 8}, "pass", 1},
                             {G0, {1, 4}, "pass", 2},
                             {G1, {0, 4}, "pass", 2},
                             {G1, {0, 5}, "pass", 2},
                             {G1, {-3, 5}, "pass", 2},
                             {G1, {-3, 6}, "pass", 2},
                             {G0, {-2, 7}, "pass", 2},
                             {G0, {-2, 9}, "pass", 3},
                             {G0, {-3, 9}, "pass", 3},
                             {G1, {-3, 6.5}, "pass", 3},
                             {G1, {-6, 6.5}, "pass", 3},
                             {G1, {-6, 8}, "pass", 3},
                             {G0, {-5, 9}, "pass", 3},
                             {G0, {-3, 9}, "pass", 4},
                             {G1, {-3, 5}, "pass", 4},
                             {G1, {-6, 5}, "pass", 4},
                             {G1, {-6, 6.5}, "pass", 4},
                             {G0, {-5, 7.5}, "pass", 4},
                             {G0, {-5, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
}

// A pocket open to the profile's end holding a bump: (0, 8) → (−2, 8) → down to (−4, 4) → up to (−5, 6)
// → down to (−10, 3), the profile's lowest point at its end (gentler than 45°). The first point is the
// top, so the face stands up to 8. Top 8, bottom 3, MID 3: levels 5.5, 3; start (1, 9).
//  pass 1 (5.5): to the face (0, 5.5); retract (1, 6.5).   pass 2 (3): to (0, 3); retract (1, 4).
//  The pocket: rim (−2, 8), no rising side (its lowest point is the end), top 8: steps of 2.5, 5.5 and
//  3, at FF2. G0 up to the start's height (1, 9).
//  pass 3 (5.5): G0 to (−2, 9), G1 down to the rim (−2, 8), down the falling side to (−3.25, 5.5) (x =
//    8 + 2(z + 2)); across to where the level meets the bump, (−4.75, 5.5) (x = 4 − 2(z + 4)); along
//    the profile through its descents: up to (−5, 6), down to the end (−10, 3); retract (−9, 4).
//  pass 4 (3, the lowest): back along z at 4 would run through the bump (its top 6 stands between):
//    G0 up to (−9, 9) first, then to (−3.25, 9); G1 down to (−3.25, 5.5), along the profile: (−4, 4),
//    (−5, 6), (−10, 3); retract (−9, 4).
//  Return, X first: (−9, 9), (1, 9).
// (Before: pass 3 ran along its level to the end's z straight through the bump — the rising side was
// looked for only in pockets that rise back — and the G0 between pocket passes ran along z at the
// retract height through it: no-gouge, fuzz seed 14727398570297873640.)
TEST(SiemensPockets, APocketOpenToTheEndGoesOverTheBumpItHolds) {
  const SiemensContour c = polyline("B", {{0, 8}, {-2, 8}, {-4, 4}, {-5, 6}, {-10, 3}});
  const auto out = roughWithCycle95(c, 3);
  expectMoves(out.moves, {
                             {G0, {1, 9}, "approach"},
                             {G0, {1, 5.5}, "pass", 1},
                             {G1, {0, 5.5}, "pass", 1},
                             {G0, {1, 6.5}, "pass", 1},
                             {G0, {1, 3}, "pass", 2},
                             {G1, {0, 3}, "pass", 2},
                             {G0, {1, 4}, "pass", 2},
                             {G0, {1, 9}, "pass", 3},
                             {G0, {-2, 9}, "pass", 3},
                             {G1, {-2, 8}, "pass", 3},
                             {G1, {-3.25, 5.5}, "pass", 3},
                             {G1, {-4.75, 5.5}, "pass", 3},
                             {G1, {-5, 6}, "pass", 3},
                             {G1, {-10, 3}, "pass", 3},
                             {G0, {-9, 4}, "pass", 3},
                             {G0, {-9, 9}, "pass", 4},
                             {G0, {-3.25, 9}, "pass", 4},
                             {G1, {-3.25, 5.5}, "pass", 4},
                             {G1, {-4, 4}, "pass", 4},
                             {G1, {-5, 6}, "pass", 4},
                             {G1, {-10, 3}, "pass", 4},
                             {G0, {-9, 4}, "pass", 4},
                             {G0, {-9, 9}, "return"},
                             {G0, {1, 9}, "return"},
                         });
}

// A pocket narrower than _VRT (1): (0, 6) → (−2, 6), down the falling wall to (−2, 2), along the
// bottom to (−2.5, 2), up the rising wall to (−2.5, 6), along to (−10, 6). Top 6, bottom 2, MID 2:
// main levels 4 and 2 (both below the face's top 6); start (1, 7).
//  pass 1 (4): G0 down to (1, 4), G1 to the face at z 0; retract (1, 5) (no G0 back: at the start's z).
//  pass 2 (2): likewise; retract (1, 3).
//  The pocket: rim (−2, 6), top 6 (no level above the rim), bottom 2, levels 4 and 2; G0 up to (1, 7).
//  pass 3 (4): G0 along to above the rim's wall (−2, 7), G1 down it to (−2, 4), across to the rising
//    wall (−2.5, 4), up it to 6. Retract: the diagonal to (−1.5, 7) passes z −2 at 6.5, above the falling
//    wall's top 6: by _VRT in each axis.
//  pass 4 (2, the lowest): G0 to (−2, 7), G1 down the wall to (−2, 2), along the bottom to (−2.5, 2), up
//    to 4. Retract: the diagonal to (−1.5, 5) would pass z −2 at 4.5, below the falling wall's top 6 —
//    into the part: the tool lifts by _VRT along X only, to (−2.5, 5) (CYCLE95.UNDERCUT note).
//  Return: X first (−2.5, 7), then Z (1, 7).
// (Before: the retract went to (−1.5, 5) through the wall: no-gouge, fuzz seed 7566792160692496541.)
TEST(SiemensPockets, ARetractWiderThanThePocketLiftsAlongXOnly) {
  const SiemensContour c = polyline("N", {{0, 6}, {-2, 6}, {-2, 2}, {-2.5, 2}, {-2.5, 6}, {-10, 6}});
  expectMoves(roughWithCycle95(c, 2).moves, {
                                                 {G0, {1, 7}, "approach"},
                                                 {G0, {1, 4}, "pass", 1},
                                                 {G1, {0, 4}, "pass", 1},
                                                 {G0, {1, 5}, "pass", 1},
                                                 {G0, {1, 2}, "pass", 2},
                                                 {G1, {0, 2}, "pass", 2},
                                                 {G0, {1, 3}, "pass", 2},
                                                 {G0, {1, 7}, "pass", 3},
                                                 {G0, {-2, 7}, "pass", 3},
                                                 {G1, {-2, 4}, "pass", 3},
                                                 {G1, {-2.5, 4}, "pass", 3},
                                                 {G1, {-2.5, 6}, "pass", 3},
                                                 {G0, {-1.5, 7}, "pass", 3},
                                                 {G0, {-2, 7}, "pass", 4},
                                                 {G1, {-2, 2}, "pass", 4},
                                                 {G1, {-2.5, 2}, "pass", 4},
                                                 {G1, {-2.5, 4}, "pass", 4},
                                                 {G0, {-2.5, 5}, "pass", 4},
                                                 {G0, {-2.5, 7}, "return"},
                                                 {G0, {1, 7}, "return"},
                                             });
}

// A contour whose first element falls away from the front at 45°: (0, 4) → (−2, 2) → (−3, 2) →
// (−3, 5), FAL 0.2·√2 (f), _VRT 0.1, MID 2. The profile, the contour offset by f on the stock side:
// the slope moved by (−0.2, +0.2) — from (−0.2, 4.2), x = z + 4.4 —, the bottom at 2 + f, the wall at
// −3 + f; the slope meets the bottom at (f − 2.4, 2 + f), the bottom the wall at (−3 + f, 2 + f); the
// profile ends at (−3 + f, 5). Its largest z is −0.2, behind the contour's first point: the part's
// face stands at z 0, so the start is _VRT beyond the face, (0.1, 5.1) (LCYC95.START note), not
// beyond the profile alone (−0.1, 5.1). Top 5, bottom 2 + f, 2 levels: 3.5 + f/2 and 2 + f.
//  pass 1 (3.5 + f/2, below the face's top 4.2): G0 straight down to (0.1, 3.5 + f/2), G1 to the
//    face (0, 3.5 + f/2), up it to the contour's first point (0, 4), across the allowance to the
//    profile's start (−0.2, 4.2), along the profile through the front stretch — down the slope,
//    along the bottom, up the wall to the previous level 5; retract (−2.9 + f, 5.1); G0 back to z 0.1.
//  pass 2 (2 + f): G0 down to (0.1, 2 + f), G1 to the face; the face's foot (4.2) stands above the
//    previous level: no cleanup; retract (0.1, 2.1 + f).
//  Return: X first to (0.1, 5.1); Z already there.
// (Before: the start was (−0.1, 5.1), and each infeed ran back along the cut axis to the face at
// z 0 — siemens-infeed, fuzz seed 17617655989876150606.)
TEST(SiemensFrontPockets, TheStartLiesBeyondThePartsFaceWhenTheAllowanceMovesTheProfileBehindIt) {
  const SiemensContour c = polyline("S", {{0, 4}, {-2, 2}, {-3, 2}, {-3, 5}});
  const double f = 0.2 * std::sqrt(2.0);
  const double l1 = 3.5 + f / 2, l2 = 2 + f;
  expectMoves(roughWithCycle95(c, 2, f, 0.1).moves, {
                                                         {G0, {0.1, 5.1}, "approach"},
                                                         {G0, {0.1, l1}, "pass", 1},
                                                         {G1, {0, l1}, "pass", 1},
                                                         {G1, {0, 4}, "pass", 1},
                                                         {G1, {-0.2, 4.2}, "pass", 1},
                                                         {G1, {f - 2.4, 2 + f}, "pass", 1},
                                                         {G1, {-3 + f, 2 + f}, "pass", 1},
                                                         {G1, {-3 + f, 5}, "pass", 1},
                                                         {G0, {-2.9 + f, 5.1}, "pass", 1},
                                                         {G0, {0.1, 5.1}, "pass", 1},
                                                         {G0, {0.1, l2}, "pass", 2},
                                                         {G1, {0, l2}, "pass", 2},
                                                         {G0, {0.1, l2 + 0.1}, "pass", 2},
                                                         {G0, {0.1, 5.1}, "return"},
                                                     });
}

// A bump beginning where the pocket's falling side reaches a pocket level: (0, 6) → (−2, 6), down the
// slope to (−4, 4), up the bump to (−5, 5), down to (−6, 4) and (−8, 2), up the wall to (−8, 6), along
// to (−10, 6). Top 6, bottom 2, MID 2: main levels 4 and 2, both below the face's top 6; start (1, 7).
//  pass 1 (4), pass 2 (2): to the face at z 0; retract (1, 5), (1, 3).
//  The pocket: rim (−2, 6), top 6, lowest point (−8, 2), levels 4 and 2; G0 up to (1, 7).
//  pass 3 (4): G0 to above the rim (−2, 7), G1 down to it, down the slope to (−4, 4) — where the bump
//    rises from the level at once: the level meets the pocket's profile there, so the pass goes on
//    along the profile from there (CYCLE95.UNDERCUT note) — over the bump (−5, 5), down to (−6, 4) and
//    (−8, 2), up the wall to the previous level 6; retract (−7, 7).
//  pass 4 (2, the lowest): G0 to above (−4, 4), G1 down to it, along the falling side over the bump to
//    (−8, 2), up the wall to 4; retract (−7, 5).
//  Return: (−7, 7), (1, 7).
// (Before: pass 3 crossed at the level from (−4, 4) to (−6, 4), under the bump: no-gouge, fuzz seed
// 15931212366711559875.)
TEST(SiemensPockets, ABumpRisingWhereTheFallingSideReachesTheLevelIsFollowed) {
  const SiemensContour c = polyline("U", {{0, 6}, {-2, 6}, {-4, 4}, {-5, 5}, {-6, 4}, {-8, 2}, {-8, 6}, {-10, 6}});
  expectMoves(roughWithCycle95(c, 2).moves, {
                                                 {G0, {1, 7}, "approach"},
                                                 {G0, {1, 4}, "pass", 1},
                                                 {G1, {0, 4}, "pass", 1},
                                                 {G0, {1, 5}, "pass", 1},
                                                 {G0, {1, 2}, "pass", 2},
                                                 {G1, {0, 2}, "pass", 2},
                                                 {G0, {1, 3}, "pass", 2},
                                                 {G0, {1, 7}, "pass", 3},
                                                 {G0, {-2, 7}, "pass", 3},
                                                 {G1, {-2, 6}, "pass", 3},
                                                 {G1, {-4, 4}, "pass", 3},
                                                 {G1, {-5, 5}, "pass", 3},
                                                 {G1, {-6, 4}, "pass", 3},
                                                 {G1, {-8, 2}, "pass", 3},
                                                 {G1, {-8, 6}, "pass", 3},
                                                 {G0, {-7, 7}, "pass", 3},
                                                 {G0, {-4, 7}, "pass", 4},
                                                 {G1, {-4, 4}, "pass", 4},
                                                 {G1, {-5, 5}, "pass", 4},
                                                 {G1, {-6, 4}, "pass", 4},
                                                 {G1, {-8, 2}, "pass", 4},
                                                 {G1, {-8, 4}, "pass", 4},
                                                 {G0, {-7, 5}, "pass", 4},
                                                 {G0, {-7, 7}, "return"},
                                                 {G0, {1, 7}, "return"},
                                             });
}

// A pocket level above the rim with a bump standing above it: (0, 2) → (−1, 2), up the wall to the rim
// (−1, 4.2), down to (−2, 3), up the bump to (−3, 5), down to (−4, 2.5), up to the end (−5.1, 8) (x = 6
// at z −4.7, 4.25 at −4.35). Top 8, bottom 2, MID 2: main levels 6, 4, 2; start (1, 9).
//  pass 1 (6): to (−4.7, 6), up to (−5.1, 8); retract (−4.1, 9); back.
//  pass 2 (4): to the wall (−1, 4), up to the rim 4.2, where the profile turns down; retract (0, 5.2);
//    back.
//  pass 3 (2): to (0, 2) (the flat lies on the level), along it, up the wall to 4; retract (0, 5).
//  The pocket: rim (−1, 4.2), top 6 (the lowest level above the rim), back at 6 at (−4.7, 6), lowest
//  point (−4, 2.5): depth 3.5, two levels of 1.75: 4.25 (above the rim) and 2.5. G0 up to (0, 9).
//  pass 4 (4.25): a level above the rim goes down at the rim's z: G0 (−1, 9), G1 (−1, 4.25), across to
//    where the level meets the bump, (−2.625, 4.25), over the bump (−3, 5), down to (−4, 2.5), up to 6
//    at (−4.7, 6); retract (−3.7, 7).
//  pass 5 (2.5, the lowest): G0 (−1, 7), G1 down to the rim, along the falling side — (−2, 3), over the
//    bump, (−4, 2.5) —, up to 4.25 at (−4.35, 4.25); retract (−3.35, 5.25).
//  Return: (−3.35, 9), (1, 9).
// (Before: pass 4 went down where its level first meets the pocket's profile, on the bump's rising
// side at −2.625, and crossed at 4.25 under the bump to its far side: no-gouge, fuzz seed
// 5698905055672233322.)
TEST(SiemensPockets, APocketLevelAboveTheRimGoesDownAtTheRimNotOnABump) {
  const SiemensContour c = polyline("V", {{0, 2}, {-1, 2}, {-1, 4.2}, {-2, 3}, {-3, 5}, {-4, 2.5}, {-5.1, 8}});
  expectMoves(roughWithCycle95(c, 2).moves, {
                                                 {G0, {1, 9}, "approach"},
                                                 {G0, {1, 6}, "pass", 1},
                                                 {G1, {-4.7, 6}, "pass", 1},
                                                 {G1, {-5.1, 8}, "pass", 1},
                                                 {G0, {-4.1, 9}, "pass", 1},
                                                 {G0, {1, 9}, "pass", 1},
                                                 {G0, {1, 4}, "pass", 2},
                                                 {G1, {-1, 4}, "pass", 2},
                                                 {G1, {-1, 4.2}, "pass", 2},
                                                 {G0, {0, 5.2}, "pass", 2},
                                                 {G0, {1, 5.2}, "pass", 2},
                                                 {G0, {1, 2}, "pass", 3},
                                                 {G1, {0, 2}, "pass", 3},
                                                 {G1, {-1, 2}, "pass", 3},
                                                 {G1, {-1, 4}, "pass", 3},
                                                 {G0, {0, 5}, "pass", 3},
                                                 {G0, {0, 9}, "pass", 4},
                                                 {G0, {-1, 9}, "pass", 4},
                                                 {G1, {-1, 4.25}, "pass", 4},
                                                 {G1, {-2.625, 4.25}, "pass", 4},
                                                 {G1, {-3, 5}, "pass", 4},
                                                 {G1, {-4, 2.5}, "pass", 4},
                                                 {G1, {-4.7, 6}, "pass", 4},
                                                 {G0, {-3.7, 7}, "pass", 4},
                                                 {G0, {-1, 7}, "pass", 5},
                                                 {G1, {-1, 4.2}, "pass", 5},
                                                 {G1, {-2, 3}, "pass", 5},
                                                 {G1, {-3, 5}, "pass", 5},
                                                 {G1, {-4, 2.5}, "pass", 5},
                                                 {G1, {-4.35, 4.25}, "pass", 5},
                                                 {G0, {-3.35, 5.25}, "pass", 5},
                                                 {G0, {-3.35, 9}, "return"},
                                                 {G0, {1, 9}, "return"},
                                             });
}

// The front stretch ending inside an arc that goes on over its top: (0, 2) falls to (−1, 0), a line
// rises to (−3 + √2, 1.5 + √2), an arc of radius 2 about (−3, 1.5) (a quarter circle) runs over its top
// (−3, 3.5) to (−3 − √2, 1.5 + √2), a line falls to (−5, 1), one rises to the end (−6, 4). Top 4,
// bottom 0, MID 1: levels 3, 2, 1, 0; start (1, 5). The profile falls from its first point (x 2): the
// front stretch runs to where it first rises back to 3, the lowest level above 2 — on the arc's
// rising half at z −3 + √(4 − 1.5²) = −1.677124 — and no further, though the arc goes on.
//  pass 1 (3, previous 4): G0 down to (1, 3), G1 to where the level meets the arc, (−1.677124, 3), along
//    the arc up to its top (−3, 3.5), where the profile turns down (an undercut begins: the stretch
//    ended before it); retract (−2, 4.5); G0 back to z 1.
// (Before: the cleanup went through the arc's descent to its end (−3 − √2, 1.5 + √2) — the whole
// element counted as the stretch's —, fuzz seed 15261219683670512766, an allowance rounding there.)
TEST(SiemensFrontPockets, TheFrontStretchEndsWhereItReachesItsLevelNotAtItsElementsEnd) {
  const double r2 = std::sqrt(2.0);
  SiemensContour c = polyline("T", {{0, 2}, {-1, 0}, {-3 + r2, 1.5 + r2}});
  c.segments.push_back(arc(SegmentKind::ArcCCW, {-3 + r2, 1.5 + r2}, {-3 - r2, 1.5 + r2}, {-3, 1.5}, 3));
  c.segments.push_back(line({-3 - r2, 1.5 + r2}, {-5, 1}, 4));
  c.segments.push_back(line({-5, 1}, {-6, 4}, 5));
  const std::vector<Move> all = roughWithCycle95(c, 1).moves;
  std::vector<Move> firstPass;
  std::copy_if(all.begin(), all.end(), std::back_inserter(firstPass), [](const Move& m) { return m.pass == 1; });
  const double hitZ = -3 + std::sqrt(4 - 1.5 * 1.5);
  expectMoves(firstPass, {
                             {G0, {1, 3}, "pass", 1},
                             {G1, {hitZ, 3}, "pass", 1},
                             {G1, {-3, 3.5}, "pass", 1},
                             {G0, {-2, 4.5}, "pass", 1},
                             {G0, {1, 4.5}, "pass", 1},
                         });
  EXPECT_EQ(firstPass[2].shape, SegmentKind::ArcCCW);
}

std::vector<Point> cornersOf(const std::vector<Segment>& path) {
  std::vector<Point> points{path.front().from};
  for (const Segment& s : path) points.push_back(s.to);
  return points;
}

void expectCorners(const std::vector<Segment>& path, const std::vector<Point>& want) {
  const std::vector<Point> got = cornersOf(path);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].z, want[i].z, 1e-9) << "corner " << i;
    EXPECT_NEAR(got[i].x, want[i].x, 1e-9) << "corner " << i;
  }
}

// A groove from z −5 to −10, 3 deep, in a collar of radius 6 (the frame of longitudinal external).
// FALZ 0.5 is left on the stock side of each wall: the wall at z −5 falls towards the axis with the
// collar (part) at +z, so its allowance lies towards −z: z −5.5; the wall at −10 rises with the part
// at −z: z −9.5; the face at z 0 (stock in front): z 0.5. The groove's bottom and the collar's top
// face across z: no FALZ on them (FALX 0). The profile: (0.5, 0) → (0.5, 6) → (−5.5, 6) → (−5.5, 3)
// → (−9.5, 3) → (−9.5, 6) → (−20, 6). (A uniform shift by +0.5 put the first wall at −4.5: inside
// the collar.)
TEST(SiemensAxisAllowance, FalzLiesOnTheStockSideOfEachWall) {
  const std::vector<Segment> groove =
      polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}}).segments;
  expectCorners(withAxisAllowances(groove, {0.5, 0}),
                {{0.5, 0}, {0.5, 6}, {-5.5, 6}, {-5.5, 3}, {-9.5, 3}, {-9.5, 6}, {-20, 6}});
}

// FALX 0.25 as well: the face (and the contour's first point on it) moves by the rectangle's corner
// on its stock side, (+0.5, +0.25); the diameters move up by 0.25; the convex corners are closed
// along the rectangle (0.5 × 0.25), the concave ones trimmed: (0.5, 0.25) → (0.5, 6.25) →
// (−5.5, 6.25) → (−5.5, 3.25) → (−9.5, 3.25) → (−9.5, 6.25) → (−20, 6.25).
TEST(SiemensAxisAllowance, BothAllowancesGrowTheProfileByTheRectangle) {
  const std::vector<Segment> groove =
      polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}}).segments;
  expectCorners(withAxisAllowances(groove, {0.5, 0.25}),
                {{0.5, 0.25}, {0.5, 6.25}, {-5.5, 6.25}, {-5.5, 3.25}, {-9.5, 3.25}, {-9.5, 6.25}, {-20, 6.25}});
}

// A falling slope (a cone narrowing towards −z, its stock above and towards −z) moves by
// (−FALZ, +FALX); the rising slope after it by (+FALZ, +FALX). The V (0, 6) → (−4, 2) → (−8, 6)
// with FALZ 0.5, FALX 0.5: the falling line through (−0.5, 6.5) and (−4.5, 2.5), the rising one
// through (−3.5, 2.5) and (−7.5, 6.5): x = z + 7 and x = −z − 1 cross at (−4, 3). Before the falling line, the face (stock towards +z) at z 0.5
// from x 6 up: the profile begins at the rectangle's corner (0.5, 6.5) and runs along x 6.5 to the
// falling line's shifted start (−0.5, 6.5).
TEST(SiemensAxisAllowance, ASlopeFallingTowardsTheAxisMovesTowardsMinusZ) {
  const std::vector<Segment> v = polyline("V", {{0, 6}, {-4, 2}, {-8, 6}}).segments;
  expectCorners(withAxisAllowances(v, {0.5, 0.5}), {{0.5, 6.5}, {-0.5, 6.5}, {-4, 3}, {-7.5, 6.5}});
}

// Planned (CYCLE95 VARI 1, MID 2.5, FALZ 0.5): every roughing feed below the collar's top (x < 6)
// between the groove's walls stays between z −5.5 and −9.5 — the walls' allowances — and the
// groove's corners (−5.5, 3) and (−9.5, 3) are reached.
TEST(SiemensAxisAllowance, TheGroovePassesKeepFalzOffBothWalls) {
  const SiemensContour groove = polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}});
  Cycle95Parameters p;
  p.contourName = "G";
  p.infeed = 2.5;
  p.allowanceZ = 0.5;
  p.roughingFeed = 0.2;
  p.undercutFeed = 0.05;
  p.finishingFeed = 0.1;
  p.type = machiningTypeOf(1).value();
  p.retract = 1;
  SiemensCycleCall call;
  call.line = 4;
  call.position = {5, 15};
  call.contour = &groove;
  const auto out = planCycle95(call, p);
  bool leftCorner = false, rightCorner = false;
  for (const Move& m : out.moves) {
    if (m.kind != MoveKind::Feed || m.to.x >= 6 - 1e-9 || m.to.z > -1) continue;
    EXPECT_LE(m.to.z, -5.5 + 1e-9) << m.to.z << " " << m.to.x;
    EXPECT_GE(m.to.z, -9.5 - 1e-9) << m.to.z << " " << m.to.x;
    leftCorner = leftCorner || nearlyEqual(m.to, {-5.5, 3}, 1e-9);
    rightCorner = rightCorner || nearlyEqual(m.to, {-9.5, 3}, 1e-9);
  }
  EXPECT_TRUE(leftCorner);
  EXPECT_TRUE(rightCorner);
}

// Found by fuzz --cycles siemens --seed 1 once FALZ lay on each element's stock side: a dome rising to
// its top (G3 X8.38 Z-1.49 CR=0.79 about (−1.49, 3.4), radius) and a line falling from there to
// (−2.34, 3.79). FALZ 0.02 moves the dome by +0.02 (its top to (−1.47, 4.19)), the falling line by
// −0.02 (its start to (−1.51, 4.19)); a flat at 4.19 joins them. Top 4.78 (the contour's end), bottom
// 3.01 (its first point), MID 0.65: 3 steps of 0.59, levels 4.19, 3.6, 3.01. Pass 1 at 4.19 (a rounding
// error below the dome's top) meets the dome at its top and goes on along the flat to where the
// profile falls, z −1.51 — before, it stopped at −1.47, reading the dome's last sliver as an arc
// starting at its top, and left the band −1.51…−1.47 above 4.19 standing (`complete`).
TEST(SiemensAxisAllowance, ALevelAtADomesTopFollowsTheFlatFalzAddsToWhereTheProfileFalls) {
  // Through the front end, as the fuzzer wrote it: the diameters halved and the G3's centre corrected
  // leave the dome's end 1.8e-8 before its top and the level a rounding error below it.
  const std::string program =
      "T1 D1\nG0 X11.96 Z1.2\nCYCLE95(\"L1\", 0.65, 0.02, 0, 0, 0.16, 0.16, 0.06, 1, 0, 0, 0.15)\nM02\n";
  const std::string contour =
      "G1X6.02Z0\nG1X6.58Z0\nG1X6.8Z-0.18\nG1X6.8Z-0.7\nG3X8.38Z-1.49CR=0.79\nG1X7.58Z-2.34\n"
      "G3X8.88Z-2.99CR=0.65\nG1X9.56Z-3.54\nRET\n";
  PlanRequest request{program, "dome.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  double deepest = 0;
  for (const Move& m : path.moves) {
    if (m.phase == MovePhase::Pass && m.pass == 1 && m.kind == MoveKind::Feed) deepest = std::min(deepest, m.to.z);
  }
  EXPECT_NEAR(deepest, -1.51, 1e-6);
}

// A rounding tangent to the face line before it (CYCLE95 VARI 4, face internal roughing, FALX on
// the transverse axis): with the allowance the line's end and the rounding's start overlap, and the
// two meet where the line touches the rounding's circle. Found by the metamorphic relation scale-k on
// a fuzzer's case: the part planned, the same part 2.5 times as large alarmed "a groove narrower than
// the allowances" — the tangency was decided on the discriminant, which grows with the part's size to
// the fourth power, against a fixed 1e-12. Every scale of the part plans (the allowance scaled too).
TEST(SiemensAxisAllowance, ARoundingTangentToTheLineBeforeItPlansAtEveryScale) {
  for (const double k : {1.0, 2.5, 10.0, 0.4}) {
    const auto n = [k](double v) {
      char text[32];
      std::snprintf(text, sizeof text, "%.6g", v * k);
      return std::string(text);
    };
    const std::string program = "T1 D1\nG0 X" + n(13.22) + " Z" + n(-0.92) + "\nCYCLE95(\"L1\", " + n(0.5) +
                                ", 0, " + n(0.22) + ", 0, 0.1, 0.1, 0.05, 4, 0, 0, " + n(0.1) + ")\nM02\n";
    const std::string contour = "G1X" + n(11.58) + "Z0\nG1X" + n(6.72) + "Z0RND=" + n(0.26) + "\nG1X" + n(4.18) +
                                "Z" + n(-0.1) + "\nRET\n";
    PlanRequest request{program, "tangent.mpf", "sinumerik-802d", {}, {}};
    request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
    const Toolpath path = planWithReference(request);
    EXPECT_FALSE(path.alarm) << "scale " << k << ": " << path.alarm->message;
    EXPECT_FALSE(path.moves.empty()) << "scale " << k;
  }
}

}  // namespace
}  // namespace cyclecert
