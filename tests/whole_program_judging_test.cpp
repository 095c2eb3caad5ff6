// PROG.WHOLE: the toolpath holds the program's moves before its first cycle (the approach, a
// facing cut). The oracles of the roughing passes must not take those for passes (a facing cut
// along X before a G72 was judged a pass standing off Δd's levels, and its end an absent retract),
// whether or not the engine draws them, and a wrong pass of the cycle is still found.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"

namespace cyclecert {
namespace {

const char* const kFacingThenG72 =
    "G21 G99;\nG00 X100. Z100.;\nG00 X82. Z1.;\nG01 X-1. F0.15;\nG00 Z3.;\nG00 X82. Z2.;\n"
    "G72 W2. R0.5;\nG72 P10 Q30 U0.4 W0.1 F0.2;\nN10 G00 Z-10.;\nN20 G01 X40.;\nN30 Z0.;\n"
    "G00 X100. Z100.;\nM30;\n";

std::vector<Finding> findingsOn(const Toolpath& path) {
  JudgeRequest request;
  request.program = {kFacingThenG72, "face.nc", "fanuc-0i-f", {}, {}};
  return judge(judgeInputFor(request, path));
}

Toolpath reference() { return planWithReference({kFacingThenG72, "face.nc", "fanuc-0i-f", {}, {}}); }

TEST(WholeProgramJudging, AFacingCutBeforeTheCycleIsNoPass) {
  const Toolpath path = reference();
  ASSERT_FALSE(path.alarm);
  ASSERT_EQ(path.cycles.size(), 1u);
  EXPECT_EQ(path.cycles.front().firstMove, 4u);  // to Z1, the facing cut, away, to A
  EXPECT_TRUE(findingsOn(path).empty()) << findingsOn(path).front().message;
}

TEST(WholeProgramJudging, APathThatStartsAtTheCycleIsJudgedAsBefore) {
  Toolpath path = reference();
  const std::size_t first = path.cycles.front().firstMove;
  path.start = path.cycles.front().start;
  path.moves.erase(path.moves.begin(), path.moves.begin() + static_cast<std::ptrdiff_t>(first));
  path.cycles.clear();
  EXPECT_TRUE(findingsOn(path).empty()) << findingsOn(path).front().message;
}

TEST(WholeProgramJudging, AWrongPassAfterTheFacingCutIsStillFound) {
  Toolpath path = reference();
  // The first pass of the cycle (after the rapid to A' and the infeed) made 0.5 deeper.
  const std::size_t pass = path.cycles.front().firstMove + 2;
  ASSERT_EQ(path.moves[pass].kind, MoveKind::Feed);
  path.moves[pass - 1].to.z -= 0.5;
  path.moves[pass].to.z -= 0.5;
  bool passLevels = false;
  for (const Finding& f : findingsOn(path)) passLevels = passLevels || f.oracle == "pass-levels";
  EXPECT_TRUE(passLevels);
}

// After the last cycle (a G70 counts) the program parts off along X: for a G72 that is the cut
// axis, and the parting cut runs through the part beyond the shape. It belongs to no cycle: it was
// judged a pass off Δd's levels, with no retract, gouging the part.
const char* const kG72G70ThenPartOff =
    "G21 G99;\nG00 X100. Z100.;\nG00 X82. Z2.;\nG72 W2. R0.5;\nG72 P10 Q30 U0.4 W0.1 F0.2;\nN10 G00 Z-10.;\n"
    "N20 G01 X40.;\nN30 Z0.;\nG70 P10 Q30;\nG00 X90. Z-20.;\nG01 X-1. F0.05;\nG00 X100.;\nZ100.;\nM30;\n";

std::vector<Finding> partOffFindings(const Toolpath& path) {
  JudgeRequest request;
  request.program = {kG72G70ThenPartOff, "partoff.nc", "fanuc-0i-f", {}, {}};
  return judge(judgeInputFor(request, path));
}

TEST(WholeProgramJudging, APartOffAfterTheLastCycleIsNoPass) {
  const Toolpath path = planWithReference({kG72G70ThenPartOff, "partoff.nc", "fanuc-0i-f", {}, {}});
  ASSERT_FALSE(path.alarm);
  ASSERT_EQ(path.cycles.size(), 2u);
  const std::vector<Finding> findings = partOffFindings(path);
  EXPECT_TRUE(findings.empty()) << findings.front().oracle << ": " << findings.front().message;
  // An engine that stops at the end of the cycles is judged alike.
  Toolpath cyclesOnly = path;
  cyclesOnly.moves.resize(path.moves.size() - 4);
  EXPECT_TRUE(partOffFindings(cyclesOnly).empty());
}

TEST(WholeProgramJudging, AWrongPassBeforeThePartOffIsStillFound) {
  Toolpath path = planWithReference({kG72G70ThenPartOff, "partoff.nc", "fanuc-0i-f", {}, {}});
  const std::size_t pass = path.cycles.front().firstMove + 2;
  ASSERT_EQ(path.moves[pass].kind, MoveKind::Feed);
  path.moves[pass - 1].to.z -= 0.5;
  path.moves[pass].to.z -= 0.5;
  bool passLevels = false;
  for (const Finding& f : partOffFindings(path)) passLevels = passLevels || f.oracle == "pass-levels";
  EXPECT_TRUE(passLevels);
}

}  // namespace
}  // namespace cyclecert
