// A process engine's reply read without the process (harness/engines/process_reply.h, the reader
// tests/fuzz/process_reply_fuzz.cpp fuzzes): each kind of reply, and bad replies as engine failures
// that name the field, never an exception.
#include <gtest/gtest.h>

#include "harness/engines/process_reply.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert {
namespace {

EngineResult resultOfLine(const std::string& line) { return processReplyResult(parseProcessReply(line, 7)); }

TEST(ProcessReply, AToolpathIsPlanned) {
  const EngineResult r = resultOfLine(
      R"({"request": 7, "toolpath": {"start": {"x": 10, "z": 2}, "moves": [{"kind": "feed", "shape": "line", "to": {"x": 10, "z": -5}, "feed": 0.2}]}})");
  ASSERT_EQ(r.kind, EngineResult::Planned) << r.detail;
  ASSERT_EQ(r.path.moves.size(), 1u);
  EXPECT_EQ(r.path.moves[0].to, (Point{-5, 10}));
}

TEST(ProcessReply, AnAlarmIsKeptWithItsLine) {
  const EngineResult r = resultOfLine(R"({"request": 7, "alarm": {"code": "PS0064", "message": "not monotonic", "line": 4}})");
  ASSERT_EQ(r.kind, EngineResult::Alarmed) << r.detail;
  ASSERT_TRUE(r.path.alarm);
  EXPECT_EQ(r.path.alarm->code, "PS0064");
  EXPECT_EQ(r.path.alarm->line, 4);
}

TEST(ProcessReply, NotApplicableAndErrorKeepTheEnginesWords) {
  const EngineResult na = resultOfLine(R"({"request": 7, "not_applicable": "no G73 here"})");
  EXPECT_EQ(na.kind, EngineResult::NotApplicable);
  EXPECT_NE(na.detail.find("no G73 here"), std::string::npos) << na.detail;
  const EngineResult error = resultOfLine(R"({"request": 7, "error": "out of memory"})");
  EXPECT_EQ(error.kind, EngineResult::Failed);
  EXPECT_NE(error.detail.find("the engine reported: \"out of memory\""), std::string::npos) << error.detail;
}

TEST(ProcessReply, ABadToolpathIsAFailureNamingTheField) {
  const EngineResult r = resultOfLine(R"({"request": 7, "toolpath": {"moves": [{"kind": "feed", "shape": "line", "to": {"x": "a", "z": 1}}]}})");
  EXPECT_EQ(r.kind, EngineResult::Failed);
  EXPECT_NE(r.detail.find("/moves/0/to/x"), std::string::npos) << r.detail;
}

TEST(ProcessReply, RepliesWithoutAResultOrNotAnObjectAreFailures) {
  EXPECT_EQ(resultOfLine(R"({"request": 7})").detail, "a reply with none of toolpath, alarm, not_applicable, error");
  EXPECT_EQ(resultOfLine("[1, 2]").kind, EngineResult::Failed);
  EXPECT_EQ(resultOfLine("42").kind, EngineResult::Failed);
}

TEST(ProcessReply, ALineThatIsNotJsonThrowsNamingTheRequest) {
  try {
    parseProcessReply("{\"request\": 7,", 7);
    FAIL() << "no ToolpathFormatError";
  } catch (const ToolpathFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("the reply to request 7"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cyclecert
