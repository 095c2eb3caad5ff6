// Issue 19, item 3: the SINUMERIK cycle parameters the reference had planned whatever their value —
// R109 (the infeed angle) and the feeds R111/R112, FF1/FF2/FF3 — are checked: a feed the call cuts
// at must be above 0 (SIEMENS.FEED, alarm 10860), an infeed angle outside 0 ≤ R109 < 90 is not
// planned (LCYC95.PARAMS, interpretation). Before, R109=95 planned a path and R111=0 cut at F0.
#include <gtest/gtest.h>

#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "reference/model/program.h"

namespace cyclecert {
namespace {

// LCYC95 on a two-step shaft (contour R1: X20 Z0, Z-10, X40 Z-20), R105 `type`, the other
// parameters as given (R109 and R111 replaceable).
Toolpath planLcyc95(int type, const std::string& r109, const std::string& r111) {
  const std::string program = "G0 X50 Z2\n_CNAME=\"R1\"\nR105=" + std::to_string(type) + " R106=0 R108=3 R109=" + r109 +
                              "\nR110=1 R111=" + r111 + " R112=0.1\nLCYC95\nM02\n";
  PlanRequest request{program, "shaft.mpf", "sinumerik-802s", {}, {}};
  request.subprograms.push_back({"R1", "G1 X20 Z0\nZ-10\nX40 Z-20\nRET\n", "test#/subprograms/R1"});
  return planWithReference(request);
}

std::string notSupportedMessage(int type, const std::string& r109) {
  try {
    planLcyc95(type, r109, "0.3");
  } catch (const NotSupported& e) {
    return e.what();
  }
  return "(planned)";
}

TEST(SiemensParameterRanges, TheControlPlansWithAnAngleOf7AndAFeedOf03) {
  const Toolpath t = planLcyc95(1, "7", "0.3");
  EXPECT_FALSE(t.alarm.has_value());
  EXPECT_FALSE(t.moves.empty());
}

TEST(SiemensParameterRanges, AnInfeedAngleOf90OrMoreOrBelow0IsNotPlanned) {
  for (const std::string angle : {"90", "95", "-10"}) {
    const std::string message = notSupportedMessage(1, angle);
    EXPECT_NE(message.find("R109 = " + angle), std::string::npos) << angle << ": " << message;
    EXPECT_NE(message.find("0 <= R109 < 90"), std::string::npos) << angle << ": " << message;
  }
  EXPECT_EQ(notSupportedMessage(1, "89.9"), "(planned)");
  EXPECT_EQ(notSupportedMessage(1, "0"), "(planned)");
}

TEST(SiemensParameterRanges, ARoughingFeedOf0OrBelowIsAlarm10860NamingR111) {
  for (const std::string feed : {"0", "-0.3"}) {
    const Toolpath t = planLcyc95(1, "0", feed);
    ASSERT_TRUE(t.alarm.has_value()) << feed;
    EXPECT_EQ(t.alarm->code, "10860") << feed;
    EXPECT_EQ(t.alarm->line, 5) << feed;
    EXPECT_NE(t.alarm->message.find("R111 = " + feed), std::string::npos) << t.alarm->message;
  }
}

TEST(SiemensParameterRanges, AFinishingCallNeedsNoRoughingFeed) {
  // R105 5 finishes only: the seed says R111 has no effect then (LCYC95.PARAMS), so 0 is no alarm.
  const Toolpath t = planLcyc95(5, "0", "0");
  EXPECT_FALSE(t.alarm.has_value()) << t.alarm->message;
  for (const Move& m : t.moves) {
    if (m.kind == MoveKind::Feed) {
      EXPECT_DOUBLE_EQ(m.feed.value_or(0), 0.1);
    }
  }
}

// SIEMENS.LEX (interpretation): a value word, an R value and a cycle argument beyond the bound is
// refused where it is written — file, line, column, the bound. Before, X99999999999 was planned.
struct Refused {
  std::string block;
  int column;
  std::string expected;
};

TEST(SiemensParameterRanges, ValuesBeyondTheBoundAreRefusedWhereTheyAreWritten) {
  const Refused cases[] = {
      {"G1 X99999999999 Z-5 F0.2", 5, "a value of X within -999999.999…999999.999"},
      {"G1 X20 Z-5 F0.2 CR=1234567", 20, "a value of CR= within -999999.999…999999.999"},
      {"R105=123456789", 6, "a value of R105 within -99999999…99999999"},
      {"CYCLE95(\"L1\", 9999999, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)", 15,
       "argument 2 of CYCLE95 within -999999.999…999999.999"},
  };
  for (const Refused& c : cases) {
    PlanRequest request{"G0 X50 Z2\n" + c.block + "\nM02\n", "big.mpf", "sinumerik-802d", {}, {}};
    try {
      planWithReference(request);
      ADD_FAILURE() << c.block << ": planned";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.loc().line, 2) << c.block;
      EXPECT_EQ(e.loc().column, c.column) << c.block;
      EXPECT_EQ(e.expected(), c.expected) << c.block;
    }
  }
  // The bound itself is read.
  PlanRequest edge{"G0 X50 Z2\nG1 X999999.999 Z-5 F0.2\nM02\n", "edge.mpf", "sinumerik-802d", {}, {}};
  EXPECT_NO_THROW(planWithReference(edge));
}

}  // namespace
}  // namespace cyclecert
