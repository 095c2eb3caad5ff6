// Judging an engine's alarm (reference/model/alarms.h): FANUC codes exactly, an engine's own codes
// on whether it alarmed and, when it names one, on the line.
#include <gtest/gtest.h>

#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

Alarm alarmOf(std::string code, int line) { return Alarm{std::move(code), "message", line, ""}; }

TEST(AlarmMatch, FanucCodesAreComparedExactly) {
  EXPECT_TRUE(isFanucAlarmCode("PS0064"));
  EXPECT_FALSE(isFanucAlarmCode("PS064"));
  EXPECT_FALSE(isFanucAlarmCode("LINUXCNC"));
  EXPECT_FALSE(alarmMismatch("PS0064", 3, alarmOf("PS0064", 3)));
  EXPECT_TRUE(alarmMismatch("PS0064", 3, alarmOf("PS0329", 3)));
  EXPECT_TRUE(alarmMismatch("PS0064", 3, alarmOf("PS0064", 4)));
  EXPECT_FALSE(alarmMismatch("PS0064", std::nullopt, alarmOf("PS0064", 4)));
}

TEST(AlarmMatch, ForeignCodesAreJudgedOnTheLineTheyName) {
  EXPECT_FALSE(alarmMismatch("PS0064", 3, alarmOf("LINUXCNC", 3)));
  EXPECT_FALSE(alarmMismatch("PS0064", 3, alarmOf("LINUXCNC", 0)));  // no line named: it alarmed
  const auto wrongLine = alarmMismatch("PS0064", 3, alarmOf("LINUXCNC", 7));
  ASSERT_TRUE(wrongLine);
  EXPECT_NE(wrongLine->find("at line 7"), std::string::npos) << *wrongLine;
}

}  // namespace
}  // namespace cyclecert
