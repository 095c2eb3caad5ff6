// The SINUMERIK oracles judge every call of a program, each against its own parameters and moves
// (issue 16); CYCLE95's undercut passes by their own rules (pocket levels, DAM, DT); DT carried by
// the toolpath as a dwell. Expected moves are written by hand from the rules (x radius; contour L1
// and the groove L3 of tests/siemens_oracle_paths.h); where a test starts from the reference's path
// it only doctors it and expects the oracle to name the doctored move.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness/judge/judging.h"
#include "harness/engines/reference_plan.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "harness/judge/toolpath_compare.h"
#include "reference/model/toolpath_json.h"
#include "tests/siemens_oracle_paths.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

// Two LCYC95 roughing calls on L1: R108=3 (line 5: four levels 17.5, 15, 12.5, 10), then R108=5
// (line 7: two levels 15, 10). Both have the start S = (z1, x21): the second begins there.
const char* kTwoCalls =
    "G0 X50 Z2\n_CNAME=\"L1\"\nR105=1 R106=0 R108=3 R109=0\nR110=1 R111=0.3 R112=0.1\nLCYC95\nR108=5\nLCYC95\nM02\n";

// The first call is lcyc95Roughing(); the second, from S: per level a G1 infeed, the cut to the
// roughing intersection, along the profile up to the previous level, retract (+1, +1), G0 back to
// z1; after the last pass G0 to S. `firstRetract` replaces the second call's first retract.
PathBuilder twoCalls(Point firstRetract) {
  PathBuilder p = lcyc95Roughing();
  p.feed(1, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 20, 0.3);
  p.rapid(firstRetract.z, firstRetract.x).rapid(1, 21);
  p.feed(1, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 15, 0.3).rapid(-9, 16);
  p.rapid(1, 21);
  return p;
}

