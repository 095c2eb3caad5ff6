// --jobs N: the ordered worker pool (harness/run/parallel_run.h), and `check` and `fuzz` runs whose
// results files and kept regressions are those of --jobs 1 (sorted, the timing left out).
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "cli_fixture.h"
#include "harness/run/parallel_run.h"

namespace cyclecert {
namespace {

// Items whose work takes longer the smaller they are, so that with several workers they finish
// out of order.
void unevenWork(long item) { std::this_thread::sleep_for(std::chrono::microseconds((20 - item % 20) * 200)); }

TEST(RunInItemOrder, CommitsEveryItemInOrderWhateverOrderTheyFinishIn) {
  for (int jobs : {1, 2, 5}) {
    std::vector<long> committed;
    std::atomic<int> inCommit{0};
    bool overlapped = false;
    runInItemOrder<long>(
        jobs,
        [](int, long item) -> std::optional<long> {
          if (item >= 100) return std::nullopt;
          unevenWork(item);
          return item * 10;
        },
        [&](int, long& r) {
          if (inCommit++ != 0) overlapped = true;
          committed.push_back(r);
          --inCommit;
          return true;
        });
    std::vector<long> expected;
    for (long i = 0; i < 100; ++i) expected.push_back(i * 10);
    EXPECT_EQ(committed, expected) << jobs << " jobs";
    EXPECT_FALSE(overlapped) << jobs << " jobs";
  }
}

TEST(RunInItemOrder, UsesSeveralWorkersAndStopsWhenACommitSaysSo) {
  std::set<int> workers;
  std::mutex m;
  std::vector<long> committed;
  runInItemOrder<long>(
      3,
      [&](int worker, long item) -> std::optional<long> {
        {
          std::lock_guard<std::mutex> lock(m);
          workers.insert(worker);
        }
        unevenWork(item);
        return item;  // endless: the commit stops the run
      },
      [&](int, long& r) {
        committed.push_back(r);
        return r < 40;
      });
  EXPECT_EQ(committed.size(), 41u);
  EXPECT_EQ(committed.back(), 40);
  EXPECT_GT(workers.size(), 1u);
}

TEST(RunInItemOrder, AnItemThatThrowsStopsTheRunAfterTheItemsBeforeIt) {
  for (int jobs : {1, 3}) {
    std::vector<long> committed;
    try {
      runInItemOrder<long>(
          jobs,
          [](int, long item) -> std::optional<long> {
            unevenWork(item);
            if (item == 17) throw std::runtime_error("case 17 is unreadable");
            return item;
          },
          [&](int, long& r) {
            committed.push_back(r);
            return true;
          });
      ADD_FAILURE() << "no exception";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "case 17 is unreadable");
    }
    ASSERT_EQ(committed.size(), 17u) << jobs << " jobs";
    EXPECT_EQ(committed.back(), 16);
  }
}

TEST(RunInItemOrder, ACommitThatThrowsStopsTheRun) {
  long commits = 0;
  EXPECT_THROW(runInItemOrder<long>(
                   4, [](int, long item) -> std::optional<long> { return item; },
                   [&](int, long& r) {
                     ++commits;
                     if (r == 5) throw std::runtime_error("disk full");
                     return true;
                   }),
               std::runtime_error);
  EXPECT_EQ(commits, 6);
}

// The CLI with --jobs 1 and --jobs 2: the same results.
class JobsCli : public CliFixture {
 protected:
  // results.jsonl's lines without the timing ("seconds"), sorted; a regression file named relative
  // to `regressions`.
  std::vector<std::string> sortedResults(const std::string& out, const std::string& regressions = "") const {
    std::vector<std::string> lines;
    std::istringstream in(read(path(out) + "/results.jsonl"));
    for (std::string line; std::getline(in, line);) {
      nlohmann::json j = nlohmann::json::parse(line);
      j.erase("seconds");
      const std::string file = j.value("file", "");
      if (!regressions.empty() && file.rfind(path(regressions), 0) == 0) j["file"] = file.substr(path(regressions).size());
      lines.push_back(j.dump());
    }
    std::sort(lines.begin(), lines.end());
    return lines;
  }
  // The first line where two sorted results differ, for the failure message.
  static std::string firstDifference(const std::vector<std::string>& a, const std::vector<std::string>& b) {
    for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
      if (a[i] != b[i]) return "line " + std::to_string(i) + ":\n  " + a[i] + "\n  " + b[i];
    }
    return a.size() == b.size() ? "none" : "sizes " + std::to_string(a.size()) + " and " + std::to_string(b.size());
  }
  // The files of a regressions folder: name → text.
  std::map<std::string, std::string> folder(const std::string& name) const {
    std::map<std::string, std::string> files;
    if (!std::filesystem::is_directory(path(name))) return files;
    for (const auto& e : std::filesystem::recursive_directory_iterator(path(name))) {
      if (e.is_regular_file()) files[std::filesystem::relative(e.path(), path(name)).string()] = read(e.path().string());
    }
    return files;
  }
  static long verdicts(const std::vector<std::string>& lines, const std::string& verdict) {
    return std::count_if(lines.begin(), lines.end(), [&](const std::string& l) {
      return nlohmann::json::parse(l).at("verdict") == verdict;
    });
  }
};

