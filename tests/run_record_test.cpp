// run.json's pieces: the spec suite hash (SHA-256 over the sorted paths and contents of rules.json
// and cases/**/*.json), the source revision and the records' round trip.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "cyclecert_git_revision.h"
#include "harness/engines/engine.h"
#include "harness/run/campaign.h"
#include "harness/run/run_record.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_suite_hash.h"

namespace cyclecert {
namespace {

namespace fs = std::filesystem;

class SpecSuiteHash : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cyclecert-hash-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  void write(const std::string& relative, const std::string& text) {
    fs::create_directories((dir_ / relative).parent_path());
    std::ofstream(dir_ / relative) << text;
  }
  std::string hash() const { return specSuiteHash(dir_.string()); }
  fs::path dir_;
};

TEST_F(SpecSuiteHash, IsSha256OverPathsSizesAndContentsInPathOrder) {
  write("rules.json", "{}");
  // sha256(b"rules.json\0" b"2\0" b"{}"), computed independently (Python's hashlib).
  EXPECT_EQ(hash(), "0df7a298ba1ffae346ca3ebf0d44ca92dbff689fadb4efa0b65e6b3bfb821742");
  write("cases/p/g71/a.json", "a");
  EXPECT_EQ(hash(), "41e7846ef924a0cba80264cf84d327dfc2846c3cbb5b8b2dea5e5edc4af35271");
}

TEST_F(SpecSuiteHash, ChangesWithAnyCaseAndIgnoresOtherFiles) {
  write("rules.json", "{}");
  write("cases/p/g71/a.json", "{\"id\": 1}");
  const std::string before = hash();
  write("cases/p/g71/notes.txt", "not part of the suite");
  write("README.md", "neither");
  EXPECT_EQ(hash(), before);
  write("cases/p/g71/a.json", "{\"id\": 2}");
  EXPECT_NE(hash(), before);
  write("cases/p/g71/a.json", "{\"id\": 1}");
  EXPECT_EQ(hash(), before);
  fs::rename(dir_ / "cases/p/g71/a.json", dir_ / "cases/p/g71/b.json");
  EXPECT_NE(hash(), before);  // the path counts, not only the contents
}

TEST(RunRecord, NamesTheEngineTheRevisionAndTheSuite) {
  const auto engine = makeEngine("mutant:retract-angle");
  const auto vs = makeEngine("reference");
  const RunRecord r = startRunRecord("fuzz", *engine, vs.get(), defaultSpecsDir(), 7, {"cyclecert", "fuzz"});
  const nlohmann::json j = runRecordJson(r);
  EXPECT_EQ(j["engine_version"], "mutant:retract-angle");
  EXPECT_EQ(j["vs"], "reference");
  EXPECT_EQ(j["seed"], 7);
  EXPECT_EQ(j["spec_suite_hash"], specSuiteHash(defaultSpecsDir()));
  EXPECT_TRUE(std::regex_match(j["git_revision"].get<std::string>(), std::regex("[0-9a-f]{40}(\\+dirty)?|unknown")))
      << j["git_revision"];
  EXPECT_EQ(j["git_revision"], CYCLECERT_GIT_REVISION);
}

TEST(RunRecord, RecordsAreWrittenAppendedAndReadBack) {
  const fs::path dir = fs::temp_directory_path() / ("cyclecert-runs-" + std::to_string(::getpid()));
  const auto engine = makeEngine("reference");
  RunRecord r = startRunRecord("check", *engine, nullptr, defaultSpecsDir(), std::nullopt, {"cyclecert", "check"});
  EXPECT_TRUE(readRunRecords(dir.string()).empty());
  recordRun(dir.string(), r, false);
  recordRun(dir.string(), r, true);
  EXPECT_EQ(readRunRecords(dir.string()).size(), 2u);
  recordRun(dir.string(), r, false);
  const auto runs = readRunRecords(dir.string());
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0], runRecordJson(r));
  std::ofstream(dir / "run.json") << "{\"runs\": {}}";
  EXPECT_THROW(readRunRecords(dir.string()), std::runtime_error);
  fs::remove_all(dir);
}

// Fuzz runs drawing other cycle formats (--formats) are other campaigns, like other seeds: case i of
// a seed is another case under another format list. A record without "formats" (the default,
// two-block, as every record written before --formats) matches a default run.
TEST(RunRecord, FuzzRunsOfOtherFormatsAreOtherCampaigns) {
  const fs::path dir = fs::temp_directory_path() / ("cyclecert-formats-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto engine = makeEngine("reference");
  RunRecord plain = startRunRecord("fuzz", *engine, nullptr, defaultSpecsDir(), 7, {"cyclecert", "fuzz"});
  EXPECT_FALSE(runRecordJson(plain).contains("formats"));
  RunRecord haas = plain;
  haas.formats = "haas,gsys-b";
  EXPECT_EQ(runRecordJson(haas)["formats"], "haas,gsys-b");
  recordRun(dir.string(), plain, false);
  recordRun(dir.string(), plain, true);  // the same campaign resumes
  try {
    recordRun(dir.string(), haas, true);
    ADD_FAILURE() << "resumed a run of other formats";
  } catch (const CampaignMismatchError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("formats two-block in " + dir.string() + "/run.json, haas,gsys-b in this run"), std::string::npos)
        << what;
    EXPECT_NE(what.find("(--formats two-block)"), std::string::npos) << what;
  }
  recordRun(dir.string(), haas, true, true);  // --mix-campaigns
  EXPECT_EQ(readRunRecords(dir.string()).size(), 3u);

  // merge: the shards of one campaign share --formats.
  RunRecord shard1 = haas, shard2 = haas;
  shard1.shard = "1/2";
  shard2.shard = "2/2";
  const auto sourced = [](const RunRecord& r, const std::string& where) {
    return std::vector<SourcedRecord>{{runRecordJson(r), where}};
  };
  EXPECT_FALSE(mergeDifference({sourced(shard1, "a"), sourced(shard2, "b")}));
  shard2.formats = "haas";
  const auto d = mergeDifference({sourced(shard1, "a"), sourced(shard2, "b")});
  ASSERT_TRUE(d);
  EXPECT_EQ(d->field, "formats");
  EXPECT_EQ(differenceText(*d), "formats haas,gsys-b in a, haas in b");
  shard2.formats.clear();
  ASSERT_TRUE(mergeDifference({sourced(shard1, "a"), sourced(shard2, "b")}));
  EXPECT_EQ(differenceText(*mergeDifference({sourced(shard1, "a"), sourced(shard2, "b")})),
            "formats haas,gsys-b in a, two-block in b");
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cyclecert
