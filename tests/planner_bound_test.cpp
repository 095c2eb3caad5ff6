// Issue 13, defect 6: the planner is bounded before it plans (PROG.CAP): passes from depth / Δd,
// moves from passes × the shape, with a clear error naming the count — never gigabytes and
// minutes for a Δd of 0.001 over a deep profile.
#include <gtest/gtest.h>

#include <chrono>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

std::string notSupportedMessage(const std::string& program) {
  try {
    planWithReference({program, "cap.nc", "fanuc-0i-f", {}, {}});
  } catch (const NotSupported& e) {
    return e.what();
  }
  return "(no NotSupported)";
}

TEST(PlannerBound, TooManyTypeIPassesAreRefusedWithTheCount) {
  // 20 mm deep (radius) with Δd 0.001: 20,000 passes, twice the cap.
  const std::string why = notSupportedMessage(
      "G00 X42 Z2;\nG71 U0.001 R0.0005;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2;\nN20 G01 Z-10;\n");
  EXPECT_NE(why.find("line 3"), std::string::npos) << why;
  EXPECT_NE(why.find("G71 would make 20,000 roughing passes"), std::string::npos) << why;
  EXPECT_NE(why.find("at most 10,000"), std::string::npos) << why;
}

TEST(PlannerBound, TheIssuesProgramIsRefusedAtOnce) {
  // Δd 0.001 over a 500 mm deep profile: 500,000 passes (was 2 million moves, 4.5 GB, 106 s).
  const auto begin = std::chrono::steady_clock::now();
  const std::string why = notSupportedMessage(
      "G00 X1002 Z2;\nG72 W0.001 R0.0005;\nG72 P10 Q20 U0 W0 F0.2;\nN10 G00 Z-498;\nN20 G01 X2;\n");
  EXPECT_NE(why.find("G72 would make 500,000 roughing passes"), std::string::npos) << why;
  EXPECT_LT(std::chrono::steady_clock::now() - begin, std::chrono::seconds(5));
}

TEST(PlannerBound, TypeIIIsBoundedByPassesTimesSegments) {
  // Type II (W0 in block ns), 9,000 passes: under the pass cap; 40 segments make it 432,000 moves
  // at most, over the move cap.
  std::string program = "G00 X40 Z2;\nG71 U0.001 R0.0005;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X22 W0;\n";
  for (int i = 1; i < 40; ++i) program += "G01 Z-" + std::to_string(i) + ";\n";
  program += "N20 G01 X40 Z-50;\n";
  const std::string why = notSupportedMessage(program);
  EXPECT_NE(why.find("G71 would make up to"), std::string::npos) << why;
  EXPECT_NE(why.find("at most 250,000 per cycle"), std::string::npos) << why;
}

TEST(PlannerBound, RealProgramsAreWellWithinTheCaps) {
  // 200 passes of 0.1 mm: planned.
  const Toolpath t = planWithReference(
      {"G00 X42 Z2;\nG71 U0.1 R0.05;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2;\nN20 G01 Z-10;\n", "cap.nc", "fanuc-0i-f", {}, {}});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_GT(t.moves.size(), 600u);
}

}  // namespace
}  // namespace cyclecert
