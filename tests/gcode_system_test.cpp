// FANUC G code systems A, B and C (parameter 3401#6 GSB, #7 GSC) and the Huazhong list: each G
// number is read in the system in force (PROG.GSYS.* in specs/rules.json), G91 makes X/Z
// increments in program blocks and shape programs, and a code of another system is refused with
// what it means there and the parameter that selects it. Issue 14.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/profile.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

using Params = std::vector<std::pair<std::string, double>>;
const Params kSystemB = {{"3401#6", 1}};
const Params kSystemC = {{"3401#7", 1}};

Toolpath plan(const std::string& program, const Params& params, const std::string& profile = "fanuc-0i-f") {
  return planWithReference({program, "program.nc", profile, params, {}});
}

std::string notSupported(const std::string& program, const Params& params, const std::string& profile = "fanuc-0i-f") {
  try {
    plan(program, params, profile);
  } catch (const NotSupported& e) {
    return e.what();
  }
  return "(no NotSupported)";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The same small cycle, with the tool at (X40, Z2) first: A = (x 20, z 2).
const std::string kCycle = std::string("G00 X40 Z2;\n") + kSmallG71Cycle + "M30;\n";

TEST(GCodeSystemTable, EachNumberIsLookedUpInItsSystem) {
  struct Lookup {
    GCodeSystem system;
    int g10, function;
  };
  const Lookup found[] = {
      {GCodeSystem::B, 900, kAbsoluteProgramming}, {GCodeSystem::B, 910, kIncrementalProgramming},
      {GCodeSystem::B, 920, 500},  {GCodeSystem::B, 940, 980},  {GCodeSystem::B, 950, 990},
      {GCodeSystem::B, 770, 900},  {GCodeSystem::B, 780, 920},  {GCodeSystem::B, 790, 940},
      {GCodeSystem::B, 330, 320},  {GCodeSystem::B, 710, 710},  {GCodeSystem::C, 700, 200},
      {GCodeSystem::C, 710, 210},  {GCodeSystem::C, 720, 700},  {GCodeSystem::C, 730, 710},
      {GCodeSystem::C, 740, 720},  {GCodeSystem::C, 200, 900},  {GCodeSystem::C, 240, 940},
      {GCodeSystem::C, 780, 760},  {GCodeSystem::A, 900, 900},  {GCodeSystem::A, 980, 980},
      {GCodeSystem::Huazhong, 900, kAbsoluteProgramming},     {GCodeSystem::Huazhong, 940, 980},
      {GCodeSystem::Huazhong, 980, 980},
  };
  for (const Lookup& l : found) {
    const GCode* code = findGCode(l.system, l.g10);
    ASSERT_NE(code, nullptr) << gCodeSystemName(l.system) << " " << l.g10;
    EXPECT_EQ(code->function, l.function) << gCodeSystemName(l.system) << " " << l.g10;
  }
  EXPECT_EQ(findGCode(GCodeSystem::B, 900)->group, GGroup::Programming);
  EXPECT_EQ(findGCode(GCodeSystem::B, 980)->group, GGroup::CycleReturn);
  EXPECT_EQ(findGCode(GCodeSystem::C, 710)->group, GGroup::Units);
  for (const auto& [system, g10] : {std::pair{GCodeSystem::B, 500}, {GCodeSystem::B, 320}, {GCodeSystem::C, 200 + 5},
                                    {GCodeSystem::A, 770}, {GCodeSystem::A, 910}, {GCodeSystem::C, 790}}) {
    EXPECT_EQ(findGCode(system, g10), nullptr) << gCodeSystemName(system) << " " << g10;
  }
}

TEST(GCodeSystemTable, ChosenFromTheProfileAndParameter3401) {
  MachineParams none, gsb, gsc, both;
  gsb.set("3401#6", 1);
  gsc.set("GSC", 1);
  both.set("GSB", 1);
  both.set("GSC", 1);
  const Profile& fanuc = *findProfile("fanuc-0i-f");
  EXPECT_EQ(gCodeSystemOf(fanuc, none), GCodeSystem::A);
  EXPECT_EQ(gCodeSystemOf(fanuc, gsb), GCodeSystem::B);
  EXPECT_EQ(gCodeSystemOf(fanuc, gsc), GCodeSystem::C);
  EXPECT_EQ(gCodeSystemOf(fanuc, both), GCodeSystem::C);
  EXPECT_EQ(gCodeSystemOf(*findProfile("fanuc-0i-c"), gsb), GCodeSystem::B);
  EXPECT_EQ(gCodeSystemOf(*findProfile("gsk"), gsb), GCodeSystem::A);
  EXPECT_EQ(gCodeSystemOf(*findProfile("hnc"), none), GCodeSystem::Huazhong);
}

TEST(GCodeSystemB, AProgramWithG90G94G92SIsPlanned) {
  const Toolpath t = plan("G21 G40 G94;\nG92 S2000;\nG97 S800 M03;\nG90 " + kCycle, kSystemB);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_TRUE(nearlyEqual(t.start, {2, 20}));
}

TEST(GCodeSystemB, G91MakesXZIncrementsInProgramBlocks) {
  // X60 Z10 = (x 30, z 10); G91 X-20 Z-8: (x 20, z 2), the cycle start (after G90 again).
  const Toolpath t = plan("G21;\nG90 G00 X60 Z10;\nG91 G00 X-20 Z-8;\nG90;\n" + std::string(kSmallG71Cycle) + "M30;\n",
                          kSystemB);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  // The toolpath starts at the first known position (PROG.WHOLE); the G91 rapid goes to A.
  EXPECT_TRUE(nearlyEqual(t.start, {10, 30}));
  ASSERT_FALSE(t.moves.empty());
  EXPECT_TRUE(nearlyEqual(t.moves.front().to, {2, 20}));
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_TRUE(nearlyEqual(t.cycles.front().start, {2, 20}));
  // A move after the cycle under G91: from A by (x -1, z -3).
  const Toolpath after = plan("G21;\nG90 G00 X40 Z2;\n" + std::string(kSmallG71Cycle) + "G91 G00 X-2 Z-3;\nM30;\n",
                              kSystemB);
  ASSERT_FALSE(after.alarm) << after.alarm->message;
  ASSERT_FALSE(after.moves.empty());
  EXPECT_TRUE(nearlyEqual(after.moves.back().to, {-1, 19}));
}

TEST(GCodeSystemB, G91HoldsInTheShapeProgram) {
  // The shape of kSmallG71Cycle (X20; Z-10; X40 Z-20 from A = (20, 2)) written in increments.
  const std::string absolute = "G21;\nG90 G00 X40 Z2;\n" + std::string(kSmallG71Cycle) + "M30;\n";
  const std::string incremental =
      "G21;\nG90 G00 X40 Z2;\nG91;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X-20;\nG01 Z-12;\nN20 X20 Z-10;\nM30;\n";
  const Toolpath a = plan(absolute, kSystemB), i = plan(incremental, kSystemB);
  ASSERT_FALSE(a.alarm) << a.alarm->message;
  ASSERT_FALSE(i.alarm) << i.alarm->message;
  ASSERT_EQ(a.moves.size(), i.moves.size());
  for (std::size_t k = 0; k < a.moves.size(); ++k) EXPECT_TRUE(nearlyEqual(a.moves[k].to, i.moves[k].to)) << k;
}

TEST(GCodeSystemB, IncrementalAddressesUWAreNotReadThere) {
  const std::string why = notSupported("G21;\nG90 G00 X40 Z2;\nG01 U-2 F0.2;\nM30;\n", kSystemB);
  EXPECT_TRUE(contains(why, "U-2")) << why;
  EXPECT_TRUE(contains(why, "G91 X")) << why;
  EXPECT_TRUE(contains(why, "3401#6=0")) << why;
  // U/W of the cycle blocks are the cycle's values, not axis words.
  EXPECT_FALSE(plan("G21;\nG90 " + kCycle, kSystemB).alarm);
}

TEST(GCodeSystemB, SystemACodesAreRefusedNamingTheParameter) {
  const Toolpath g50 = plan("G21;\nG50 S2000;\n" + kCycle, kSystemB);
  ASSERT_TRUE(g50.alarm);
  EXPECT_EQ(g50.alarm->code, "PS0010");
  EXPECT_EQ(g50.alarm->line, 2);
  EXPECT_TRUE(contains(g50.alarm->message, "G code system A (--param 3401#6=0")) << g50.alarm->message;
  EXPECT_TRUE(contains(g50.alarm->message, "which G code system B writes G92")) << g50.alarm->message;
  const Toolpath g32 = plan("G21;\nG32 Z-10 F1.5;\n", kSystemB);
  ASSERT_TRUE(g32.alarm);
  EXPECT_TRUE(contains(g32.alarm->message, "writes G33")) << g32.alarm->message;
  // System B's single cycle: not planned, as system A's G90.
  EXPECT_TRUE(contains(notSupported("G21;\nG00 X40 Z2;\nG77 X30 Z-10 F0.2;\n", kSystemB), "G77 outer diameter cutting cycle"));
}

TEST(GCodeSystemA, SystemBCCodesAreRefusedNamingTheParameter) {
  const Toolpath g91 = plan("G21;\nG00 X40 Z2;\nG91 G01 X-2 F0.2;\n", {});
  ASSERT_TRUE(g91.alarm);
  EXPECT_EQ(g91.alarm->code, "PS0010");
  EXPECT_TRUE(contains(g91.alarm->message, "G code system B (--param 3401#6=1)")) << g91.alarm->message;
  EXPECT_TRUE(contains(g91.alarm->message, "U/W (incremental)")) << g91.alarm->message;
  const Toolpath g77 = plan("G21;\nG00 X40 Z2;\nG77 X30 Z-10 F0.2;\n", {});
  ASSERT_TRUE(g77.alarm);
  EXPECT_TRUE(contains(g77.alarm->message, "outer diameter cutting cycle, which G code system A writes G90"))
      << g77.alarm->message;
  const std::string g90 = notSupported("G90 G00 X40 Z2;\n", {});
  EXPECT_TRUE(contains(g90, "G90 outer diameter cutting cycle is not planned")) << g90;
  EXPECT_TRUE(contains(g90, "--param 3401#6=1) and G code system C (--param 3401#7=1) G90 is absolute programming"))
      << g90;
}

TEST(GCodeSystemC, TheRenumberedCyclesAndUnitsAreRead) {
  const std::string program =
      "G71 G40;\nG92 S2000;\nG90 G00 X40 Z2;\nG73 U2 R0.5;\nG73 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-10;\n"
      "N20 X40 Z-20;\nG72 P10 Q20;\nM30;\n";
  const Toolpath c = plan(program, kSystemC);
  ASSERT_FALSE(c.alarm) << c.alarm->message;
  ASSERT_EQ(c.cycles.size(), 2u);  // G73: the turning cycle; G72: the finishing cycle
  EXPECT_EQ(c.cycles[0].code, "G71");
  EXPECT_EQ(c.cycles[1].code, "G70");
  // The same cycles in system A.
  const Toolpath a = plan("G21 G40;\nG50 S2000;\nG00 X40 Z2;\n" + std::string(kSmallG71Cycle) + "G70 P10 Q20;\nM30;\n", {});
  ASSERT_FALSE(a.alarm) << a.alarm->message;
  ASSERT_EQ(a.moves.size(), c.moves.size());
  for (std::size_t k = 0; k < a.moves.size(); ++k) EXPECT_TRUE(nearlyEqual(a.moves[k].to, c.moves[k].to)) << k;
  // G20 in system C is the outer-diameter cycle, not inch input.
  EXPECT_TRUE(contains(notSupported("G20 X30 Z-10 F0.2;\n", kSystemC), "outer diameter cutting cycle"));
}

TEST(GCodeSystemHuazhong, G91IsIncrementalProgramming) {
  // Before: "G91 incremental mode is not modelled".
  const std::string program =
      "G21 G94 G90;\nG00 X60 Z10;\nG91 G00 X-20 Z-8;\nG90;\nG71 U2 R0.5 P10 Q20 X0.4 Z0.1 F100;\nN10 G00 X20;\nG01 Z-10;\n"
      "N20 X40 Z-20;\nM30;\n";
  const Toolpath t = plan(program, {}, "hnc");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.start, {10, 30}));
  ASSERT_FALSE(t.moves.empty());
  EXPECT_TRUE(nearlyEqual(t.moves.front().to, {2, 20}));  // the G91 rapid to A (PROG.WHOLE)
  ASSERT_EQ(t.cycles.size(), 1u);
  EXPECT_TRUE(nearlyEqual(t.cycles.front().start, {2, 20}));
}

