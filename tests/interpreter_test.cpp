// The program runner: modal state, planes, units, what runs after a cycle, and the alarms of
// blocks the controller refuses.
#include <gtest/gtest.h>

#include <algorithm>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "reference/model/program.h"

namespace cyclecert {
namespace {

Toolpath plan(const std::string& program, const std::string& profile = "fanuc-0i-f",
              std::vector<std::pair<std::string, double>> params = {}) {
  return planWithReference({program, "test.nc", profile, std::move(params), {}});
}

const char* kShaft =
    "G00 X40 Z2;\n"
    "G71 U2 R0.5;\n"
    "G71 P10 Q20 U0.4 W0.1 F0.2;\n"
    "N10 G00 X20;\n"
    "G01 Z-10;\n"
    "N20 X40 Z-20;\n";

TEST(Interpreter, PathStartsAtTheCycleStartAndReturnsThere) {
  const Toolpath t = plan(kShaft);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_EQ(t.cycles[0].code, "G71");
  EXPECT_EQ(t.cycles[0].line, 3);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {2, 20}));
  EXPECT_EQ(t.cycles[0].shape.size(), 3u);  // A→B, B→(−10), →C
  EXPECT_TRUE(nearlyEqual(t.cycles[0].allowance, {0.1, 0.2}));
}

