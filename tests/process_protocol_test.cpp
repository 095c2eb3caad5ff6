// The process protocol against faulty engines (tests/data/engines/faulty.py: the reference's answers
// with one fault on one case): extra lines before or after the reply, a closed stdout, a hang, a
// crash, endless output, NaN in a reply, an engine that stops reading. Each time exactly the faulty
// case is an engine failure that says what happened, the cases around it get their own right
// verdicts (no reply is shifted onto another case), and the run ends within a bound.
#include <gtest/gtest.h>

#include <chrono>
#include <sstream>

#include "harness/engines/engine.h"
#include "harness/run/check_run.h"
#include "tests/check_run_fixture.h"

namespace cyclecert {
namespace {

using Clock = std::chrono::steady_clock;

const std::string kFaulty = "fanuc-0i-f/g71/ps0064-z-reverse";  // the middle one of the three

struct Fault {
  const char* name;     // faulty.py's FAULT
  const char* message;  // in the faulty case's detail
  double timeoutSeconds = 30;
  double boundSeconds = 20;  // the whole check of three cases ends sooner
};

std::ostream& operator<<(std::ostream& out, const Fault& f) { return out << f.name; }

class FaultyEngine : public CheckRun, public ::testing::WithParamInterface<Fault> {
 protected:
  std::string engine(const std::string& fault, const std::string& on) const {
    // exec: no shell stays behind holding the engine's stdout (a closed stdout is seen when every
    // process of the engine has closed it).
    return "process:exec python3 " + source("tests/data/engines/faulty.py") + " " + fault + " " + on + " " + cli();
  }
};

TEST_P(FaultyEngine, OnlyTheFaultyCaseFailsAndTheRunEnds) {
  const Fault f = GetParam();
  EngineOptions o;
  o.timeoutSeconds = f.timeoutSeconds;
  auto e = makeEngine(engine(f.name, kFaulty), o);
  std::ostringstream progress;
  const auto started = Clock::now();
  runCheck(*e, options(), progress);
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - started).count(), f.boundSeconds) << progress.str();
  const auto lines = results();
  ASSERT_EQ(lines.size(), 3u) << progress.str();
  for (const nlohmann::json& r : lines) {
    if (r["case"] == kFaulty) {
      EXPECT_EQ(r["verdict"], "engine-failure") << r.dump();
      EXPECT_NE(r["detail"].get<std::string>().find(f.message), std::string::npos) << r.dump();
    } else {
      EXPECT_EQ(r["verdict"], "pass") << r.dump();  // the reference's own answer, on its own case
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Protocol, FaultyEngine,
    ::testing::Values(Fault{"json-before", "not the reply to request"},
                      Fault{"log-before", "'planning the case...'"},
                      Fault{"json-after", "after its reply, the engine wrote more: '{\"alarm\": {\"code\": \"PS0064\""},
                      Fault{"log-after", "after its reply, the engine wrote more: 'done planning"},
                      // No wait for the timeout: 30 s would break the bound.
                      Fault{"close-stdout", "the engine closed its output"},
                      Fault{"hang", "no reply within 1 s (the engine hangs)", 1, 20},
                      Fault{"crash", "exited with status 3 before replying"},
                      Fault{"flood", "a reply longer than 67108864 bytes"},
                      Fault{"flood-lines", "'flood"},
                      Fault{"nan", "/toolpath/moves/0/to/x"}),
    [](const ::testing::TestParamInfo<Fault>& info) {
      std::string name = info.param.name;
      for (char& ch : name) {
        if (ch == '-') ch = '_';
      }
      return name;
    });

// The three cases loaded, for runBatch.
std::vector<SpecCase> threeCases() {
  std::vector<SpecCase> cases;
  for (const char* id : {"fanuc-0i-f/g71/g01-head-stepped-shaft", "fanuc-0i-f/g71/ps0064-z-reverse", "gsk/g72/first-infeed-g01"}) {
    cases.push_back(loadSpecCase(source("specs/cases/" + std::string(id) + ".json")));
  }
  return cases;
}

// The reference's answer to each case but `faulty`, and that `faulty` failed saying `message`.
void expectOnlyFailure(const std::vector<SpecCase>& cases, const std::vector<EngineResult>& got, std::size_t faulty,
                       const std::string& message) {
  ASSERT_EQ(got.size(), cases.size());
  auto reference = makeEngine("reference");
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (i == faulty) {
      EXPECT_EQ(got[i].kind, EngineResult::Failed) << i << ": " << kindName(got[i].kind);
      EXPECT_NE(got[i].detail.find(message), std::string::npos) << got[i].detail;
      continue;
    }
    const EngineResult want = reference->run(cases[i]);
    EXPECT_EQ(got[i].kind, want.kind) << i << ": " << got[i].detail;
    EXPECT_EQ(got[i].path.moves.size(), want.path.moves.size()) << i;
  }
}

// A second reply that comes after the next request was written carries the earlier request's
// number: the batch turns that earlier case into the failure, and the next case is asked again.
TEST_F(CheckRun, ALateSecondReplyFailsItsOwnCaseInABatch) {
  const auto cases = threeCases();
  auto e = makeEngine("process:python3 " + source("tests/data/engines/faulty.py") + " late-json-after " + kFaulty + " " + cli());
  const auto started = Clock::now();
  const auto got = e->runBatch(cases);
  EXPECT_LT(Clock::now() - started, std::chrono::seconds(20));
  expectOnlyFailure(cases, got, 1, "replied twice to this case");
}

// One case at a time (check), the earlier result is already out: the late reply is still never
// taken as the next case's.
TEST_F(CheckRun, ALateSecondReplyIsNotTakenForTheNextCase) {
  auto e = makeEngine("process:python3 " + source("tests/data/engines/faulty.py") + " late-json-after " + kFaulty + " " + cli());
  std::ostringstream progress;
  runCheck(*e, options(), progress);
  const auto lines = results();
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[2]["case"], "gsk/g72/first-infeed-g01");
  EXPECT_EQ(lines[2]["verdict"], "pass") << lines[2].dump();
}