TEST(GCodeSystemOracles, JudgeTheReferencesPathsOfSystemBAndCPrograms) {
  const std::pair<std::string, Params> programs[] = {
      {"G21 G94;\nG92 S2000;\nG90 G00 X60 Z10;\nG91 G00 X-20 Z-8;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F150;\n"
       "N10 G00 X-20;\nG01 Z-12;\nN20 X20 Z-10;\nG70 P10 Q20;\nG90 G00 X80 Z20;\nM30;\n",
       kSystemB},
      {"G71 G95;\nG92 S2000;\nG90 G00 X40 Z2;\nG73 U2 R0.5;\nG73 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-10;\n"
       "N20 X40 Z-20;\nG72 P10 Q20;\nM30;\n",
       kSystemC},
  };
  for (const auto& [text, params] : programs) {
    JudgeRequest request;
    request.program = {text, "gsys.nc", "fanuc-0i-f", params, {}};
    const Toolpath path = planWithReference(request.program);
    ASSERT_FALSE(path.alarm) << path.alarm->message;
    const JudgeInput in = judgeInputFor(request, path);
    ASSERT_EQ(in.program.cycles.size(), 1u) << text;
    EXPECT_TRUE(nearlyEqual(in.program.cycles.at(0).start, {2, 20})) << text;
    const std::vector<Finding> findings = judge(in);
    EXPECT_TRUE(findings.empty()) << text << findingsText(findings);
  }
}

