// FANUC Series 10/11 program format (parameter 0001#1 FCV, rules G71.FS10.*): the one-block
// `G71/G72 P Q U W D F` plans the same toolpath as the Series 0 two-block form of the same cycle,
// D is read in least input increments, and with FCV = 0 a D in the P/Q block is a clear error.
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

Toolpath plan(const std::string& program, const Params& params) {
  return planWithReference({program, "fs10.nc", "fanuc-0i-f", params, {}});
}

bool near(double a, double b) { return std::abs(a - b) <= 1e-9; }

void expectSameToolpath(const Toolpath& a, const Toolpath& b) {
  ASSERT_FALSE(a.alarm) << a.alarm->message;
  ASSERT_FALSE(b.alarm) << b.alarm->message;
  ASSERT_EQ(a.moves.size(), b.moves.size());
  ASSERT_GT(a.moves.size(), 4u);  // a real cycle, not two empty plans
  for (std::size_t i = 0; i < a.moves.size(); ++i) {
    const Move& m = a.moves[i];
    const Move& n = b.moves[i];
    EXPECT_EQ(m.kind, n.kind) << "move " << i;
    EXPECT_EQ(m.shape, n.shape) << "move " << i;
    EXPECT_TRUE(near(m.to.x, n.to.x) && near(m.to.z, n.to.z)) << "move " << i;
    EXPECT_EQ(m.center.has_value(), n.center.has_value()) << "move " << i;
    EXPECT_EQ(m.feed, n.feed) << "move " << i;
  }
}

struct FormPair {
  const char* name;
  std::string twoBlock;  // Series 0: Δd and e in a first block
  std::string oneBlock;  // Series 10/11: D in least input increments, e from parameter 5133
  double retract;        // e in mm, for parameter 5133
  Params extra;
};

void PrintTo(const FormPair& f, std::ostream* os) { *os << f.name; }

class SameCycleBothFormats : public ::testing::TestWithParam<FormPair> {};

TEST_P(SameCycleBothFormats, PlanTheSameToolpath) {
  const FormPair& f = GetParam();
  Params series0 = f.extra;
  Params series10 = f.extra;
  series10.push_back({"FCV", 1});
  series10.push_back({"5133", f.retract});
  expectSameToolpath(plan(f.twoBlock, series0), plan(f.oneBlock, series10));
}

const std::string kInchShape = "N10 G00 X1.2;\nN20 G01 Z-0.5;\nN30 X1.6 Z-0.7;\nN40 X1.9;\n";
const std::string kShape = "N10 G00 X30;\nN20 G01 Z-40;\nN30 X40 Z-30;\nN40 X48;\n";
const std::string kArcShape = "N10 G00 X16;\nN20 G01 Z-10;\nN30 G03 X28 Z-16 R6;\nN40 G01 Z-25;\nN50 X38;\n";
const std::string kPocket = "N10 G00 X32 W0;\nN20 G01 Z-4;\nN30 X38 Z-7;\nN40 X26;\nN50 Z-13;\nN60 X38;\n";
const std::string kFace = "N10 G00 Z-8;\nG01 X60;\nN20 X30 Z-2;\n";

INSTANTIATE_TEST_SUITE_P(
    Series10, SameCycleBothFormats,
    ::testing::Values(
        FormPair{"g71_type1_outer", "G00 X50 Z-60;\nG71 U2 R0.5;\nG71 P10 Q40 U0.5 W-0.2 F0.25;\n" + kShape,
                 "G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 D2000 F0.25;\n" + kShape, 0.5, {}},
        FormPair{"g71_type1_arc", "G00 X40 Z2;\nG71 U2.5 R0.5;\nG71 P10 Q50 U0.4 W0.1 F0.15;\n" + kArcShape,
                 "G00 X40 Z2;\nG71 P10 Q50 U0.4 W0.1 D2500 F0.15;\n" + kArcShape, 0.5, {}},
        FormPair{"g71_type2_pocket", "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q60 U0.4 W0 F0.2;\n" + kPocket,
                 "G00 X40 Z2;\nG71 P10 Q60 U0.4 W0 I0 K0 D2000 F0.2;\n" + kPocket, 0.5, {{"5134", 0.5}}},
        FormPair{"g72_face", "G00 X90 Z1;\nG72 W2.5 R0.5;\nG72 P10 Q20 U0.2 W0.1 F150;\n" + kFace,
                 "G00 X90 Z1;\nG72 P10 Q20 U0.2 W0.1 D2500 F150;\n" + kFace, 0.5, {{"DTP", 1}}},
        FormPair{"g71_inch", "G20;\nG00 X2.0 Z0.1;\nG71 U0.09 R0.02;\nG71 P10 Q40 U0.016 W0.004 F0.008;\n" + kInchShape,
                 "G20;\nG00 X2.0 Z0.1;\nG71 P10 Q40 U0.016 W0.004 D900 F0.008;\n" + kInchShape, 0.508, {}}),
    [](const ::testing::TestParamInfo<FormPair>& info) { return std::string(info.param.name); });

