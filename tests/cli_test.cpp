// The `cyclecert` command as a user and a CI job meet it: help on every command, exit codes,
// outputs written, and clear errors for bad input.
#include <gtest/gtest.h>

#include "tests/cli_fixture.h"
#include <sys/wait.h>
#include <unistd.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

namespace {

namespace fs = std::filesystem;

class Cli : public CliFixture {};

const char* kShaft =
    "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 G00 X20;\nG01 Z-10;\nN20 X40 Z-20;\n";

TEST_F(Cli, HelpOnEveryCommand) {
  for (const std::string args : {"--help", "plan --help", "params --help", "profiles --help", "help plan"}) {
    const CliRun r = run(args);
    EXPECT_EQ(r.exitCode, 0) << args;
    EXPECT_NE(r.out.find("Usage"), std::string::npos) << args;
  }
  EXPECT_NE(run("plan --help").out.find("--param NAME=VALUE"), std::string::npos);
}

TEST_F(Cli, UsageErrorsExitWith2) {
  EXPECT_EQ(run("").exitCode, 2);
  EXPECT_EQ(run("frobnicate").exitCode, 2);
  EXPECT_EQ(run("plan").exitCode, 2);
  EXPECT_EQ(run("plan " + path("missing.nc")).exitCode, 2);
  const std::string program = write("p.nc", kShaft);
  CliRun r = run("plan " + program + " --bogus");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown option --bogus"), std::string::npos);
  r = run("plan " + program + " --profile nosuch");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unknown profile 'nosuch'"), std::string::npos);
  r = run("plan " + program + " --param RF7=1");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("RF7"), std::string::npos);
  r = run("plan " + program + " --param RF1=2");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("0 or 1"), std::string::npos);
}