TEST(SiemensCallOracles, TwoCallsByTheRulesPass) {
  const std::vector<Finding> f = judged(kTwoCalls, "sinumerik-802s", twoCalls({-19, 21}).path);
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

// Before issue 16's change the Siemens oracles judged a program's only call, so nothing of a
// program with two calls: this 45° retract in the second call went unreported.
TEST(SiemensCallOracles, A45DegreeRetractInTheSecondCallIsReported) {
  const PathBuilder p = twoCalls({-20 + std::sqrt(0.5), 20 + std::sqrt(0.5)});
  const std::vector<Finding> all = judged(kTwoCalls, "sinumerik-802s", p.path);
  const std::vector<Finding> f = of(all, "siemens-retract");
  ASSERT_EQ(f.size(), 1u) << findingsText(all);
  const std::size_t retract = lcyc95Roughing().path.moves.size() + 5;
  EXPECT_EQ(f[0].move, retract);
  EXPECT_NE(f[0].message.find("LCYC95 at line 7"), std::string::npos) << f[0].message;
  EXPECT_EQ(f[0].rules, (std::vector<std::string>{"LCYC95.ROUGH"}));  // the call's own rules only
  // The second call's levels are its own (R108=5): none of its cuts is reported as off the first
  // call's levels (R108=3: 17.5, 15, 12.5, 10 — its 15 and 10 are on them anyway), and no other
  // oracle objects.
  EXPECT_EQ(all.size(), 1u) << findingsText(all);
}

// A level of the second call that would be right for the first: R108=5 gives 15 and 10, so a cut at
// 12.5 (R108=3's third level) is off the second call's levels.
TEST(SiemensCallOracles, EachCallIsJudgedAgainstItsOwnLevels) {
  PathBuilder p = lcyc95Roughing();
  p.feed(1, 15, 0.3).feed(-10, 15, 0.3).feed(-10, 16, 0.3).feed(-20, 16, 0.3).feed(-20, 20, 0.3).rapid(-19, 21).rapid(1, 21);
  p.feed(1, 12.5, 0.3).feed(-10, 12.5, 0.3).feed(-10, 15, 0.3).rapid(-9, 16).rapid(1, 16);
  p.feed(1, 10, 0.3).feed(0, 10, 0.3).feed(-10, 10, 0.3).feed(-10, 12.5, 0.3).rapid(-9, 13.5);
  p.rapid(1, 21);
  const std::vector<Finding> all = judged(kTwoCalls, "sinumerik-802s", p.path);
  const std::vector<Finding> f = of(all, "siemens-infeed-steps");
  ASSERT_EQ(f.size(), 1u) << findingsText(all);
  EXPECT_EQ(f[0].move, lcyc95Roughing().path.moves.size() + 8);  // the cut at 12.5
  EXPECT_NE(f[0].message.find("LCYC95 at line 7"), std::string::npos) << f[0].message;
  EXPECT_NE(f[0].message.find("2 equal steps of 5"), std::string::npos) << f[0].message;
}

// The seed's L42: R105=1 at line 7, R105=5 at line 9. The reference's path passes every oracle
// (TheSeedsTwoL42CallsAreJudgedAsOnePart); its finishing pass at R111 instead of R112 is the second
// call's finding.
TEST(SiemensCallOracles, TheSeedsFinishingCallIsJudgedByItsOwnFeed) {
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/sinumerik-802s/lcyc95/seed-l42-both-calls.json");
  Toolpath path = planSpecCase(c);
  std::size_t finishing = 0;
  while (finishing < path.moves.size() && !(path.moves[finishing].phase == MovePhase::Finish &&
                                            path.moves[finishing].kind == MoveKind::Feed)) {
    ++finishing;
  }
  ASSERT_LT(finishing, path.moves.size());
  path.moves[finishing].feed = 0.4;
  const std::vector<Finding> all = judge(judgeInputFor(judgeRequestFor(c), path));
  const std::vector<Finding> f = of(all, "siemens-feeds");
  ASSERT_EQ(f.size(), 1u) << findingsText(all);
  EXPECT_EQ(f[0].move, finishing);
  EXPECT_NE(f[0].message.find("LCYC95 at line 9"), std::string::npos) << f[0].message;
  EXPECT_NE(f[0].message.find("R112=0.25"), std::string::npos) << f[0].message;
}

// --- undercuts (CYCLE95.UNDERCUT) ---

// The groove L3 with MID 3: the pocket from the level 17.5 above its rim (−10, 16) down to its floor
// 12 in the fewest equal steps not above 3: two of 2.75 (14.75, 12). grooveRoughing() cuts across
// at 14.75; stepping by MID from the top (14.5, then 12) cuts across off the pocket's levels.
TEST(SiemensUndercutOracles, ACutAcrossThePocketOffItsEqualLevelsIsReported) {
  const std::vector<Finding> good = judged(grooveProgram(), "sinumerik-802d", grooveRoughing(0.15).path, kGroove, "L3");
  EXPECT_TRUE(of(good, "siemens-infeed-steps").empty()) << findingsText(good);
  const PathBuilder p = grooveRoughing(0.15, 14.5);
  const std::vector<Finding> all = judged(grooveProgram(), "sinumerik-802d", p.path, kGroove, "L3");
  const std::vector<Finding> f = of(all, "siemens-infeed-steps");
  ASSERT_EQ(f.size(), 1u) << findingsText(all);
  EXPECT_EQ(f[0].move, 25u);  // the cut across at 14.5
  EXPECT_NE(f[0].message.find("undercut"), std::string::npos) << f[0].message;
  EXPECT_NE(f[0].message.find("2 equal steps of 2.75"), std::string::npos) << f[0].message;
}

// The groove with DAM 2 and DT 0.5, planned by the reference: every oracle passes it. The oracle
// siemens-chip-breaking then finds each doctored chip break: the pocket's cut across (5 long at
// 14.75: pieces to z−12, −14 and −15) made whole, a dwell left out, a dwell on the last piece.
const char* kGrooveDam = "G0 X50 Z2\nCYCLE95(\"L3\", 3, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0.5, 2, 1)\nM02\n";

Toolpath grooveWithDam() { return planWithReference(siemensRequest(kGrooveDam, "sinumerik-802d", kGroove, "L3").program); }

// The index of the move ending at (z, x) in the pocket (feed FF2).
std::size_t pocketMoveTo(const Toolpath& path, double z, double x) {
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& m = path.moves[i];
    if (m.feed == 0.15 && nearlyEqual(m.to, {z, x}, 1e-9)) return i;
  }
  return path.moves.size();
}

TEST(SiemensUndercutOracles, TheReferenceInterruptsThePocketsCutAcrossAndDwells) {
  const Toolpath path = grooveWithDam();
  const std::vector<Finding> f = judged(kGrooveDam, "sinumerik-802d", path, kGroove, "L3");
  EXPECT_TRUE(f.empty()) << findingsText(f);
  const std::size_t first = pocketMoveTo(path, -12, 14.75);
  ASSERT_LT(first + 2, path.moves.size());
  EXPECT_EQ(path.moves[first].dwell.value_or(0), 0.5);
  EXPECT_EQ(path.moves[first + 1].to.z, -14);
  EXPECT_EQ(path.moves[first + 1].dwell.value_or(0), 0.5);
  EXPECT_EQ(path.moves[first + 2].to.z, -15);
  EXPECT_FALSE(path.moves[first + 2].dwell.has_value());
}

