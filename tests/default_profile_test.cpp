// The profile read when none is named is decided once (reference/profiles/default_profile.h) and
// it is FANUC 0i-F (README: "--profile … default fanuc-0i-f"): the helpers say so, and the
// reference, a fuzz case and the fuzzer's profile choice read it.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/fuzz/case_generator.h"
#include "harness/fuzz/named_choices.h"
#include "reference/profiles/default_profile.h"
#include "tests/small_g71_program.h"

namespace cyclecert {
namespace {

TEST(DefaultProfile, IsFanuc0iFAndNamesAKnownProfile) {
  EXPECT_EQ(kDefaultProfileName, "fanuc-0i-f");
  ASSERT_NE(findProfile(kDefaultProfileName), nullptr);
  EXPECT_EQ(&defaultProfile(), findProfile("fanuc-0i-f"));
}

TEST(DefaultProfile, StandsInForAnEmptyNameOnly) {
  EXPECT_EQ(profileNameOrDefault(""), "fanuc-0i-f");
  EXPECT_EQ(profileNameOrDefault("gsk"), "gsk");
  EXPECT_EQ(profileNameOrDefault("no-such-profile"), "no-such-profile");  // the caller reports it
}

TEST(DefaultProfile, TheReferencePlansUnderItWhenNoneIsNamed) {
  const std::string program = std::string("G00 X40 Z2;\n") + kSmallG71Cycle + "M30;\n";
  EXPECT_EQ(planWithReference({program, "program.nc", "", {}, {}}).profile, "fanuc-0i-f");
}

TEST(DefaultProfile, AFuzzCaseStartsWithIt) { EXPECT_EQ(FuzzCase{}.profile, "fanuc-0i-f"); }

// The fuzzer's profile choice 0…9: 0i-F six times in ten, 0i-C two, GSK two.
TEST(FuzzChoices, AProfileChoicePicksByItsShare) {
  for (int choice = 0; choice < 10; ++choice) {
    EXPECT_EQ(profileChosen(choice), choice < 6 ? "fanuc-0i-f" : choice < 8 ? "fanuc-0i-c" : "gsk") << choice;
  }
}

TEST(FuzzChoices, AChoiceNotDrawnReadsAsZero) {
  const std::vector<int> drawn = {7, 3};
  EXPECT_EQ(choiceAt(drawn, 0), 7);
  EXPECT_EQ(choiceAt(drawn, 1), 3);
  EXPECT_EQ(choiceAt(drawn, 2), 0);
}

}  // namespace
}  // namespace cyclecert