// --specs takes the suite's folder; a spec case file or a missing folder is named, not a library's
// "recursive directory iterator" message.
TEST_F(Cli, SpecsThatIsNoFolderIsNamed) {
  const std::string file = write("case.json", "{}");
  CliRun r = run("check --engine reference --specs " + file + " --out " + path("out1"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(file + ": a file, not a folder"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("--specs DIR takes the folder holding cases/ and rules.json"), std::string::npos) << r.err;
  r = run("check --engine reference --specs " + path("nowhere") + " --out " + path("out2"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("nowhere/cases: no such directory"), std::string::npos) << r.err;
}

TEST_F(Cli, PlanWritesJsonAndAWellFormedSvg) {
  const std::string program = write("p.nc", kShaft);
  const CliRun r = run("plan " + program + " --json " + path("t.json") + " --svg " + path("t.svg"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("planned 1 cycle(s)"), std::string::npos);
  const auto j = nlohmann::json::parse(read(path("t.json")));
  EXPECT_EQ(j["units"], "mm");
  EXPECT_EQ(j["profile"], "fanuc-0i-f");
  EXPECT_TRUE(j["alarm"].is_null());
  ASSERT_FALSE(j["moves"].empty());
  EXPECT_EQ(j["moves"][0]["kind"], "rapid");
  EXPECT_EQ(j["moves"][0]["to"]["x"], 20.2);  // A' = X40/2 + U0.4/2
  boost::property_tree::ptree tree;
  std::istringstream svg(read(path("t.svg")));
  EXPECT_NO_THROW(boost::property_tree::read_xml(svg, tree));
  EXPECT_EQ(tree.count("svg"), 1u);
}

TEST_F(Cli, JsonGoesToStandardOutputByDefault) {
  const CliRun r = run("plan " + write("p.nc", kShaft));
  ASSERT_EQ(r.exitCode, 0);
  EXPECT_NO_THROW({ const nlohmann::json j = nlohmann::json::parse(r.out); static_cast<void>(j); });
}

TEST_F(Cli, NumberAndMnemonicParametersGiveTheSamePlan) {
  const std::string program = write("p.nc", kShaft);
  const CliRun byNumber = run("plan " + program + " --param 5105#1=1");
  const CliRun byName = run("plan " + program + " --param RF1=1");
  const CliRun neither = run("plan " + program);
  ASSERT_EQ(byNumber.exitCode, 0);
  EXPECT_EQ(byNumber.out, byName.out);
  EXPECT_NE(byNumber.out, neither.out);  // RF1 removes the semi-finish pass
}

TEST_F(Cli, AlarmExitsWith1AndStillWritesTheJson) {
  const std::string program = write("a.nc", "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q20 U0.4 W0.1 F0.2;\nN10 X20;\nN20 G01 X40 Z-20;\n");
  const CliRun r = run("plan " + program + " --json " + path("a.json"));
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.out.find("alarm PS0065 at line 4"), std::string::npos);
  const auto j = nlohmann::json::parse(read(path("a.json")));
  EXPECT_EQ(j["alarm"]["code"], "PS0065");
  EXPECT_EQ(j["alarm"]["line"], 4);
}

TEST_F(Cli, MalformedProgramNamesFileLineAndColumn) {
  const std::string program = write("bad.nc", "G00 X40 Z2;\nG71 U2 R#1;\n");
  const CliRun r = run("plan " + program);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(program + ":2:9: expected an address letter, a number, a comment or the end of the block, found #"), std::string::npos) << r.err;
  const CliRun bad = run("plan " + write("nan.nc", "G00 Xnan Z2;\n"));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find(":1:6: expected a finite number after address X, found nan"), std::string::npos) << bad.err;
}

TEST_F(Cli, NotYetSupportedExitsWith3) {
  const CliRun r = run("plan " + write("g75.nc", "G0 X70 Z2;\nG75 R1;\nG75 X40 Z-20 P3000 Q2000 F0.1;\n"));
  EXPECT_EQ(r.exitCode, 3);
  EXPECT_NE(r.err.find("line 2: G75 outer diameter grooving cycle is not planned by the reference yet"), std::string::npos) << r.err;
}

TEST_F(Cli, PlanACaseReportsWhetherTheExpectationIsMet) {
  const CliRun r = run("plan --case specs/cases/gsk/g72/o0005.json --json " + path("o.json"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("case gsk/g72/o0005: expectation met"), std::string::npos) << r.out;
  const CliRun corrupt = run("plan --case " + write("c.json", "{\"id\": 3"));
  EXPECT_EQ(corrupt.exitCode, 2);
  EXPECT_NE(corrupt.err.find("c.json:1:9: /id: expected valid JSON"), std::string::npos) << corrupt.err;
}

TEST_F(Cli, ToolOffsetAndMdiOptions) {
  const std::string program = write("c.nc", std::string("G42;\n") + kShaft);
  const CliRun plain = run("plan " + program);
  const CliRun offset = run("plan " + program + " --nose-radius 0.4 --tip 3");
  ASSERT_EQ(offset.exitCode, 0) << offset.err;
  EXPECT_NE(plain.out, offset.out);
  EXPECT_NE(plain.err.find("nose radius is 0"), std::string::npos) << plain.err;
  EXPECT_NE(nlohmann::json::parse(offset.out)["cycles"][0]["compensated"], false);
  EXPECT_EQ(run("plan " + program + " --tip 12").exitCode, 2);
  EXPECT_EQ(run("plan " + program + " --tip 2.5").exitCode, 2);
  EXPECT_EQ(run("plan " + program + " --nose-radius -1").exitCode, 2);
  const CliRun mdi = run("plan " + program + " --mdi");
  EXPECT_EQ(mdi.exitCode, 1);
  EXPECT_NE(mdi.err.find("PS0067"), std::string::npos);
}

TEST_F(Cli, RulesCountsTheCasesCitingEachRule) {
  const CliRun all = run("rules --cycle G72");
  ASSERT_EQ(all.exitCode, 0) << all.err;
  EXPECT_NE(all.out.find("G72.EX.O0005"), std::string::npos);
  EXPECT_NE(all.out.find("0 rule(s) cited by no spec case"), std::string::npos) << all.out;
  const auto j = nlohmann::json::parse(run("rules --json --cycle G72").out);
  ASSERT_TRUE(j.is_array());
  EXPECT_GE(j[0]["cases"].get<int>(), 1);
  // A rule marked out of scope (seed 004's threading cycle, which it names without describing) is
  // listed apart with its reason and does not fail --uncited; rules in scope do.
  const CliRun thread = run("rules --uncited --cycle LCYC97");
  EXPECT_EQ(thread.exitCode, 0) << thread.out;
  EXPECT_NE(thread.out.find("SEED004.THREAD"), std::string::npos) << thread.out;
  EXPECT_NE(thread.out.find("out of scope: "), std::string::npos) << thread.out;
  EXPECT_NE(thread.out.find("0 rule(s) cited by no spec case; 1 more out of scope"), std::string::npos) << thread.out;
  EXPECT_EQ(run("rules --uncited --cycle PROGRAM").exitCode, 1);  // PROG.GSYS.HNC and others: in scope
  EXPECT_EQ(run("rules --bogus").exitCode, 2);
}

TEST_F(Cli, ParamsAndProfilesListTheirCatalogues) {
  const CliRun params = run("params");
  EXPECT_EQ(params.exitCode, 0);
  EXPECT_NE(params.out.find("5105#1  RF1"), std::string::npos) << params.out;
  EXPECT_NO_THROW({ const nlohmann::json j = nlohmann::json::parse(run("params --json").out); static_cast<void>(j); });
  const CliRun profiles = run("profiles");
  EXPECT_NE(profiles.out.find("gsk"), std::string::npos);
  EXPECT_NE(profiles.out.find("5108#1 (DTP) = 1"), std::string::npos) << profiles.out;
}

}  // namespace
