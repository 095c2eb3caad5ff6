// Where a contour subprogram is found (issue 16, item 1; rule SIEMENS.SUB): printed after the main
// program, given with it (a spec case's "subprograms"), or a sibling file NAME.spf / NAME.SPF; a
// missing one is an error naming the three places. And the spec case reader's "subprograms".
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/spec/spec_case.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_parser.h"
#include "reference/siemens/siemens_subprograms.h"

namespace cyclecert {
namespace {

class SiemensSubprogramsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cyclecert-siemens-sub-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  std::filesystem::path dir_;
};

const SiemensProgram kMainOnly = parseSiemensProgram("G0X50Z2\nM02\n", "main.mpf");

TEST_F(SiemensSubprogramsTest, APrintedSubprogramIsFoundByName) {
  const SiemensProgram p = parseSiemensProgram("G0X50Z2\nM02\nL42.spf\nG1X0Z0\nZ-5\nM02\n", "main.mpf");
  SiemensSubprograms subs(p, {}, "");
  const SiemensBlocks& b = subs.find("l42", "main.mpf", 1, 1);  // names compare without case
  ASSERT_EQ(b.blocks.size(), 3u);
  EXPECT_EQ(b.file, "main.mpf");
  EXPECT_EQ(b.blocks[0].line, 4);
}

TEST_F(SiemensSubprogramsTest, AGivenSubprogramIsReadWithItsOwnFileName) {
  SiemensSubprograms subs(kMainOnly, {{"L18", "G1X0Z0\nRET\n", "case.json#/subprograms/L18"}}, "");
  const SiemensBlocks& b = subs.find("L18", "main.mpf", 1, 1);
  EXPECT_EQ(b.file, "case.json#/subprograms/L18");
  EXPECT_EQ(b.blocks.size(), 2u);
}

TEST_F(SiemensSubprogramsTest, ASiblingFileSpfOrSPFIsRead) {
  write("L7.spf", "G1X0Z0\nM17\n");
  write("L8.SPF", "G1X0Z0\nZ-1\nM17\n");
  SiemensSubprograms subs(kMainOnly, {}, dir_.string());
  EXPECT_EQ(subs.find("L7", "main.mpf", 1, 1).blocks.size(), 2u);
  const SiemensBlocks& l8 = subs.find("L8", "main.mpf", 1, 1);
  EXPECT_EQ(l8.blocks.size(), 3u);
  EXPECT_EQ(l8.file, (dir_ / "L8.SPF").string());
}

TEST_F(SiemensSubprogramsTest, AMissingSubprogramNamesTheThreePlaces) {
  SiemensSubprograms subs(kMainOnly, {}, dir_.string());
  try {
    subs.find("L99", "main.mpf", 4, 8);
    FAIL() << "found a subprogram that is nowhere";
  } catch (const ParseError& e) {
    const std::string m = e.what();
    EXPECT_EQ(e.loc().line, 4);
    EXPECT_EQ(e.loc().column, 8);
    EXPECT_NE(m.find("printed after the main program's M02/M30 under a line 'L99.spf'"), std::string::npos) << m;
    EXPECT_NE(m.find("the case's \"subprograms\" object"), std::string::npos) << m;
    EXPECT_NE(m.find("L99.spf or L99.SPF in " + dir_.string()), std::string::npos) << m;
  }
}

TEST(SpecCaseSubprograms, TheReaderKeepsThemAndRefusesANonString) {
  nlohmann::json j = {{"id", "t/x"},       {"title", "t"},          {"profile", "sinumerik-802s"},
                      {"program", "G0X50Z2\n_CNAME=\"L1\"\nR105=1\nLCYC95\nM02\n"},
                      {"derivation", "d"}, {"rules", {"LCYC95.PARAMS"}}, {"expect", {{"alarm", "61002"}}},
                      {"subprograms", {{"L1", "G1X0Z0\nZ-5\nM17\n"}}}};
  const SpecCase c = specCaseFrom(j, "cases/t.json");
  ASSERT_EQ(c.subprograms.size(), 1u);
  EXPECT_EQ(c.subprograms[0].first, "L1");
  EXPECT_EQ(c.subprograms[0].second, "G1X0Z0\nZ-5\nM17\n");
  j["subprograms"]["L1"] = 5;
  try {
    specCaseFrom(j, "cases/t.json");
    FAIL() << "a number as a subprogram's text was accepted";
  } catch (const SpecError& e) {
    EXPECT_NE(std::string(e.what()).find("/subprograms/L1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cyclecert
