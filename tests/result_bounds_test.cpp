// Issue 19, item 2 ("result and report sizes", "arc flattening"): what one case may put into the
// oracles and into results.jsonl is bounded (README "Limits"), each bound reported, never a
// minutes-long judgement, a silent pass or a line no reader takes.
#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "harness/io/input_file.h"
#include "harness/judge/judging.h"
#include "harness/results/results_file.h"
#include "oracles/judgement.h"
#include "reference/model/alarms.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

// The start at X44 (radius 22) stands clear of the part grown by its allowances (radius 20.2).
const std::string kProgram = std::string("G00 X44 Z2;\n") + kSmallG71Cycle + "M30;\n";

std::vector<Finding> judgeProgramPath(const Toolpath& path) {
  JudgeRequest request;
  request.program = {kProgram, "hand-made.nc", "fanuc-0i-f", {}, {}};
  return judge(judgeInputFor(request, path));
}

// A feed of pass 1 to `to` at `feed`.
Move passFeed(Point to, double feed) {
  Move m;
  m.kind = MoveKind::Feed;
  m.to = to;
  m.feed = feed;
  m.phase = MovePhase::Pass;
  m.pass = 1;
  return m;
}

// The reference's own plan of kProgram with `extra` inserted after its first move.
Toolpath planWith(const std::vector<Move>& extra) {
  Toolpath path = planFanucProgram(kProgram);
  path.moves.insert(path.moves.begin() + 1, extra.begin(), extra.end());
  return path;
}

// … with `arcs` full circles of `radius` mm as feeds at F0.2 (each starts and ends where the first
// move ends, its centre `radius` above).
Toolpath planWithCircles(int arcs, double radius) {
  const Point at = planFanucProgram(kProgram).moves.front().to;
  Move circle = passFeed(at, 0.2);
  circle.shape = SegmentKind::ArcCW;
  circle.center = Point{at.z, at.x + radius};
  return planWith(std::vector<Move>(static_cast<std::size_t>(arcs), circle));
}

// The findings are the one `measurable` finding (PROG.CAP) at `move`, saying `says` and that the
// path is not judged.
void expectOneMeasurableFinding(const std::vector<Finding>& findings, std::size_t move, const std::string& says) {
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_EQ(findings[0].oracle, "measurable");
  EXPECT_EQ(findings[0].move, std::optional<std::size_t>(move));
  EXPECT_NE(findings[0].message.find(says), std::string::npos) << findings[0].message;
  EXPECT_NE(findings[0].message.find("not judged"), std::string::npos) << findings[0].message;
}

TEST(JudgeBounds, TheReferencesPlanIsJudgedWithoutTheMeasurableFinding) {
  // The control for the cases below: the same program, its own plan, no finding at all.
  EXPECT_TRUE(judgeProgramPath(planFanucProgram(kProgram)).empty());
}

