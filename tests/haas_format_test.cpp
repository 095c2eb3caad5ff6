// The haas profile (rules HAAS.*): the one-block `G71/G72 P Q U W D I K F S T [R1]` with D in the
// program's units, I/K the rough-pass allowance, R1 type II, and G41/G42 inside P…Q compensating the
// shape; the oracles read the same program the same way.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "reference/gcode/parser.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

using Params = std::vector<std::pair<std::string, double>>;

Toolpath plan(const std::string& program, const std::string& profile, const Params& params = {},
              ToolOffset tool = {}) {
  PlanRequest request{program, "haas.nc", profile, params, {}};
  request.options.tool = tool;
  return planWithReference(request);
}

void expectSameToolpath(const Toolpath& a, const Toolpath& b) {
  ASSERT_FALSE(a.alarm) << a.alarm->message;
  ASSERT_FALSE(b.alarm) << b.alarm->message;
  ASSERT_EQ(a.moves.size(), b.moves.size());
  ASSERT_GT(a.moves.size(), 4u);
  for (std::size_t i = 0; i < a.moves.size(); ++i) {
    EXPECT_EQ(a.moves[i].kind, b.moves[i].kind) << "move " << i;
    EXPECT_EQ(a.moves[i].shape, b.moves[i].shape) << "move " << i;
    EXPECT_NEAR(a.moves[i].to.x, b.moves[i].to.x, 1e-9) << "move " << i;
    EXPECT_NEAR(a.moves[i].to.z, b.moves[i].to.z, 1e-9) << "move " << i;
  }
}

const std::string kShape = "N10 G00 X30;\nN20 G01 Z-40;\nN30 X40 Z-30;\nN40 X48;\n";
const std::string kTaper = "N10 G00 X18;\nN20 G01 Z-12;\nN30 X24 Z-18;\nN40 X28;\n";
const std::string kChamfer = "N20 G01 X10 Z-3;\nN30 Z-10;\nN40 X18;\nN50 Z-18;\nN60 X30;\n";
const std::string kStep = "N20 Z-10;\nN30 X34;\nN40 Z-20;\nN50 X38;\n";

// HAAS.G71.D: D2. is 2 mm (program units, decimal point), the same cycle as FANUC's U2 first block.
TEST(HaasFormat, OneBlockDIsTheDepthInProgramUnits) {
  expectSameToolpath(plan("G00 X31 Z1;\nG71 U2 R0.5;\nG71 P10 Q40 U0.4 W0.1 F0.2;\n" + kTaper, "fanuc-0i-f"),
                     plan("G00 X31 Z1;\nG71 P10 Q40 U0.4 W0.1 D2. F0.2;\n" + kTaper, "haas", {{"5133", 0.5}}));
}

TEST(HaasFormat, DInInchProgramsIsInches) {
  const std::string shape = "N10 G00 X1.2;\nN20 G01 Z-0.5;\nN30 X1.6 Z-0.7;\nN40 X1.9;\n";
  expectSameToolpath(plan("G20;\nG00 X2.0 Z0.1;\nG71 U0.09 R0.02;\nG71 P10 Q40 U0.016 W0.004 F0.008;\n" + shape,
                          "fanuc-0i-f"),
                     plan("G20;\nG00 X2.0 Z0.1;\nG71 P10 Q40 U0.016 W0.004 D.09 F0.008;\n" + shape, "haas",
                          {{"5133", 0.508}}));
}

TEST(HaasFormat, G72OneBlock) {
  const std::string face = "N10 G00 Z-8;\nG01 X60;\nN20 X30 Z-2;\n";
  expectSameToolpath(plan("G00 X90 Z1;\nG72 W2.5 R0.5;\nG72 P10 Q20 U0.2 W0.1 F150;\n" + face, "fanuc-0i-f"),
                     plan("G00 X90 Z1;\nG72 P10 Q20 D2.5 U0.2 W0.1 F150;\n" + face, "haas", {{"5133", 0.5}}));
}

// The same Haas block on FANUC 0i-F is refused, and the message names the Haas profile.
TEST(HaasFormat, HaasBlockOnFanucNamesTheProfile) {
  const Toolpath t = plan("G00 X31 Z1;\nG71 P10 Q40 U0.4 W0.1 D2. F0.2;\n" + kTaper, "fanuc-0i-f");
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0009");
  EXPECT_NE(t.alarm->message.find("--profile haas"), std::string::npos) << t.alarm->message;
}

// HAAS.G71.SETTINGS: without D, Settings 72/73 (parameters 5132/5133) with the profile's defaults.
TEST(HaasFormat, DefaultsAreSettings72And73) {
  const Profile* haas = findProfile("haas");
  ASSERT_NE(haas, nullptr);
  EXPECT_DOUBLE_EQ(haas->defaults.get("5132"), 2.54);
  EXPECT_DOUBLE_EQ(haas->defaults.get("5133"), 1.27);
  expectSameToolpath(plan("G00 X31 Z1;\nG71 U2.54 R1.27;\nG71 P10 Q40 U0.4 W0.1 F0.2;\n" + kTaper, "fanuc-0i-f"),
                     plan("G00 X31 Z1;\nG71 P10 Q40 U0.4 W0.1 F0.2;\n" + kTaper, "haas"));
}

