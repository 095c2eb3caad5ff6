// The SINUMERIK oracles (oracles/siemens/) on hand-built paths: each passes a path that follows the
// rules and reports a path that breaks its rule — a 45° retract, R108 as the step, an undercut at FF1,
// a missing return, a straight LCYC95 infeed, a G1 CYCLE95 infeed, an uninterrupted cut with DAM —
// and the alarm oracle expects the alarm the rules demand. Every expected move is written here by
// hand from the rules (x radius; the contour L1 is (z0,x10) → (−10,10) → (−10,16) → (−20,16) →
// (−20,20), so the start is (z1,x21) and the depth 10 divides into 4 steps of 2.5 for R108 = 3).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "oracles/judgement.h"
#include "oracles/siemens/siemens_allowance_rectangle.h"
#include "tests/siemens_oracle_paths.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

TEST(SiemensOracles, Lcyc95RoughingByTheRulesPasses) {
  const std::vector<Finding> f = judged(lcyc95Program("1"), "sinumerik-802s", lcyc95Roughing().path);
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

TEST(SiemensOracles, RetractAt45DegreesIsReported) {
  // Pass 1 retracts 1 mm at 45° (0.707107 per axis) instead of 1 mm in each axis.
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.feed(1, 17.5, 0.3).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-20 + std::sqrt(0.5), 20 + std::sqrt(0.5)).rapid(1, 21);
  p.feed(1, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17.5, 0.3).rapid(-19, 18.5).rapid(1, 18.5);
  p.feed(1, 12.5, 0.3).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.feed(1, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(1, 21);
  const std::vector<Finding> f = of(judged(lcyc95Program("1"), "sinumerik-802s", p.path), "siemens-retract");
  ASSERT_EQ(f.size(), 1u) << findingsText(f);
  EXPECT_EQ(f[0].move, 4u);
  EXPECT_TRUE(f[0].witness.segment.has_value());
  EXPECT_NE(f[0].message.find("R110=1"), std::string::npos) << f[0].message;
}

TEST(SiemensOracles, StepOfR108WithAShortLastStepIsReported) {
  // Levels 17, 14, 11 and a last step of 1 to 10, instead of four equal steps of 2.5.
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.feed(1, 17, 0.3).feed(-20, 17, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.feed(1, 14, 0.3).feed(-10, 14, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17, 0.3).rapid(-19, 18).rapid(1, 18);
  p.feed(1, 11, 0.3).feed(-10, 11, 0.3).feed(-10, 14, 0.3).rapid(-9, 15).rapid(1, 15);
  p.feed(1, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 11, 0.3).rapid(-9, 12);
  p.rapid(1, 21);
  const std::vector<Finding> all = judged(lcyc95Program("1"), "sinumerik-802s", p.path);
  const std::vector<Finding> f = of(all, "siemens-infeed-steps");
  ASSERT_EQ(f.size(), 3u) << findingsText(all);
  EXPECT_EQ(f[0].move, 2u);   // the cut at 17
  EXPECT_EQ(f[1].move, 7u);   // at 14
  EXPECT_EQ(f[2].move, 14u);  // at 11
  EXPECT_NE(f[0].message.find("4 equal steps of 2.5"), std::string::npos) << f[0].message;
  EXPECT_TRUE(of(all, "siemens-retract").empty()) << findingsText(all);
}

TEST(SiemensOracles, Lcyc95MissingReturnToTheStartIsReported) {
  PathBuilder p = lcyc95Roughing();
  p.path.moves.pop_back();  // the G0 to S after the last retract
  EXPECT_EQ(of(judged(lcyc95Program("1"), "sinumerik-802s", p.path), "siemens-returns").size(), 1u);
}

TEST(SiemensOracles, Lcyc95ReturnAxisByAxisIsReported) {
  PathBuilder p = lcyc95Roughing();
  p.path.moves.pop_back();
  p.rapid(-9, 21).rapid(1, 21);  // LCYC95 returns in both axes together
  EXPECT_EQ(of(judged(lcyc95Program("1"), "sinumerik-802s", p.path), "siemens-returns").size(), 1u);
}

TEST(SiemensOracles, Lcyc95RoughingFeedOtherThanR111IsReported) {
  PathBuilder p = lcyc95Roughing();
  p.path.moves[2].feed = 0.1;  // the cut of pass 1 at R112
  const std::vector<Finding> f = of(judged(lcyc95Program("1"), "sinumerik-802s", p.path), "siemens-feeds");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].move, 2u);
}

