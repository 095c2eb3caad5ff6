// Modal groups as FANUC's manual defines them (PROG.GROUP.*), the units assumption (PROG.UNITS)
// and the codes every shop lathe program carries (PROG.SHOP). Expected values are derived by hand
// from the program text: the small G71 cycle positioned at X40 Z2 starts at A = (x 20, z 2).
#include <gtest/gtest.h>

#include <algorithm>

#include "harness/judge/judging.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/toolpath_json.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

bool hasWarningWith(const Toolpath& t, const std::string& text) {
  return std::any_of(t.warnings.begin(), t.warnings.end(),
                     [&](const Warning& w) { return w.message.find(text) != std::string::npos; });
}

// The oracles read the program as the runner does: on a planned program they find nothing.
void expectOraclesAgree(const std::string& program) {
  JudgeRequest request;
  request.program = {program, "modal.nc", "fanuc-0i-f", {}, {}};
  const JudgeInput in = judgeInputFor(request, planWithReference(request.program));
  const std::vector<Finding> findings = judge(in);
  EXPECT_TRUE(findings.empty()) << program << findingsText(findings);
}

std::string alarmCode(const Toolpath& t) { return t.alarm ? t.alarm->code : "none"; }

TEST(GCodeTable, GroupsOfTheLatheSystemA) {
  const std::pair<int, GGroup> expected[] = {
      {0, GGroup::Motion},          {30, GGroup::Motion},           {40, GGroup::OneShot},
      {500, GGroup::OneShot},       {710, GGroup::OneShot},         {960, GGroup::SpindleSpeedMode},
      {970, GGroup::SpindleSpeedMode}, {980, GGroup::FeedMode},     {990, GGroup::FeedMode},
      {200, GGroup::Units},         {210, GGroup::Units},           {410, GGroup::NoseRadiusComp},
      {800, GGroup::DrillingCycle}, {550, GGroup::WorkCoordinates}, {190, GGroup::Plane},
      {920, GGroup::Motion},
  };
  for (const auto& [g10, group] : expected) {
    const GCode* code = findGCode(g10);
    ASSERT_NE(code, nullptr) << g10;
    EXPECT_EQ(code->group, group) << g10;
  }
  EXPECT_EQ(groupNumber(GGroup::Plane), 16);
  for (const int absent : {910, 330, 430, 1000, -1, 5}) EXPECT_EQ(findGCode(absent), nullptr) << absent;
}

TEST(ModalGroups, TwoCodesOfOneGroupAreNoAlarmTheLastActs) {
  // G00 G01: the move after the cycle is a feed; G01 G00: a rapid (PROG.GROUP.LAST).
  const Toolpath t = planFanucProgram(std::string("G20 G21;\nG00 X40 Z2;\n") + kSmallG71Cycle +
                                      "G00 G01 X50 Z5 F0.3;\nG01 G00 X60;\nG18 G17 G18;\nG41 G40;\nM30;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_GE(t.moves.size(), 2u);
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));  // G21 last: millimetres, not 25.4 times more
  const Move& feed = t.moves[t.moves.size() - 2];
  EXPECT_EQ(feed.kind, MoveKind::Feed);
  EXPECT_TRUE(nearlyEqual(feed.to, {5, 25}));
  EXPECT_EQ(t.moves.back().kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {5, 30}));
}

TEST(ModalGroups, TheLastGroupZeroCommandDecidesWhatTheAxisWordsMean) {
  // G04 G50 X42 Z2: G50 (last) sets the position, the cycle starts at (x 21, z 2). G50 G04: the
  // dwell (last) leaves the tool at X80 Z50. The oracles follow the same reading.
  const std::string g50Last = std::string("G00 X80 Z50;\nG04 G50 X42 Z2;\n") + kSmallG71Cycle + "M30;\n";
  const std::string dwellLast = std::string("G00 X80 Z50;\nG50 G04 X40 Z2;\n") + kSmallG71Cycle + "M30;\n";
  EXPECT_TRUE(nearlyEqual(planFanucProgram(g50Last).start, {2, 21}));
  EXPECT_TRUE(nearlyEqual(planFanucProgram(dwellLast).start, {50, 40}));
  expectOraclesAgree(g50Last);
  expectOraclesAgree(dwellLast);
}

