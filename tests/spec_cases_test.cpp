// Every spec case under specs/cases is well-formed, cites only catalogued rules, and the reference
// meets its hand-derived expectation.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "harness/engines/reference_plan.h"
#include "harness/judge/spec_check.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

std::vector<std::string> caseFiles() { return findSpecCaseFiles(defaultSpecsDir() + "/cases"); }

const RuleCatalogue& catalogue() {
  static const RuleCatalogue c = loadRuleCatalogue(defaultSpecsDir() + "/rules.json");
  return c;
}

class SpecCases : public ::testing::TestWithParam<std::string> {};

TEST_P(SpecCases, IdMatchesItsPath) {
  const SpecCase c = loadSpecCase(GetParam());
  const auto relative = std::filesystem::relative(GetParam(), defaultSpecsDir() + "/cases").replace_extension("");
  EXPECT_EQ(c.id, relative.generic_string());
}

TEST_P(SpecCases, CitesOnlyCataloguedRules) {
  const SpecCase c = loadSpecCase(GetParam());
  for (const std::string& rule : c.rules) EXPECT_TRUE(catalogue().contains(rule)) << c.file << " cites unknown rule " << rule;
}

TEST_P(SpecCases, ReferenceMeetsTheHandDerivedExpectation) {
  const SpecCase c = loadSpecCase(GetParam());
  const Toolpath path = planSpecCase(c);
  const auto unmet = unmetExpectation(c, path);
  EXPECT_FALSE(unmet.has_value()) << c.id << ": " << unmet.value_or("");
}

std::string caseName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = std::filesystem::relative(info.param, defaultSpecsDir() + "/cases").replace_extension("").string();
  std::replace_if(name.begin(), name.end(), [](char ch) { return !std::isalnum(static_cast<unsigned char>(ch)); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(All, SpecCases, ::testing::ValuesIn(caseFiles()), caseName);

TEST(SpecSuite, HasAtLeastOneCasePerTypeIRule) {
  // The type I rules of issue 2: each must be cited by at least one spec case.
  const std::vector<std::string> typeIRules = {
      "G71.FMT.ZX", "G71.FMT.YZ", "G71.FMT.XY", "G71.ADDR.SHARED", "G71.DD.MODAL", "G71.E.MODAL",
      "G71.ALLOW.UNITS", "G71.FST", "G71.OP", "G71.QUAD", "G71.LIMIT.HEIGHT", "G71.T1.MONO",
      "G71.HEAD.G0G1", "G71.HEAD.NOX", "G71.CHECK", "G71.TYPE.SELECT", "G71.T1.ALARM", "G71.T1.RETRACT45",
      "G71.T1.SEMIFIN", "G71.DTP", "G72.FMT", "G72.POINTS", "G72.DD", "G72.ALLOW", "G72.FST", "G72.RANGE",
      "G72.NSNF.GCODES", "G72.T1.MONO", "G72.TYPE.SELECT", "G72.RETRACT", "G72.STEP1", "G72.STEP2",
      "G72.STEP3", "G72.STEP4", "G72.STEP5", "G72.STEP6", "G72.STEP7", "G72.STEP8", "G72.EX.O0005",
      "HNC.G71.EX1"};
  std::set<std::string> cited;
  for (const auto& f : caseFiles()) {
    for (const auto& r : loadSpecCase(f).rules) cited.insert(r);
  }
  for (const auto& r : typeIRules) EXPECT_TRUE(cited.count(r)) << "no spec case cites " << r;
}

// A corrupt spec file is a clear error naming the file and the field, never a crash.
TEST(SpecCaseErrors, NameTheFileAndTheField) {
  const auto message = [](const std::string& text) {
    try {
      parseSpecCase(text, "bad.json");
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("{").find("bad.json:1:2: (document): expected valid JSON"), std::string::npos);
  EXPECT_NE(message(R"({"id": "a", "program": NaN})").find("bad.json:1:24: /program: expected valid JSON"), std::string::npos)
      << message(R"({"id": "a", "program": NaN})");
  EXPECT_NE(message("[]").find("expected a JSON object"), std::string::npos);
  const std::string base = R"({"id": "a/b/c", "title": "t", "profile": "gsk", "rules": ["G72.FMT"], "program": "G0 X1;", "derivation": "by hand from the steps")";
  EXPECT_NE(message(base + "}").find("bad.json: /expect: expected a value (field missing)"), std::string::npos);
  EXPECT_NE(message(base + R"(, "expect": {"toolpath": [{"kind": "fly", "to": {"x": 1, "z": 2}}]}})")
                .find("/expect/toolpath/0/kind"),
            std::string::npos);
  EXPECT_NE(message(base + R"(, "expect": {"toolpath": [{"kind": "feed", "to": {"z": 2}}]}})")
                .find("/expect/toolpath/0/to/x"),
            std::string::npos);
  EXPECT_NE(message(base + R"(, "expect": {"toolpath": [{"kind": "feed", "shape": "arc_cw", "to": {"x": 1, "z": 2}}]}})")
                .find("/expect/toolpath/0/center"),
            std::string::npos);
  EXPECT_NE(message(base + R"(, "expect": {"alarm": {"code": "PS0064", "line": 0}}})").find("/expect/alarm/line"),
            std::string::npos);
  EXPECT_NE(message(base + R"(, "params": {"RF1": "on"}, "expect": {"alarm": "PS0064"}})").find("/params/RF1"),
            std::string::npos);
  EXPECT_EQ(message(base + R"(, "expect": {"alarm": "PS0064"}})"), "no error");
}

}  // namespace
}  // namespace cyclecert