TEST(SiemensOracles, Lcyc95InfeedAngle) {
  // R109=7: an infeed of depth d runs d·tan 7° along −z: from (1,21) to 17.5 ends at z 1 − 3.5·tan 7°.
  const double t = std::tan(7 * 3.14159265358979323846 / 180);
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.feed(1 - 3.5 * t, 17.5, 0.3).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.feed(1 - 6 * t, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17.5, 0.3).rapid(-19, 18.5).rapid(1, 18.5);
  p.feed(1 - 6 * t, 12.5, 0.3).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.feed(1 - 6 * t, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(1, 21);
  const std::vector<Finding> good = judged(lcyc95Program("1", "7"), "sinumerik-802s", p.path);
  EXPECT_TRUE(good.empty()) << findingsText(good);
  // The same path for R109=0 infeeds at an angle; the straight path for R109=7 does not.
  EXPECT_EQ(of(judged(lcyc95Program("1", "0"), "sinumerik-802s", p.path), "siemens-infeed").size(), 4u);
  EXPECT_EQ(of(judged(lcyc95Program("1", "7"), "sinumerik-802s", lcyc95Roughing().path), "siemens-infeed").size(), 4u);
}

// LCYC95 R105=9 (complete): the passes, no return after the last retract; the finishing approach
// axis by axis (x first), G0 to the contour start (0,10), the contour at R112, G0 back to S.
PathBuilder lcyc95Complete() {
  PathBuilder p = lcyc95Roughing();
  p.path.moves.pop_back();
  p.rapid(-9, 21).rapid(1, 21).rapid(0, 10);
  p.feed(-10, 10, 0.1).feed(-10, 16, 0.1).feed(-20, 16, 0.1).feed(-20, 20, 0.1);
  p.rapid(1, 21);
  return p;
}

TEST(SiemensOracles, Lcyc95CompleteByTheRulesPasses) {
  const std::vector<Finding> f = judged(lcyc95Program("9"), "sinumerik-802s", lcyc95Complete().path);
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

TEST(SiemensOracles, CompleteMachiningReturningAfterRoughingIsReported) {
  // The roughing-only return (both axes to S) before the finishing approach.
  PathBuilder p = lcyc95Roughing();
  p.rapid(0, 10).feed(-10, 10, 0.1).feed(-10, 16, 0.1).feed(-20, 16, 0.1).feed(-20, 20, 0.1).rapid(1, 21);
  EXPECT_EQ(of(judged(lcyc95Program("9"), "sinumerik-802s", p.path), "siemens-returns").size(), 1u);
}

TEST(SiemensOracles, FinishingAtR111AndWithoutTheReturnIsReported) {
  PathBuilder p = lcyc95Complete();
  p.path.moves[p.path.moves.size() - 3].feed = 0.3;
  p.path.moves.pop_back();
  const std::vector<Finding> all = judged(lcyc95Program("9"), "sinumerik-802s", p.path);
  EXPECT_EQ(of(all, "siemens-feeds").size(), 1u) << findingsText(all);
  EXPECT_EQ(of(all, "siemens-returns").size(), 1u) << findingsText(all);
}

TEST(SiemensOracles, Cycle95RoughingByTheRulesPasses) {
  const std::vector<Finding> f = judged(cycle95Program("1"), "sinumerik-802d", cycle95Roughing().path);
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

TEST(SiemensOracles, Cycle95FeedInfeedAndBothAxesReturnAreReported) {
  PathBuilder p = cycle95Roughing();
  p.path.moves[1].kind = MoveKind::Feed;  // the first infeed with G1
  p.path.moves[1].feed = 0.3;
  p.path.moves.pop_back();
  p.path.moves.pop_back();
  p.rapid(1, 21);  // both axes at once
  const std::vector<Finding> all = judged(cycle95Program("1"), "sinumerik-802d", p.path);
  EXPECT_EQ(of(all, "siemens-infeed").size(), 1u) << findingsText(all);
  EXPECT_EQ(of(all, "siemens-returns").size(), 1u) << findingsText(all);
}

TEST(SiemensOracles, Cycle95DamInterruptsTheCutsAlongTheLevels) {
  // DAM 8: pass 1's cut from z1 to z−20 in pieces of 8 (z−7, −15, −20); pass 2's (11 long) at z−7.
  PathBuilder p({2, 25});
  p.rapid(1, 21);
  p.rapid(1, 17.5).feed(-7, 17.5, 0.3).feed(-15, 17.5, 0.3).feed(-20, 17.5, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.rapid(1, 15).feed(-7, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 17.5, 0.3).rapid(-19, 18.5).rapid(1, 18.5);
  p.rapid(1, 12.5).feed(-7, 12.5, 0.3).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.rapid(1, 10).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(-9, 21).rapid(1, 21);
  const std::vector<Finding> good = judged(cycle95Program("1", "8"), "sinumerik-802d", p.path);
  EXPECT_TRUE(good.empty()) << findingsText(good);
  // Without interruptions: pass 1 (21 long), 2 and 3 (11 long) are reported.
  EXPECT_EQ(of(judged(cycle95Program("1", "8"), "sinumerik-802d", cycle95Roughing().path), "siemens-chip-breaking").size(), 3u);
}

TEST(SiemensOracles, Cycle95UndercutAtFF2Passes) {
  const std::vector<Finding> f = judged(grooveProgram(), "sinumerik-802d", grooveRoughing(0.15).path, kGroove, "L3");
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

TEST(SiemensOracles, Cycle95UndercutAtFF1IsReported) {
  const std::vector<Finding> all = judged(grooveProgram(), "sinumerik-802d", grooveRoughing(0.3).path, kGroove, "L3");
  const std::vector<Finding> f = of(all, "siemens-feeds");
  ASSERT_EQ(f.size(), 8u) << findingsText(all);  // the 8 feeds in the pocket
  EXPECT_EQ(f[0].move, 24u);
  EXPECT_NE(f[0].message.find("FF2=0.15"), std::string::npos) << f[0].message;
}

TEST(SiemensOracles, AlarmsTheRulesDemandAreExpected) {
  // 61002: R105 outside 1…12; 61610: R108 = 0 when roughing; 10931: the contour against the
  // finishing direction. An engine that plans instead is reported, naming the code.
  const struct {
    std::string program, subprogram, code;
  } cases[] = {
      {lcyc95Program("13"), kL1, "61002"},
      {"G0 X50 Z2\n_CNAME=\"L1\"\nR105=1 R106=0 R108=0 R109=0\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", kL1, "61610"},
      {lcyc95Program("1"), "G1 X40 Z-20\nX32\nZ-10\nX20\nZ0\nRET\n", "10931"},
  };
  for (const auto& c : cases) {
    const std::vector<Finding> f = of(judged(c.program, "sinumerik-802s", Toolpath{}, c.subprogram), "siemens-alarm");
    ASSERT_EQ(f.size(), 1u) << c.code;
    EXPECT_NE(f[0].message.find(c.code), std::string::npos) << f[0].message;
  }
  // … and the good program alarmed is reported too.
  Toolpath alarmed;
  alarmed.alarm = Alarm{"61610", "no infeed", 5, ""};
  EXPECT_EQ(of(judged(lcyc95Program("1"), "sinumerik-802s", alarmed), "siemens-alarm").size(), 1u);
}

// The frame: in every machining type's spec case, the first retract shortened to a 45° retract of
// R110 / _VRT (its vector scaled by 1/√2) is reported — longitudinal, face and internal, LCYC95 and
// CYCLE95.
TEST(SiemensOracles, RetractAt45DegreesIsReportedInEveryFrame) {
  for (const std::string id : {"sinumerik-802s/lcyc95/r105-1-rough-step-shaft", "sinumerik-802s/lcyc95/r105-2-face-rough",
                               "sinumerik-802s/lcyc95/r105-3-internal-rough", "sinumerik-802d/cycle95/vari-1-falz-falx"}) {
    const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/" + id + ".json");
    Toolpath path = planSpecCase(c);
    std::size_t retract = 1;
    while (retract < path.moves.size() &&
           !(path.moves[retract - 1].kind == MoveKind::Feed && path.moves[retract].kind == MoveKind::Rapid)) {
      ++retract;
    }
    ASSERT_LT(retract, path.moves.size()) << id;
    const Point from = path.from(retract);
    path.moves[retract].to = from + std::sqrt(0.5) * (path.moves[retract].to - from);
    const std::vector<Finding> f = of(judge(judgeInputFor(judgeRequestFor(c), path)), "siemens-retract");
    ASSERT_EQ(f.size(), 1u) << id;
    EXPECT_EQ(f[0].move, retract) << id;
  }
}

// The seed's L42 program calls LCYC95 twice on one contour: R105=1 (roughing to R106 = 0.3), then
// R105=5 (finishing). The material oracles judge the two calls as one part — the first call's stock,
// the second's finishing path as what must be left — so the reference's path passes, and the same
// path without its finishing pass leaves the allowance standing: `complete` (0.3 mm and more).
TEST(SiemensOracles, TheSeedsTwoL42CallsAreJudgedAsOnePart) {
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/sinumerik-802s/lcyc95/seed-l42-both-calls.json");
  const Toolpath path = planSpecCase(c);
  EXPECT_TRUE(judge(judgeInputFor(judgeRequestFor(c), path)).empty());
  Toolpath rough = path;
  rough.moves.erase(std::remove_if(rough.moves.begin(), rough.moves.end(),
                                   [](const Move& m) { return m.phase == MovePhase::Finish; }),
                    rough.moves.end());
  ASSERT_LT(rough.moves.size(), path.moves.size());
  const std::vector<Finding> f = of(judge(judgeInputFor(judgeRequestFor(c), rough)), "complete");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].rules, (std::vector<std::string>{"LCYC95.ROUGH", "LCYC95.FINISH"}));
}

TEST(SiemensOracles, FanucOraclesDoNotJudgeSiemensPrograms) {
  // On a SINUMERIK program only the SINUMERIK oracles and the material ones (no-gouge, rapids-in-air,
  // complete) run, and the material ones cite the call's own cycle's rules. An empty path leaves
  // the whole stock: complete reports it.
  const std::vector<Finding> f = judged(lcyc95Program("1"), "sinumerik-802s", PathBuilder({2, 25}).path);
  ASSERT_FALSE(f.empty());
  bool complete = false;
  for (const Finding& x : f) {
    const bool material = x.oracle == "no-gouge" || x.oracle == "rapids-in-air" || x.oracle == "complete";
    EXPECT_TRUE(material || x.oracle.rfind("siemens-", 0) == 0) << x.oracle;
    if (material) {
      for (const std::string& rule : x.rules) EXPECT_EQ(rule.rfind("LCYC95.", 0), 0u) << x.oracle << " " << rule;
    }
    complete = complete || x.oracle == "complete";
  }
  EXPECT_TRUE(complete);
}


// A contour that begins by falling towards the axis (CYCLE95.UNDERCUT, interpretation): L1 runs
// (z 0, x 1.5) down the front wall to (0, 1), along to (−1, 1), up to (−1, 1.5). Nothing of the
// profile stands before the fall, so it is no undercut: the main passes reach it from the start
// side. MID 0.5 over the height 1.5 − 1 gives one step; S = (0 + _VRT, 1.5 + _VRT) = (0.1, 1.6).
// By hand (the program's G0 X4.2 Z0.6 gives the first position, no move): G0 to S; G0 down to the level (0.1, 1); G1 at FF1 0.1 to (0, 1), (−1, 1), up the wall to
// (−1, 1.5); G0 retract by _VRT in each axis to (−0.9, 1.6); G0 back to S (X is there already).
// Before: both the reference and the oracles took the fall for an undercut; the reference roughed
// it again at FF2 after its main pass, and the oracles found the main pass's FF1 in it.
TEST(SiemensOracles, AFallFromTheContoursFrontIsNoUndercut) {
  const std::string program = "T1 D1\nG0 X4.2 Z0.6\nCYCLE95(\"L1\", 0.5, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 0.1)\nM02\n";
  const std::string contour = "G1X3Z0\nG1X2Z0\nG1X2Z-1\nG1X3Z-1\nRET\n";
  PlanRequest request{program, "front.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  const std::vector<std::pair<Point, std::optional<double>>> expected = {
      {{0.1, 1.6}, std::nullopt}, {{0.1, 1}, std::nullopt}, {{0, 1}, 0.1},
      {{-1, 1}, 0.1},           {{-1, 1.5}, 0.1},           {{-0.9, 1.6}, std::nullopt}, {{0.1, 1.6}, std::nullopt}};
  std::vector<std::pair<Point, std::optional<double>>> got;
  for (const Move& m : path.moves) {
    got.push_back({m.to, m.kind == MoveKind::Feed ? std::optional<double>(m.feed) : std::nullopt});
    EXPECT_TRUE(std::find(m.rules.begin(), m.rules.end(), "CYCLE95.UNDERCUT") == m.rules.end());
  }
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].first.z, expected[i].first.z, 1e-9) << i;
    EXPECT_NEAR(got[i].first.x, expected[i].first.x, 1e-9) << i;
    EXPECT_EQ(got[i].second.has_value(), expected[i].second.has_value()) << i;
    if (got[i].second && expected[i].second) {
      EXPECT_NEAR(*got[i].second, *expected[i].second, 1e-12) << i;
    }
  }
  EXPECT_TRUE(judged(program, "sinumerik-802d", path, contour).empty());
}


