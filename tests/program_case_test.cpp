// harness/spec/program_case: a bare program wrapped as a spec case (what `cyclecert diff` hands to
// engines), its rules, its parameters and the overrides of a case file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/spec/program_case.h"

namespace cyclecert {
namespace {

using Rules = std::vector<std::string>;

TEST(ProgramCase, RulesComeFromTheHeaderCommentInOrderEachOnce) {
  EXPECT_EQ(rulesOfProgram("(rules: G71.QUAD, G70.EX G71.QUAD)\nG71 U1 R1\n"), (Rules{"G71.QUAD", "G70.EX"}));
}

TEST(ProgramCase, AHeaderWithoutRuleIdsFallsBackToTheCyclesCalled) {
  // "lower-case" and "x y" are no rule IDs; the cycles then decide.
  EXPECT_EQ(rulesOfProgram("(rules: lower-case)\nG72 W1 R1\nG70 P1 Q2\n"), (Rules{"G72.FMT", "G70.EX"}));
}

TEST(ProgramCase, TheCyclesCalledOutsideCommentsNameTheirFormatRules) {
  // G071 is G71; the G73 in a comment and G71.1 / G730 are no calls of the cycles.
  EXPECT_EQ(rulesOfProgram("(G73 here is a comment)\nG071 U2 R1\nG71.1\nG730\nG73 U1 W1 R2\nG71 P1 Q2\n"),
            (Rules{"G71.FMT.ZX", "G73.EX"}));
}

TEST(ProgramCase, AProgramWithoutACycleStillCitesOneRule) {
  EXPECT_EQ(rulesOfProgram("G00 X10 Z5\n"), (Rules{"G71.FMT.ZX"}));
}

TEST(ProgramCase, AParameterSetTwiceByNumberAndMnemonicKeepsTheLastOnly) {
  nlohmann::json params = nlohmann::json::object();
  setCaseParam(params, "5105#1", 1);
  setCaseParam(params, "RF1", 0);
  ASSERT_EQ(params.size(), 1u) << params.dump();
  EXPECT_EQ(params["RF1"], 0);
}

TEST(ProgramCase, AProgramBecomesACaseEveryOracleJudges) {
  const SpecCase c = specCaseForProgram("/tmp/my part #2.nc", "(profile: gsk)\nG00 X10 Z5\n", "diff",
                                        {"", {{"5133", 0.5}}, 0.01, "a test"});
  EXPECT_EQ(c.id, "gsk/diff/my_part__2");
  EXPECT_EQ(c.profile, "gsk");
  EXPECT_TRUE(c.oraclesOnly);
  EXPECT_DOUBLE_EQ(c.tolerance, 0.01);
  EXPECT_EQ(c.raw["params"]["5133"], 0.5);
  EXPECT_NE(c.derivation.find("wrapped by a test; nothing was derived by hand"), std::string::npos) << c.derivation;
}

TEST(ProgramCase, AProfileGivenOverridesTheHeaderAndAnOddFileNameStillMakesAnId) {
  const SpecCase c = specCaseForProgram(".nc", "(profile: gsk)\nG00 X10 Z5\n", "diff", {"fanuc-0i-c", {}, {}, "a test"});
  EXPECT_EQ(c.profile, "fanuc-0i-c");
  EXPECT_EQ(c.id, "fanuc-0i-c/diff/program.nc");
}

TEST(ProgramCase, InvalidUtf8InAProgramIsReplacedNotRefused) {
  const SpecCase c = specCaseForProgram("legacy.nc", "(caf\xe9)\nG00 X10 Z5\n", "diff", {"", {}, {}, "a test"});
  EXPECT_NE(c.program.find("\xEF\xBF\xBD"), std::string::npos);  // U+FFFD
}

TEST(ProgramCase, OverridesOfACaseFileGoIntoItsJsonSoRawAndCaseAgree) {
  const SpecCase base = specCaseForProgram("a.nc", "G00 X10 Z5\n", "diff", {"", {{"RF1", 1}}, {}, "a test"});
  const SpecCase c = withCaseOverrides(base, "gsk", {{"5105#1", 0}});
  EXPECT_EQ(c.profile, "gsk");
  EXPECT_EQ(c.raw["profile"], "gsk");
  ASSERT_EQ(c.raw["params"].size(), 1u) << c.raw["params"].dump();
  EXPECT_EQ(c.raw["params"]["5105#1"], 0);
  EXPECT_EQ(withCaseOverrides(base, "", {}).raw, base.raw);
}

TEST(ProgramCase, OnlyAJsonFileIsASpecCase) {
  EXPECT_TRUE(isSpecCaseFile("specs/cases/x.json"));
  EXPECT_TRUE(isSpecCaseFile("X.JSON"));
  EXPECT_FALSE(isSpecCaseFile("part.nc"));
  EXPECT_FALSE(isSpecCaseFile("json"));
}

}  // namespace
}  // namespace cyclecert
