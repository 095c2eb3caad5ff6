// `cyclecert engines`: every line starts with its engine's name, set apart from the description by
// at least two spaces however long the name is (a long mutant name used to run into its
// description: `mutant:shape-feed-in-roughingthe reference…`), and the reference's line names the
// cycles and dialects it plans.
#include <sstream>
#include <string>

#include "harness/engines/engine.h"
#include "tests/cli_fixture.h"

namespace cyclecert {
namespace {

class EnginesListing : public CliFixture {};

TEST_F(EnginesListing, EveryLineStartsWithTheEngineNameAndTwoSpaces) {
  const CliRun r = run("engines");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto engines = listEngines();
  std::istringstream lines(r.out);
  std::string line;
  std::size_t i = 0;
  while (std::getline(lines, line)) {
    ASSERT_LT(i, engines.size()) << "more lines than engines: " << line;
    const std::string& name = engines[i].first;
    std::string firstWord;
    std::istringstream(line) >> firstWord;
    EXPECT_EQ(firstWord, name) << line;
    EXPECT_EQ(line.compare(name.size(), 2, "  "), 0) << "fewer than two spaces after the name: " << line;
    ++i;
  }
  EXPECT_EQ(i, engines.size());
}

TEST(EnginesDescription, TheReferencesLineNamesTheCyclesAndDialectsItPlans) {
  for (const auto& [name, description] : listEngines()) {
    if (name != "reference") continue;
    for (const char* what : {"G70", "G71", "G72", "G73", "FANUC 0i-F", "0i-C", "GSK", "Huazhong", "Haas"}) {
      EXPECT_NE(description.find(what), std::string::npos) << what << " missing from: " << description;
    }
    return;
  }
  FAIL() << "no reference engine listed";
}

}  // namespace
}  // namespace cyclecert