// A V pocket (CYCLE95.UNDERCUT): L1 (radius) (0, 0) → (0, 6) → (−5, 6) → (−10, 2) → (−15, 6) →
// (−15, 8) → (−25, 8), MID 4, _VRT 1: main levels 4, 0; the pocket from level 8 (strictly above the
// rim (−5, 6)) down to x 2 in two steps of 3 (levels 5, 2). Its first level runs down the falling side
// from the rim to (−6.25, 5) (tests/cycle95_test.cpp derives the whole path by hand). Before, it
// plunged straight down at z −6.25: the ridge between the falling side and the plunge, z −5 … −6.25
// above the side up to 8, stayed standing, which `complete` now finds on such a path.
TEST(SiemensOracles, APocketLevelRunsDownItsFallingSide) {
  const std::string program = "T1 D1\nG0 X30 Z5\nCYCLE95(\"L1\", 4, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 1)\nM02\n";
  const std::string contour = "G1 X0 Z0\nX12\nZ-5\nX4 Z-10\nX12 Z-15\nX16\nZ-25\nRET\n";
  PlanRequest request{program, "v.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  EXPECT_TRUE(judged(program, "sinumerik-802d", path, contour).empty());
  // The plunge of before: G0 (−6.25, 9), G1 (−6.25, 5) instead of G0 (−5, 9), G1 (−5, 6), G1 (−6.25, 5).
  Toolpath plunge = path;
  std::size_t rim = 0;
  while (rim < plunge.moves.size() &&
         !(nearlyEqual(plunge.from(rim), {-5, 9}, 1e-9) && nearlyEqual(plunge.moves[rim].to, {-5, 6}, 1e-9))) {
    ++rim;
  }
  ASSERT_LT(rim + 1, plunge.moves.size());
  ASSERT_TRUE(nearlyEqual(plunge.moves[rim + 1].to, {-6.25, 5}, 1e-9));
  plunge.moves[rim - 1].to = {-6.25, 9};
  plunge.moves.erase(plunge.moves.begin() + static_cast<std::ptrdiff_t>(rim));
  EXPECT_FALSE(of(judged(program, "sinumerik-802d", plunge, contour), "complete").empty());
}

// A rim on a main level (CYCLE95.UNDERCUT): L1 (radius) (0, 0) → (0, 4) → (−5, 4) → (−10, 2) →
// (−15, 2) → (−15, 8) → (−25, 8), MID 4: main levels 4 and 0; level 4 runs along the flat to the rim
// (−5, 4) and stops there. The pocket's top is the level strictly above the rim, 8: from 8 down to 2,
// two steps of 3 (levels 5 and 2). Level 5 stands above the rim: it crosses from the rim's z −5 to
// the rising wall at z −15. Before, the top was the rim's own level 4, and the band between 4 and 8
// over z −5 … −15 stayed standing (`complete` found it).
TEST(SiemensOracles, ARimOnALevelIsRoughedFromTheLevelAbove) {
  const std::string program = "T1 D1\nG0 X30 Z5\nCYCLE95(\"L1\", 4, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 1)\nM02\n";
  const std::string contour = "G1 X0 Z0\nX8\nZ-5\nX4 Z-10\nZ-15\nX16\nZ-25\nRET\n";
  PlanRequest request{program, "rim.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  EXPECT_TRUE(judged(program, "sinumerik-802d", path, contour).empty());
  bool crossesAtFive = false;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& m = path.moves[i];
    crossesAtFive = crossesAtFive || (m.kind == MoveKind::Feed && nearlyEqual(path.from(i), {-5, 5}, 1e-9) &&
                                      nearlyEqual(m.to, {-15, 5}, 1e-9) && m.feed && std::abs(*m.feed - 0.05) < 1e-12);
  }
  EXPECT_TRUE(crossesAtFive);
}

// A contour that begins by falling (L1, radius: (0, 8) → (−2, 6) → (−6, 6) → (−8, 10) → (−12, 10)),
// FAL 0.5, MID 2, VARI 9. The allowance moves the profile's start along the first element's normal,
// (−0.7071, +0.7071)·0.5, to (−0.354, 8.354): behind the contour's front z 0. Levels: top 10.5, bottom
// 6.5, two steps of 2: 8.5 and 6.5; level 6.5 lies below the face's top 8.354 and meets the part's
// face — at the contour's z 0 (LCYC95.ROUGH note), where before it ran on to the profile's z −0.354,
// 0.354 mm into the part below the falling chamfer (no-gouge against the finished contour). Behind
// the face a feed at 6.5 may only run on the profile's own flat (the contour's 6 + FAL 0.5), which
// begins where the chamfer's offset line x = z + 8 + 0.5·√2 meets 6.5: z = −1.5 − 0.7071 = −2.2071
// (the pass that met the face cleans up along it, LCYC95.ROUGH note).
TEST(SiemensOracles, ALevelMeetsTheFaceAtTheContoursFrontNotBehindIt) {
  const std::string program = "T1 D1\nG0 X30 Z5\nCYCLE95(\"L1\", 2, 0, 0, 0.5, 0.1, 0.05, 0.05, 9, 0, 0, 1)\nM02\n";
  const std::string contour = "G1 X16 Z0\nX12 Z-2\nZ-6\nX20 Z-8\nZ-12\nRET\n";
  PlanRequest request{program, "fall.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  EXPECT_TRUE(judged(program, "sinumerik-802d", path, contour).empty());
  bool stopsAtTheFace = false;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& m = path.moves[i];
    if (m.kind != MoveKind::Feed || std::abs(m.to.x - 6.5) > 1e-9 || std::abs(path.from(i).x - 6.5) > 1e-9) continue;
    const bool onTheFlat = std::max(m.to.z, path.from(i).z) <= -1.5 - 0.5 * std::sqrt(2.0) + 1e-6;
    EXPECT_TRUE(m.to.z >= -1e-9 || onTheFlat) << "level 6.5 runs behind the face, off the profile, at move " << i;
    stopsAtTheFace = stopsAtTheFace || std::abs(m.to.z) < 1e-9;
  }
  EXPECT_TRUE(stopsAtTheFace);
}

// A zero-width spike (found by `fuzz --cycles siemens`): L1 runs out along X10.82 to Z-5.19 and back
// along the same line to Z-4.65 before falling into a pocket (VARI 12, face internal). The main pass
// that climbs the spike's wall to its rim cuts at FF1; the pocket's falling side is the same line,
// descended at FF2. Before, siemens-feeds took the climb at the rim's z for the pocket's and asked
// FF2 of it (23 of 2,000 generated cases failed so on the reference).
TEST(SiemensOracles, AClimbToTheRimOfAZeroWidthSpikeIsTheMainPass) {
  const std::string program =
      "T1 D1\nG0 X22.92 Z-7.94\nCYCLE95(\"L1\", 0.75, 0.04, 0, 0, 0.13, 0.07, 0.06, 12, 0, 3.3, 0.5)\nM02\n";
  const std::string contour =
      "G1 X19.44 Z0\nG1 X19.44 Z-0.37\nG1 X17.94 Z-1.12\nG1 X14.2 Z-1.69 RND=0.27\nG1 X14.2 Z-2.52\n"
      "G3 X10.82 Z-4.21 CR=3.38\nG1 X10.82 Z-5.19\nG1 X10.82 Z-4.65\nG1 X8.66 Z-4.65\nG1 X8.66 Z-5.19\n"
      "G1 X6.64 Z-6.2\nRET\n";
  PlanRequest request{program, "spike.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  EXPECT_TRUE(of(judged(program, "sinumerik-802d", path, contour), "siemens-feeds").empty());
}

// A groove behind a raised contour start (LCYC95.ROUGH / CYCLE95.UNDERCUT, interpretation): L1
// begins at (z 0, x 1.4), rounds up to (−0.1, 1.5), falls to (−0.1, 1), runs to (−1.1, 1) and rises
// to (−1.1, 1.5). Below the contour's first point the part's face stands at z 0, up to x 1.4; the
// one level (1.5 − MID 0.5 = 1) lies below that top, so its main pass meets the face at z 0 and
// stops there, and the groove behind is an undercut roughed at FF2. Before: the main pass ran on
// at x 1 through the part's front (z 0 … −0.1, below the rounding) and along the groove at FF1.
// Having met the face, the pass goes up it to the contour's start (0, 1.4) and along the rounding
// to the previous level 1.5 (the contour-parallel cleanup): feeds on the profile, not along the level.
TEST(SiemensOracles, ALevelBelowARaisedContourStartStopsAtThePartsFace) {
  const std::string program = "T1 D1\nG0 X4.2 Z0.6\nCYCLE95(\"L1\", 0.5, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 0.1)\nM02\n";
  const std::string contour = "G1X2.8Z0\nG3X3Z-0.1CR=0.2\nG1X2Z-0.1\nG1X2Z-1.1\nG1X3Z-1.1\nRET\n";
  PlanRequest request{program, "face.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  bool grooveCutAtFf2 = false;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& m = path.moves[i];
    const bool undercut = std::find(m.rules.begin(), m.rules.end(), "CYCLE95.UNDERCUT") != m.rules.end();
    if (m.kind != MoveKind::Feed) continue;
    const bool alongTheLevel = std::abs(path.from(i).x - 1) < 1e-9 && std::abs(m.to.x - 1) < 1e-9;
    if (!undercut && alongTheLevel) {
      EXPECT_GE(std::min(path.from(i).z, m.to.z), -1e-9) << "main-pass feed " << i << " behind the face";
    }
    if (undercut && std::abs(m.to.x - 1) < 1e-9 && m.to.z < -1 && m.feed && std::abs(*m.feed - 0.05) < 1e-12) {
      grooveCutAtFf2 = true;
    }
  }
  EXPECT_TRUE(grooveCutAtFf2);
  EXPECT_TRUE(judged(program, "sinumerik-802d", path, contour).empty());
}

// FALZ on each element's stock side (CYCLE95.ROUGH note): the groove L3 (above) with FALZ 0.5, FAL
// and FALX 0, MID 3. The profile is the contour grown by 0.5 in z on the stock side of each wall: the
// face z 0 → 0.5, the rising walls at −5, −15 and −20 → −4.5, −14.5, −19.5, the groove's near wall
// at −10 (falling, its stock towards −z) → −10.5: (0.5, 10) → (−4.5, 10) → (−4.5, 16) → (−10.5, 16) →
// (−10.5, 12) → (−14.5, 12) → (−14.5, 16) → (−19.5, 16) → (−19.5, 20). Start (0.5 + 1, 20 + 1); depth
// 10 in 4 steps of 2.5 (17.5, 15, 12.5, 10); the pocket from 17.5 down to 12 in 2 steps (14.75, 12)
// at FF2, down the near wall's allowance at −10.5. The old uniform shift by +0.5 put that wall at
// −9.5: 0.5 into the collar (z −5 … −10 up to x 16).
const char* kGrooveFalz = "G0 X50 Z2\nCYCLE95(\"L3\", 3, 0.5, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)\nM02\n";

PathBuilder grooveRoughingWithFalz(double nearWallZ) {
  const double w = nearWallZ;
  PathBuilder p({2, 25});
  p.rapid(1.5, 21);
  p.rapid(1.5, 17.5).feed(-19.5, 17.5, 0.3).feed(-19.5, 20, 0.3).rapid(-18.5, 21).rapid(1.5, 21);
  p.rapid(1.5, 15).feed(-4.5, 15, 0.3).feed(-4.5, 16, 0.3).feed(w, 16, 0.3).rapid(w + 1, 17).rapid(1.5, 17);
  p.rapid(1.5, 12.5).feed(-4.5, 12.5, 0.3).feed(-4.5, 15, 0.3).rapid(-3.5, 16).rapid(1.5, 16);
  p.rapid(1.5, 10).feed(0.5, 10, 0.3).feed(-4.5, 10, 0.3).feed(-4.5, 12.5, 0.3).rapid(-3.5, 13.5);
  p.rapid(-3.5, 21);
  p.rapid(w, 21).feed(w, 14.75, 0.15).feed(-14.5, 14.75, 0.15).feed(-14.5, 16, 0.15).feed(-19.5, 16, 0.15);
  p.feed(-19.5, 17.5, 0.15).rapid(-18.5, 18.5);
  p.rapid(w, 18.5).feed(w, 12, 0.15).feed(-14.5, 12, 0.15).feed(-14.5, 14.75, 0.15).rapid(-13.5, 15.75);
  p.rapid(-13.5, 21).rapid(1.5, 21);
  return p;
}

TEST(SiemensOracles, FalzStaysOffAGroovesNearWall) {
  const std::vector<Finding> f = judged(kGrooveFalz, "sinumerik-802d", grooveRoughingWithFalz(-10.5).path, kGroove, "L3");
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

// A descent from the top of a wall the contour begins with, rising at its first point's z, is an
// undercut (CYCLE95.UNDERCUT note): L1 rises from (z 0, x 4) to (0, 8), falls along a slope to
// (−4, 4) and runs to (−6, 4). The reference roughs the stock above the slope as a pocket at FF2
// 0.05 (SiemensFrontPockets.AWallRisingAtTheFrontStandsBeforeThePocketBehindIt): siemens-feeds takes
// those feeds for the pocket's — and asks FF2 of them, so the same path with the slope's feeds at
// FF1 0.2 is a finding. Before, the oracle counted a descent at the front's z as no undercut and
// asked FF1 there (fuzz seed 14762804858427687941).
TEST(SiemensOracles, ADescentFromTheTopOfARisingFrontWallIsAnUndercut) {
  const std::string program = "T1 D1\nG0 X20 Z3\nCYCLE95(\"L1\", 2.5, 0, 0, 0, 0.2, 0.05, 0.1, 1, 0, 0, 1)\nM02\n";
  const std::string contour = "G1 X8 Z0\nX16\nX8 Z-4\nZ-6\nRET\n";
  PlanRequest request{program, "wall.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  Toolpath path = planWithReference(request);
  EXPECT_TRUE(of(judged(program, "sinumerik-802d", path, contour), "siemens-feeds").empty());
  bool onTheSlope = false;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    Move& m = path.moves[i];
    const bool down = m.kind == MoveKind::Feed && m.to.x < path.from(i).x - 1e-9 && m.to.z < -1e-9;
    if (down) m.feed = 0.2, onTheSlope = true;
  }
  ASSERT_TRUE(onTheSlope);
  EXPECT_FALSE(of(judged(program, "sinumerik-802d", path, contour), "siemens-feeds").empty());
}

// A pocket behind a spike after the front (fuzz seed 6552314345380442963): L1 rises at z 0 from x 1.4
// to 1.5 and falls back to 1 (a spike of no width at the front), runs to −1, rises to 1.5 and falls
// back to 1 (a second spike), runs to −2, rises to 1.5 and on to (−2.1, 1.6). The descent down the
// face is only that wall; the one behind the second spike is a pocket the reference roughs at FF2
// 0.05 (SiemensFrontPockets.APocketBehindASpikeAfterTheFrontIsAnUndercut): siemens-feeds takes its
// feeds for the pocket's and 'complete' finds no stock left. Before, the oracle's walk from the front
// descent ran on to the profile's top and took the pocket with it (FF1 asked there).
TEST(SiemensOracles, APocketBehindASpikeAfterTheFrontIsThePockets) {
  const std::string program = "T1 D1\nG0 X7.44 Z2.12\nCYCLE95(\"L1\", 0.5, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 0.1)\nM02\n";
  const std::string contour =
      "G1X2.8Z0\nG1X3Z0\nG1X2Z0\nG1X2Z-1\nG1X3Z-1\nG1X2Z-1\nG1X2Z-2\nG1X3Z-2\nG1X3.2Z-2.1\nRET\n";
  PlanRequest request{program, "spikes.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  const auto findings = judged(program, "sinumerik-802d", path, contour);
  EXPECT_TRUE(of(findings, "siemens-feeds").empty());
  EXPECT_TRUE(of(findings, "complete").empty());
}

// A pocket's pass descends from its rim along a rounding of the allowance that falls less than the
// tolerance (found by `fuzz --cycles siemens`, seed 15755400384260043841): L1's last element falls
// 0.1 (radius) from (−2.08, 9.34) after a flat, FAL 0.11 rounds the convex corner, and the pocket's
// one pass runs from the rim (−2.08, 9.45) along that rounding, which ends 0.0007 lower, then down
// the offset slope — at FF2 0.14. siemens-feeds takes a descending move in the pocket for the
// pocket's even within the tolerance of its top; before, it asked FF1 of the rounding.
TEST(SiemensOracles, APocketPassDescendingAlongASmallRoundingAtItsRimIsThePockets) {
  const std::string program =
      "T1 D1\nG0 X22.16 Z1.74\nCYCLE95(\"L1\", 1.52, 0, 0, 0.11, 0.11, 0.14, 0.11, 1, 0, 0, 0.78)\nM02\n";
  const std::string contour =
      "G1X18.68Z0\nG1X16.96Z0\nG1X16.96Z-1.22\nG1X18.68Z-1.22\nG1X18.68Z-2.08\nG1X18.48Z-2.94\nRET\n";
  PlanRequest request{program, "rim.mpf", "sinumerik-802d", {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  const Toolpath path = planWithReference(request);
  EXPECT_TRUE(of(judged(program, "sinumerik-802d", path, contour), "siemens-feeds").empty());
}

// The reference's path of a program, for the oracles to judge (the tests below expect no finding of
// the oracle their rule concerns, or doctor one move and expect it named).
Toolpath referencePath(const std::string& program, const std::string& profile, const std::string& contour) {
  PlanRequest request{program, "case.mpf", profile, {}, {}};
  request.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  return planWithReference(request);
}

// Every oracle's findings on the reference's path of the program.
std::vector<Finding> referenceFindings(const std::string& program, const std::string& profile, const std::string& contour) {
  return judged(program, profile, referencePath(program, profile, contour), contour);
}

// A pocket narrower than _VRT (issue 16, fuzz seed 7566792160692496541): L1 (radius) rounds from
// (0, 2.01) to (−0.5, 2.51), falls down the wall at z −0.5 to 1, runs to −1.5 and rises to 2.51;
// _VRT 1.01 is wider than the pocket (1). The last pocket pass ends on the rising wall at the level
// 1.3775 (the pocket's levels 2.51 … 1 in four steps of 0.3775): the diagonal retract by 1.01 would
// cross z −0.5 at 2.3775, below the falling wall's top 2.51 — into the part; the tool lifts by _VRT
// along X only (CYCLE95.UNDERCUT note), which siemens-retract accepts there, and nothing gouges.
// The first pocket pass's retract from the pocket's top (−1.5, 2.51) crosses z −0.5 at 3.51, above
// the wall: there a lift along X only is a finding.
const char* const kNarrowPocket =
    "T1 D1\nG0 X13.86 Z4.42\nCYCLE95(\"L1\", 0.5, 0, 0, 0, 0.1, 0.1, 0.05, 1, 0, 0, 1.01)\nM02\n";
const char* const kNarrowPocketContour = "G1X4.02Z0\nG2X5.02Z-0.5CR=1\nG1X2Z-0.5\nG1X2Z-1.5\nG1X5.02Z-1.5\nRET\n";

TEST(SiemensOracles, ARetractOverANarrowPocketLiftsAlongXWhereTheDiagonalMeetsThePart) {
  const Toolpath path = referencePath(kNarrowPocket, "sinumerik-802d", kNarrowPocketContour);
  const std::vector<Finding> all = judged(kNarrowPocket, "sinumerik-802d", path, kNarrowPocketContour);
  EXPECT_TRUE(of(all, "siemens-retract").empty()) << findingsText(all);
  EXPECT_TRUE(of(all, "no-gouge").empty()) << findingsText(all);
}

TEST(SiemensOracles, ALiftAlongXOnlyWhereTheDiagonalIsFreeIsReported) {
  Toolpath path = referencePath(kNarrowPocket, "sinumerik-802d", kNarrowPocketContour);
  // The first pocket pass's retract: from the rising wall's top (−1.5, 2.51) to (−0.49, 3.52).
  const auto retract = std::find_if(path.moves.begin(), path.moves.end(), [&](const Move& m) {
    return m.kind == MoveKind::Rapid && std::abs(m.to.z + 0.49) < 1e-9 && std::abs(m.to.x - 3.52) < 1e-9;
  });
  ASSERT_NE(retract, path.moves.end());
  const std::size_t i = static_cast<std::size_t>(retract - path.moves.begin());
  ASSERT_NEAR(path.from(i).z, -1.5, 1e-9);
  ASSERT_NEAR(path.from(i).x, 2.51, 1e-9);
  retract->to.z = -1.5;  // lifted along X only
  const std::vector<Finding> f = of(judged(kNarrowPocket, "sinumerik-802d", path, kNarrowPocketContour), "siemens-retract");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].move, i);
}

// Face external roughing (fuzz seed 7602198448822310842): L1 ends with G2 X1.68 Z0 CR=0.9 and a line
// along X at Z0; FAL 0.03 rounds the corner between them. The pocket the arc closes (its rim where the
// profile falls from (Z−0.24, X(radius)3.66)) is back at its top, the profile's top Z0.03, at the end
// of that rounding: the pocket pass climbs along the arc and the rounding to the top at FF2 (0.07) —
// the rounding's last piece starts 0.0027 below the top, within the tolerance, and is the pocket's
// all the same (before: read as a main pass's, at FF1).
TEST(SiemensOracles, ARoundingClosingAPocketAtItsTopIsThePockets) {
  const std::string program =
      "T1 D1\nG0 X9.62 Z1.16\nCYCLE95(\"L1\", 0.57, 0, 0, 0.03, 0.1, 0.07, 0.07, 2, 0, 0, 0.24)\nM02\n";
  const std::string contour =
      "G1X7.3Z-1\nG1X7.3Z-1.53\nG1X5.18Z-1.53\nG1X5.18Z-1\nG1X4.42Z-0.62\nG1X3.66Z-0.24\nG1X2.58Z-0.45\n"
      "G2X1.68Z0CR=0.9\nG1X0.74Z0\nRET\n";
  const std::vector<Finding> all = referenceFindings(program, "sinumerik-802d", contour);
  EXPECT_TRUE(of(all, "siemens-feeds").empty()) << findingsText(all);
}

// Face external complete machining (fuzz seed 12256850900456832735): L1's pocket behind the rim at
// Z-1.98 holds a spike rising back to Z-1.98 (X9.16, out and back along the same line), which FALX
// 0.23 widens into a flat of 0.46 at Z-1.98; the pocket's top is the main level just above the rim,
// 0.0027 higher. The pocket passes run along that flat, inside the pocket, at FF2 (0.12) — not a
// main pass's cut along the top level, which lies at the top (before: FF1 asked of it).
TEST(SiemensOracles, AFlatInsideAPocketJustBelowItsTopIsThePockets) {
  const std::string program =
      "T1 D1\nG0 X26.8 Z3.12\nCYCLE95(\"L1\", 0.7, 0, 0.23, 0, 0.11, 0.12, 0.1, 10, 0, 0, 0.47)\nM02\n";
  const std::string contour =
      "G1X20.56Z-7.25\nG1X20.56Z-6.22\nG1X17.18Z-4.53\nG2X12.08Z-1.98CR=5.1\nG1X12.08Z-2.71\nG1X9.16Z-2.71\n"
      "G1X9.16Z-1.98\nG1X9.16Z-2.78\nG1X5.32Z-2.78\nG1X5.32Z-1.98\nG1X4.42Z-1.53\nG1X1.36Z0\nRET\n";
  const std::vector<Finding> all = referenceFindings(program, "sinumerik-802d", contour);
  EXPECT_TRUE(of(all, "siemens-feeds").empty()) << findingsText(all);
}

// LCYC95 roughing (fuzz seed 8782156830944809353): L1 rises from (0, 1) to (0, 1.1) and runs to
// (−0.1, 1.1); R108 0.5, R110 0.1: one level, 1 (the profile's bottom), start (0.1, 1.2). The pass
// goes up the face to the previous level 1.1 and retracts by (0.1, 0.1) — to the start itself: the
// return to the start is a move of no length, none (before: "the path makes 0 move(s) there").
TEST(SiemensOracles, ARetractEndingAtTheStartNeedsNoReturn) {
  const std::string program =
      "T1 D1\nG0 X3.4 Z0.6\n_CNAME=\"L1\"\nR105=1 R106=0 R108=0.5 R109=0\nR110=0.1 R111=0.1 R112=0.05\nLCYC95\nM02\n";
  const std::string contour = "G1X2Z0\nG1X2.2Z0\nG1X2.2Z-0.1\nRET\n";
  const std::vector<Finding> all = referenceFindings(program, "sinumerik-802s", contour);
  EXPECT_TRUE(of(all, "siemens-returns").empty()) << findingsText(all);
}

// CYCLE95 (fuzz seed 15499951743135697239): L1 falls from (0, 1.32) to (−0.1, 1) and rises on an arc;
// FAL 0.01 moves the profile's start behind the contour's, to about (−0.0095, 1.323). The one level
// (1.0273) meets the part's face at z 0; the pass goes up the face to the contour's first point and
// across the allowance to the profile's start — a move rising 0.003 over 0.0095, within the
// tolerance of a level: no cut of a level (before: "a roughing cut 0.009114 below the profile's top").
TEST(SiemensOracles, TheMoveAcrossTheAllowanceAtTheFaceIsNoLevelsCut) {
  const std::string program =
      "T1 D1\nG0 X5.28 Z1.32\nCYCLE95(\"L1\", 1.61, 0, 0, 0.01, 0.26, 0.26, 0.09, 1, 0, 0, 0.35)\nM02\n";
  const std::string contour = "G1X2.64Z0\nG1X2Z-0.1\nG3X2.64Z-0.42CR=0.64\nRET\n";
  const std::vector<Finding> all = referenceFindings(program, "sinumerik-802d", contour);
  EXPECT_TRUE(of(all, "siemens-infeed-steps").empty()) << findingsText(all);
}

// CYCLE95 finishing only (fuzz seed 14625125955531410820): L1 rises up the face from (0, 1) to
// (0, 1.26) and falls to (−0.26, 1); FAL 0.01. The documented G0 back from the contour's end to the
// start (0.11, 1.37) runs along x = z + 1.26, through the contour's corner (0, 1.26), where the
// allowance in front of the face (removed along X only) still stands: the cycle's documented move,
// which rapids-in-air leaves to the sequence as no-gouge does (LCYC95.FINISH note).
TEST(SiemensOracles, TheDocumentedFinishingReturnIsNoRapidThroughMaterial) {
  const std::string program =
      "T1 D1\nG0 X3.74 Z0.61\nCYCLE95(\"L1\", 0.5, 0, 0, 0.01, 0.1, 0.1, 0.05, 5, 0, 0, 0.1)\nM02\n";
  const std::string contour = "G1X2Z0\nG1X2.52Z0\nG1X2Z-0.26\nRET\n";
  const std::vector<Finding> all = referenceFindings(program, "sinumerik-802d", contour);
  EXPECT_TRUE(of(all, "rapids-in-air").empty()) << findingsText(all);
}

// CYCLE95 (fuzz seed 17617655989876150606): L1 falls from (0, 2.4) to (−1.4, 1) and rises on an
// arc; FAL 0.2 moves the profile's start behind the contour's, to (−0.1414, 2.5414). The start is
// _VRT (0.1) beyond the part's face at z 0 — (0.1, …), not beyond the profile alone (−0.0414, …) —
// and each infeed goes straight down from it (LCYC95.START note); the axes return X then Z.
TEST(SiemensOracles, TheStartLiesBeyondThePartsFace) {
  const std::string program =
      "T1 D1\nG0 X10.58 Z2.78\nCYCLE95(\"L1\", 0.5, 0, 0, 0.2, 0.26, 0.26, 0.06, 1, 0, 0, 0.1)\nM02\n";
  const std::string contour = "G1X4.8Z0\nG1X2Z-1.4\nG3X5.02Z-2.91CR=3.02\nRET\n";
  const Toolpath path = referencePath(program, "sinumerik-802d", contour);
  ASSERT_FALSE(path.moves.empty());
  EXPECT_NEAR(path.moves.front().to.z, 0.1, 1e-9);
  const std::vector<Finding> all = judged(program, "sinumerik-802d", path, contour);
  EXPECT_TRUE(of(all, "siemens-infeed").empty()) << findingsText(all);
  EXPECT_TRUE(of(all, "siemens-returns").empty()) << findingsText(all);
  EXPECT_TRUE(of(all, "no-gouge").empty()) << findingsText(all);
}

TEST(SiemensOracles, FalzShiftedIntoAGroovesNearWallIsAGouge) {
  const std::vector<Finding> all = judged(kGrooveFalz, "sinumerik-802d", grooveRoughingWithFalz(-9.5).path, kGroove, "L3");
  EXPECT_FALSE(of(all, "no-gouge").empty()) << findingsText(all);
}

Segment lineFromTo(Point from, Point to) {
  Segment s;
  s.from = from;
  s.to = to;
  return s;
}

// The oracles' own growth by the rectangle, on a V (0, 6) → (−4, 2) → (−8, 6) with FALZ 0.5, FALX 0.5
// (frame coordinates z, x): the face below (0, 6) moves to (0.5, 6.5), where the profile begins; the
// falling side moves by (−0.5, +0.5) — through (−0.5, 6.5) and (−4.5, 2.5), x = z + 7 —, the rising
// side by (+0.5, +0.5) — through (−3.5, 2.5) and (−7.5, 6.5), x = −z − 1; they cross at (−4, 3).
TEST(SiemensAllowanceRectangle, AVsSidesMoveApartAndMeetAtTheBottom) {
  const std::vector<Segment> grown =
      grownByAllowanceRectangle({lineFromTo({0, 6}, {-4, 2}), lineFromTo({-4, 2}, {-8, 6})}, {0.5, 0.5});
  const std::vector<Point> want{{0.5, 6.5}, {-0.5, 6.5}, {-4, 3}, {-7.5, 6.5}};
  ASSERT_EQ(grown.size() + 1, want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    const Point got = i == 0 ? grown.front().from : grown[i - 1].to;
    EXPECT_NEAR(got.z, want[i].z, 1e-9) << "corner " << i;
    EXPECT_NEAR(got.x, want[i].x, 1e-9) << "corner " << i;
  }
}

// A concave arc (a bowl) from (0, 5) to (−8, 5) about (−4, 8), radius 5, lowest point (−4, 3), with
// FALZ 0.3: its falling half moves to the centre (−4.3, 8), its rising half to (−3.7, 8); the halves
// cross at z −4, x = 8 − √(25 − 0.09) = 3.009008, the grown profile's lowest point.
TEST(SiemensAllowanceRectangle, ABowlsHalvesCrossBelowItsCentre) {
  Segment bowl = lineFromTo({0, 5}, {-8, 5});
  bowl.kind = SegmentKind::ArcCW;
  bowl.center = {-4, 8};
  const std::vector<Segment> grown = grownByAllowanceRectangle({bowl}, {0.3, 0});
  double lowest = 1e9;
  Point at{};
  for (const Segment& s : grown) {
    for (const Point& p : {s.from, s.to}) {
      if (p.x < lowest) lowest = p.x, at = p;
    }
  }
  EXPECT_NEAR(lowest, 8 - std::sqrt(25 - 0.09), 1e-9);
  EXPECT_NEAR(at.z, -4, 1e-9);
}

}  // namespace
}  // namespace cyclecert