TEST(Interpreter, BlocksAfterTheCycleResumeAfterNfAndBecomeMoves) {
  const Toolpath t = plan(std::string(kShaft) + "G00 X100 Z50;\nM30;\nG00 X200;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.moves.back().phase, MovePhase::Program);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {50, 50}));  // M30 ends the program
}

TEST(Interpreter, ShapeNotDirectlyAfterTheCycleResumesAfterTheCycleBlock) {
  // G72.NSNF.FOLLOW: ns…nf elsewhere ⇒ execution continues with the block after the cycle.
  const Toolpath t = plan(
      "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nG00 X60;\nM30;\n"
      "N10 G00 X20;\nG01 Z-10;\nN20 X40 Z-20;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {2, 30}));
}

TEST(Interpreter, InchProgramsAreConvertedToMillimetres) {
  const Toolpath t = plan("G20;\nG00 X2 Z0.1;\nG71 U0.1 R0.02;\nG71 P1 Q2 U0.02 W0.004 F0.01;\nN1 G00 X1;\nN2 G01 X2 Z-1;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2.54, 25.4}, 1e-9));
  EXPECT_NEAR(*t.moves[2].feed, 0.254, 1e-12);
}

TEST(Interpreter, PlanesG17AndG19MapOntoTheCycleFrame) {
  const Toolpath zx = plan(kShaft);
  // G19 (Y 1st, Z 2nd, radius): Δd by W, Δu by W (not halved), Δw by V.
  const Toolpath yz = plan("G19;\nG00 Z20 Y2;\nG71 W2 R0.5;\nG71 P10 Q20 W0.2 V0.1 F0.2;\nN10 G00 Z10;\nG01 Y-10;\nN20 Z20 Y-20;\n");
  ASSERT_FALSE(yz.alarm) << yz.alarm->message;
  EXPECT_EQ(yz.plane, "G19");
  ASSERT_EQ(yz.moves.size(), zx.moves.size());
  for (std::size_t i = 0; i < zx.moves.size(); ++i) EXPECT_TRUE(nearlyEqual(yz.moves[i].to, zx.moves[i].to, 1e-9)) << i;
  // G17 (X 1st, diameter; Y 2nd): Δd by V, Δu by V, Δw by U (a diameter, halved).
  const Toolpath xy = plan("G17;\nG00 Y20 X4;\nG71 V2 R0.5;\nG71 P10 Q20 V0.2 U0.2 F0.2;\nN10 G00 Y10;\nG01 X-20;\nN20 Y20 X-40;\n");
  ASSERT_FALSE(xy.alarm) << xy.alarm->message;
  ASSERT_EQ(xy.moves.size(), zx.moves.size());
  for (std::size_t i = 0; i < zx.moves.size(); ++i) EXPECT_TRUE(nearlyEqual(xy.moves[i].to, zx.moves[i].to, 1e-9)) << i;
}

TEST(Interpreter, UnknownGCodeIsPS0010) {
  const Toolpath t = plan("G00 X40 Z2;\nG123 X1;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0010");
  EXPECT_EQ(t.alarm->line, 2);
}

TEST(Interpreter, ImpossibleArcsInTheShapeAreAlarms) {
  const std::string head = "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\n";
  Toolpath t = plan(head + "G02 X30 Z-20 R2;\nN20 G01 X40;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0023");
  EXPECT_EQ(t.alarm->line, 5);
  t = plan(head + "G02 X30 Z-5;\nN20 G01 X40;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0023");
  t = plan(head + "G03 X30 Z-5 I0 K-9;\nN20 G01 X40;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0020");
}

TEST(Interpreter, IKArcsAndRArcsGiveTheSamePath) {
  const std::string head = "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-5;\n";
  const Toolpath r = plan(head + "G03 X30 Z-10 R5;\nN20 G01 X40;\n");
  const Toolpath ik = plan(head + "G03 X30 Z-10 I0 K-5;\nN20 G01 X40;\n");
  ASSERT_FALSE(r.alarm);
  ASSERT_FALSE(ik.alarm);
  ASSERT_EQ(r.moves.size(), ik.moves.size());
  for (std::size_t i = 0; i < r.moves.size(); ++i) EXPECT_TRUE(nearlyEqual(r.moves[i].to, ik.moves[i].to, 1e-9));
}

TEST(Interpreter, NoFeedAnywhereIsPS0011) {
  const Toolpath t = plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1;\nN10 G00 X20;\nN20 G01 X40 Z-20;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0011");
}

TEST(Interpreter, CyclesTheReferenceCannotPlanAreNotSupported) {
  EXPECT_THROW(plan("G00 X70 Z10;\nG75 X40 Z-20 P3000 Q5000 F0.1;\n"), NotSupported);
}

TEST(Interpreter, HeadBlockWithBothAxesSelectsTypeII) {
  const Toolpath t = plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0 F0.2;\nN10 G00 X20 W0;\nN20 G01 X40 Z-20;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  // Type II follows the shape after each cut (G71.T2.FOLLOW) where type I retracts at 45°.
  EXPECT_TRUE(std::any_of(t.moves.begin(), t.moves.end(), [](const Move& m) {
    return std::find(m.rules.begin(), m.rules.end(), "G71.T2.FOLLOW") != m.rules.end();
  }));
}

TEST(Interpreter, G70FinishesAlongTheShapeWithItsOwnFeedAndReturns) {
  const Toolpath t = plan(std::string(kShaft) + "G70 P10 Q20;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.cycles.size(), 2u);
  EXPECT_EQ(t.cycles[1].code, "G70");
  const std::size_t first = t.cycles[1].firstMove;
  ASSERT_EQ(t.cycles[1].moveCount, 4u);  // X20 rapid, Z-10, X40 Z-20, back to A
  EXPECT_EQ(t.moves[first].kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(t.moves[first + 2].to, {-20, 20}));
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {2, 20}));
}

TEST(Interpreter, CyclesInMdiModeArePS0067) {
  RunOptions mdi;
  mdi.mdi = true;
  const Toolpath t = planWithReference({kShaft, "mdi.nc", "gsk", {}, mdi});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0067");
  EXPECT_EQ(t.alarm->line, 2);
}

TEST(Interpreter, CompensationBeforeTheCycleIsWarnedAbout) {
  const Toolpath t = plan("G21 G42;\n" + std::string(kShaft));  // G21: no units warning first
  ASSERT_FALSE(t.alarm);
  ASSERT_FALSE(t.warnings.empty());
  EXPECT_NE(t.warnings[0].message.find("G42 is active but the tool's nose radius is 0"), std::string::npos);
  EXPECT_FALSE(t.cycles[0].compensated);
}

TEST(Interpreter, CompensationOffsetsTheShapeTheCycleRoughs) {
  RunOptions tool;
  tool.tool = {0.4, 3};
  const Toolpath t = planWithReference({"G42;\n" + std::string(kShaft), "c.nc", "fanuc-0i-f", {}, tool});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_TRUE(t.cycles[0].compensated);
  // G71.TNRC.ZERO: A keeps a zero vector; block ns (X20, then Z-10 on the right side, tip 3) ends at
  // B + r·(0, 1) + r·(−1, −1) = (2 − 0.4, 10).
  EXPECT_TRUE(nearlyEqual(t.cycles[0].shape[0].from, {2, 20}, 1e-9));
  EXPECT_TRUE(nearlyEqual(t.cycles[0].shape[0].to, {1.6, 10}, 1e-9));
  // A radius larger than the shape allows is PS0041.
  tool.tool = {6, 3};
  const Toolpath big = planWithReference({"G42;\nG00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\n"
                                          "G01 Z-10;\nG02 X24 Z-12 R2;\nN20 G01 X40 Z-20;\n", "c.nc", "fanuc-0i-f", {}, tool});
  ASSERT_TRUE(big.alarm);
  EXPECT_EQ(big.alarm->code, "PS0041");
}

TEST(Interpreter, AlarmKeepsTheMovesOfEarlierCycles) {
  const Toolpath t = plan(std::string(kShaft) + "G71 P10 Q99 F0.2;\n");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0063");
  EXPECT_EQ(t.cycles.size(), 1u);
  EXPECT_FALSE(t.moves.empty());
}

TEST(Interpreter, MalformedProgramIsAParseErrorWithLocation) {
  try {
    plan("G00 X40 Z2;\nG71 U2 R;\n");
    FAIL() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().column, 9);
    EXPECT_EQ(e.loc().file, "test.nc");
  }
}

TEST(Interpreter, ProfileComesFromTheHeaderComment) {
  EXPECT_EQ(profileFromHeader("(source: seed 001)\n(profile: gsk)\nG00 X1;"), "gsk");
  EXPECT_EQ(profileFromHeader("G00 X1;"), "");
  EXPECT_THROW(plan(kShaft, "heidenhain"), UnknownProfile);
}

}  // namespace
}  // namespace cyclecert
