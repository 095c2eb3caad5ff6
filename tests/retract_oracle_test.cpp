// The retract oracle with e = 0 (R0, or parameter 5133 = 0): the 45° retract has no length, so no
// move shows it; the oracle must not ask for one (it reported "does not retract at 45° by e = 0"
// after every pass of the reference's own path). With e > 0 a missing retract is still found.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"

namespace cyclecert {
namespace {

std::vector<Finding> retractFindings(const std::string& program, const Toolpath* path = nullptr) {
  JudgeRequest request;
  request.program = {program, "retract.nc", "fanuc-0i-f", {}, {}};
  const Toolpath planned = path ? *path : planWithReference(request.program);
  std::vector<Finding> out;
  for (const Finding& f : judge(judgeInputFor(request, planned))) {
    if (f.oracle == "retract") out.push_back(f);
  }
  return out;
}

std::string program(const char* retract) {
  return std::string("G21;\nG00 X40. Z2.;\nG71 U2. R") + retract +
         ";\nG71 P10 Q30 U0.4 W0.1 F0.2;\nN10 G00 X30.;\nN20 G01 Z-20.;\nN30 X38.;\nM30;\n";
}

TEST(RetractOracle, ARetractOfNoLengthIsNotAskedFor) {
  EXPECT_TRUE(retractFindings(program("0")).empty());
}

TEST(RetractOracle, AMissingRetractIsFoundWhenEIsNotZero) {
  // The reference's path with e = 0.5, its first 45° retract removed: the pass ends and the tool
  // rapids back at the pass level.
  const std::string withRetract = program("0.5");
  Toolpath path = planWithReference({withRetract, "retract.nc", "fanuc-0i-f", {}, {}});
  ASSERT_GE(path.moves.size(), 4u);
  ASSERT_EQ(path.moves[3].kind, MoveKind::Feed);  // approach, infeed, pass, retract
  const Point passEnd = path.moves[2].to;
  path.moves.erase(path.moves.begin() + 3);
  path.moves[3].to.x = passEnd.x;  // the rapid back along z stays at the pass level
  EXPECT_FALSE(retractFindings(withRetract, &path).empty());
}

}  // namespace
}  // namespace cyclecert