TEST(ModalGroups, MotionAndNonMotionCodesShareABlock) {
  const std::string program = std::string("G21 G54 G99 G40 G18 G00 X42 Z2 T0101 M03;\n") + kSmallG71Cycle + "M30;\n";
  const Toolpath t = planFanucProgram(program);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 21}));
  expectOraclesAgree(program);
}

TEST(ModalGroups, CompensationStartOrCancelInAnArcBlockIsPS0034) {
  EXPECT_EQ(alarmCode(planFanucProgram("G21;\nG00 X40 Z2;\nG42 G02 X30 Z-3 R5 F0.2;\nM30;\n")), "PS0034");
  const Toolpath cancel = planFanucProgram("G21;\nG00 X40 Z2;\nG42 G01 X38 F0.2;\nG40 G03 X30 Z-2 R5;\nM30;\n");
  EXPECT_EQ(alarmCode(cancel), "PS0034");
  ASSERT_TRUE(cancel.alarm);
  EXPECT_EQ(cancel.alarm->line, 4);
  // Start-up in a G01 block, and G42 in a block without axis words in G02 mode: no alarm.
  EXPECT_EQ(alarmCode(planFanucProgram("G21;\nG00 X40 Z2;\nG42 G01 X38 F0.2;\nG40 G01 X40;\nM30;\n")), "none");
  EXPECT_EQ(alarmCode(planFanucProgram("G21;\nG00 X40 Z2;\nG02;\nG42;\nG40;\nM30;\n")), "none");
}

TEST(ModalGroups, PlaneChangeUnderCompensationIsPS0037) {
  const Toolpath t = planFanucProgram("G21;\nG00 X40 Z2;\nG42 G01 X38 F0.2;\nG17;\nM30;\n");
  EXPECT_EQ(alarmCode(t), "PS0037");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->line, 4);
  EXPECT_EQ(alarmCode(planFanucProgram("G21;\nG00 X40 Z2;\nG42 G01 X38 F0.2;\nG40 G17;\nG18;\nM30;\n")), "none");
  EXPECT_EQ(alarmCode(planFanucProgram("G21;\nG17;\nG18;\nM30;\n")), "none");
}

TEST(ModalGroups, CodesOutsideSystemAArePS0010WithTheSystemAWay) {
  const Toolpath g91 = planFanucProgram("G21;\nG00 X40 Z2;\nG91 G01 U-2 F0.2;\nM30;\n");
  EXPECT_EQ(alarmCode(g91), "PS0010");
  ASSERT_TRUE(g91.alarm);
  EXPECT_EQ(g91.alarm->line, 3);
  EXPECT_NE(g91.alarm->message.find("U/W (incremental)"), std::string::npos) << g91.alarm->message;
  EXPECT_NE(planFanucProgram("G33 Z-10 F1.5;\n").alarm->message.find("G32"), std::string::npos);
  EXPECT_EQ(alarmCode(planFanucProgram("G43 Z1;\n")), "PS0010");
}

TEST(Units, AProgramWithoutG20G21IsReadInTheProfilesDefaultWithAWarning) {
  const Toolpath t = planFanucProgram(std::string("G00 X40 Z2;\n") + kSmallG71Cycle + "M30;\n");
  ASSERT_FALSE(t.alarm);
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
  EXPECT_TRUE(hasWarningWith(t, "no G20/G21 before the first move: the program is read in millimetres, the "
                                "fanuc-0i-f profile's default; add G20 for inch"));
  EXPECT_EQ(std::count_if(t.warnings.begin(), t.warnings.end(),
                          [](const Warning& w) { return w.message.find("G20/G21") != std::string::npos; }),
            1);
  EXPECT_EQ(t.warnings.front().line, 1);
  EXPECT_NE(toJson(t).dump().find("no G20/G21"), std::string::npos);  // in the JSON too
  const Toolpath gsk = planWithReference({std::string("G00 X40 Z2;\n") + kSmallG71Cycle, "p.nc", "gsk", {}, {}});
  EXPECT_TRUE(hasWarningWith(gsk, "the gsk profile's default"));
}