TEST(SiemensUndercutOracles, APocketsCutAcrossLongerThanDamIsReported) {
  Toolpath path = grooveWithDam();
  const std::size_t first = pocketMoveTo(path, -12, 14.75);
  ASSERT_LT(first + 2, path.moves.size());
  path.moves.erase(path.moves.begin() + static_cast<std::ptrdiff_t>(first), path.moves.begin() + static_cast<std::ptrdiff_t>(first) + 2);
  const std::vector<Finding> all = judged(kGrooveDam, "sinumerik-802d", path, kGroove, "L3");
  const std::vector<Finding> f = of(all, "siemens-chip-breaking");
  ASSERT_EQ(f.size(), 1u) << findingsText(all);
  EXPECT_EQ(f[0].move, first);
  EXPECT_NE(f[0].message.find("5 long"), std::string::npos) << f[0].message;
  EXPECT_EQ(f[0].rules, (std::vector<std::string>{"CYCLE95.DAM", "CYCLE95.UNDERCUT"}));
}

TEST(SiemensUndercutOracles, AMissingOrMisplacedDwellIsReported) {
  Toolpath path = grooveWithDam();
  const std::size_t first = pocketMoveTo(path, -12, 14.75);
  ASSERT_LT(first + 2, path.moves.size());
  path.moves[first].dwell.reset();     // an interruption without the dwell
  path.moves[first + 2].dwell = 0.5;   // a dwell after the last piece, which ends on the profile
  path.moves[1].dwell = 0.5;           // a dwell after the G0 infeed: no cut along a level, not judged
  const std::vector<Finding> all = judged(kGrooveDam, "sinumerik-802d", path, kGroove, "L3");
  const std::vector<Finding> f = of(all, "siemens-chip-breaking");
  ASSERT_EQ(f.size(), 2u) << findingsText(all);
  EXPECT_EQ(f[0].move, first);
  EXPECT_NE(f[0].message.find("a dwell of 0 s at the interruption"), std::string::npos) << f[0].message;
  EXPECT_EQ(f[1].move, first + 2);
}

// DT without DAM: nothing is interrupted, so nothing dwells (DAM = 0: "uninterrupted roughing steps
// without dwell times").
TEST(SiemensUndercutOracles, WithoutDamNothingDwells) {
  const char* program = "G0 X50 Z2\nCYCLE95(\"L3\", 3, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0.5, 0, 1)\nM02\n";
  const Toolpath path = planWithReference(siemensRequest(program, "sinumerik-802d", kGroove, "L3").program);
  for (const Move& m : path.moves) EXPECT_FALSE(m.dwell.has_value());
  PathBuilder p = grooveRoughing(0.15);
  p.path.moves[2].dwell = 0.5;  // after pass 1's cut along the level
  const std::vector<Finding> f = of(judged(program, "sinumerik-802d", p.path, kGroove, "L3"), "siemens-chip-breaking");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0].move, 2u);
}

// --- the dwell in the toolpath JSON ---

TEST(ToolpathDwell, IsWrittenReadAndOptional) {
  Move m;
  m.kind = MoveKind::Feed;
  m.to = {-2, 17.5};
  m.feed = 0.3;
  m.dwell = 0.5;
  const nlohmann::json j = toJson(m);
  EXPECT_EQ(j.at("dwell").get<double>(), 0.5);
  EXPECT_EQ(moveFromJson(j, "/moves/0").dwell.value_or(0), 0.5);
  m.dwell.reset();
  EXPECT_FALSE(toJson(m).contains("dwell"));  // older toolpath JSON stays as it was
  EXPECT_FALSE(moveFromJson(toJson(m), "/moves/0").dwell.has_value());
}

TEST(ToolpathDwell, ANegativeOrNonNumericDwellIsRefusedNamingTheField) {
  for (const char* bad : {R"({"kind": "feed", "to": {"x": 1, "z": 2}, "dwell": -1})",
                          R"({"kind": "feed", "to": {"x": 1, "z": 2}, "dwell": "1 s"})"}) {
    try {
      moveFromJson(nlohmann::json::parse(bad), "/moves/4");
      ADD_FAILURE() << bad;
    } catch (const ToolpathFormatError& e) {
      EXPECT_NE(std::string(e.what()).find("/moves/4/dwell"), std::string::npos) << e.what();
    }
  }
}

TEST(ToolpathDwell, IsComparedWhereTheExpectationGivesIt) {
  Move expected;
  expected.kind = MoveKind::Feed;
  expected.to = {-2, 17.5};
  expected.feed = 0.3;
  Move actual = expected;
  expected.dwell = 0.5;
  const auto d = firstMoveDivergence({expected}, {actual}, 1e-3);
  ASSERT_TRUE(d.has_value());
  EXPECT_NE(d->text.find("dwell 0.5 s"), std::string::npos) << d->text;
  actual.dwell = 0.5;
  EXPECT_FALSE(firstMoveDivergence({expected}, {actual}, 1e-3).has_value());
  expected.dwell.reset();  // not given: not compared
  EXPECT_FALSE(firstMoveDivergence({expected}, {actual}, 1e-3).has_value());
}

}  // namespace
}  // namespace cyclecert