// HAAS.G71.IK: I (radius) and K add to U/2 and W.
TEST(HaasFormat, IAndKAddToTheFinishAllowance) {
  expectSameToolpath(plan("G00 X31 Z1;\nG71 P10 Q40 U0.6 W0.15 D2. F0.2;\n" + kTaper, "haas", {{"5133", 0.5}}),
                     plan("G00 X31 Z1;\nG71 P10 Q40 U0.4 W0.1 I0.1 K0.05 D2. F0.2;\n" + kTaper, "haas",
                          {{"5133", 0.5}}));
}

// HAAS.G71.R1: R1 selects type II as W0 in block ns does.
TEST(HaasFormat, R1SelectsTypeII) {
  expectSameToolpath(plan("G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q50 U0.4 W0.1 F0.2;\nN10 G01 X30 W0;\n" + kStep,
                          "fanuc-0i-f"),
                     plan("G00 X40 Z2;\nG71 P10 Q50 U0.4 W0.1 D2. R1 F0.2;\nN10 G01 X30;\n" + kStep, "haas",
                          {{"5133", 0.5}}));
}

TEST(HaasFormat, AnotherRIsPS0009) {
  for (const char* r : {"R2", "R1."}) {
    const Toolpath t =
        plan("G00 X40 Z2;\nG71 P10 Q50 U0.4 W0.1 D2. " + std::string(r) + " F0.2;\nN10 G01 X30;\n" + kStep, "haas");
    ASSERT_TRUE(t.alarm) << r;
    EXPECT_EQ(t.alarm->code, "PS0009") << r;
    EXPECT_NE(t.alarm->message.find("R1"), std::string::npos) << t.alarm->message;
  }
}

// HAAS.TNRC.SHAPE: G42 in block ns compensates the shape as G42 before the cycle does on FANUC;
// FANUC alarms PS0325 for the same program.
TEST(HaasFormat, G42InBlockNsCompensatesTheShape) {
  const ToolOffset tool{0.4, 3};
  const std::string haasProgram = "G00 X30 Z2;\nG71 P10 Q60 U0.4 W0.1 D4. F0.2;\nN10 G42 G00 X0;\n" + kChamfer + "G40;\n";
  const Toolpath haas = plan(haasProgram, "haas", {{"5133", 0.5}}, tool);
  expectSameToolpath(plan("G00 X30 Z2;\nG42;\nG71 U4 R0.5;\nG71 P10 Q60 U0.4 W0.1 F0.2;\nN10 G00 X0;\n" + kChamfer +
                              "G40;\n",
                          "fanuc-0i-f", {}, tool),
                     haas);
  ASSERT_EQ(haas.cycles.size(), 1u);
  EXPECT_TRUE(haas.cycles[0].compensated);
  const Toolpath fanuc = plan("G00 X30 Z2;\nG71 U4 R0.5;\nG71 P10 Q60 U0.4 W0.1 F0.2;\nN10 G42 G00 X0;\n" + kChamfer,
                              "fanuc-0i-f", {}, tool);
  ASSERT_TRUE(fanuc.alarm);
  EXPECT_EQ(fanuc.alarm->code, "PS0325");
}

TEST(HaasFormat, CompensationStartedLaterInTheShapeIsNotSupported) {
  EXPECT_THROW(plan("G00 X30 Z2;\nG71 P10 Q60 U0.4 W0.1 D4. F0.2;\nN10 G00 X0;\nN20 G42 G01 X10 Z-3;\nN30 Z-10;\n"
                    "N40 X18;\nN50 Z-18;\nN60 X30;\n",
                    "haas", {}, ToolOffset{0.4, 3}),
               NotSupported);
}

TEST(HaasFormat, OnlyTheZxPlane) {
  EXPECT_THROW(plan("G17;\nG00 X31 Y1;\nG71 P10 Q40 U0.4 W0.1 D2. F0.2;\n" + kShape, "haas"), NotSupported);
}

TEST(HaasFormat, OraclesReadTheHaasBlock) {
  const Profile& haas = *findProfile("haas");
  const Program program = parseProgram("G00 X40 Z2;\nG71 P10 Q50 U0.4 W0.1 I0.1 K0.05 D2. R1 F0.2;\n"
                                       "N10 G42 G01 X30;\n" + kStep + "G40;\n",
                                       "haas.nc");
  const ProgramSpec spec = readProgramSpec(program, haas, haas.defaults, ToolOffset{0.4, 3});
  ASSERT_EQ(spec.cycles.size(), 1u);
  const CycleSpec& c = spec.cycles[0];
  ASSERT_FALSE(c.forbiddenBy) << c.forbiddenBy->code << " " << c.forbiddenBy->message;
  EXPECT_DOUBLE_EQ(c.depthOfCut, 2.0);
  EXPECT_TRUE(c.typeII);
  EXPECT_NEAR(c.allowance.x, 0.3, 1e-12);
  EXPECT_NEAR(c.allowance.z, 0.15, 1e-12);
  // Compensated: block ns is the start-up, ending at B + r·n + r·T = (15 + 0.4 - 0.4, 2 + 0 - 0.4).
  EXPECT_NEAR(c.shape.front().to.x, 15.0, 1e-9);
  EXPECT_NEAR(c.shape.front().to.z, 1.6, 1e-9);

  const ProgramSpec onFanuc = readProgramSpec(program, *findProfile("fanuc-0i-f"),
                                              findProfile("fanuc-0i-f")->defaults, ToolOffset{0.4, 3});
  ASSERT_TRUE(onFanuc.firstAlarm());
  EXPECT_EQ(onFanuc.firstAlarm()->code, "PS0009");
}

}  // namespace
}  // namespace cyclecert
