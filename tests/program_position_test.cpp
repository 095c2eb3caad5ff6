// Issue 13, defects 4 and 5: a block with codes of several modal groups and motion moves as the
// manual says (G54–G59, G80 with G00), G50 sets the position without motion, and the position
// after G28/G30/G53 (or before any positioning) is unknown: a cycle from there is a clear error,
// never a plan from a guessed point (PROG.WCS, PROG.POSITION, PROG.GCODES).
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

Toolpath plan(const std::string& program) { return planFanucProgram(program, "pos.nc"); }

// A = (x 20, z 2) once positioned; U+ allowance: a start anywhere below x 20 is PS0322.
const char* const kCycle = kSmallG71Cycle;

TEST(ProgramPosition, WorkCoordinateSystemAndMotionInOneBlockMove) {
  for (const char* g : {"G54", "G55", "G56", "G57", "G58", "G59"}) {
    const Toolpath t = plan(std::string(g) + " G00 X40. Z2.;\n" + kCycle);
    ASSERT_FALSE(t.alarm) << g << ": " << t.alarm->code << " " << t.alarm->message;
    EXPECT_TRUE(nearlyEqual(t.start, {2, 20})) << g;
  }
}

TEST(ProgramPosition, WorkCoordinateSystemMotionAfterTheCycleIsAMove) {
  const Toolpath t = plan("G00 X40 Z2;\n" + std::string(kCycle) + "G55 G00 X100. Z50.;\nM30;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.moves.back().phase, MovePhase::Program);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {50, 50}));
}

TEST(ProgramPosition, G80IsAG0iTFCodeAndItsBlockMoves) {
  Toolpath t = plan("G80;\nG00 X40 Z2;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
  t = plan("G80 G00 X40. Z2.;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
}

TEST(ProgramPosition, DrillingCyclesAreNotSupportedNotUnknownCodes) {
  for (const char* g : {"G83", "G84", "G85", "G87", "G88", "G89", "G32", "G29", "G52"}) {
    EXPECT_THROW(plan(std::string("G00 X40 Z2;\n") + g + " Z-10 F0.1;\n"), NotSupported) << g;
  }
}

// PROG.WHOLE: the path starts at the first known position; every later move is drawn.
TEST(ProgramPosition, TheApproachBeforeTheFirstCycleIsDrawn) {
  const Toolpath t = plan("G00 X100. Z100.;\nG00 X40. Z2.;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {100, 50}));
  ASSERT_FALSE(t.moves.empty());
  EXPECT_EQ(t.moves.front().phase, MovePhase::Program);
  EXPECT_TRUE(nearlyEqual(t.moves.front().to, {2, 20}));
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_EQ(t.cycles.front().firstMove, 1u);
}

TEST(ProgramPosition, AProgramWithoutCyclesPlansItsMoves) {
  const Toolpath t = plan("G00 X100. Z100.;\nG00 X40. Z2.;\nG01 Z-20. F0.2;\nG00 X100. Z100.;\nM30;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(t.cycles.empty());
  ASSERT_EQ(t.moves.size(), 3u);
  EXPECT_EQ(t.moves[1].kind, MoveKind::Feed);
  EXPECT_TRUE(nearlyEqual(t.moves[1].to, {-20, 20}));
}

TEST(ProgramPosition, OnePlanePerToolpath) {
  // Before any move is drawn the path follows the plane; after, a move in another plane is refused.
  EXPECT_FALSE(plan("G00 X40. Z2.;\nG18;\n" + std::string(kCycle)).alarm);
  EXPECT_THROW(plan("G00 X100. Z100.;\nG00 X40. Z2.;\nG17 G00 X30. Y5.;\nM30;\n"), NotSupported);
}

// PROG.SHOP: a '%3304' program name is Huazhong's; a FANUC profile says so instead of reading it.
TEST(ProgramPosition, APercentProgramNameIsHuazhongs) {
  const std::string program = "%3304\nG00 X40. Z2.;\n" + std::string(kCycle);
  EXPECT_NE(notSupportedMessage(program).find("--profile hnc"), std::string::npos) << notSupportedMessage(program);
  EXPECT_NE(notSupportedMessage(program).find("O3304"), std::string::npos);
  const Toolpath hnc = planWithReference({"%3304\nG00 X40. Z2.;\nG01 Z-5. F0.2;\nM30;\n", "p.nc", "hnc", {}, {}});
  EXPECT_FALSE(hnc.alarm);
  EXPECT_EQ(hnc.moves.size(), 1u);
}

TEST(ProgramPosition, G50SetsThePositionWithoutMotion) {
  const Toolpath t = plan("G50 X40. Z2.;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
  // After the path has started, G50 moves nothing and the next move starts at the new coordinates.
  const Toolpath after = plan("G00 X40 Z2;\n" + std::string(kCycle) + "G50 X0 Z0;\nG00 X10;\nM30;\n");
  ASSERT_FALSE(after.alarm);
  EXPECT_TRUE(nearlyEqual(after.moves.back().to, {0, 5}));
}

TEST(ProgramPosition, DwellWordsAreNotMotion) {
  const Toolpath t = plan("G00 X40 Z2;\n" + std::string(kCycle) + "G04 X1.5;\nM30;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {2, 20}));  // the cycle's return, no move to x 0.75
}

TEST(ProgramPosition, ACycleBeforeAnyPositioningIsAClearError) {
  const std::string why = notSupportedMessage(kCycle);
  EXPECT_NE(why.find("line 2"), std::string::npos) << why;
  EXPECT_NE(why.find("unknown at the start of the program"), std::string::npos) << why;
  EXPECT_NE(why.find("G00 X.. Z.."), std::string::npos) << why;
}

TEST(ProgramPosition, ACycleAfterG28WithoutPositioningIsAClearError) {
  const std::string why = notSupportedMessage("G00 X40 Z2;\nG28 U0 W0;\n" + std::string(kCycle));
  EXPECT_NE(why.find("unknown after G28 at line 2"), std::string::npos) << why;
  // Positioning both axes afterwards makes the position known again.
  const Toolpath t = plan("G28 U0 W0;\nG00 X40 Z2;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
  // One axis is not enough.
  EXPECT_NE(notSupportedMessage("G28 U0 W0;\nG00 X40;\n" + std::string(kCycle)).find("position of Z unknown after G28 at line 1"),
            std::string::npos);
}

TEST(ProgramPosition, G30AndG53LoseTheCommandedAxes) {
  EXPECT_NE(notSupportedMessage("G00 X40 Z2;\nG30 U0;\n" + std::string(kCycle)).find("position of X unknown after G30 at line 2"),
            std::string::npos);
  EXPECT_NE(notSupportedMessage("G00 X40 Z2;\nG53 Z0;\n" + std::string(kCycle)).find("position of Z unknown after G53 at line 2"),
            std::string::npos);
  // An axis G53 did not command keeps its position.
  const Toolpath t = plan("G00 X40 Z2;\nG53 X100;\nG00 X40;\n" + std::string(kCycle));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
}

TEST(ProgramPosition, IncrementalMotionFromAnUnknownPositionIsAClearError) {
  const std::string why = notSupportedMessage("G28 U0 W0;\nG00 U-10 W-2;\n" + std::string(kCycle));
  EXPECT_NE(why.find("line 2"), std::string::npos) << why;
  EXPECT_NE(why.find("unknown after G28 at line 1"), std::string::npos) << why;
}

TEST(ProgramPosition, AfterG28ThePositioningIsDrawnFromTheIntermediatePoint) {
  const std::string program = "G00 X40 Z2;\n" + std::string(kCycle) + "G28 U0 W0;\n";
  // Ending there is fine: the return to the reference position is not shown, and a warning says so.
  const Toolpath t = plan(program + "M30;\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_FALSE(t.warnings.empty());
  EXPECT_NE(t.warnings.back().message.find("G28"), std::string::npos);
  // The two-tool program: G28, the next tool, its positioning, G70. The positioning is drawn as a
  // rapid from the intermediate point (U0 W0: A itself, x 20 z 2) to (x 25, z 3); G70 starts there.
  const Toolpath two = plan(program + "T0202;\nG00 X50 Z3;\nG70 P10 Q20;\nM30;\n");
  ASSERT_FALSE(two.alarm);
  ASSERT_EQ(two.cycles.size(), 2u);
  const Move& positioning = two.moves[two.cycles[1].firstMove - 1];
  EXPECT_EQ(positioning.kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(two.from(two.cycles[1].firstMove - 1), {2, 20}));
  EXPECT_TRUE(nearlyEqual(positioning.to, {3, 25}));
  EXPECT_TRUE(nearlyEqual(two.cycles[1].start, {3, 25}));
  // Only straight absolute positioning is drawn so: an arc or an incremental move from there, or a
  // cycle before both axes are positioned again, is still a clear error.
  EXPECT_NE(notSupportedMessage(program + "G02 X50 Z-5 R10;\n").find("unknown after G28 at line 7"), std::string::npos);
  EXPECT_NE(notSupportedMessage(program + "G00 U10 W2;\n").find("unknown after G28 at line 7"), std::string::npos);
  EXPECT_NE(notSupportedMessage(program + "G00 X50;\nG70 P10 Q20;\n").find("position of Z unknown after G28 at line 7"),
            std::string::npos);
}

TEST(ProgramPosition, G28IntermediatePointIsARapid) {
  const Toolpath t = plan("G00 X40 Z2;\n" + std::string(kCycle) + "G01 X60 F0.3;\nG28 U10 W0;\nM30;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(t.moves.back().kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {2, 35}));
}

}  // namespace
}  // namespace cyclecert