TEST_F(JobsCli, FuzzWritesTheSameResultsAndRegressionsWithTwoJobs) {
  for (const std::string engine : {"reference", "mutant:retract-angle"}) {
    const std::string common = "fuzz --engine " + engine + " --seed 11 --cases 300 --shrink-budget 40 ";
    const CliRun one = run(common + "--jobs 1 --out " + path("one") + " --regressions " + path("reg1"));
    const CliRun two = run(common + "--jobs 2 --out " + path("two") + " --regressions " + path("reg2"));
    ASSERT_NE(one.exitCode, 2) << one.err;
    EXPECT_EQ(one.exitCode, two.exitCode) << two.err;
    const auto a = sortedResults("one", "reg1"), b = sortedResults("two", "reg2");
    EXPECT_EQ(a.size(), 300u) << engine;
    EXPECT_TRUE(a == b) << engine << ": " << firstDifference(a, b);
    EXPECT_EQ(folder("reg1"), folder("reg2")) << engine;
    if (engine != "reference") {
      EXPECT_GT(verdicts(a, "fail"), 0) << "the mutant should fail some cases";
      EXPECT_FALSE(folder("reg1").empty()) << "the mutant's first failure should be kept";
    }
    for (const char* d : {"one", "two", "reg1", "reg2"}) std::filesystem::remove_all(path(d));
  }
}

TEST_F(JobsCli, FuzzShardsMaxFailuresAndResumeWithTwoJobsAsWithOne) {
  const std::string common = "fuzz --engine mutant:retract-angle --no-save --seed 3 --cases 200 --shrink-budget 20 "
                             "--shard 2/3 --max-failures 3 ";
  ASSERT_EQ(run(common + "--jobs 1 --out " + path("one")).exitCode, 1);
  ASSERT_EQ(run(common + "--jobs 2 --out " + path("two")).exitCode, 1);
  const auto a = sortedResults("one");
  EXPECT_EQ(verdicts(a, "fail"), 3);
  EXPECT_TRUE(a == sortedResults("two")) << firstDifference(a, sortedResults("two"));
  // Resumed with more cases and no limit: the rest of the shard, as one worker runs it.
  const std::string more = "fuzz --engine mutant:retract-angle --no-save --seed 3 --cases 260 --shrink-budget 20 "
                           "--shard 2/3 --resume ";
  ASSERT_EQ(run(more + "--jobs 1 --out " + path("one")).exitCode, 1);
  const CliRun r = run(more + "--jobs 2 --out " + path("two"));
  ASSERT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.out.find("already done"), std::string::npos) << r.out;
  const auto c = sortedResults("one");
  EXPECT_EQ(c.size(), 87u);  // i < 260 with i mod 3 = 1
  EXPECT_TRUE(c == sortedResults("two")) << firstDifference(c, sortedResults("two"));
}

