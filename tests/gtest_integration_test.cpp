// include/cyclecert/gtest.h, the GoogleTest integration of the C++ package: a spec case and the
// fuzz property fail for a faulty engine (with the case, the oracle and the seed in the message),
// pass for the reference, and skip a case the engine calls not applicable.
// (tools/test-installed-package.sh runs the macros end to end against a staged install.)
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cyclecert/gtest.h>

namespace cyclecert {
namespace {

const std::string kRetractCase = gtest::installedSpecsDir() + "/cases/fanuc-0i-f/g71/dtp-direct-return.json";

std::unique_ptr<Engine> referenceEngine() { return makeEngine("reference"); }
std::unique_ptr<Engine> retractAmountMutant() { return makeEngine("mutant:retract-amount"); }

// An engine that does nothing: every case is "not applicable" to it.
class NothingEngine : public Engine {
 public:
  std::string name() const override { return "nothing"; }
  std::string description() const override { return "plans nothing"; }
  std::string version() const override { return "0"; }
  EngineResult run(const SpecCase&) override { return EngineResult::notApplicable("this engine plans nothing"); }
};
std::unique_ptr<Engine> nothingEngine() { return std::make_unique<NothingEngine>(); }

TEST(GTestIntegration, TheSpecsDirIsTheSourceTreesInTheBuild) {
  EXPECT_TRUE(std::filesystem::is_regular_file(kRetractCase)) << kRetractCase;
}

TEST(GTestIntegration, ASpecCasePassesForTheReference) { gtest::checkOneSpecCase(referenceEngine, kRetractCase); }

TEST(GTestIntegration, ASpecCaseFailsForAFaultyEngineNamingTheCase) {
  EXPECT_NONFATAL_FAILURE(gtest::checkOneSpecCase(retractAmountMutant, kRetractCase),
                          "fanuc-0i-f/g71/dtp-direct-return");
}

TEST(GTestIntegration, ACaseTheEngineDoesNotPlanIsSkippedWithItsReason) {
  // GTEST_SKIP inside the helper marks this test skipped (and returns from the helper).
  gtest::checkOneSpecCase(nothingEngine, kRetractCase);
  if (!IsSkipped()) ADD_FAILURE() << "checkOneSpecCase did not skip a not-applicable case";
}

TEST(GTestIntegration, TheFuzzPropertyPassesForTheReference) {
  gtest::checkFuzzProperty(referenceEngine, "GTestIntegration", "Reference", 100, 1);
}

TEST(GTestIntegration, TheFuzzPropertyFailsForAFaultyEngineWithTheSeedAndTheShrunkProgram) {
  EXPECT_NONFATAL_FAILURE(gtest::checkFuzzProperty(retractAmountMutant, "GTestIntegration", "Mutant", 100, 7),
                          "CYCLECERT_FUZZ_SEED=7 replays the run");
  EXPECT_NONFATAL_FAILURE(gtest::checkFuzzProperty(retractAmountMutant, "GTestIntegration", "Mutant", 100, 7),
                          "shrunk program:\nG");
}

TEST(GTestIntegration, TestNamesAreIdentifiers) {
  EXPECT_EQ(gtest::testNameOf("gsk/g74_1/o0008-as-printed"), "gsk_g74_1_o0008_as_printed");
}

}  // namespace
}  // namespace cyclecert
