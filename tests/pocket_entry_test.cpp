// The pocket-entry oracle (G71.T2.POCKET.EXIT), run alone: type II's approach into a pocket stops
// the clearance 5134 short of the material and feeds the rest. It passes the reference and catches
// mutant:pocket-entry-rapid (the approach at rapid all the way) by itself.
#include <gtest/gtest.h>

#include "harness/engines/engine.h"
#include "harness/judge/judging.h"
#include "harness/spec/spec_case.h"
#include "oracles/material_replay.h"
#include "oracles/oracles.h"

namespace cyclecert {
namespace {

// G71 type II, outer, radius values: A' at x 5, up to x 8.3 at z −4, down into a pocket to x 6 at
// z −8, up to x 9 at z −12 and x 11 at z −14; Δd 1, 5134 = 0.5. The passes at x 7.5 and below
// enter the pocket beyond its peak (x 8 at z −4), whose top (x 8.3) stands until the pass at level 8 cuts it.
SpecCase pocketCase(double clearance) {
  return specCaseFrom(nlohmann::json{{"id", "fanuc-0i-f/g71/pocket-entry"},
                                     {"title", "G71 type II, one pocket"},
                                     {"rules", {"G71.T2.POCKET.EXIT"}},
                                     {"profile", "fanuc-0i-f"},
                                     {"params", {{"5134", clearance}}},
                                     {"program",
                                      "G00 X22 Z1;\nG71 U1 R0.5;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X10 W0;\n"
                                      "G01 X16.6 Z-4;\nX12 Z-8;\nX18 Z-12;\nN20 X22 Z-14;\nM30;\n"},
                                     {"expect", {{"oracles", "pass"}}},
                                     {"derivation", "hand-written: see the test's comment"}},
                      "test");
}

std::vector<Finding> pocketEntryFindings(const std::string& engine, const SpecCase& c) {
  const EngineResult r = makeEngine(engine)->run(c);
  EXPECT_EQ(r.kind, EngineResult::Planned) << r.detail;
  const JudgeInput in = judgeInputFor(judgeRequestFor(c), r.path);
  const std::optional<MaterialReplay> replay = replayMaterial(in);
  EXPECT_TRUE(replay.has_value());
  std::vector<Finding> out;
  makePocketEntryOracle()->judge(JudgeContext{in, replay ? &*replay : nullptr}, out);
  return out;
}

TEST(PocketEntry, TheReferenceStopsTheClearanceShortAndFeedsTheRest) {
  const std::vector<Finding> f = pocketEntryFindings("reference", pocketCase(0.5));
  EXPECT_TRUE(f.empty()) << findingsText(f);
}

TEST(PocketEntry, AnApproachAtRapidAllTheWayIsFoundByThisOracleAlone) {
  const std::vector<Finding> f = pocketEntryFindings("mutant:pocket-entry-rapid", pocketCase(0.5));
  ASSERT_FALSE(f.empty());
  for (const Finding& one : f) EXPECT_EQ(one.oracle, "pocket-entry");
}

// With 5134 = 0 the rapid may end at the entry point: the oracle judges nothing.
TEST(PocketEntry, WithoutAClearanceThereIsNothingToJudge) {
  EXPECT_TRUE(pocketEntryFindings("mutant:pocket-entry-rapid", pocketCase(0)).empty());
}

// Two shapes the fuzzer found, judged by every oracle on the reference's plan:
//  - the clearance (1 mm) reaches above the level the tool left the shape at (radius 2.01 after
//    the chamfer to 1.73): the approach into the pocket is fed all the way from there, and the
//    feed out before it is the retract (retract took the valley's 45° retract further on instead);
//  - A (x 1.02) below the retract from the valley (x 1.03): the rapid back down to A's level
//    enters no pocket (pocket-entry took it for one).
TEST(PocketEntry, TheReferencePassesEveryOracleWhereTheClearanceReachesHighOrAStandsLow) {
  const struct {
    const char* profile;
    double clearance;
    const char* program;
  } cases[] = {{"fanuc-0i-c", 1,
                "G00 X3.78 Z0.75;\nG71 U0.84 R0.12;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2 W0;\nG01 X3.46 Z0.65;\n"
                "G01 X3.46 Z0.55;\nN20 G01 X3.78 Z0.45;\nM30;\n"},
               {"fanuc-0i-f", 0.1,
                "G00 X2.04 Z0;\nG71 U0.5 R0.02;\nG71 P10 Q20 U0.02 W0 F0.2;\nN10 G00 X2 W0;\nG01 X2 Z-0.05;\n"
                "N20 G01 X2 Z-0.1;\nM30;\n"}};
  for (const auto& k : cases) {
    const SpecCase c = specCaseFrom(nlohmann::json{{"id", std::string(k.profile) + "/g71/clearance"},
                                                   {"title", "G71 type II with 5134"},
                                                   {"rules", {"G71.T2.POCKET.EXIT"}},
                                                   {"profile", k.profile},
                                                   {"params", {{"5134", k.clearance}}},
                                                   {"program", k.program},
                                                   {"expect", {{"oracles", "pass"}}},
                                                   {"derivation", "found by cyclecert fuzz"}},
                                    "test");
    const EngineResult r = makeEngine("reference")->run(c);
    ASSERT_EQ(r.kind, EngineResult::Planned) << r.detail;
    const std::vector<Finding> f = judge(judgeInputFor(judgeRequestFor(c), r.path));
    EXPECT_TRUE(f.empty()) << k.program << findingsText(f);
  }
}

}  // namespace
}  // namespace cyclecert
