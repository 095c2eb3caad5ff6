// Results are never lost or mixed without a word (issue 13, defect 9): one run at a time per
// output directory (OUT/run.lock, flock(2)); a result that cannot be written stops the run with
// exit 2 and the number of results that are safe; --resume and merge refuse runs of another
// campaign unless --mix-campaigns.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <thread>

#include "harness/run/campaign.h"
#include "harness/run/run_lock.h"
#include "tests/cli_fixture.h"

extern char** environ;

namespace cyclecert {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class RunIntegrity : public CliFixture {
 protected:
  // A fuzz run of the reference: fast, and every case passes.
  CliRun fuzz(const std::string& out, const std::string& extra = "", const std::string& prefix = "") const {
    return run("fuzz --engine reference --no-save --out " + path(out) + " " + extra, prefix);
  }

  // The results in a results file that are whole lines of JSON (a torn last line is not).
  static std::size_t completeResults(const std::string& file) {
    std::istringstream lines(read(file));
    std::size_t complete = 0;
    for (std::string line; std::getline(lines, line);) {
      if (json::accept(line)) ++complete;
    }
    return complete;
  }

  static std::size_t runRecords(const std::string& outDir) {
    return json::parse(read(outDir + "/run.json"))["runs"].size();
  }

  // A small spec suite: one case and the rule catalogue, so that `check` is quick.
  std::string smallSpecs() const { return copySpecSuite({"fanuc-0i-f/g71/g01-head-stepped-shaft"}); }
};

// --- the lock ---------------------------------------------------------------------------------

TEST(RunLock, ASecondLockOnTheSameDirectoryIsRefusedUntilTheFirstIsReleased) {
  const fs::path dir = fs::temp_directory_path() / ("cyclecert-lock-" + std::to_string(::getpid()));
  {
    const RunLock first(dir.string(), "cyclecert fuzz --engine reference");
    try {
      const RunLock second(dir.string(), "cyclecert check");
      ADD_FAILURE() << "a second lock was granted";
    } catch (const RunLockedError& e) {
      EXPECT_NE(std::string(e.what()).find("is in use by another cyclecert run (pid " + std::to_string(::getpid()) +
                                           ": cyclecert fuzz --engine reference)"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_NO_THROW(RunLock(dir.string(), "cyclecert check"));  // released with the first
  fs::remove_all(dir);
}

TEST_F(RunIntegrity, ASecondRunIntoALockedOutIsRefusedAndWritesNothing) {
  ASSERT_EQ(fuzz("out", "--seed 1 --cases 10").exitCode, 0);
  const std::string results = read(path("out/results.jsonl")), runs = read(path("out/run.json"));
  const std::string specs = smallSpecs();
  {
    const RunLock held(path("out"), "the first run");
    for (const std::string& second :
         {"fuzz --engine reference --no-save --seed 2 --cases 10 --out " + path("out"),
          "fuzz --engine reference --no-save --seed 1 --cases 10 --shard 1/2 --resume --out " + path("out"),
          "check --engine reference --no-regressions --specs " + specs + " --out " + path("out"),
          "merge --out " + path("out") + " " + path("out")}) {
      const CliRun r = run(second);
      EXPECT_EQ(r.exitCode, 2) << second;
      EXPECT_NE(r.err.find("'" + path("out") + "' is in use by another cyclecert run"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("the first run"), std::string::npos) << r.err;
      EXPECT_NE(r.err.find("give another --out"), std::string::npos) << r.err;
    }
  }
  EXPECT_EQ(read(path("out/results.jsonl")), results);
  EXPECT_EQ(read(path("out/run.json")), runs);
  EXPECT_EQ(fuzz("out", "--seed 1 --cases 10").exitCode, 0);  // the lock is gone with its holder
}

// Two real runs: the first holds the lock while it runs; killed, it leaves no stale lock.
TEST_F(RunIntegrity, AConcurrentRunIsRefusedAndAKilledRunLeavesNoStaleLock) {
  const std::string out = path("out");
  // A minute at most, should the test stop before it kills the run.
  std::vector<std::string> args{CYCLECERT_CLI, "fuzz", "--engine", "reference", "--no-save", "--seed", "3",
                                "--time", "60", "--out", out};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t first = 0;
  ASSERT_EQ(posix_spawn(&first, CYCLECERT_CLI, &actions, nullptr, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  struct KilledAtTheEnd {
    pid_t pid;
    ~KilledAtTheEnd() {
      if (pid > 0 && ::kill(pid, SIGKILL) == 0) ::waitpid(pid, nullptr, 0);
    }
  } killed{first};
  // run.json is written once the lock is held; the first result once the run is under way.
  for (int i = 0; i < 400 && completeResults(out + "/results.jsonl") == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_GT(completeResults(out + "/results.jsonl"), 0u);

  const CliRun second = fuzz("out", "--seed 4 --cases 10");
  EXPECT_EQ(second.exitCode, 2);
  EXPECT_NE(second.err.find("is in use by another cyclecert run (pid " + std::to_string(first)), std::string::npos)
      << second.err;
  EXPECT_EQ(json::parse(read(out + "/run.json"))["runs"][0]["seed"], 3);  // still the first run's

  ::kill(first, SIGKILL);  // no chance to release anything itself
  ::waitpid(first, nullptr, 0);
  killed.pid = -1;
  const CliRun third = fuzz("out", "--seed 1 --cases 10");
  EXPECT_EQ(third.exitCode, 0) << third.err;
  EXPECT_EQ(completeResults(out + "/results.jsonl"), 10u);
}

// --- write errors -----------------------------------------------------------------------------

// The file size limit (RLIMIT_FSIZE: `ulimit -f`, in 512-byte blocks) stands in for a full disk:
// a write past it fails with EFBIG once SIGXFSZ is ignored, which the exec'd run inherits.
const char* kSixteenKiB = "ulimit -f 32; trap '' XFSZ; exec";

TEST_F(RunIntegrity, AFailedWriteStopsTheFuzzRunWithTheNumberOfSafeResults) {
  const CliRun r = fuzz("out", "--seed 1 --cases 5000", kSixteenKiB);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  const std::size_t safe = completeResults(path("out/results.jsonl"));
  EXPECT_GT(safe, 0u);
  EXPECT_LT(safe, 5000u);
  EXPECT_NE(r.err.find("cannot write '" + path("out/results.jsonl") + "': File too large"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("; stopped: " + std::to_string(safe) + " results are safe in it"), std::string::npos)
      << r.err << "\n(" << safe << " complete lines)";
  // No summary claims results that are not there, and no report is made of them.
  EXPECT_EQ(r.out.find(" pass, "), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(path("out/report.json")));
  // The safe results are a campaign that --resume continues.
  const CliRun resumed = fuzz("out", "--seed 1 --cases 5000 --resume");
  EXPECT_EQ(resumed.exitCode, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(std::to_string(safe) + " already done"), std::string::npos) << resumed.out;
}

TEST_F(RunIntegrity, AFailedWriteStopsTheCheckRunAndTheMerge) {
  const std::string specs = smallSpecs();
  const std::string check = "check --engine mutant:retract-angle --no-regressions --specs " + specs + " --out ";
  // A limit run.json fits in and the case's result (a failure, with its plot) does not.
  ASSERT_EQ(run(check + path("probe")).exitCode, 1);
  const std::size_t blocks = fs::file_size(path("probe/run.json")) / 512 + 1;
  ASSERT_GT(fs::file_size(path("probe/results.jsonl")), blocks * 512);
  CliRun r = run(check + path("out"), "ulimit -f " + std::to_string(blocks) + "; trap '' XFSZ; exec");
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("cannot write '" + path("out/results.jsonl") + "': File too large; stopped: 0 results are safe in it"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(r.out.find(" pass, "), std::string::npos) << r.out;
  EXPECT_EQ(completeResults(path("out/results.jsonl")), 0u);

  ASSERT_EQ(fuzz("a", "--seed 1 --cases 300").exitCode, 0);
  r = run("merge --out " + path("m") + " " + path("a"), kSixteenKiB);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  const std::size_t safe = completeResults(path("m/results.jsonl"));
  EXPECT_LT(safe, 300u);
  EXPECT_NE(r.err.find("stopped: " + std::to_string(safe) + " results are safe"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("merged"), std::string::npos) << r.out;
}

// --- resume -----------------------------------------------------------------------------------

TEST_F(RunIntegrity, ResumingAnotherCampaignIsRefusedNamingTheField) {
  ASSERT_EQ(fuzz("out", "--seed 1 --cases 20").exitCode, 0);
  const std::string results = read(path("out/results.jsonl"));
  const struct {
    std::string options, says;
  } others[] = {
      {"--seed 2 --cases 20", "seed 1 in " + path("out") + "/run.json, 2 in this run"},
      {"--cases 20", "resume with the same options (--seed 1)"},  // a resume without --seed draws a new one
      {"--seed 1 --cases 20 --vs mutant:retract-angle", "vs none in " + path("out") + "/run.json, mutant:retract-angle"},
      {"--seed 1 --cases 20 --shard 1/2", "shard none in "},
  };
  for (const auto& other : others) {
    const CliRun r = fuzz("out", other.options + " --resume");
    EXPECT_EQ(r.exitCode, 2) << other.options;
    EXPECT_NE(r.err.find("cannot resume the run in '" + path("out") + "': this run is of another campaign"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(other.says), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--mix-campaigns"), std::string::npos) << r.err;
  }
  CliRun r = run("fuzz --engine mutant:retract-angle --no-save --seed 1 --cases 20 --resume --out " + path("out"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("engine reference in " + path("out") + "/run.json, mutant:retract-angle in this run"),
            std::string::npos)
      << r.err;
  EXPECT_EQ(read(path("out/results.jsonl")), results);  // nothing written by the refused runs
  EXPECT_EQ(runRecords(path("out")), 1u);

  // The same campaign resumes, further too (case i is the same whatever --cases); or another on purpose.
  r = fuzz("out", "--seed 1 --cases 30 --resume");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("20 already done"), std::string::npos) << r.out;
  r = fuzz("out", "--seed 2 --cases 10 --resume --mix-campaigns");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(completeResults(path("out/results.jsonl")), 40u);
  EXPECT_EQ(runRecords(path("out")), 3u);
  EXPECT_EQ(fuzz("out", "--seed 2 --cases 10 --mix-campaigns").exitCode, 2);  // goes with --resume
}

TEST_F(RunIntegrity, ResumingACheckWithAnotherEngineOrSuiteIsRefused) {
  const std::string specs = smallSpecs();
  const auto check = [&](const std::string& engine, const std::string& extra) {
    return run("check --engine " + engine + " --no-regressions --specs " + specs + " --out " + path("out") + " " + extra);
  };
  ASSERT_EQ(check("reference", "").exitCode, 0);
  CliRun r = check("mutant:retract-angle", "--resume");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("engine reference in " + path("out") + "/run.json, mutant:retract-angle in this run"),
            std::string::npos)
      << r.err;
  std::ofstream(path("specs/cases/fanuc-0i-f/g71/g01-head-stepped-shaft.json"), std::ios::app) << " ";
  r = check("reference", "--resume");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("spec_suite_hash "), std::string::npos) << r.err;
  EXPECT_EQ(completeResults(path("out/results.jsonl")), 1u);
  r = check("mutant:retract-angle", "--resume --mix-campaigns");
  EXPECT_EQ(r.exitCode, 1) << r.err;  // run: the mutant fails the case
  EXPECT_EQ(completeResults(path("out/results.jsonl")), 2u);
}

// --- merge ------------------------------------------------------------------------------------

TEST_F(RunIntegrity, MergingRunsOfDifferentCampaignsIsRefusedNamingTheField) {
  ASSERT_EQ(fuzz("s1", "--seed 9 --cases 20 --shard 1/2").exitCode, 0);
  ASSERT_EQ(fuzz("s2", "--seed 9 --cases 20 --shard 2/2").exitCode, 0);
  ASSERT_EQ(fuzz("seed", "--seed 8 --cases 20 --shard 2/2").exitCode, 0);
  ASSERT_EQ(fuzz("cases", "--seed 9 --cases 40 --shard 2/2").exitCode, 0);
  ASSERT_EQ(fuzz("shards", "--seed 9 --cases 20 --shard 2/3").exitCode, 0);
  ASSERT_NE(run("fuzz --engine mutant:retract-angle --no-save --shrink-budget 5 --seed 9 --cases 20 --shard 2/2 --out " +
                path("engine"))
                .exitCode,
            2);
  // Another spec suite: the record as a run over an edited suite leaves it.
  fs::copy(path("s2"), path("suite"));
  json records = json::parse(read(path("suite/run.json")));
  records["runs"][0]["spec_suite_hash"] = "0123";
  std::ofstream(path("suite/run.json")) << records.dump();

  const struct {
    std::string input, says;
  } others[] = {
      {"seed", "seed 9 in " + path("s1") + "/run.json, 8 in " + path("seed") + "/run.json"},
      {"cases", "cases 20 in " + path("s1") + "/run.json, 40 in " + path("cases") + "/run.json"},
      {"shards", "shard count 2 in " + path("s1") + "/run.json, 3 in " + path("shards") + "/run.json"},
      {"suite", "spec_suite_hash "},
  };
  for (const auto& other : others) {
    const CliRun r = run("merge --out " + path("m-" + other.input) + " " + path("s1") + " " + path(other.input));
    EXPECT_EQ(r.exitCode, 2) << other.input;
    EXPECT_NE(r.err.find("cannot merge runs of different campaigns: " + other.says), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--mix-campaigns"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("m-" + other.input + "/results.jsonl"))) << other.input;
  }
  CliRun r = run("merge --out " + path("m") + " " + path("s1") + " " + path("s2"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(completeResults(path("m/results.jsonl")), 20u);
  // Fuzz runs of another engine fill that engine's part of one report, which compares the engines
  // (make run's report joins reference's and linuxcnc's): they merge.
  r = run("merge --out " + path("m-engine") + " " + path("s1") + " " + path("engine"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(completeResults(path("m-engine/results.jsonl")), 20u);
  r = run("merge --mix-campaigns --out " + path("mixed") + " " + path("s1") + " " + path("seed"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(completeResults(path("mixed/results.jsonl")), 20u);
}

TEST_F(RunIntegrity, CheckRunsOfDifferentEnginesOnOneSuiteMerge) {
  const std::string specs = smallSpecs();
  ASSERT_EQ(run("check --engine reference --no-regressions --specs " + specs + " --out " + path("a")).exitCode, 0);
  ASSERT_EQ(run("check --engine mutant:retract-angle --no-regressions --specs " + specs + " --out " + path("b")).exitCode, 1);
  const CliRun r = run("merge --out " + path("m") + " " + path("a") + " " + path("b"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(completeResults(path("m/results.jsonl")), 2u);
}

TEST(Campaign, ACheckRunAndAFuzzRunOfOneEngineGoTogetherAndAResumedRunMayGrow) {
  const json check{{"command", "check"}, {"engine", "reference"}, {"spec_suite_hash", "a"}};
  const json fuzz{{"command", "fuzz"}, {"engine", "reference"}, {"seed", 1}, {"cases", 10}, {"spec_suite_hash", "b"}};
  json longer = fuzz;
  longer["cases"] = 20;
  EXPECT_FALSE(mergeDifference({{{check, "a"}}, {{fuzz, "b"}}}));
  EXPECT_FALSE(resumeDifference({{fuzz, "a"}}, {longer, "b"}));
  EXPECT_FALSE(resumeDifference({{check, "a"}}, {fuzz, "b"}));  // a fuzz run added to a check run
  json other = fuzz;
  other["engine"] = "mutant:retract-angle";
  const auto engine = resumeDifference({{check, "a"}}, {other, "b"});
  ASSERT_TRUE(engine);
  EXPECT_EQ(differenceText(*engine), "engine reference in a, mutant:retract-angle in b");
  // Within one input a resumed run may have grown; across inputs the latest runs must agree.
  EXPECT_FALSE(mergeDifference({{{fuzz, "a"}, {longer, "a"}}, {{longer, "b"}}}));
  const auto d = mergeDifference({{{fuzz, "a"}, {longer, "a"}}, {{fuzz, "b"}}});
  ASSERT_TRUE(d);
  EXPECT_EQ(differenceText(*d), "cases 20 in a, 10 in b");
}

}  // namespace
}  // namespace cyclecert