TEST(Units, G20OrG21BeforeTheFirstMoveSilencesTheWarning) {
  for (const std::string units : {"G21;\n", "G20;\nG21;\n"}) {
    const Toolpath t = planFanucProgram(units + "G00 X40 Z2;\n" + kSmallG71Cycle + "M30;\n");
    EXPECT_FALSE(hasWarningWith(t, "G20/G21")) << units;
  }
  // G20 read in inch: the cycle start is 25.4 times the millimetre one.
  const Toolpath inch = planFanucProgram("G20;\nG00 X2. Z0.1;\nG71 U0.1 R0.02;\nG71 P10 Q20 U0.02 W0.004 F0.01;\n"
                                         "N10 G00 X1.;\nG01 Z-0.4;\nN20 X2. Z-0.8;\nM30;\n");
  ASSERT_FALSE(inch.alarm) << inch.alarm->message;
  EXPECT_TRUE(nearlyEqual(inch.start, {2.54, 25.4}));
  EXPECT_FALSE(hasWarningWith(inch, "G20/G21"));
  // G21 after the first move does not undo the assumption: the warning names line 1.
  const Toolpath late = planFanucProgram(std::string("G00 X40 Z2;\nG21;\n") + kSmallG71Cycle);
  EXPECT_TRUE(hasWarningWith(late, "no G20/G21"));
}

// PROG.SHOP: a program as shops write it, every item of the list, plans the cycle with the
// start, the shape end (the empty block N119 as Q) and the blocks after M00/M01. (The oracle
// programs start at X42: from X40, level with C, the oracles flag the small cycle's return.)
TEST(ShopProgram, TheCodesEveryLatheProgramCarriesAreRead) {
  const std::string program =
      "%\n"
      "O1234 (SHAFT)\n"
      "G21 G99;\n"
      "G50 S2000;\n"       // the spindle speed clamp: no coordinate setting
      "G96 S180 M03;\n"
      "T0101;\n"
      "M08;\n"
      "G00 X42. Z2. T0101 M04;\n"
      "G71 U2. R0.5;\n"
      "G71 P10 Q119 U0.4 W0.1 F0.2;\n"
      "N10 G00 X20.;\n"
      "G01 Z-10.;\n"
      "X40. Z-20.;\n"
      "N119;\n"
      "/ M01;\n"
      "M09;\nM05;\nM00;\nM01;\n"
      "G97 S500;\nG98;\n"
      "G00 X60. Z10.;\n"
      "M30;\n"
      "%\n";
  const Toolpath t = planFanucProgram(program);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {2, 21}));
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_TRUE(nearlyEqual(t.cycles[0].shape.back().to, {-20, 20}));  // C = end of X40 Z-20
  EXPECT_TRUE(nearlyEqual(t.moves.back().to, {10, 30}));              // after M00/M01: still moving
  EXPECT_FALSE(hasWarningWith(t, "G20/G21"));
  expectOraclesAgree(program);
}

TEST(ShopProgram, G50WithOnlySIsTheClampNotACoordinateSetting) {
  const std::string program = std::string("G21;\nG00 X42 Z2;\nG50 S1500;\n") + kSmallG71Cycle + "M30;\n";
  EXPECT_TRUE(nearlyEqual(planFanucProgram(program).start, {2, 21}));
  expectOraclesAgree(program);
}

TEST(ShopProgram, G92SInSystemAIsReportedWithG50S) {
  try {
    planFanucProgram("G21;\nG92 S2000;\nG00 X40 Z2;\n");
    FAIL() << "G92 is system A's threading cycle: not planned";
  } catch (const NotSupported& e) {
    EXPECT_NE(std::string(e.what()).find("clamp is G50 S"), std::string::npos) << e.what();
  }
}

// Issue 14: G90/G92/G94 of a program written for G code system B/C are system A's cycles here; the
// message says what they mean there and how system A writes it, instead of pointing nowhere.
TEST(ModalGroups, SystemACycleCodesSayWhatTheyMeanInSystemBC) {
  const std::string g90 = notSupportedMessage("G90 G00 X40 Z2;\n");
  EXPECT_NE(g90.find("G90 outer diameter cutting cycle"), std::string::npos) << g90;
  EXPECT_NE(g90.find("3401#6=1"), std::string::npos) << g90;
  EXPECT_NE(g90.find("absolute programming"), std::string::npos) << g90;
  EXPECT_NE(notSupportedMessage("G00 X40 Z2;\nG94 G01 X20 F0.2;\n").find("feed per minute, which G code system A writes G98"),
            std::string::npos);
  EXPECT_NE(notSupportedMessage("G92 X40 Z2;\n").find("coordinate system setting, maximum spindle speed clamp, which G code system A writes G50"), std::string::npos);
}

}  // namespace
}  // namespace cyclecert
