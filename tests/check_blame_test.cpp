// An expected toolpath that is not met fails the rules of the move where it diverges (as the
// reference annotates that move), not every rule the case cites — so the report's rule × engine
// matrix blames a wrong retract on the retract rule, not on the cycle's format rule.
#include <gtest/gtest.h>

#include <algorithm>

#include "harness/engines/engine.h"
#include "harness/run/check_run.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

bool names(const std::vector<std::string>& rules, const std::string& id) {
  return std::find(rules.begin(), rules.end(), id) != rules.end();
}

TEST(CheckBlame, AnUnmetExpectationNamesTheRulesOfTheDivergingMove) {
  // Seed 004's G72 with modal Δd and e: the case cites the format and depth rules; the mutant
  // retracts straight out, so the expectation first fails at the retract after the first pass.
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/gsk/g72/modal-dd-e.json");
  ASSERT_TRUE(names(c.rules, "G72.FMT"));
  ASSERT_FALSE(names(c.rules, "G72.RETRACT"));
  const auto mutant = makeEngine("mutant:retract-angle");
  const CaseResult r = checkCase(*mutant, c);
  ASSERT_EQ(r.verdict, "fail");
  const auto expectation = std::find_if(r.findings.begin(), r.findings.end(),
                                        [](const Finding& f) { return f.oracle == "expectation"; });
  ASSERT_NE(expectation, r.findings.end()) << r.detail;
  EXPECT_EQ(expectation->move, 3u);
  EXPECT_TRUE(names(expectation->rules, "G72.RETRACT"));
  EXPECT_FALSE(names(expectation->rules, "G72.FMT"));
  EXPECT_EQ(expectation->message, r.detail);
}

TEST(CheckBlame, TheEngineThatMeetsTheExpectationHasNoSuchFinding) {
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/gsk/g72/modal-dd-e.json");
  const auto reference = makeEngine("reference");
  const CaseResult r = checkCase(*reference, c);
  EXPECT_EQ(r.verdict, "pass");
  EXPECT_TRUE(r.findings.empty());
}

}  // namespace
}  // namespace cyclecert
