// Reading G74.1's two blocks (reference/cycles/g74_1.cpp): the ranges of G74_1.RANGE and their
// alarms (docs/g74_1.md §1, I1–I6b), P/Q units by parameter 182.7, the profile, G41/G42.
#include <gtest/gtest.h>

#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "reference/model/params.h"

namespace cyclecert {
namespace {

Toolpath planGsk(const std::string& program, std::vector<std::pair<std::string, double>> params = {{"182#7", 1}},
                 const std::string& profile = "gsk") {
  return planWithReference({program, "test.nc", profile, std::move(params), {}});
}

// A straight groove (X40 Z0, 4 deep, 2 wide radius); `first` and `second` add words to its blocks.
std::string groove(const std::string& first, const std::string& second) {
  return "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H-4 D-4" + first + ";\nG74.1 R0.5" + second + ";\n";
}

void expectAlarm(const Toolpath& t, const std::string& code, int line, const std::string& mentions) {
  ASSERT_TRUE(t.alarm) << "no alarm; expected " << code;
  EXPECT_EQ(t.alarm->code, code) << t.alarm->message;
  EXPECT_EQ(t.alarm->line, line) << t.alarm->message;
  EXPECT_EQ(t.alarm->when, "cycle block");
  EXPECT_NE(t.alarm->message.find(mentions), std::string::npos) << t.alarm->message;
}

TEST(G74_1Reading, TheGrooveBlocksRanges) {
  // Line 2 is the first block: ∠a, ∠b in (0, 90]; ∠p in [0, 90); h, d not 0 and |·| ≤ 9999.9999.
  expectAlarm(planGsk(groove(" A0", "")), "PS0003", 2, "A0 at column");
  expectAlarm(planGsk(groove(" A95", "")), "PS0003", 2, "0 < ∠ ≤ 90");
  expectAlarm(planGsk(groove(" B0", "")), "PS0003", 2, "B0");
  expectAlarm(planGsk(groove(" L90", "")), "PS0003", 2, "0 ≤ ∠p < 90");
  expectAlarm(planGsk(groove(" L-1", "")), "PS0003", 2, "L-1");
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H0 D-4;\nG74.1 R0.5;\n"), "PS0003", 2, "without 0");
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H-4 D10000;\nG74.1 R0.5;\n"), "PS0003", 2, "D10000");
}

TEST(G74_1Reading, TheStepAmountsMustBePositive) {
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P0 Q2 H-4 D-4;\nG74.1 R0.5;\n"), "PS0062", 2, "P0");
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q-2 H-4 D-4;\nG74.1 R0.5;\n"), "PS0062", 2, "Q-2");
  expectAlarm(planGsk(groove("", " V0")), "PS0062", 3, "V0");
}

TEST(G74_1Reading, TheCuttingBlocksRanges) {
  // Line 3 is the second block: e 0…99.9999, J 0/1/2, r1…r4 0…99.9999, P(abde) digits 0/1.
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R100;\n"), "PS0003", 3, "R100");
  expectAlarm(planGsk(groove("", " J3")), "PS0003", 3, "J3");
  expectAlarm(planGsk(groove("", " A100")), "PS0003", 3, "A100");
  expectAlarm(planGsk(groove("", " E-1")), "PS0003", 3, "E-1");
  expectAlarm(planGsk(groove("", " P2")), "PS0003", 3, "four digits");
  expectAlarm(planGsk(groove("", " P11111")), "PS0003", 3, "P11111");
  expectAlarm(planGsk(groove("", " U10000")), "PS0003", 3, "U10000");
}

TEST(G74_1Reading, MissingWordsOfTheGrooveBlock) {
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 D-4;\nG74.1 R0.5;\n"), "PS0003", 2, "no H");
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 H-4 D-4;\nG74.1 R0.5;\n"), "PS0061", 2, "no Q");
  // I1: a second block with no first block before it.
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 R0.5;\n"), "PS0061", 2, "no first G74.1 block");
}

TEST(G74_1Reading, AnAddressTheBlockDoesNotTakeIsPS0009) {
  expectAlarm(planGsk(groove(" R1", "")), "PS0009", 2, "the first G74.1 block takes");
  expectAlarm(planGsk(groove("", " K3")), "PS0009", 3, "the second G74.1 block takes");
  // I1: a G74.1 block with X is a first block, whatever else it has.
  expectAlarm(planGsk(groove("", " X3")), "PS0009", 3, "R0.5 at column 7: the first G74.1 block takes");
}

TEST(G74_1Reading, PAndQInLeastIncrementsByDefault) {
  // 182.7 = 0: P10000 = 1 mm (Δi/2 0.5), Q20000 = 2 mm — the straight groove's first cycle: feed to
  // w 2, back to 1.5, to 4; the next cycle 0.5 further (x 19.5).
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P10000 Q20000 H-4 D-4;\nG74.1 R0.5;\n", {});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_GE(t.moves.size(), 6u);
  EXPECT_NEAR(t.moves[1].to.z, -2, 1e-9);
  EXPECT_NEAR(t.moves[5].to.x, 19.5, 1e-9);
  // A decimal point in increments is PS0007, naming the parameter.
  expectAlarm(planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1.0 Q20000 H-4 D-4;\nG74.1 R0.5;\n", {}), "PS0007", 2, "182#7=1");
  EXPECT_NE(MachineParams::find("182#7"), nullptr);
}

TEST(G74_1Reading, NegativeAllowancesAndToolWidthAreMagnitudes) {
  // I4 and I: U-0.4 W-0.2 I-0.5 act as U0.4 W0.2 I0.5: A11 at u 0.2 + 0.5 (x 19.3).
  const Toolpath t = planGsk(groove("", " U-0.4 W-0.2 I-0.5"));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_NEAR(t.moves.front().to.x, 19.3, 1e-9);
}

TEST(G74_1Reading, OnlyTheGskProfileHasG74_1) {
  EXPECT_THROW(planGsk(groove("", ""), {}, "fanuc-0i-f"), NotSupported);
}

TEST(G74_1Reading, APointedToolUnderG41WithoutANoseRadiusIsAPointAGroovingToolIgnoresIt) {
  // I13: no nose radius, nothing to offset: the point path of G40 (the runner warns).
  const Toolpath point = planGsk("G41;\n" + groove("", ""));
  ASSERT_FALSE(point.alarm) << point.alarm->message;
  EXPECT_EQ(point.moves.size(), planGsk(groove("", "")).moves.size());
  const Toolpath t = planGsk("G41;\n" + groove("", " I0.5"));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  bool warned = false;
  for (const Warning& w : t.warnings) warned = warned || w.message.find("ignored by G74.1") != std::string::npos;
  EXPECT_TRUE(warned);
}

TEST(G74_1Reading, OtherPlanesAreRefusedNamingTheRule) {
  for (const char* plane : {"G17", "G19"}) {
    try {
      planGsk(std::string(plane) + ";\nG00 X50 Y0 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5;\n");
      ADD_FAILURE() << plane << " was planned";
    } catch (const NotSupported& e) {
      EXPECT_NE(std::string(e.what()).find("I28"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(plane), std::string::npos) << e.what();
    }
  }
}

TEST(G74_1Reading, TheFirstBlockAloneMovesNothing) {
  const Toolpath t = planGsk("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P1 Q2 H-4 D-4;\nG00 X60;\n");
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(t.moves.size(), 1u);  // G00 X60 only
  EXPECT_NEAR(t.moves[0].to.x, 30, 1e-9);
  EXPECT_NEAR(t.moves[0].to.z, 5, 1e-9);
}

}  // namespace
}  // namespace cyclecert
