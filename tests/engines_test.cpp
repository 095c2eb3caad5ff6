// The engines and the check run: the reference passes every spec case, every mutant is detected,
// an external process speaking JSON lines plugs in, and a crash, a hang, garbage or an oversized
// reply is an engine failure for that case while the run goes on; results survive a killed run.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include "harness/engines/engine.h"
#include "harness/engines/reference_plan.h"
#include "harness/run/check_run.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "tests/check_run_fixture.h"

namespace cyclecert {
namespace {

TEST(Engines, ReferencePassesEverySpecCase) {
  auto engine = makeEngine("reference");
  std::ostringstream progress;
  const fs::path out = fs::temp_directory_path() / ("cyclecert-check-ref-" + std::to_string(::getpid()));
  const CheckSummary s = runCheck(*engine, {defaultSpecsDir(), defaultRegressionsDir(), out.string(), false}, progress);
  fs::remove_all(out);
  EXPECT_EQ(s.fail, 0) << progress.str();
  EXPECT_EQ(s.engineFailure, 0) << progress.str();
  EXPECT_GT(s.pass, 90);
}

TEST(Engines, EveryMutantIsDetectedByCheck) {
  const auto engines = listEngines();
  int mutants = 0;
  for (const auto& [name, description] : engines) {
    if (name.rfind("mutant:", 0) != 0) continue;
    ++mutants;
    auto engine = makeEngine(name);
    std::ostringstream progress;
    const fs::path out = fs::temp_directory_path() / ("cyclecert-check-" + name.substr(7) + "-" + std::to_string(::getpid()));
    const CheckSummary s = runCheck(*engine, {defaultSpecsDir(), defaultRegressionsDir(), out.string(), false}, progress);
    fs::remove_all(out);
    EXPECT_GT(s.fail, 0) << name << " (" << description << ") escaped every spec case";
  }
  EXPECT_GE(mutants, 12);
}

TEST(Engines, UnknownEngineListsTheKnownOnes) {
  try {
    makeEngine("frobnicator");
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mutant:retract-angle"), std::string::npos);
  }
}

TEST_F(CheckRun, AProcessSpeakingJsonLinesPlugsIn) {
  auto engine = makeEngine("process:python3 " + source("examples/engine.py") + " " + cli());
  std::ostringstream progress;
  const CheckSummary s = runCheck(*engine, options(), progress);
  EXPECT_EQ(s.pass, 3) << progress.str();
  EXPECT_EQ(results().size(), 3u);
}

// The process protocol carries a SINUMERIK case's contour subprograms to the engine: the request
// is the whole case, its `subprograms` object included, so examples/engine.py (which hands the case
// to `cyclecert plan --case`) plans the same path as the reference; without them it could not.
TEST(Engines, AProcessEngineReceivesTheContourSubprograms) {
  const SpecCase c = loadSpecCase(source("specs/cases/sinumerik-802s/lcyc95/r105-1-rough-step-shaft.json"));
  ASSERT_FALSE(c.subprograms.empty());
  auto engine = makeEngine("process:python3 " + source("examples/engine.py") + " " + CYCLECERT_CLI);
  const EngineResult got = engine->run(c);
  ASSERT_EQ(got.kind, EngineResult::Planned) << got.detail;
  const Toolpath want = planSpecCase(c);
  ASSERT_EQ(got.path.moves.size(), want.moves.size());
  for (std::size_t i = 0; i < want.moves.size(); ++i) {
    EXPECT_LT(distance(got.path.moves[i].to, want.moves[i].to), 1e-9) << "move " << i;
  }
}

// `check --engine linuxcnc` end to end, through the engine factory: every spec case gets an answer
// from rs274 (a toolpath, an alarm, or not applicable); the only engine failures are the kept
// regressions on which rs274 hangs (their notes say "timed out"), stopped by the timeout.
TEST(Engines, LinuxCncAnswersEverySpecCaseThroughCheck) {
  if (!fs::exists(fs::path(CYCLECERT_CLI).parent_path() / "linuxcnc/usr/bin/rs274"))
    GTEST_SKIP() << "rs274 is not fetched (make rs274: harness/engines/linuxcnc/fetch-rs274.sh build)";
  int hangs = 0;
  for (const std::string& file : findSpecCaseFiles(defaultRegressionsDir())) {
    if (loadSpecCase(file).raw.value("notes", nlohmann::json::array()).dump().find("timed out") != std::string::npos) ++hangs;
  }
  EngineOptions options;
  options.timeoutSeconds = 2;
  auto engine = makeEngine("linuxcnc", options);
  std::ostringstream progress;
  const fs::path out = fs::temp_directory_path() / ("cyclecert-check-linuxcnc-" + std::to_string(::getpid()));
  const CheckSummary s = runCheck(*engine, {defaultSpecsDir(), defaultRegressionsDir(), out.string(), false}, progress);
  fs::remove_all(out);
  EXPECT_EQ(s.engineFailure, hangs) << progress.str();
  EXPECT_GE(hangs, 1);
  EXPECT_GT(s.pass + s.fail, 0) << "no case was applicable to LinuxCNC";
  EXPECT_GT(s.notApplicable, 0) << "FANUC-only cases (separate Δu/Δw, parameters) must not be translated";
}

TEST_F(CheckRun, ACrashIsAnEngineFailureAndTheProcessIsRestarted) {
  const std::string marker = (dir_ / "crashed").string();
  auto engine = makeEngine("process:" + script("crash-on-first.sh") + " " + marker + " " + cli());
  std::ostringstream progress;
  const CheckSummary s = runCheck(*engine, options(), progress);
  EXPECT_EQ(s.engineFailure, 1) << progress.str();
  EXPECT_EQ(s.pass, 2) << progress.str();  // restarted, the next cases are answered
  EXPECT_NE(progress.str().find("exited with status 3"), std::string::npos) << progress.str();
}

TEST_F(CheckRun, AHangIsStoppedByTheTimeout) {
  EngineOptions o;
  o.timeoutSeconds = 0.3;
  auto engine = makeEngine("process:" + script("hang.sh"), o);
  std::ostringstream progress;
  const auto started = std::chrono::steady_clock::now();
  const CheckSummary s = runCheck(*engine, options(), progress);
  EXPECT_EQ(s.engineFailure, 3);
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(10));
  EXPECT_NE(progress.str().find("no reply within"), std::string::npos) << progress.str();
}

TEST_F(CheckRun, GarbageAndOversizedRepliesAreEngineFailures) {
  auto garbage = makeEngine("process:" + script("garbage.sh"));
  std::ostringstream p1;
  EXPECT_EQ(runCheck(*garbage, options(), p1).engineFailure, 3);
  EXPECT_NE(p1.str().find("invalid JSON reply"), std::string::npos) << p1.str();
  EngineOptions small;
  small.maxReplyBytes = 1000;
  auto huge = makeEngine("process:" + script("huge.sh"), small);
  std::ostringstream p2;
  EXPECT_EQ(runCheck(*huge, options(), p2).engineFailure, 3);
  EXPECT_NE(p2.str().find("longer than 1000 bytes"), std::string::npos) << p2.str();
}

TEST_F(CheckRun, AKilledRunKeepsItsResultsAndResumes) {
  const std::string engine = "process:" + script("answer-then-hang.sh") + " " + cli();
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::setpgid(0, 0);  // its own group, killed whole below as a CI runner would kill a job
    const std::string specs = (dir_ / "specs").string(), out = (dir_ / "out").string();
    // One worker: with more, each worker's engine would answer its own first case.
    ::execl(CYCLECERT_CLI, "cyclecert", "check", "--engine", engine.c_str(), "--specs", specs.c_str(), "--out",
            out.c_str(), "--timeout", "600", "--jobs", "1", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait for the first result, then kill the run while the engine hangs on the second case.
  for (int i = 0; i < 200 && results().empty(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ::kill(-pid, SIGKILL);
  ::waitpid(pid, nullptr, 0);
  ASSERT_EQ(results().size(), 1u);
  EXPECT_EQ(results()[0]["verdict"], "pass");
  const auto first = results()[0];
  // A torn last line, as a kill during a write would leave, is dropped on --resume.
  std::ofstream(dir_ / "out/results.jsonl", std::ios::app) << R"({"engine": "x", "ca)";
  auto reference = makeEngine("process:python3 " + source("examples/engine.py") + " " + cli());
  CheckOptions o = options();
  o.resume = true;
  std::ostringstream progress;
  // Resuming skips only the same engine's cases; this engine's name differs, so it runs all three.
  const CheckSummary s = runCheck(*reference, o, progress);
  EXPECT_EQ(s.skipped, 0);  // a different engine name: nothing of its own to skip
  EXPECT_EQ(results().size(), 4u);  // the kept line + three new ones, the torn line gone
  EXPECT_EQ(results()[0], first);
}

TEST_F(CheckRun, ResumeSkipsWhatIsDone) {
  auto engine = makeEngine("reference");
  std::ostringstream progress;
  runCheck(*engine, options(), progress);
  CheckOptions o = options();
  o.resume = true;
  const CheckSummary again = runCheck(*engine, o, progress);
  EXPECT_EQ(again.skipped, 3);
  EXPECT_EQ(again.pass, 0);
  EXPECT_EQ(results().size(), 3u);
}

}  // namespace
}  // namespace cyclecert
