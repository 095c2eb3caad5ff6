// Every oracle passes on every reference output of the spec cases (the reference is the yardstick),
// and the alarm oracle agrees with every alarm case.
#include <gtest/gtest.h>

#include <filesystem>

#include "harness/judging.h"
#include "harness/reference_plan.h"
#include "harness/rule_catalogue.h"
#include "harness/spec_case.h"

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

}  // namespace
}  // namespace cyclecert