TEST(JudgeBounds, AnArcTooLargeToMeasureIsOneFindingNamingItsMove) {
  // A full circle of radius 999,000 mm: at kMeasuringChord (1e-6 mm) a chord spans at most
  // 4·asin(√(1e-6 / 1,998,000)) ≈ 2.83e-6 rad, so the circle takes ≈ 2.2 million chords, more than
  // the 1,000,000 an arc may take. Before the bound the oracles threw, and `check` counted the
  // case as passed with a note in its detail.
  expectOneMeasurableFinding(judgeProgramPath(planWithCircles(1, 999'000)), 1, "radius 999000");
}

TEST(JudgeBounds, ArcsTakingTooManyChordsInAllAreOneFindingAtTheMoveThatCrossesTheBudget) {
  // Full circles of radius 100,000 mm: ≈ 2π / (4·asin(√(1e-6 / 200,000))) ≈ 702,500 chords each,
  // within the per-arc bound; 10,000,000 in all are passed during the 15th (14 × 702,500 =
  // 9,835,000), which is move 15 (the circles are moves 1 to 20). Measuring them took seconds each.
  expectOneMeasurableFinding(judgeProgramPath(planWithCircles(20, 100'000)), 15, "10,000,000");
}

TEST(JudgeBounds, AnOracleListsAtMostAHundredFindingsAndSaysHowManyMore) {
  // 150 feeds at F0.3 while the cycle's F is 0.2: the feeds oracle finds each one (G71.FST); the
  // list keeps 100, the 100th saying "and 50 more".
  const Point at = planFanucProgram(kProgram).moves.front().to;
  std::vector<Move> feeds;
  for (int i = 0; i < 150; ++i) feeds.push_back(passFeed({at.z, at.x + (i % 2 ? 0.0 : 0.01)}, 0.3));  // up and down in air
  const Toolpath path = planWith(feeds);
  std::size_t ofFeeds = 0;
  std::string last;
  for (const Finding& f : judgeProgramPath(path)) {
    if (f.oracle != "feeds") continue;
    ++ofFeeds;
    last = f.message;
  }
  EXPECT_EQ(ofFeeds, kMostFindingsPerOracle);
  EXPECT_NE(last.find("and 50 more feeds findings"), std::string::npos) << last;
}

TEST(ResultLineBounds, ALineTooLongForTheReadersLeavesOutThePlotFirst) {
  CaseResult r;
  r.engine = "reference";
  r.caseId = "huge";
  r.verdict = "fail";
  r.detail = "no-gouge";
  Finding f;
  f.oracle = "no-gouge";
  f.message = "gouge";
  r.findings.push_back(f);
  // A plot of some 70 MiB: more than the 64 MiB a reader takes.
  r.plot = nlohmann::json{{"title", std::string(70u << 20, 'x')}};
  const std::string line = resultLine(r);
  ASSERT_LE(line.size(), kMaxInputBytes + 1);
  const nlohmann::json j = nlohmann::json::parse(line);
  EXPECT_FALSE(j.contains("plot"));
  EXPECT_EQ(j["left_out"], nlohmann::json::array({"the plot"}));
  EXPECT_EQ(j["findings"].size(), 1u);  // the findings stay
  EXPECT_EQ(j["verdict"], "fail");
}

TEST(ResultLineBounds, AnOrdinaryLineIsWrittenWhole) {
  CaseResult r;
  r.engine = "reference";
  r.caseId = "small";
  r.verdict = "fail";
  r.plot = nlohmann::json{{"title", "t"}};
  const nlohmann::json j = nlohmann::json::parse(resultLine(r));
  EXPECT_TRUE(j.contains("plot"));
  EXPECT_FALSE(j.contains("left_out"));
}

TEST(BoundedLine, ALineBeyondTheBoundIsSkippedToItsEndAndTheNextIsRead) {
  std::istringstream in("short\n" + std::string(100, 'y') + "\nafter\nlast-without-newline");
  std::string line;
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::Line);
  EXPECT_EQ(line, "short");
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::TooLong);
  EXPECT_TRUE(line.empty());
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::Line);
  EXPECT_EQ(line, "after");
  EXPECT_EQ(readBoundedLine(in, line, 100), BoundedLine::Line);
  EXPECT_EQ(line, "last-without-newline");
  EXPECT_EQ(readBoundedLine(in, line, 100), BoundedLine::End);
}

TEST(BoundedLine, ALineOfExactlyTheBoundIsKept) {
  std::istringstream in(std::string(10, 'z') + "\n\n");
  std::string line;
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::Line);
  EXPECT_EQ(line, std::string(10, 'z'));
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::Line);  // the empty line
  EXPECT_TRUE(line.empty());
  EXPECT_EQ(readBoundedLine(in, line, 10), BoundedLine::End);
}

TEST(BoundedLine, LinesLongerThanOneReadChunkAreJoinedOrSkippedWhole) {
  // The reader takes 64 KiB at a time: a line of several chunks is one line, kept or skipped whole.
  const std::string longLine(200000, 'a'), longer(300000, 'b');
  std::istringstream in(longLine + "\n" + longer + "\nnext\n" + longLine);
  std::string line;
  EXPECT_EQ(readBoundedLine(in, line, 250000), BoundedLine::Line);
  EXPECT_EQ(line, longLine);
  EXPECT_EQ(readBoundedLine(in, line, 250000), BoundedLine::TooLong);
  EXPECT_TRUE(line.empty());
  EXPECT_EQ(readBoundedLine(in, line, 250000), BoundedLine::Line);
  EXPECT_EQ(line, "next");
  EXPECT_EQ(readBoundedLine(in, line, 250000), BoundedLine::Line);  // the last, without a newline
  EXPECT_EQ(line, longLine);
  EXPECT_EQ(readBoundedLine(in, line, 250000), BoundedLine::End);
  // Lines ending at a chunk's edge: one character short of it, on it, one past it.
  for (std::size_t n : {65535, 65536, 65537}) {
    std::istringstream edge(std::string(n, 'c') + "\nx\n");
    EXPECT_EQ(readBoundedLine(edge, line, 250000), BoundedLine::Line);
    EXPECT_EQ(line.size(), n);
    EXPECT_EQ(readBoundedLine(edge, line, 250000), BoundedLine::Line);
    EXPECT_EQ(line, "x");
    EXPECT_EQ(readBoundedLine(edge, line, 250000), BoundedLine::End);
  }
}

TEST(NegativeSign, AMinusSignAfterFInACycleBlockIsPS0006NotFeedZero) {
  // PROG.SIGN: F-0.2 in the G71 block. Before, the cycle read the negative F as no feed and said
  // PS0011 FEED ZERO.
  const Toolpath t = planFanucProgram(
      "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F-0.2;\nN10 G00 X20;\nG01 Z-10;\nN20 X40 Z-20;\nM30;\n");
  ASSERT_TRUE(t.alarm.has_value());
  EXPECT_EQ(t.alarm->code, "PS0006");
  EXPECT_EQ(t.alarm->line, 3);
  EXPECT_NE(t.alarm->message.find("F-0.2 at column 23"), std::string::npos) << t.alarm->message;
}

TEST(NegativeSign, AMinusSignAfterSOrTAnywhereIsPS0006) {
  for (const std::string block : {"S-500", "T-0101"}) {
    const Toolpath t = planFanucProgram("G00 X40 Z2;\n" + block + ";\nM30;\n");
    ASSERT_TRUE(t.alarm.has_value()) << block;
    EXPECT_EQ(t.alarm->code, "PS0006") << block;
    EXPECT_EQ(t.alarm->line, 2) << block;
  }
}

}  // namespace
}  // namespace cyclecert