// An engine that stops reading its stdin: writing a large case blocks once the pipe is full, and
// the timeout covers that write too.
TEST_F(CheckRun, AnEngineThatStopsReadingCostsOneTimeout) {
  auto cases = threeCases();
  cases[1].raw["notes"] = std::string(1 << 20, 'n');  // far beyond a pipe's buffer
  EngineOptions o;
  // 3 s, not 1: the engine's other cases run `cyclecert plan` in a Python process, which on a
  // loaded machine took longer than 1 s (a red ctest with the cases the engine did answer timed out).
  o.timeoutSeconds = 3;
  // It answers the first case, then sleeps without reading.
  auto e = makeEngine("process:python3 " + source("tests/data/engines/faulty.py") + " stop-reading " + cases[0].id + " " + cli(), o);
  const auto started = Clock::now();
  const auto got = e->runBatch(cases);
  EXPECT_LT(Clock::now() - started, std::chrono::seconds(20));
  expectOnlyFailure(cases, got, 1, "did not read the case within 3 s");
}

// The reference plans no moves for a G71 with RF1 = 1 whose start point is on the level where the
// shape ends; a process engine relaying it must not be refused (the fuzz case of seed 7).
TEST(ProcessProtocol, AnEmptyToolpathIsAValidReply) {
  auto e = makeEngine("process:sh " + source("tests/data/engines/empty-toolpath.sh"));
  const EngineResult r = e->run(loadSpecCase(source("specs/cases/fanuc-0i-f/g71/g01-head-stepped-shaft.json")));
  EXPECT_EQ(r.kind, EngineResult::Planned) << r.detail;
  EXPECT_TRUE(r.path.moves.empty());
}

// The request number each reply must echo grows with each request.
TEST(ProcessProtocol, EachRequestCarriesANumberTheReplyEchoes) {
  auto e = makeEngine("process:sh " + source("tests/data/engines/echo-wrong-request.sh"));
  const EngineResult r = e->run(loadSpecCase(source("specs/cases/fanuc-0i-f/g71/g01-head-stepped-shaft.json")));
  EXPECT_EQ(r.kind, EngineResult::Failed);
  EXPECT_NE(r.detail.find("not the reply to request 1"), std::string::npos) << r.detail;
  EXPECT_NE(r.detail.find("\"request\": 1"), std::string::npos) << r.detail;
}

}  // namespace
}  // namespace cyclecert
