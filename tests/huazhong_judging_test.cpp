// The oracles judge a planned Huazhong G71 (HNC.G71.FST, HNC.G71.RETURN): after the roughing, which
// ends back at A, the program goes on with the block after G71, so ns…nf run again as the finishing
// run — found at the end of the path by where each block leaves the tool, never by the engine's
// phase labels. Each test judges a path derived from the reference's by one deliberate fault; before
// the oracles modelled the run they refused every planned Huazhong cycle (NotSupported), so each
// test failed then.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "oracles/run_after_cycle.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

std::string corpusText(const std::string& name) {
  std::ifstream in(std::string(CYCLECERT_SOURCE_DIR) + "/corpus/" + name);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

JudgeRequest requestFor(const std::string& program) {
  JudgeRequest request;
  request.program = {program, "hnc.nc", "hnc", {}, {}};
  return request;
}

std::vector<Finding> judged(const JudgeRequest& request, const Toolpath& path) {
  return judge(judgeInputFor(request, path));
}

bool hasFinding(const std::vector<Finding>& findings, const std::string& oracle) {
  for (const Finding& f : findings) {
    if (f.oracle == oracle) return true;
  }
  return false;
}

bool hasFindingCiting(const std::vector<Finding>& findings, const std::string& oracle, const std::string& rule) {
  for (const Finding& f : findings) {
    if (f.oracle == oracle && std::find(f.rules.begin(), f.rules.end(), rule) != f.rules.end()) return true;
  }
  return false;
}

// The first move at or after `from` that is a cutting feed ending at p.
std::size_t feedEndingAt(const Toolpath& path, Point p, std::size_t from = 0) {
  for (std::size_t i = from; i < path.moves.size(); ++i) {
    if (path.moves[i].kind == MoveKind::Feed && distance(path.moves[i].to, p) < 1e-6) return i;
  }
  ADD_FAILURE() << "no feed ending at (z " << p.z << ", x " << p.x << ")";
  return 0;
}

// Seed 003 example 1 (outer stepped shaft) and example 2 (inner bore), whole programs: roughing,
// tool change, finishing run of N11…N20 / N11…N17, and (example 1) the part-off with T02.
const char* const kExamples[] = {"seed003-ex1-outer-shaft.nc", "seed003-ex2-inner-bore.nc"};

TEST(HuazhongJudging, EveryOraclePassesOnTheReferenceSeedExamples) {
  for (const char* name : kExamples) {
    const JudgeRequest request = requestFor(corpusText(name));
    const Toolpath path = planWithReference(request.program);
    ASSERT_FALSE(path.alarm) << name;
    const JudgeInput in = judgeInputFor(request, path);
    // The finishing run is modelled, not skipped: the oracles judge against the finish shape.
    EXPECT_TRUE(in.program.hasFinishingCycle) << name;
    ASSERT_NE(in.program.singleRoughingCycle(), nullptr) << name;
    const RunLocation where = locateRunAfterHuazhong(in);
    ASSERT_TRUE(where.run) << name;
    EXPECT_TRUE(nearlyEqual(path.from(where.run->roughingEnd), in.program.cycles.front().start)) << name;
    const std::vector<Finding> findings = judge(in);
    EXPECT_TRUE(findings.empty()) << name << ":\n" << findingsText(findings);
  }
}

// Example 1: the finishing run of N13 (Z-20 on φ10, x = 5) runs 0.5 mm inside the part.
TEST(HuazhongJudging, AGougingFinishingRunIsFound) {
  const JudgeRequest request = requestFor(corpusText(kExamples[0]));
  Toolpath path = planWithReference(request.program);
  const std::size_t chamfer = feedEndingAt(path, {-2, 5}, path.cycles.at(0).firstMove + path.cycles.at(0).moveCount);
  path.moves[chamfer].to = {-2, 4.5};
  path.moves[chamfer + 1].to = {-20, 4.5};
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFinding(findings, "no-gouge")) << findingsText(findings);
}

// Example 1: the finishing run's cuts made as rapids. The tool point runs along the finish shape,
// with the allowance beside it, not across it (no rapids-in-air): a rapid removes nothing, so the
// allowance stands at the end (complete), and the feeds are not the blocks'.
TEST(HuazhongJudging, ARapidFinishingRunIsFound) {
  const JudgeRequest request = requestFor(corpusText(kExamples[0]));
  Toolpath path = planWithReference(request.program);
  const std::size_t first = feedEndingAt(path, {-2, 5}, path.cycles.at(0).firstMove + path.cycles.at(0).moveCount);
  for (std::size_t i = first; i < first + 3; ++i) {
    path.moves[i].kind = MoveKind::Rapid;
    path.moves[i].feed.reset();
  }
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFindingCiting(findings, "feeds", "HNC.G71.FST")) << findingsText(findings);
  EXPECT_TRUE(hasFinding(findings, "complete")) << findingsText(findings);
}

