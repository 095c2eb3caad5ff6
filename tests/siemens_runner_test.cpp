// The SINUMERIK runner (issue 16, item 1; rules LCYC95.PARAMS, CYCLE95.PARAMS, SIEMENS.RPARAM,
// SIEMENS.CYCLE95.DEFAULTS, SIEMENS.VARI, PROG.WHOLE): the call it builds for LCYC95 from R105…R112
// and _CNAME, and for CYCLE95 from its arguments, seen through recording planners; the program's
// own moves; the alarms and refusals. And `cyclecert plan` on seed 004's programs.
#include <gtest/gtest.h>

#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "reference/model/profile.h"
#include "reference/siemens/siemens_runner.h"
#include "tests/cli_fixture.h"

namespace cyclecert {
namespace {

// What a recording planner saw.
struct Seen {
  int calls = 0;
  SiemensCycleCall call;
  SiemensContour contour;
  Lcyc95Parameters lcyc95;
  Cycle95Parameters cycle95;
};

std::optional<MachiningType> anyType(double) { return MachiningType{}; }

SiemensPlanners recordingInto(Seen& seen) {
  SiemensPlanners p;
  const auto outcome = [&seen](const SiemensCycleCall& c) {
    ++seen.calls;
    seen.call = c;
    seen.contour = *c.contour;
    Move back;  // one move, so that the runner's appending shows
    back.kind = MoveKind::Rapid;
    back.to = c.position;
    back.phase = MovePhase::Return;
    return SiemensCycleOutcome{{back}, {}, c.position};
  };
  p.lcyc95 = [&seen, outcome](const SiemensCycleCall& c, const Lcyc95Parameters& params) {
    seen.lcyc95 = params;
    return outcome(c);
  };
  p.cycle95 = [&seen, outcome](const SiemensCycleCall& c, const Cycle95Parameters& params) {
    seen.cycle95 = params;
    return outcome(c);
  };
  p.typeOf = anyType;
  return p;
}

Toolpath run(const std::string& text, const std::string& profile, const SiemensPlanners& planners = {}) {
  SiemensRunInput input{text, "t.mpf", {}, "", ToolOffset{0.8, 3}};
  return planSiemensProgram(input, *findProfile(profile), planners);
}

const char* const kSeedL42 =
    "T1D1\nM03S800\nG0X50Z2\n_CNAME=\"L42\"\nR105=1 R106=0.3 R108=2 R109=7\nR110=1.5 R111=0.4 R112=0.25\nLCYC95\n"
    "R105=5 R106=0\nLCYC95\nG0X200Z200\nM02\nL42.spf\nG1X0Z0\nG3X20.8Z-25.8K-15I0\nG2X31.6Z-39.5CR=8\nG1Z-45\nM02\n";

TEST(SiemensRunner, Lcyc95ReadsR105ToR112AtTheCallAndTheContourNamedByCname) {
  Seen seen;
  const Toolpath t = run(kSeedL42, "sinumerik-802s", recordingInto(seen));
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_EQ(seen.calls, 2);
  // The second call (line 9): R105=5 R106=0 set again, the others as before.
  EXPECT_EQ(seen.call.line, 9);
  EXPECT_EQ(seen.lcyc95.allowance, 0);
  EXPECT_EQ(seen.lcyc95.maxInfeed, 2);
  EXPECT_EQ(seen.lcyc95.infeedAngle, 7);
  EXPECT_EQ(seen.lcyc95.retract, 1.5);
  EXPECT_EQ(seen.lcyc95.roughingFeed, 0.4);
  EXPECT_EQ(seen.lcyc95.finishingFeed, 0.25);
  // G0X50Z2 under G23: z 2, x 25 (radius).
  EXPECT_EQ(seen.call.position, (Point{2, 25}));
  EXPECT_EQ(seen.call.tool.noseRadius, 0.8);
  EXPECT_EQ(seen.call.tool.tip, 3);
  EXPECT_EQ(seen.contour.name, "L42");
  ASSERT_EQ(seen.contour.segments.size(), 3u);
  EXPECT_EQ(seen.contour.segments[0].sourceLine, 14);
  // The toolpath: from the first known position (2, 25): the two cycles' one move each, then G0X200Z200.
  EXPECT_EQ(t.profile, "sinumerik-802s");
  EXPECT_EQ(t.start, (Point{2, 25}));
  ASSERT_EQ(t.cycles.size(), 2u);
  EXPECT_EQ(t.cycles[0].code, "LCYC95");
  EXPECT_EQ(t.cycles[0].line, 7);
  EXPECT_EQ(t.cycles[1].firstMove, 1u);
  ASSERT_EQ(t.moves.size(), 3u);
  EXPECT_EQ(t.moves[2].to, (Point{200, 100}));
  EXPECT_EQ(t.moves[2].phase, MovePhase::Program);
  EXPECT_EQ(t.moves[2].kind, MoveKind::Rapid);
}

TEST(SiemensRunner, TheFirstLcyc95CallSeesTheFirstValues) {
  Seen seen;
  SiemensPlanners planners = recordingInto(seen);
  const Toolpath t = run("G0X50Z2\n_CNAME=\"L42\"\nR105=1 R106=0.3 R108=2\nLCYC95\nM02\nL42.spf\nG1X0Z0\nZ-5\nM02\n",
                         "sinumerik-802s", planners);
  ASSERT_FALSE(t.alarm);
  EXPECT_EQ(seen.lcyc95.allowance, 0.3);
  EXPECT_EQ(seen.lcyc95.infeedAngle, 0);  // R109 never set: 0 (SIEMENS.RPARAM)
}

TEST(SiemensRunner, AMachiningTypeOutside1To12Alarms61002) {
  for (const char* r105 : {"R105=13", "R105=0", "R105=1.5"}) {
    Seen seen;
    const Toolpath t = run(std::string("G0X50Z2\n_CNAME=\"L1\"\n") + r105 + "\nLCYC95\nM02\nL1.spf\nG1X0Z0\nZ-5\nM02\n",
                           "sinumerik-802s", recordingInto(seen));
    ASSERT_TRUE(t.alarm) << r105;
    EXPECT_EQ(t.alarm->code, "61002");
    EXPECT_EQ(t.alarm->line, 4);
    EXPECT_NE(t.alarm->message.find(std::string(r105).replace(4, 1, " = ")), std::string::npos) << t.alarm->message;
    EXPECT_EQ(seen.calls, 0);
  }
}

TEST(SiemensRunner, Cycle95TakesItsArgumentsAndDefaultsForEmptyOnes) {
  Seen seen;
  const Toolpath t = run("G0X0Z2\nCYCLE95(\"L18\", 1.5, , 0.3, 0.2, 0.25, 0.15, 0.1, 9, 0.5, 20)\nM02\n"
                         "L18.spf\nG1X0Z0F0.2\nG03X20Z-10CR=10\nRET\n",
                         "sinumerik-802d", recordingInto(seen));
  ASSERT_FALSE(t.alarm);
  ASSERT_EQ(seen.calls, 1);
  EXPECT_EQ(seen.cycle95.contourName, "L18");
  EXPECT_EQ(seen.cycle95.infeed, 1.5);
  EXPECT_EQ(seen.cycle95.allowanceZ, 0);  // empty: 0
  EXPECT_EQ(seen.cycle95.allowanceX, 0.3);
  EXPECT_EQ(seen.cycle95.allowance, 0.2);
  EXPECT_EQ(seen.cycle95.roughingFeed, 0.25);
  EXPECT_EQ(seen.cycle95.undercutFeed, 0.15);
  EXPECT_EQ(seen.cycle95.finishingFeed, 0.1);
  EXPECT_EQ(seen.cycle95.dwell, 0.5);
  EXPECT_EQ(seen.cycle95.interruptLength, 20);
  EXPECT_EQ(seen.cycle95.retract, 1);  // _VRT missing: 1 mm (SIEMENS.CYCLE95.DEFAULTS)
  EXPECT_EQ(seen.contour.segments.size(), 1u);
  EXPECT_EQ(seen.call.position, (Point{2, 0}));
}

TEST(SiemensRunner, Cycle95ArgumentErrorsNameTheirColumn) {
  const auto errorOf = [](const std::string& call) -> std::string {
    try {
      run("G0X0Z2\n" + call + "\nM02\nL18.spf\nG1X0Z0\nZ-5\nRET\n", "sinumerik-802d");
    } catch (const ParseError& e) {
      return std::to_string(e.loc().line) + ":" + std::to_string(e.loc().column) + " " + e.what();
    }
    return "no error";
  };
  EXPECT_NE(errorOf("CYCLE95(, 1.5)").find("2:9 "), std::string::npos) << errorOf("CYCLE95(, 1.5)");
  EXPECT_NE(errorOf("CYCLE95(, 1.5)").find("the contour subprogram's name"), std::string::npos);
  EXPECT_NE(errorOf("CYCLE95(\"L18\", \"x\")").find("2:16 "), std::string::npos) << errorOf("CYCLE95(\"L18\", \"x\")");
  EXPECT_NE(errorOf("CYCLE95(\"L18\", \"x\")").find("a number for MID"), std::string::npos);
  EXPECT_NE(errorOf("CYCLE95(\"L18\",1,1,1,1,1,1,1,1,1,1,1,1)").find("at most 12 arguments"), std::string::npos);
  EXPECT_NE(errorOf("CYCLE95").find("CYCLE95's arguments"), std::string::npos);
  EXPECT_NE(errorOf("CYCLE95(\"L19\", 1)").find("no subprogram L19"), std::string::npos);
}

// The seed's L42 as printed: its G3 (K-15 I0, radius 15, from the axis to X20.8 Z-25.8) sweeps
// about 136° (atan2 of (10.4, −10.8) from the +Z direction), over the quarter circle LCYC95.CONTOUR
// allows: the planner alarms at the call (line 7) rather than plan an arc the cycle does not take.
TEST(SiemensRunner, TheSeedsL42AsPrintedHasAnArcOverAQuarterCircle) {
  const Toolpath t = run(kSeedL42, "sinumerik-802s");
  ASSERT_TRUE(t.alarm.has_value());
  EXPECT_EQ(t.alarm->code, "10931");
  EXPECT_EQ(t.alarm->line, 7);
  EXPECT_NE(t.alarm->message.find("quarter circle"), std::string::npos) << t.alarm->message;
}

TEST(SiemensRunner, EachControlReadsItsOwnCycleAndDiameterWords) {
  const auto refusal = [](const std::string& text, const std::string& profile) -> std::string {
    try {
      run(text, profile);
    } catch (const NotSupported& e) {
      return e.what();
    }
    return "accepted";
  };
  EXPECT_NE(refusal("G0X0Z2\nCYCLE95(\"L1\", 1)\nM02\n", "sinumerik-802s").find("--profile sinumerik-802d"), std::string::npos);
  EXPECT_NE(refusal("G0X0Z2\nLCYC95\nM02\n", "sinumerik-802d").find("--profile sinumerik-802s"), std::string::npos);
  EXPECT_NE(refusal("DIAMON\n", "sinumerik-802s").find("the 802S/C writes G23"), std::string::npos);
  EXPECT_NE(refusal("G23\n", "sinumerik-802d").find("DIAMON/DIAMOF"), std::string::npos);
  EXPECT_NE(refusal("G0X40Z-43\nLCYC97\nM02\n", "sinumerik-802s").find("SEED004.THREAD"), std::string::npos);
  EXPECT_NE(refusal("G0X28Z-14\nCYCLE97(1.5, 3)\nM02\n", "sinumerik-802d").find("SEED004.THREAD"), std::string::npos);
  EXPECT_NE(refusal("LCYC95\nM02\n", "sinumerik-802s").find("position of X unknown"), std::string::npos);
  EXPECT_NE(refusal("G91\n", "sinumerik-802s").find("G91 is not read"), std::string::npos);
}

TEST(SiemensRunner, DiameterAndRadiusProgrammingOfTheMainProgramsMoves) {
  // 802S: G23 (the default) halves X; G22 reads it as a radius. 802D: DIAMOF likewise.
  const Toolpath s = run("G0X50Z2\nG1X40F0.2\nG22\nG1X10\nM02\n", "sinumerik-802s");
  ASSERT_EQ(s.moves.size(), 2u);
  EXPECT_EQ(s.moves[0].to, (Point{2, 20}));
  EXPECT_EQ(s.moves[0].feed, 0.2);
  EXPECT_EQ(s.moves[1].to, (Point{2, 10}));
  const Toolpath d = run("G0X50Z2\nDIAMOF\nG1X10F0.1\nG2Z-8CR=10\nM02\n", "sinumerik-802d");
  ASSERT_EQ(d.moves.size(), 2u);
  EXPECT_EQ(d.moves[0].to, (Point{2, 10}));
  EXPECT_EQ(d.moves[1].shape, SegmentKind::ArcCW);
}

class SiemensPlanCli : public CliFixture {};

// L42 as printed alarms at its first LCYC95 (the 136° arc); L18's CYCLE95 is planned and the
// program stops at CYCLE97, which the seed calls but does not describe (SEED004.THREAD).
TEST_F(SiemensPlanCli, TheSeedProgramsAreReadToTheirAlarmOrTheThreadCycle) {
  const CliRun l42 = run(std::string("plan ") + CYCLECERT_SOURCE_DIR + "/corpus/seed004-l42-lcyc95.nc");
  EXPECT_EQ(l42.exitCode, 1) << l42.err;
  EXPECT_NE(l42.err.find("alarm 10931"), std::string::npos) << l42.err;
  const CliRun l18 = run(std::string("plan ") + CYCLECERT_SOURCE_DIR + "/corpus/seed004-l18-cycle95.nc");
  EXPECT_EQ(l18.exitCode, 3) << l18.err;
  EXPECT_NE(l18.err.find("CYCLE97"), std::string::npos) << l18.err;
  EXPECT_NE(l18.err.find("SEED004.THREAD"), std::string::npos) << l18.err;
}

TEST_F(SiemensPlanCli, ASiblingSpfFileIsTheContour) {
  const std::string main = write("main.mpf", "G0X50Z2\n_CNAME=\"L5\"\nR105=1\nLCYC95\nM02\n");
  const CliRun missing = run("plan " + main + " --profile sinumerik-802s");
  EXPECT_EQ(missing.exitCode, 2) << missing.err;
  EXPECT_NE(missing.err.find("no subprogram L5"), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("main.mpf:2:1"), std::string::npos) << missing.err;
  write("L5.SPF", "G1X0Z0\nZ-5\nM17\n");
  const CliRun found = run("plan " + main + " --profile sinumerik-802s");
  // Found and planned: R108 is not set (0), so the roughing alarms (LCYC95.ALARMS, 61610).
  EXPECT_EQ(found.exitCode, 1) << found.err;
  EXPECT_NE(found.err.find("alarm 61610"), std::string::npos) << found.err;
}

TEST_F(SiemensPlanCli, AFanucProfileOnASiemensProgramSaysWhichProfileReadsIt) {
  const CliRun r = run(std::string("plan ") + CYCLECERT_SOURCE_DIR + "/corpus/seed004-l42-lcyc95.nc --profile fanuc-0i-f");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--profile sinumerik-802s"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("_CNAME= at line 13"), std::string::npos) << r.err;
}

TEST_F(SiemensPlanCli, TheProfilesAreListed) {
  const CliRun r = run("profiles");
  EXPECT_NE(r.out.find("sinumerik-802s"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sinumerik-802d"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace cyclecert