// PROG.GSYS.B: the codes a shape program ns…nf may contain are judged by their function in the
// program's system (G72.NSNF.GCODES). The reference's path and the oracles' reading of the cycle.
struct ShapeCodeVerdict {
  Toolpath path;
  std::optional<Alarm> oracleForbids;  // the oracles' own reading of the G71 cycle
};

ShapeCodeVerdict planAndRead(const std::string& program, const Params& params, const std::string& profile = "fanuc-0i-f") {
  JudgeRequest request;
  request.program = {program, "shape.nc", profile, params, {}};
  ShapeCodeVerdict v{planWithReference(request.program), std::nullopt};
  const JudgeInput in = judgeInputFor(request, v.path);
  EXPECT_EQ(in.program.cycles.size(), 1u) << program;
  if (!in.program.cycles.empty()) v.oracleForbids = in.program.cycles.front().forbiddenBy;
  EXPECT_TRUE(judge(in).empty()) << program << findingsText(judge(in));
  return v;
}

// The shape of kSmallG71Cycle from A = (X40, Z2): B at X20, then Z-10 (12 along Z), then X40 Z-20.
TEST(GCodeSystemShape, G91InsideNsNfPlansTheSamePathAsSystemAsUW) {
  // Before: "G91 cannot be used between P and Q" (PS0325), read by its system A number.
  const std::string systemA =
      "G21;\nG00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 U-20;\nG01 W-12;\nN20 U20 W-10;\n"
      "G70 P10 Q20;\nG00 X80 Z20;\nM30;\n";
  const std::string systemB =
      "G21;\nG90 G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G91 G00 X-20;\nG01 Z-12;\nN20 X20 Z-10;\n"
      "G70 P10 Q20;\nG90 G00 X80 Z20;\nM30;\n";
  const ShapeCodeVerdict a = planAndRead(systemA, {}), b = planAndRead(systemB, kSystemB);
  ASSERT_FALSE(a.path.alarm) << a.path.alarm->message;
  ASSERT_FALSE(b.path.alarm) << b.path.alarm->message;
  EXPECT_FALSE(b.oracleForbids) << b.oracleForbids->message;
  ASSERT_EQ(b.path.cycles.size(), 2u);  // G71 and G70
  // The finishing pass ends at C = (x 20, z -20): the increments were applied in both cycles.
  ASSERT_EQ(a.path.moves.size(), b.path.moves.size());
  for (std::size_t k = 0; k < a.path.moves.size(); ++k) {
    EXPECT_TRUE(nearlyEqual(a.path.moves[k].to, b.path.moves[k].to)) << k;
    EXPECT_EQ(a.path.moves[k].kind, b.path.moves[k].kind) << k;
  }
  bool finishReachesC = false;
  for (const Move& m : b.path.moves) finishReachesC = finishReachesC || (m.phase == MovePhase::Finish && nearlyEqual(m.to, {-20, 20}));
  EXPECT_TRUE(finishReachesC);
}

