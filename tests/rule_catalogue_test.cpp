// specs/rules.json holds every rule ID of the rule digest (RULES.md), all cycles.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "harness/spec/rule_catalogue.h"

namespace cyclecert {
namespace {

// Every ID of ../shared/RULES.md, copied here so that a clean clone can check the catalogue.
const std::vector<std::string> kDigestIds = {
    "G71.FMT.ZX", "G71.FMT.YZ", "G71.FMT.XY", "G71.ADDR.SHARED", "G71.DD.MODAL", "G71.E.MODAL",
    "G71.ALLOW.UNITS", "G71.FST", "G71.CSS", "G71.OP", "G71.QUAD", "G71.LIMIT.HEIGHT", "G71.T1.MONO",
    "G71.T2.MONO", "G71.HEAD.G0G1", "G71.HEAD.NOX", "G71.CHECK", "G71.CHECK.QSR", "G71.CHECK.FCK",
    "G71.TYPE.SELECT", "G71.T1.ALARM", "G71.T1.RETRACT45", "G71.T1.SEMIFIN", "G71.T2.FOLLOW",
    "G71.T2.VALLEY", "G71.T2.RETURN", "G71.T2.ORDER", "G71.T2.POCKET.EXIT", "G71.T2.DW0", "G71.CHAMFER",
    "G71.TNRC.PLACE", "G71.TNRC.CANCEL", "G71.TNRC.ZERO", "G71.TNRC.NT1", "G71.TNRC.NT2", "G71.DTP",
    "G71.NSP", "G72.FMT", "G72.POINTS", "G72.DD", "G72.ALLOW", "G72.FST", "G72.RANGE", "G72.NSNF.FOLLOW",
    "G72.NSNF.GCODES", "G72.NSNF.DIR", "G72.T1.MONO", "G72.T2.MONO", "G72.TYPE.SELECT", "G72.T2",
    "G72.RETRACT", "G72.STEP1", "G72.STEP2", "G72.STEP3", "G72.STEP4", "G72.STEP5", "G72.STEP6",
    "G72.STEP7", "G72.STEP8", "G72.SINGLE", "G72.RESUME", "G72.MDI", "G72.EX.O0005", "G74_1.FMT",
    "G74_1.ADDR", "G74_1.RANGE", "G74_1.STEP1", "G74_1.STEP2", "G74_1.STEP3", "G74_1.STEP4",
    "G74_1.STEP5", "G74_1.STEP6", "G74_1.STEP7", "G74_1.STEP8", "G74_1.STEP9", "G74_1.STEP10",
    "G74_1.EX.O0008", "HNC.G71.FMT", "HNC.G71.PQ", "HNC.G71.HEAD", "HNC.G71.SUB", "HNC.G71.MDI",
    "HNC.G71.FST", "HNC.G71.RETURN", "HNC.G71.EX1", "HNC.G71.EX2", "FANUC.G71.OLDPARAM", "G73.EX",
    "G70.EX", "LCYC95.PARAMS", "LCYC95.PRE", "LCYC95.CONTOUR", "LCYC95.ROUGH", "LCYC95.FINISH",
    "LCYC95.COMPLETE", "CYCLE95.PARAMS", "CYCLE95.UNDERCUT", "CYCLE95.ROUGH", "SEED004.EX.L42",
    "SEED004.EX.L18", "SEED004.THREAD"};

const RuleCatalogue& catalogue() {
  static const RuleCatalogue c = loadRuleCatalogue(defaultSpecsDir() + "/rules.json");
  return c;
}

TEST(RuleCatalogue, HoldsEveryDigestRule) {
  for (const auto& id : kDigestIds) EXPECT_TRUE(catalogue().contains(id)) << id << " missing from specs/rules.json";
}

TEST(RuleCatalogue, EveryRuleHasSourceSectionAndSummary) {
  std::set<std::string> seen;
  for (const RuleEntry& r : catalogue().rules) {
    EXPECT_TRUE(seen.insert(r.id).second) << "duplicate rule " << r.id;
    EXPECT_FALSE(r.seed.empty()) << r.id;
    EXPECT_FALSE(r.section.empty()) << r.id;
    EXPECT_FALSE(r.summary.empty()) << r.id;
  }
}

TEST(RuleCatalogue, RecordsTheInterpretationsTheReferenceMakes) {
  for (const char* id : {"G72.STEP2", "G72.STEP3", "G72.STEP5", "G72.STEP6", "G71.DTP", "G71.T1.ALARM"}) {
    const auto it = std::find_if(catalogue().rules.begin(), catalogue().rules.end(),
                                 [&](const RuleEntry& r) { return r.id == id; });
    ASSERT_NE(it, catalogue().rules.end()) << id;
    EXPECT_FALSE(it->notes.empty()) << id << " needs an interpretation note";
  }
}

TEST(RuleCatalogue, UnreadableOrCorruptCatalogueIsAClearError) {
  EXPECT_THROW(loadRuleCatalogue("/nonexistent/rules.json"), std::runtime_error);
}

}  // namespace
}  // namespace cyclecert
