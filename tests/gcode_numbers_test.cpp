// Issue 13, defect 6: numbers are read as the controller reads them (no exponent form), every
// dimension and feed word is range-checked (PS0003), an address a block gives no meaning is
// PS0009 (PROG.RANGE, PROG.ADDRESS), each naming line and column.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "reference/gcode/parser.h"
#include "reference/model/alarms.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

Toolpath plan(const std::string& program) { return planFanucProgram(program, "num.nc"); }

const char* const kCycle = kSmallG71Cycle;

void expectAlarm(const Toolpath& t, const std::string& code, int line, const std::string& inMessage) {
  ASSERT_TRUE(t.alarm) << "no alarm, expected " << code;
  EXPECT_EQ(t.alarm->code, code) << t.alarm->message;
  EXPECT_EQ(t.alarm->line, line) << t.alarm->message;
  EXPECT_NE(t.alarm->message.find(inMessage), std::string::npos) << t.alarm->message;
}

TEST(GcodeNumbers, AnExponentIsReadAsTheAddressEAsTheControllerDoes) {
  const Program p = parseProgram("G00 X1e308 Z2;\n", "e.nc");
  ASSERT_EQ(p.blocks.size(), 1u);
  ASSERT_EQ(p.blocks[0].words.size(), 4u);
  EXPECT_EQ(p.blocks[0].words[1].text, "X1");
  EXPECT_EQ(p.blocks[0].words[2].letter, 'E');
  EXPECT_EQ(p.blocks[0].words[2].column, 7);
}

TEST(GcodeNumbers, AnExponentFormIsPS0009AtTheE) {
  const Toolpath t = plan("G00 X1e308 Z2;\n" + std::string(kCycle));
  expectAlarm(t, "PS0009", 1, "e308 at column 7");
  EXPECT_NE(t.alarm->message.find("exponent"), std::string::npos) << t.alarm->message;
  // In the shape program, which the cycle reads itself.
  const Toolpath shape = plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-1E1;\nN20 X40 Z-20;\n");
  expectAlarm(shape, "PS0009", 5, "E1 at column 8");
}

TEST(GcodeNumbers, AnEWordOutsideAThreadingBlockIsPS0009) {
  const Toolpath t = plan("G00 X40 Z2;\n" + std::string(kCycle) + "G01 X50 E2.;\n");
  expectAlarm(t, "PS0009", 7, "thread lead");
  EXPECT_EQ(t.alarm->message.find("exponent"), std::string::npos) << "E2. stands apart: " << t.alarm->message;
}

TEST(GcodeNumbers, AddressesAMotionBlockDoesNotUseArePS0009) {
  expectAlarm(plan("G00 X40 Z2 P5;\n" + std::string(kCycle)), "PS0009", 1, "P5 at column 12");
  expectAlarm(plan("G00 X40 Z2 K1;\n" + std::string(kCycle)), "PS0009", 1, "K1 at column 12");
  // An arc in G18 takes I and K (or R), not J.
  expectAlarm(plan("G00 X40 Z2;\n" + std::string(kCycle) + "G02 X50 Z-25 J1;\n"), "PS0009", 7, "J1");
}

TEST(GcodeNumbers, ChamferingInG01IsNotSupportedRatherThanIgnored) {
  EXPECT_THROW(plan("G00 X40 Z2;\n" + std::string(kCycle) + "G01 X50 Z-30 R2 F0.2;\nG01 X60;\n"), NotSupported);
  EXPECT_THROW(plan("G00 X40 Z2;\n" + std::string(kCycle) + "G01 Z-30 C1 F0.2;\n"), NotSupported);
}

TEST(GcodeNumbers, DimensionsBeyondTheRangeArePS0003NamingTheColumn) {
  expectAlarm(plan("G00 X2000000000. Z2;\n" + std::string(kCycle)), "PS0003", 1, "X2000000000. at column 5");
  expectAlarm(plan("G00 X40 Z1000000;\n" + std::string(kCycle)), "PS0003", 1, "Z1000000 at column 9");
  // 999999.999 mm is the largest: accepted (as a word; the move itself is valid).
  EXPECT_FALSE(plan("G00 X40 Z999999.999;\nG00 Z2;\n" + std::string(kCycle)).alarm);
  // Inch: 99999.9999.
  expectAlarm(plan("G20;\nG00 X100000. Z0.1;\n"), "PS0003", 2, "X100000. at column 5");
  // The shape program and the feed too.
  expectAlarm(plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 W-1000000000;\nN20 X40 Z-20;\n"),
              "PS0003", 5, "W-1000000000 at column 5");
  expectAlarm(plan("G00 X40 Z2 F10000000;\n"), "PS0003", 1, "F10000000");
}

TEST(GcodeNumbers, AnOutOfRangeCycleAddressIsStillDatedCycleBlock) {
  const Toolpath t = plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W1000000 F0.2;\nN10 G00 X20;\nN20 G01 X40 Z-20;\n");
  expectAlarm(t, "PS0003", 3, "W1000000");
  EXPECT_EQ(t.alarm->when, "cycle block");
}

}  // namespace
}  // namespace cyclecert