// A = (X44, Z2), above the shape's end (X40): the last pass and the return stay clear of the
// allowance (with A at X40 the return to A runs inside it: a no-gouge finding, also in system A).
TEST(GCodeSystemShape, FeedModesAreAllowedAndTheReturnLevelIsNot) {
  const std::string head = "G21;\nG90 G00 X44 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\n";
  // System B's G95 is system A's G99 (feed per revolution), which ns…nf may contain. Before: PS0325.
  const ShapeCodeVerdict feed = planAndRead(head + "G95 G01 Z-10;\nN20 X40 Z-20;\nM30;\n", kSystemB);
  EXPECT_FALSE(feed.path.alarm) << feed.path.alarm->message;
  EXPECT_FALSE(feed.oracleForbids) << feed.oracleForbids->message;
  // System B's G98 is the canned cycle return level, not in the list: PS0325 at its block (line 6).
  // Before: planned, read as system A's G98 feed per minute.
  const ShapeCodeVerdict level = planAndRead(head + "G98 G01 Z-10;\nN20 X40 Z-20;\nM30;\n", kSystemB);
  ASSERT_TRUE(level.path.alarm);
  EXPECT_EQ(level.path.alarm->code, "PS0325");
  EXPECT_EQ(level.path.alarm->line, 6);
  EXPECT_TRUE(contains(level.path.alarm->message, "canned cycle return")) << level.path.alarm->message;
  ASSERT_TRUE(level.oracleForbids);
  EXPECT_EQ(level.oracleForbids->code, "PS0325");
  EXPECT_EQ(level.oracleForbids->line, 6);
  // System A: G98 is feed per minute and allowed, G28 is not (unchanged).
  EXPECT_FALSE(plan("G21;\nG00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG98 G01 Z-10 F150;\n"
                    "N20 X40 Z-20;\nM30;\n", {}).alarm);
  const Toolpath g28 = plan("G21;\nG00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG28 U0;\n"
                            "G01 Z-10;\nN20 X40 Z-20;\nM30;\n", {});
  ASSERT_TRUE(g28.alarm);
  EXPECT_EQ(g28.alarm->code, "PS0325");
}

