// A spec case that names a profile or a parameter value cyclecert does not know is refused when it
// is read, naming the file, the field (a JSON pointer) and what was expected — not later, by the
// engine, in words that name neither.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

nlohmann::json validCase() {
  return {{"id", "t/x"},          {"title", "t"},       {"profile", "fanuc-0i-f"}, {"program", "G0 X10 Z2\nM30\n"},
          {"derivation", "d"},    {"rules", {"G71.X"}}, {"expect", {{"alarm", "PS0062"}}}};
}

std::string errorOf(const nlohmann::json& j) {
  try {
    specCaseFrom(j, "cases/t.json");
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(SpecCaseErrors, AnUnknownProfileNamesTheFileAndTheField) {
  nlohmann::json j = validCase();
  j["profile"] = "x";
  const std::string e = errorOf(j);
  EXPECT_NE(e.find("cases/t.json: /profile: expected one of"), std::string::npos) << e;
  EXPECT_NE(e.find("fanuc-0i-f"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown profile 'x'"), std::string::npos) << e;
}

TEST(SpecCaseErrors, AParameterOutOfItsRangeNamesTheFileAndTheField) {
  nlohmann::json j = validCase();
  j["params"] = {{"CSB", 2}};
  std::string e = errorOf(j);
  EXPECT_NE(e.find("cases/t.json: /params/CSB: expected"), std::string::npos) << e;
  EXPECT_NE(e.find("is a bit: expected 0 or 1"), std::string::npos) << e;
  j["params"] = {{"RF9", 1}};
  e = errorOf(j);
  EXPECT_NE(e.find("cases/t.json: /params/RF9: expected"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown parameter 'RF9'"), std::string::npos) << e;
}

TEST(SpecCaseErrors, AValidCaseIsRead) {
  nlohmann::json j = validCase();
  j["params"] = {{"RF1", 1}};
  EXPECT_EQ(errorOf(j), "");
}

}  // namespace
}  // namespace cyclecert