TEST_F(JobsCli, ATimeBudgetStopsTwoJobsAndKeepsWhatTheyRecorded) {
  const CliRun r = run("fuzz --engine reference --no-save --seed 4 --time 1 --jobs 2 --out " + path("out"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto at = r.out.find(" cases in ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const long cases = std::stol(r.out.substr(r.out.find(": ") + 2));
  const double seconds = std::stod(r.out.substr(at + 10));
  EXPECT_GT(cases, 0) << r.out;
  EXPECT_GE(seconds, 1.0) << r.out;
  EXPECT_LT(seconds, 3.0) << r.out;
  EXPECT_EQ(static_cast<long>(sortedResults("out").size()), cases);  // every case counted is recorded, once
}

// --time bounds a batch too: an engine taking a quarter second a case would take 16 s over one
// batch of 64 cases once it had started it in time (LinuxCNC's 64-case batches overran `make run`'s
// --time 30 by half a minute). The cases are given in chunks that fit in the time left.
TEST_F(JobsCli, ATimeBudgetBoundsTheBatchOfASlowEngine) {
  const std::string engine = "'process:" + std::string(CYCLECERT_SOURCE_DIR) + "/tests/data/engines/slow.sh'";
  for (const int jobs : {1, 2}) {
    const std::string out = "out" + std::to_string(jobs);
    const auto start = std::chrono::steady_clock::now();
    const CliRun r = run("fuzz --engine " + engine + " --no-save --seed 4 --time 2 --jobs " + std::to_string(jobs) +
                         " --out " + path(out));
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_EQ(r.exitCode, 0) << r.err << r.out;
    EXPECT_LT(seconds, 5.0) << "jobs " << jobs << ": " << r.out;
    const long cases = std::stol(r.out.substr(r.out.find(": ") + 2));
    EXPECT_GT(cases, 0) << r.out;
    EXPECT_EQ(static_cast<long>(sortedResults(out).size()), cases) << r.out;
  }
}

TEST_F(JobsCli, CheckWritesTheSameResultsInTheSameOrderWithTwoJobs) {
  for (const std::string engine : {"reference", "mutant:retract-angle"}) {
    const std::string common = "check --engine " + engine + " --no-regressions ";
    const CliRun one = run(common + "--jobs 1 --out " + path("one"));
    const CliRun two = run(common + "--jobs 2 --out " + path("two"));
    ASSERT_NE(one.exitCode, 2) << one.err;
    EXPECT_EQ(one.exitCode, two.exitCode) << two.err;
    const auto a = sortedResults("one");
    EXPECT_GT(a.size(), 100u);
    EXPECT_TRUE(a == sortedResults("two")) << engine << ": " << firstDifference(a, sortedResults("two"));
    if (engine != "reference") {
      EXPECT_GT(verdicts(a, "fail"), 0) << "the mutant should fail some cases";
    }
    // In the same order too: the results are written in case order.
    const auto ids = [&](const std::string& out) {
      std::vector<std::string> v;
      std::istringstream in(read(path(out) + "/results.jsonl"));
      for (std::string line; std::getline(in, line);) v.push_back(nlohmann::json::parse(line).at("case"));
      return v;
    };
    EXPECT_EQ(ids("one"), ids("two"));
    for (const char* d : {"one", "two"}) std::filesystem::remove_all(path(d));
  }
}

TEST_F(JobsCli, CheckShardsMergeIntoTheWholeRun) {
  ASSERT_EQ(run("check --engine reference --no-regressions --jobs 1 --out " + path("whole")).exitCode, 0);
  ASSERT_EQ(run("check --engine reference --no-regressions --jobs 2 --shard 1/2 --out " + path("s1")).exitCode, 0);
  const CliRun s2 = run("check --engine reference --no-regressions --shard auto --out " + path("s2"), "CYCLECERT_SHARD=2/2");
  ASSERT_EQ(s2.exitCode, 0) << s2.err;
  const auto half = sortedResults("s1");
  EXPECT_GT(half.size(), 0u);
  EXPECT_LT(half.size(), sortedResults("whole").size());
  const CliRun m = run("merge --out " + path("merged") + " " + path("s1") + " " + path("s2"));
  ASSERT_EQ(m.exitCode, 0) << m.err;
  EXPECT_TRUE(sortedResults("merged") == sortedResults("whole"))
      << firstDifference(sortedResults("merged"), sortedResults("whole"));
}

TEST_F(JobsCli, BadJobsAndShardValuesAreUsageErrors) {
  for (const char* bad : {"0", "x", "1.5", "-2", "99999"}) {
    for (const char* command : {"fuzz", "check"}) {
      const CliRun r = run(std::string(command) + " --engine reference --jobs " + bad + " --out " + path("out"));
      EXPECT_EQ(r.exitCode, 2) << command << " --jobs " << bad;
      EXPECT_NE(r.err.find("--jobs expects a whole number of workers from 1 to"), std::string::npos) << r.err;
    }
  }
  const CliRun none = run("check --engine reference --shard auto --out " + path("out"),
                          "unset CYCLECERT_SHARD CI_NODE_INDEX CI_NODE_TOTAL JOB_COMPLETION_INDEX SLURM_ARRAY_TASK_ID;");
  EXPECT_EQ(none.exitCode, 2);
  EXPECT_NE(none.err.find("CI_NODE_INDEX"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("JOB_COMPLETION_INDEX"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("SLURM_ARRAY_TASK_ID"), std::string::npos) << none.err;
  const CliRun bad = run("check --engine reference --shard 0/2 --out " + path("out"));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("K/N"), std::string::npos) << bad.err;
  for (const char* command : {"fuzz", "check"}) {
    const CliRun help = run(std::string(command) + " --help");
    EXPECT_NE(help.out.find("--jobs N"), std::string::npos) << command;
    EXPECT_NE(help.out.find("--shard auto"), std::string::npos) << command;
  }
}

}  // namespace
}  // namespace cyclecert
