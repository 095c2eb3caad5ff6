// The oracles must judge any engine, the reference included: they may read programs (the G-code
// front end, the interpreter basics, the model) but never include the reference planners, the
// engine runner or the harness. CMake enforces it too: cyclecert_oracles links cyclecert_interp only.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace {

TEST(Architecture, OraclesNeverIncludeThePlanners) {
  const std::regex forbidden(R"(#include\s+"(reference/cycles/|reference/engine/|harness/))");
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(std::string(CYCLECERT_SOURCE_DIR) + "/oracles")) {
    const auto ext = entry.path().extension();
    if (ext != ".h" && ext != ".cpp") continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      EXPECT_FALSE(std::regex_search(line, forbidden)) << entry.path().string() << ":" << n << ": " << line;
    }
  }
  EXPECT_GT(files, 5);
}

}  // namespace