// Example 1: the first roughing pass left out, so the second removes 2.7 mm (Δd = 1.5).
TEST(HuazhongJudging, APassTooDeepIsFound) {
  const JudgeRequest request = requestFor(corpusText(kExamples[0]));
  Toolpath path = planWithReference(request.program);
  const std::size_t firstPass = feedEndingAt(path, {-86.9, 25.8});
  ASSERT_EQ(firstPass, 2u);  // A → A' (0), A' → level 1 (1), the pass (2), retract (3), rapid back (4)
  path.moves.erase(path.moves.begin() + 1, path.moves.begin() + 5);
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFinding(findings, "depth-per-pass")) << findingsText(findings);
}

// A roughing that stops at C' instead of returning to A (HNC.G71.RETURN) before the block after G71.
TEST(HuazhongJudging, ARoughingThatDoesNotReturnToTheStartIsFound) {
  const JudgeRequest request = requestFor(corpusText(kExamples[0]));
  Toolpath path = planWithReference(request.program);
  const CycleRecord& cycle = path.cycles.at(0);
  const std::size_t end = cycle.firstMove + cycle.moveCount;
  path.moves.erase(path.moves.begin() + static_cast<std::ptrdiff_t>(end - 2), path.moves.begin() + static_cast<std::ptrdiff_t>(end));
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFindingCiting(findings, "returns-to-start", "HNC.G71.RETURN")) << findingsText(findings);
}

// An engine that skips ns…nf after the cycle as FANUC does: the finishing run is missing, the
// allowance stands and the path does not end with the program's blocks.
TEST(HuazhongJudging, AMissingFinishingRunIsFound) {
  const std::string program =
      "G00 X54 Z3;\nG71 U1.5 R1 P11 Q13 X0.6 Z0.1 F100;\nN11 G00 X10;\nN12 G01 Z-20;\nN13 X54;\nG00 X100 Z100;\nM30;\n";
  const JudgeRequest request = requestFor(program);
  Toolpath path = planWithReference(request.program);
  const std::size_t end = path.cycles.at(0).firstMove + path.cycles.at(0).moveCount;
  path.moves.erase(path.moves.begin() + static_cast<std::ptrdiff_t>(end), path.moves.end() - 1);
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFindingCiting(findings, "returns-to-start", "HNC.G71.FST")) << findingsText(findings);
  EXPECT_TRUE(hasFinding(findings, "complete")) << findingsText(findings);
}

// HNC.G71.FST: F set between G71 and ns applies to the finishing run; an engine that keeps the
// G71 block's F there is found.
TEST(HuazhongJudging, TheFinishingRunFeedIsTheOneSetBetweenG71AndNs) {
  const std::string program =
      "G00 X40 Z2;\nG71 U1.25 R0.5 P10 Q30 X0.4 Z0.1 F0.2;\nF0.1;\nN10 G00 X30;\nN20 G01 Z-20;\nN30 X40;\n"
      "G00 X50 Z10;\nM30;\n";
  const JudgeRequest request = requestFor(program);
  Toolpath path = planWithReference(request.program);
  ASSERT_TRUE(judged(request, path).empty()) << findingsText(judged(request, path));
  const std::size_t finishing = feedEndingAt(path, {-20, 15});
  ASSERT_EQ(path.moves[finishing].feed, 0.1);
  path.moves[finishing].feed = 0.2;
  const std::vector<Finding> findings = judged(request, path);
  EXPECT_TRUE(hasFindingCiting(findings, "feeds", "HNC.G71.FST")) << findingsText(findings);
}

// What the oracles cannot follow after a Huazhong G71 is refused, not judged wrongly: a
// subprogram call in ns…nf (HNC.G71.SUB), compensation with a nose radius (the finishing run is
// offset from the blocks' words).
TEST(HuazhongJudging, WhatTheOraclesCannotFollowIsRefused) {
  const Toolpath empty;
  JudgeRequest sub = requestFor("G00 X54 Z3;\nG71 U1.5 R1 P11 Q12 X0.6 Z0.1 F100;\nN11 G00 X0;\nN12 M98 P100;\nM30;\n");
  EXPECT_THROW(judgeInputFor(sub, empty), NotSupported);
  JudgeRequest compensated = requestFor(corpusText(kExamples[0]));
  compensated.program.options.tool.noseRadius = 0.4;
  compensated.program.options.tool.tip = 3;
  EXPECT_THROW(judgeInputFor(compensated, empty), NotSupported);
}

TEST(HuazhongJudging, ItsAlarmsAreJudged) {
  JudgeRequest request;
  request.program = {"G00 X54 Z3;\nG71 U1 R1 X0.4 Z0.1 F100;\nN10 G00 X20;\nN20 G01 X50 Z-30;\n", "hnc.nc", "hnc", {}, {}};
  const Toolpath path = planWithReference(request.program);
  ASSERT_TRUE(path.alarm);
  EXPECT_EQ(path.alarm->code, "PS0061");
  const std::vector<Finding> findings = judge(judgeInputFor(request, path));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

}  // namespace
}  // namespace cyclecert
