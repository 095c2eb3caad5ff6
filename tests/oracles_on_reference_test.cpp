// Every oracle passes on every reference output of the spec cases (the reference is the yardstick),
// and the alarm oracle agrees with every alarm case.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

class OraclesOnReference : public ::testing::TestWithParam<std::string> {};

TEST_P(OraclesOnReference, FindNothing) {
  const SpecCase c = loadSpecCase(GetParam());
  const JudgeRequest request = judgeRequestFor(c);
  const JudgeInput in = judgeInputFor(request, planSpecCase(c));
  const std::vector<Finding> findings = judge(in);
  EXPECT_TRUE(findings.empty()) << c.id << ":\n" << findingsText(findings);
}

std::string caseName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::relative(info.param, defaultSpecsDir() + "/cases").replace_extension("").string();
  std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(SpecCases, OraclesOnReference,
                         ::testing::ValuesIn(findSpecCaseFiles(defaultSpecsDir() + "/cases")), caseName);

// The oracles read a program's blocks as the runner does (positionAfterBlock): G04's X is a dwell
// time, G53's words machine coordinates, G50's the position set, G28's the intermediate point. A
// reader that took every block with axis words for a move put the cycle start at X1.5 after a
// dwell and found the reference's plan wanting.
TEST(OraclesReadTheProgramAsTheRunner, GroupZeroCommandsDoNotMoveTheStartPoint) {
  const std::string cycle =
      "G71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-10;\nN20 X40 Z-20;\nM30;\n";
  for (const std::string before : {"G00 X42 Z2;\nG04 X1.5;\n", "G00 X42 Z2;\nG53 X300 Z200;\n",
                                    "G50 X42 Z2;\n", "G00 X80 Z50;\nG28 X42 Z2;\nG00 X42 Z2;\n"}) {
    JudgeRequest request;
    request.program = {before + cycle, "start.nc", "fanuc-0i-f", {}, {}};
    Toolpath path;
    try {
      path = planWithReference(request.program);
    } catch (const NotSupported&) {
      continue;  // G53 leaves the position unknown: the reference does not plan the cycle
    }
    const JudgeInput in = judgeInputFor(request, path);
    EXPECT_TRUE(nearlyEqual(in.program.cycles.at(0).start, {2, 21})) << before;
    const std::vector<Finding> findings = judge(in);
    EXPECT_TRUE(findings.empty()) << before << findingsText(findings);
  }
}

}  // namespace
}  // namespace cyclecert
