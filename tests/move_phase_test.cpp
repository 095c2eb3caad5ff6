// The move phase is an enum (MovePhase) spelled in the toolpath JSON exactly as the README's
// "Toolpath JSON" documents it: approach, pass, semi-finish, finish, return, program; a move without
// a phase has no "phase". Any other spelling is refused at its JSON path, naming the six.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "reference/model/toolpath_json.h"

namespace cyclecert {
namespace {

using nlohmann::json;

// The documented spellings, written down by hand from README "Toolpath JSON".
const std::vector<std::pair<MovePhase, std::string>> kDocumented = {
    {MovePhase::Approach, "approach"}, {MovePhase::Pass, "pass"},     {MovePhase::SemiFinish, "semi-finish"},
    {MovePhase::Finish, "finish"},     {MovePhase::Return, "return"}, {MovePhase::Program, "program"},
};

json moveWithPhase(const json& phase) {
  return {{"kind", "feed"}, {"to", {{"x", 1}, {"z", 2}}}, {"feed", 0.2}, {"phase", phase}};
}

std::string refusal(const json& path) {
  try {
    toolpathFromJson(path);
  } catch (const ToolpathFormatError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(MovePhase, EachPhaseIsSpelledAsTheReadmeDocuments) {
  for (const auto& [phase, spelling] : kDocumented) {
    EXPECT_EQ(phaseName(phase), spelling);
    EXPECT_EQ(phaseNamed(spelling), phase) << spelling;
    Move m;
    m.phase = phase;
    EXPECT_EQ(toJson(m)["phase"], spelling);
  }
}

TEST(MovePhase, EveryPhaseSurvivesTheJsonRoundTrip) {
  for (const auto& [phase, spelling] : kDocumented) {
    Move m;
    m.kind = MoveKind::Feed;
    m.to = {-3, 4};
    m.feed = 0.1;
    m.phase = phase;
    m.pass = phase == MovePhase::Pass ? 2 : 0;
    const Move back = moveFromJson(toJson(m), "/moves/0");
    EXPECT_EQ(back.phase, phase) << spelling;
    EXPECT_EQ(back.pass, m.pass) << spelling;
  }
}

TEST(MovePhase, AMoveWithoutAPhaseHasNoPhaseField) {
  Move m;
  EXPECT_EQ(m.phase, MovePhase::None);
  EXPECT_FALSE(toJson(m).contains("phase"));
  json noPhase = moveWithPhase("pass");
  noPhase.erase("phase");
  EXPECT_EQ(moveFromJson(noPhase, "/moves/0").phase, MovePhase::None);
  EXPECT_EQ(moveFromJson(moveWithPhase(nullptr), "/moves/0").phase, MovePhase::None);
  EXPECT_EQ(phaseNamed(""), std::nullopt);
}

TEST(MovePhase, AnUnknownPhaseIsRefusedNamingTheFieldAndTheSpellingsAccepted) {
  for (const std::string bad : {"rough", "Pass", "semi_finish", ""}) {
    const json path = {{"moves", json::array({moveWithPhase("approach"), moveWithPhase(bad)})}};
    const std::string why = refusal(path);
    EXPECT_NE(why.find("/moves/1/phase: expected one of"), std::string::npos) << why;
    for (const auto& [phase, spelling] : kDocumented) {
      EXPECT_NE(why.find("\"" + spelling + "\""), std::string::npos) << spelling << " in: " << why;
    }
    EXPECT_NE(why.find("found \"" + bad + "\""), std::string::npos) << why;
  }
}

TEST(MovePhase, APhaseOfAnotherTypeIsRefusedAsNotAString) {
  const std::string why = refusal({{"moves", json::array({moveWithPhase(3)})}});
  EXPECT_NE(why.find("/moves/0/phase"), std::string::npos) << why;
  EXPECT_NE(why.find("(a string), found 3"), std::string::npos) << why;
}

}  // namespace
}  // namespace cyclecert
