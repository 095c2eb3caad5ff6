// G74.1 and the oracles: the oracles' program reader reads G74.1's blocks into a GrooveSpec (they are
// no moves); the groove oracles and the generic ones that apply judge it (tests/groove_oracles_test.cpp);
// `judge --program` and `plan` on seed 002's example exit cleanly, every oracle passing.
#include <gtest/gtest.h>

#include <string>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "oracles/judgement.h"
#include "tests/cli_fixture.h"

namespace cyclecert {
namespace {

const char* kO0008 =
    "O0008;\nG00 X70 Z10 M3 S500;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5;\nM30;\n";

TEST(G74_1Judging, TheOraclesReaderReadsTheGrooveBlocksAsNoMoves) {
  const PlanRequest request{kO0008, "o0008.nc", "gsk", {}, {}};
  const ReadRequest read = readRequest(request);
  const ProgramSpec spec = readProgramSpec(*read.program, *read.profile, read.params, ToolOffset{});
  EXPECT_TRUE(spec.hasGrooveCycle);
  EXPECT_TRUE(spec.cycles.empty());
  ASSERT_EQ(spec.grooves.size(), 1u);
  EXPECT_NE(spec.singleGroove(), nullptr);
  // The groove block's X66 Z0 is not read as a move after the positioning X70 Z10.
  EXPECT_EQ(spec.movesBeforeCycles.size(), 0u);
  ASSERT_TRUE(spec.judgedFamily());
  EXPECT_EQ(*spec.judgedFamily(), CycleFamily::G74_1);
}

TEST(G74_1Judging, OnlyTheOraclesWhoseRulesApplyJudgeG74_1) {
  // The roughing cycles' pass oracles (Δd, levels, G71's retract, pocket entries, the return to A)
  // and the SINUMERIK ones have no G74.1 rule to judge.
  for (const auto& oracle : allOracles()) {
    const std::string id = oracle->id();
    const bool groove = id.rfind("groove-", 0) == 0 || id == "alarm" || id == "feeds" || id == "no-gouge" ||
                        id == "rapids-in-air" || id == "complete";
    EXPECT_EQ(oracle->judges(CycleFamily::G74_1), groove) << id;
  }
  EXPECT_EQ(cycleCode(CycleFamily::G74_1), "G74.1");
  EXPECT_EQ(cycleFamilyOfCode("G74.1"), CycleFamily::G74_1);
  EXPECT_FALSE(isSiemensFamily(CycleFamily::G74_1));
}

class G74_1Cli : public CliFixture {};

TEST_F(G74_1Cli, PlanAndJudgeSeed002sExample) {
  const std::string program = std::string(CYCLECERT_SOURCE_DIR) + "/corpus/seed002-o0008-g74_1.nc";
  CliRun r = run("plan " + program + " --json " + path("o0008.json") + " --svg " + path("o0008.svg"));
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("83 moves"), std::string::npos) << r.out;
  r = run("judge --program " + program + " " + path("o0008.json") + " --json");
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_EQ(r.out.find("\"oracle\""), std::string::npos) << r.out;  // no finding
}

}  // namespace
}  // namespace cyclecert
