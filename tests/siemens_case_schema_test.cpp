// specs/schema/case.schema.json takes a SINUMERIK case (issue 16, item 1; rule SIEMENS.SUB): the
// profiles sinumerik-802s/802d, a "subprograms" object of name → text, a five-digit SINUMERIK
// alarm number; and refuses a subprogram whose text is not a string.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace cyclecert {
namespace {

class SiemensCaseSchema : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("python3 -c 'import jsonschema' 2>/dev/null") != 0) GTEST_SKIP() << "python3-jsonschema is not installed";
    dir_ = std::filesystem::temp_directory_path() / ("cyclecert-siemens-schema-" + std::to_string(::getpid()) + "-" +
                                                     ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_ / "sinumerik-802s" / "lcyc95");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The validator's exit code and output for one case with this "subprograms" value.
  std::pair<int, std::string> validate(const std::string& subprograms) const {
    std::ofstream(dir_ / "sinumerik-802s" / "lcyc95" / "r105.json")
        << R"({"id": "sinumerik-802s/lcyc95/r105", "title": "R105 outside 1…12", "profile": "sinumerik-802s",)"
        << R"( "rules": ["SIEMENS.VARI"], "program": "G0X50Z2\n_CNAME=\"L1\"\nR105=13\nLCYC95\nM02\n",)"
        << R"( "subprograms": )" << subprograms << ","
        << R"( "expect": {"alarm": {"code": "61002", "line": 4}}, "derivation": "R105 = 13 is outside 1…12: alarm 61002 at the call."})";
    const std::string out = (dir_ / "out.txt").string();
    const std::string source = CYCLECERT_SOURCE_DIR;
    const std::string command = "python3 " + source + "/specs/schema/validate_cases.py " + source +
                                "/specs/schema/case.schema.json " + dir_.string() + " >" + out + " 2>&1";
    const int status = std::system(command.c_str());
    std::ifstream in(out);
    std::ostringstream text;
    text << in.rdbuf();
    return {WEXITSTATUS(status), text.str()};
  }

  std::filesystem::path dir_;
};

TEST_F(SiemensCaseSchema, ACaseWithSubprogramsValidates) {
  const auto [code, output] = validate(R"({"L1": "G1X0Z0\nZ-5\nM17\n"})");
  EXPECT_EQ(code, 0) << output;
}

TEST_F(SiemensCaseSchema, ASubprogramThatIsNotTextIsRefused) {
  const auto [code, output] = validate(R"({"L1": 5})");
  EXPECT_NE(code, 0) << output;
  EXPECT_NE(output.find("/subprograms/L1"), std::string::npos) << output;
}

}  // namespace
}  // namespace cyclecert
