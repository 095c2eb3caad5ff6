// Each metamorphic relation's limits (oracles/metamorphic/relations.h: relationJudges and each
// relation's `outside`): the sources a relation transforms but cannot judge, from how they ran —
// each limit stated in the relation's description or oracles/metamorphic/README.md.
#include <gtest/gtest.h>

#include <string>

#include "oracles/metamorphic/relations.h"

namespace cyclecert {
namespace {

bool judges(const std::string& id, const SourceRun& run) {
  const Relation* r = findRelation(id);
  if (!r) throw std::runtime_error("no relation " + id);
  return relationJudges(*r, run);
}

TEST(RelationLimits, APlainFanucRunIsJudgedByEveryRelation) {
  for (const Relation& r : allRelations()) EXPECT_TRUE(relationJudges(r, {"fanuc-0i-f", false, ""})) << r.id;
}

TEST(RelationLimits, ASourceAlarmingAWordOutOfRangeIsJudgedByNone) {
  for (const Relation& r : allRelations()) EXPECT_FALSE(relationJudges(r, {"fanuc-0i-f", false, "PS0003"})) << r.id;
}

TEST(RelationLimits, ScaleKDoesNotScaleTheToolsNoseRadius) {
  EXPECT_FALSE(judges("scale-k", {"sinumerik-802d", true, ""}));
  EXPECT_TRUE(judges("scale-k", {"sinumerik-802d", false, ""}));
  EXPECT_TRUE(judges("translate-z", {"sinumerik-802d", true, ""}));
}

TEST(RelationLimits, ThePs0322HeightLimitHasNoG72OrHuazhongCounterpart) {
  EXPECT_FALSE(judges("transpose", {"fanuc-0i-f", false, "PS0322"}));
  EXPECT_FALSE(judges("hnc-one-block", {"fanuc-0i-f", false, "PS0322"}));
  EXPECT_TRUE(judges("mirror-z", {"fanuc-0i-f", false, "PS0322"}));
}

TEST(RelationLimits, TheOneBlockDialectsAreWrittenFromTheFanuc0iFReadingOrTheirOwn) {
  for (const std::string id : {"hnc-one-block", "haas-one-block"}) {
    EXPECT_FALSE(judges(id, {"gsk", false, ""})) << id;
    EXPECT_FALSE(judges(id, {"fanuc-0i-c", false, ""})) << id;
  }
  EXPECT_TRUE(judges("hnc-one-block", {"hnc", false, ""}));
  EXPECT_TRUE(judges("haas-one-block", {"haas", false, ""}));
  EXPECT_FALSE(judges("haas-one-block", {"hnc", false, ""}));
  EXPECT_TRUE(judges("fs10-one-block", {"gsk", false, ""}));
}

}  // namespace
}  // namespace cyclecert
