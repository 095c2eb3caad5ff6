// MachineParams and profiles: parameters by number or mnemonic, validation, profile defaults.
#include <gtest/gtest.h>

#include <cmath>

#include "reference/model/params.h"
#include "reference/model/profile.h"

namespace cyclecert {
namespace {

TEST(Params, NumberAndMnemonicNameTheSameParameter) {
  MachineParams a, b;
  a.setFromText("5105#1=1");
  b.setFromText("RF1=1");
  EXPECT_EQ(a.get("RF1"), 1);
  EXPECT_EQ(b.get("5105#1"), 1);
  EXPECT_TRUE(a.bit("rf1"));  // mnemonics are case-insensitive
  b.setFromText(" DTP = 1 ");
  EXPECT_TRUE(b.bit("5108#1"));
}

TEST(Params, DefaultsAreTheControllersShippedValues) {
  const MachineParams p;
  for (const char* name : {"5132", "5133", "5145", "5146", "RF1", "DTP"}) EXPECT_EQ(p.get(name), 0) << name;
}

TEST(Params, BadNamesAndValuesAreClearErrors) {
  MachineParams p;
  EXPECT_THROW(p.setFromText("9999=1"), UnknownParam);
  EXPECT_THROW(p.setFromText("RF1"), std::invalid_argument);       // no '='
  EXPECT_THROW(p.setFromText("RF1=2"), std::invalid_argument);     // a bit
  EXPECT_THROW(p.setFromText("5132=-1"), std::invalid_argument);   // a length
  EXPECT_THROW(p.setFromText("5132=abc"), std::invalid_argument);
  EXPECT_THROW(p.setFromText("5132=1x"), std::invalid_argument);
  EXPECT_THROW(p.set("5132", std::nan("")), std::invalid_argument);
  try {
    p.setFromText("RF9=1");
  } catch (const UnknownParam& e) {
    EXPECT_NE(std::string(e.what()).find("RF9"), std::string::npos);
  }
}

TEST(Params, CatalogueCitesRules) {
  for (const ParamSpec& spec : MachineParams::catalogue()) {
    EXPECT_FALSE(spec.rules.empty()) << spec.number;
    EXPECT_FALSE(spec.description.empty()) << spec.number;
  }
}

TEST(Profiles, GskReturnsStraightAndFanucConventionally) {
  ASSERT_NE(findProfile("gsk"), nullptr);
  ASSERT_NE(findProfile("fanuc-0i-f"), nullptr);
  EXPECT_TRUE(findProfile("gsk")->defaults.bit("DTP"));
  EXPECT_FALSE(findProfile("fanuc-0i-f")->defaults.bit("DTP"));
  EXPECT_EQ(findProfile("heidenhain"), nullptr);
}

}  // namespace
}  // namespace cyclecert
