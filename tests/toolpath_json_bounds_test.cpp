// The toolpath JSON reader bounds what an engine may hand the oracles (issue 13, defects 6 and 8):
// more moves than any plan holds, or a coordinate beyond any machine's travel, is refused at its
// JSON path before the oracles' geometry meets it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "reference/model/toolpath_json.h"

namespace cyclecert {
namespace {

using nlohmann::json;

std::string refusal(const json& j) {
  try {
    toolpathFromJson(j);
  } catch (const ToolpathFormatError& e) {
    return e.what();
  }
  return "(accepted)";
}

json oneMove(double x, double z) {
  return {{"moves", json::array({{{"kind", "rapid"}, {"to", {{"x", x}, {"z", z}}}}})}};
}

TEST(ToolpathJsonBounds, MoreMovesThanAnyPlanHoldsAreRefusedBeforeTheyAreRead) {
  json j = {{"moves", json::array()}};
  j["moves"].get_ref<json::array_t&>().resize(kMostMovesPerToolpath + 1);  // nulls: never read
  const std::string why = refusal(j);
  EXPECT_NE(why.find("/moves: expected at most 1000000 moves"), std::string::npos) << why;
  EXPECT_NE(why.find("found 1000001"), std::string::npos) << why;
}

TEST(ToolpathJsonBounds, ACoordinateBeyondAnyMachinesTravelIsRefusedAtItsPath) {
  EXPECT_EQ(refusal(oneMove(9'999'999, -9'999'999)), "(accepted)");
  const std::string why = refusal(oneMove(1e15, 0));
  EXPECT_NE(why.find("/moves/0/to/x: expected a coordinate within ±10,000,000 mm"), std::string::npos) << why;
}

}  // namespace
}  // namespace cyclecert
