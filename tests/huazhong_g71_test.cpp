// Huazhong (HNC) one-block G71 of seed 003 (rules HNC.G71.*): the roughing of
// `G71 U R P Q X Z F` is the roughing of FANUC's two blocks `G71 U R; G71 P Q U W F;` (X/Z there
// are U/W here). Where they differ: after the cycle the Huazhong program goes on with the block
// after G71, so ns…nf run again as finishing; FANUC skips ns…nf when they follow the cycle.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

Toolpath plan(const std::string& program, const std::string& profile) {
  return planWithReference({program, "hnc.nc", profile, {}, {}});
}

const std::string kContour = "N11 G00 X0;\nN12 G01 X10 Z-2;\nN13 Z-20;\nN14 G02 U10 W-5 R5;\nN15 G01 W-10;\n"
                             "N16 G03 U14 W-7 R7;\nN17 G01 Z-52;\nN18 U10 W-10;\nN19 W-25;\nN20 X52;\n";

TEST(HuazhongG71, OneBlockRoughsLikeFanucTwoBlocks) {
  const Toolpath hnc = plan("G00 X54 Z3;\nG71 U1.5 R1 P11 Q20 X0.6 Z0.1 F100;\n" + kContour + "M30;\n", "hnc");
  const Toolpath fanuc = plan("G00 X54 Z3;\nG71 U1.5 R1;\nG71 P11 Q20 U0.6 W0.1 F100;\n" + kContour + "M30;\n",
                              "fanuc-0i-f");
  ASSERT_FALSE(hnc.alarm) << hnc.alarm->message;
  ASSERT_FALSE(fanuc.alarm) << fanuc.alarm->message;
  ASSERT_EQ(hnc.cycles.size(), 1u);
  ASSERT_EQ(fanuc.cycles.size(), 1u);
  const std::size_t n = fanuc.cycles[0].moveCount;
  ASSERT_GT(n, 20u);
  ASSERT_EQ(hnc.cycles[0].moveCount, n);
  for (std::size_t i = 0; i < n; ++i) {
    const Move& a = hnc.moves[hnc.cycles[0].firstMove + i];
    const Move& b = fanuc.moves[fanuc.cycles[0].firstMove + i];
    EXPECT_EQ(a.kind, b.kind) << "move " << i;
    EXPECT_EQ(a.shape, b.shape) << "move " << i;
    EXPECT_NEAR(a.to.x, b.to.x, 1e-9) << "move " << i;
    EXPECT_NEAR(a.to.z, b.to.z, 1e-9) << "move " << i;
  }
  // The difference: FANUC skips N11…N20 after the cycle; the Huazhong runs them as finishing.
  EXPECT_EQ(fanuc.moves.size(), n);
  EXPECT_EQ(hnc.moves.size(), n + 10);
}

TEST(HuazhongG71, SubprogramInShapeIsNotSupported) {
  EXPECT_THROW(plan("G00 X54 Z3;\nG71 U1.5 R1 P11 Q12 X0.6 Z0.1 F100;\nN11 G00 X0;\nN12 M98 P100;\nM30;\n", "hnc"),
               NotSupported);
}

TEST(HuazhongG71, G72IsNotSupported) {
  EXPECT_THROW(plan("G00 X54 Z3;\nG72 W1 R1;\nG72 P11 Q12 U0.6 W0.1 F100;\nN11 G00 Z-10;\nN12 G01 X0;\nM30;\n", "hnc"),
               NotSupported);
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

// HNC.G71.FMT: a FANUC/Haas one-block G71 handed to the hnc profile is PS0009 naming the profiles
// that read it, not planned with W and D ignored (it was: U read as Δd, the allowances dropped).
TEST(HuazhongG71Addresses, FanucOrHaasOneBlockFormatIsAnImproperAddress) {
  const std::string program =
      "G21;\nG00 X40. Z2.;\nG71 P10 Q20 U0.4 W0.1 D1.5 F0.2;\nN10 G00 X20.;\nN20 G01 X40. Z-20.;\nM30;\n";
  const Toolpath t = planWithReference({program, "hnc.nc", "hnc", {}, {}});
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0009");
  EXPECT_EQ(t.alarm->line, 3);
  EXPECT_NE(t.alarm->message.find("W0.1 at column"), std::string::npos) << t.alarm->message;
  EXPECT_NE(t.alarm->message.find("--profile haas"), std::string::npos) << t.alarm->message;
  // The oracles' reading of the program asks for the same alarm.
  JudgeRequest request;
  request.program = {program, "hnc.nc", "hnc", {}, {}};
  EXPECT_TRUE(judge(judgeInputFor(request, t)).empty());
}

}  // namespace
}  // namespace cyclecert