TEST(GCodeSystemShape, SystemCReadsItsOwnNumbers) {
  // System C's G94 is feed per minute (allowed); its G71 is metric input (not in the list).
  const std::string head = "G71;\nG90 G00 X44 Z2;\nG73 U2 R0.5;\nG73 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\n";
  EXPECT_FALSE(planAndRead(head + "G94 G01 Z-10 F150;\nN20 X40 Z-20;\nM30;\n", kSystemC).path.alarm);
  const ShapeCodeVerdict units = planAndRead(head + "G71 G01 Z-10;\nN20 X40 Z-20;\nM30;\n", kSystemC);
  ASSERT_TRUE(units.path.alarm);
  EXPECT_EQ(units.path.alarm->code, "PS0325");
  ASSERT_TRUE(units.oracleForbids);
  EXPECT_EQ(units.oracleForbids->code, "PS0325");
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

// The haas and gsk profiles read system A and ignore 3401: the way to system B/C they name is a
// FANUC profile with the parameter, not the parameter alone (which would change nothing there).
TEST(GCodeSystemMessages, AProfileWithoutParameter3401NamesAFanucProfile) {
  for (const char* profile : {"haas", "gsk"}) {
    const std::string why = notSupported("G90 G00 X40. Z2.;\nM30;\n", {{"3401#6", 1}}, profile);
    EXPECT_NE(why.find("--profile fanuc-0i-f --param 3401#6=1"), std::string::npos) << profile << ": " << why;
  }
  const std::string fanuc = notSupported("G90 G00 X40. Z2.;\nM30;\n", {});
  EXPECT_NE(fanuc.find("(--param 3401#6=1)"), std::string::npos) << fanuc;
}

}  // namespace
}  // namespace cyclecert