const std::string kOneBlockProgram = "G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 D2000 F0.25;\n" + kShape;

// Before G71.FS10.FCV0 the D was ignored and the alarm blamed the first block or parameter 5132.
TEST(Series10Format, DWithoutFcvIsPS0009NamingTheParameter) {
  const Toolpath t = plan(kOneBlockProgram, {{"5132", 2}, {"5133", 0.5}});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0009");
  EXPECT_EQ(t.alarm->line, 2);
  EXPECT_TRUE(t.moves.empty());
  for (const char* part : {"D2000", "column", "Series 10/11", "0001#1", "FCV=1"}) {
    EXPECT_NE(t.alarm->message.find(part), std::string::npos) << part << " not in: " << t.alarm->message;
  }
}

TEST(Series10Format, DWithADecimalPointIsPS0007) {
  const Toolpath t = plan("G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 D2. F0.25;\n" + kShape, {{"FCV", 1}});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0007");
  EXPECT_NE(t.alarm->message.find("least input increments"), std::string::npos) << t.alarm->message;
}

TEST(Series10Format, DZeroIsPS0062) {
  const Toolpath t = plan("G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 D0 F0.25;\n" + kShape, {{"FCV", 1}});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0062");
}

TEST(Series10Format, NonZeroIOrKIsNotSupportedNotIgnored) {
  EXPECT_THROW(plan("G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 I0.3 D2000 F0.25;\n" + kShape, {{"FCV", 1}}), NotSupported);
  EXPECT_THROW(plan("G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 K0.1 D2000 F0.25;\n" + kShape, {{"FCV", 1}}), NotSupported);
}

// D overwrites parameter 5132 like a first block's Δd: a later cycle without D uses it.
TEST(Series10Format, DStaysInForceForALaterCycle) {
  const std::string twice = "G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 D2000 F0.25;\n" + kShape +
                            "G00 X50 Z-60;\nG71 P10 Q40 U0.5 W-0.2 F0.25;\n";
  const Toolpath t = plan(twice, {{"FCV", 1}, {"5132", 5}, {"5133", 0.5}});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.cycles.size(), 2u);
  EXPECT_EQ(t.cycles[0].moveCount, t.cycles[1].moveCount);
}

TEST(Series10Format, OraclesReadTheOneBlockForm) {
  MachineParams params = findProfile("fanuc-0i-f")->defaults;
  params.set("FCV", 1);
  const Program program = parseProgram(kOneBlockProgram, "fs10.nc");
  const ProgramSpec spec = readProgramSpec(program, *findProfile("fanuc-0i-f"), params, ToolOffset{});
  ASSERT_EQ(spec.cycles.size(), 1u);
  EXPECT_FALSE(spec.cycles[0].forbiddenBy);
  EXPECT_DOUBLE_EQ(spec.cycles[0].depthOfCut, 2.0);

  params.set("FCV", 0);
  params.set("5132", 2);
  const ProgramSpec refused = readProgramSpec(program, *findProfile("fanuc-0i-f"), params, ToolOffset{});
  ASSERT_EQ(refused.cycles.size(), 1u);
  ASSERT_TRUE(refused.cycles[0].forbiddenBy);
  EXPECT_EQ(refused.cycles[0].forbiddenBy->code, "PS0009");
}

}  // namespace
}  // namespace cyclecert
