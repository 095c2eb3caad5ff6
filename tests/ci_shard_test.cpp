// --shard auto: the shard read from each CI system's variables (harness/run/ci_shard.h), set in the
// process environment by the test and restored after it.
#include <gtest/gtest.h>

#include <cstdlib>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>

#include "harness/run/ci_shard.h"

namespace cyclecert {
namespace {

// Every variable --shard auto reads.
const char* const kShardVariables[] = {"CYCLECERT_SHARD",       "CYCLECERT_SHARD_COUNT",  "CI_NODE_INDEX",
                                       "CI_NODE_TOTAL",         "JOB_COMPLETION_INDEX",   "SLURM_ARRAY_TASK_ID",
                                       "SLURM_ARRAY_TASK_COUNT", "SLURM_ARRAY_TASK_MIN",   "SLURM_ARRAY_TASK_STEP"};

// Clears the shard variables for the test and puts back what the process had.
class ShardEnvironment : public ::testing::Test {
 protected:
  void SetUp() override {
    for (const char* name : kShardVariables) {
      if (const char* v = std::getenv(name)) saved_[name] = v;
      ::unsetenv(name);
    }
  }
  void TearDown() override {
    for (const char* name : kShardVariables) {
      if (saved_.count(name)) ::setenv(name, saved_[name].c_str(), 1);
      else ::unsetenv(name);
    }
  }
  static void set(const std::map<std::string, std::string>& variables) {
    for (const auto& [name, value] : variables) ::setenv(name.c_str(), value.c_str(), 1);
  }
  static std::string shard() { return shardOption("auto").text(); }
  // The message of the error --shard auto gives.
  static std::string error() {
    try {
      shardOption("auto");
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "(no error)";
  }

  std::map<std::string, std::string> saved_;
};

TEST_F(ShardEnvironment, GitLabsIndexIsOneBased) {
  set({{"CI_NODE_INDEX", "1"}, {"CI_NODE_TOTAL", "4"}});
  EXPECT_EQ(shard(), "1/4");
  set({{"CI_NODE_INDEX", "4"}});
  EXPECT_EQ(shard(), "4/4");
  set({{"CI_NODE_INDEX", "5"}});
  EXPECT_NE(error().find("shard 5 of 4"), std::string::npos) << error();
  set({{"CI_NODE_INDEX", "two"}});
  EXPECT_NE(error().find("CI_NODE_INDEX='two'"), std::string::npos) << error();
  ::unsetenv("CI_NODE_TOTAL");
  set({{"CI_NODE_INDEX", "2"}});
  EXPECT_NE(error().find("CI_NODE_TOTAL is not set"), std::string::npos) << error();
}

TEST_F(ShardEnvironment, KubernetesIndexIsZeroBasedAndTheCountComesFromCyclecertShardCount) {
  set({{"JOB_COMPLETION_INDEX", "0"}, {"CYCLECERT_SHARD_COUNT", "3"}});
  EXPECT_EQ(shard(), "1/3");
  set({{"JOB_COMPLETION_INDEX", "2"}});
  EXPECT_EQ(shard(), "3/3");
  set({{"JOB_COMPLETION_INDEX", "3"}});
  EXPECT_NE(error().find("shard 4 of 3"), std::string::npos) << error();
  ::unsetenv("CYCLECERT_SHARD_COUNT");
  set({{"JOB_COMPLETION_INDEX", "1"}});
  EXPECT_NE(error().find("set CYCLECERT_SHARD_COUNT to them"), std::string::npos) << error();
}

TEST_F(ShardEnvironment, SlurmIdsCountFromTheArraysFirstIdInItsSteps) {
  set({{"SLURM_ARRAY_TASK_ID", "0"}, {"SLURM_ARRAY_TASK_COUNT", "4"}, {"SLURM_ARRAY_TASK_MIN", "0"}});
  EXPECT_EQ(shard(), "1/4");  // --array=0-3
  set({{"SLURM_ARRAY_TASK_ID", "3"}});
  EXPECT_EQ(shard(), "4/4");
  set({{"SLURM_ARRAY_TASK_ID", "1"}, {"SLURM_ARRAY_TASK_MIN", "1"}});
  EXPECT_EQ(shard(), "1/4");  // --array=1-4
  set({{"SLURM_ARRAY_TASK_ID", "4"}});
  EXPECT_EQ(shard(), "4/4");
  set({{"SLURM_ARRAY_TASK_ID", "12"}, {"SLURM_ARRAY_TASK_MIN", "0"}, {"SLURM_ARRAY_TASK_STEP", "4"}});
  EXPECT_EQ(shard(), "4/4");  // --array=0-15:4
  set({{"SLURM_ARRAY_TASK_ID", "5"}});
  EXPECT_NE(error().find("CYCLECERT_SHARD=K/N instead"), std::string::npos) << error();
  ::unsetenv("SLURM_ARRAY_TASK_STEP");
  ::unsetenv("SLURM_ARRAY_TASK_MIN");
  EXPECT_NE(error().find("SLURM_ARRAY_TASK_MIN is not set"), std::string::npos) << error();
}

TEST_F(ShardEnvironment, CyclecertShardWinsOverTheCiSystemsVariables) {
  set({{"CI_NODE_INDEX", "1"}, {"CI_NODE_TOTAL", "2"}, {"SLURM_ARRAY_TASK_ID", "0"}, {"CYCLECERT_SHARD", "3/5"}});
  EXPECT_EQ(shard(), "3/5");
  set({{"CYCLECERT_SHARD", "6/5"}});
  EXPECT_NE(error().find("CYCLECERT_SHARD: expected K/N"), std::string::npos) << error();
  ::unsetenv("CYCLECERT_SHARD");
  EXPECT_EQ(shard(), "1/2");  // then GitLab's
}

TEST_F(ShardEnvironment, NoneSetIsAnErrorListingWhatIsRead) {
  const std::string e = error();
  for (const char* name : {"CYCLECERT_SHARD", "CI_NODE_INDEX", "CI_NODE_TOTAL", "JOB_COMPLETION_INDEX",
                           "CYCLECERT_SHARD_COUNT", "SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_COUNT", "--shard K/N"}) {
    EXPECT_NE(e.find(name), std::string::npos) << name << " in: " << e;
  }
}

TEST(ShardText, KOfNWithinRange) {
  EXPECT_EQ(parseShard("2/4").text(), "2/4");
  EXPECT_EQ(shardOption("1/1").text(), "1/1");
  for (const char* bad : {"", "3", "0/2", "3/2", "a/2", "1/", "/2", "1/0", "-1/2", "1/2/3", "1/100001"}) {
    EXPECT_THROW(parseShard(bad), std::invalid_argument) << bad;
  }
}

}  // namespace
}  // namespace cyclecert
