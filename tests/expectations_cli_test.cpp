// `check`/`fuzz --expectations`, `--strict` and `cyclecert baseline`, run as CI runs them: a
// mutant's failures baselined and then expected (green), the same run red once an entry is gone,
// an entry whose case passes, malformed files, the report showing expected failures apart — and
// LinuxCNC green with its shipped expectations, red on a failure they do not list.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "harness/engines/linuxcnc/linuxcnc_engine.h"
#include "tests/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A mutant that retracts straight out instead of at 45°: the two stepped cases fail, the alarm
// case passes.
const char* kMutant = "mutant:retract-angle";
const char* kFailing[] = {"fanuc-0i-f/g71/quad-upos-wpos-outer-negz", "fanuc-0i-f/g71/g01-head-stepped-shaft"};
const char* kPassing = "fanuc-0i-f/g71/ps0064-z-reverse";

class ExpectationsCli : public CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    copySpecSuite({kFailing[0], kFailing[1], kPassing});
  }

  CliRun check(const std::string& out, const std::string& extra = "") const {
    return run("check --engine " + std::string(kMutant) + " --specs " + path("specs") + " --no-regressions --out " +
               path(out) + " " + extra);
  }

};

TEST_F(ExpectationsCli, ABaselineOfARunMakesTheSameRunGreen) {
  ASSERT_EQ(check("first").exitCode, 1);
  const CliRun baseline = run("baseline " + path("first"));
  ASSERT_EQ(baseline.exitCode, 0) << baseline.err;
  const json written = json::parse(baseline.out);
  ASSERT_EQ(written["expectations"].size(), 2u) << baseline.out;
  for (const json& entry : written["expectations"]) {
    EXPECT_EQ(entry["outcome"], "fail");
    EXPECT_NE(entry["reason"].get<std::string>().find("retract"), std::string::npos) << entry;
  }
  const std::string file = write("expected.json", baseline.out);

  const CliRun green = check("second", "--expectations " + file);
  EXPECT_EQ(green.exitCode, 0) << green.out << green.err;
  EXPECT_NE(green.out.find("1 pass, 0 fail, 0 not applicable, 0 engine failure(s), 2 expected failure(s)"),
            std::string::npos)
      << green.out;
  for (const json& line : jsonLines(path("second/results.jsonl"))) {
    if (line["verdict"] == "fail") {
      EXPECT_EQ(line["expectation"]["status"], "expected-failure") << line["case"];
      EXPECT_EQ(line["expectation"]["source"], file + ": /expectations/" + (line["case"] == written["expectations"][0]["case"] ? "0" : "1"));
    } else {
      EXPECT_FALSE(line.contains("expectation")) << line["case"];
    }
  }
  // The report shows them apart: a field and counts in report.json, skipped in JUnit, a section in HTML.
  const json report = json::parse(read(path("second/report.json")));
  EXPECT_EQ(report["engines"][0]["expectations"], (json{{"expected_failure", 2}, {"new_failure", 0}, {"unexpected_pass", 0}}));
  if (std::system("python3 -c 'import jsonschema' 2>/dev/null") == 0) {  // the expectation fields are in the schema
    const std::string schema = std::string(CYCLECERT_SOURCE_DIR) + "/specs/schema/";
    EXPECT_EQ(std::system(("python3 " + schema + "validate_report.py " + schema + "report.schema.json " +
                           path("second/report.json") + " >/dev/null")
                              .c_str()),
              0);
  }
  const std::string junit = read(path("second/junit.xml"));
  EXPECT_NE(junit.find("failures=\"0\" errors=\"0\" skipped=\"2\""), std::string::npos) << junit.substr(0, 600);
  EXPECT_NE(junit.find("<skipped message=\"expected failure: expectation, retract"), std::string::npos);
  if (std::system("command -v xmllint >/dev/null 2>&1") == 0) {  // jenkinsci's junit-10.xsd, as tests/junit_test.cpp
    EXPECT_EQ(std::system(("xmllint --noout --schema " + std::string(CYCLECERT_SOURCE_DIR) + "/tests/data/junit/junit-10.xsd " +
                           path("second/junit.xml") + " 2>/dev/null")
                              .c_str()),
              0);
  }
  const std::string html = read(path("second/index.html"));
  EXPECT_NE(html.find("Expected failures \u00b7 2"), std::string::npos);
  EXPECT_NE(html.find("article class=\"failure v-fail v-expected\""), std::string::npos);

  // The text format reads back the same.
  const CliRun text = run("baseline " + path("first") + " --format text");
  ASSERT_EQ(text.exitCode, 0) << text.err;
  EXPECT_EQ(check("third", "--expectations " + write("expected.txt", text.out)).exitCode, 0);
}

TEST_F(ExpectationsCli, AFailureTheFileDoesNotListTurnsTheRunRed) {
  ASSERT_EQ(check("first").exitCode, 1);
  json written = json::parse(run("baseline " + path("first")).out);
  const std::string dropped = written["expectations"][1]["case"];
  written["expectations"].erase(1);
  const CliRun red = check("second", "--expectations " + write("expected.json", written.dump()));
  EXPECT_EQ(red.exitCode, 1);
  EXPECT_NE(red.out.find("1 pass, 1 fail, 0 not applicable, 0 engine failure(s), 1 expected failure(s)"), std::string::npos)
      << red.out;
  EXPECT_NE(red.err.find("fail: " + dropped), std::string::npos) << red.err;
  EXPECT_EQ(red.err.find("fail: " + written["expectations"][0]["case"].get<std::string>()), std::string::npos) << red.err;
  const json report = json::parse(read(path("second/report.json")));
  EXPECT_EQ(report["engines"][0]["expectations"]["new_failure"], 1);
}

TEST_F(ExpectationsCli, AnEntryWhoseCasePassesWarnsAndFailsOnlyWithStrict) {
  ASSERT_EQ(check("first").exitCode, 1);
  const std::string baseline = run("baseline " + path("first") + " --format text").out;
  const std::string file = write("expected.txt", baseline + std::string(kPassing) + " fail # it used to\n");
  const CliRun warned = check("second", "--expectations " + file);
  EXPECT_EQ(warned.exitCode, 0) << warned.out << warned.err;
  EXPECT_NE(warned.err.find("unexpectedly passing: " + std::string(kPassing) + " is pass now; " + file + ":"),
            std::string::npos)
      << warned.err;
  EXPECT_NE(warned.out.find("2 expected failure(s), 1 unexpectedly passing"), std::string::npos) << warned.out;
  EXPECT_EQ(check("third", "--expectations " + file + " --strict").exitCode, 1);
  // An entry for a case that is not in the suite is stale: warned, and red with --strict.
  const std::string stale = write("stale.txt", baseline + "fanuc-0i-f/g71/no-such-case fail # gone\n");
  const CliRun unused = check("fourth", "--expectations " + stale + " --strict");
  EXPECT_EQ(unused.exitCode, 1);
  EXPECT_NE(unused.err.find("stale.txt:4 (case fanuc-0i-f/g71/no-such-case, fail) matched no result"), std::string::npos)
      << unused.err;
  EXPECT_EQ(check("fifth", "--expectations " + write("exact.txt", baseline) + " --strict").exitCode, 0);
}

TEST_F(ExpectationsCli, BadExpectationFilesAndOptionsAreUsageErrors) {
  const CliRun malformed = check("out", "--expectations " + write("bad.txt", "a fail # r\nb maybe # r\n"));
  EXPECT_EQ(malformed.exitCode, 2);
  EXPECT_NE(malformed.err.find("bad.txt:2:3: expected an outcome (fail, engine-failure or not-applicable), got 'maybe'"),
            std::string::npos)
      << malformed.err;
  EXPECT_FALSE(fs::exists(path("out/results.jsonl"))) << "refused before running";
  const CliRun missing = check("out", "--expectations " + path("none.json"));
  EXPECT_EQ(missing.exitCode, 2);
  EXPECT_NE(missing.err.find(path("none.json")), std::string::npos) << missing.err;
  const CliRun strict = check("out", "--strict");
  EXPECT_EQ(strict.exitCode, 2);
  EXPECT_NE(strict.err.find("--strict goes with --expectations FILE"), std::string::npos) << strict.err;
  EXPECT_EQ(run("fuzz --engine reference --strict --cases 1").exitCode, 2);
  const CliRun format = run("baseline " + path("out") + " --format yaml");
  EXPECT_EQ(format.exitCode, 2);
  EXPECT_NE(format.err.find("--format expects json or text, got 'yaml'"), std::string::npos) << format.err;
  const CliRun noResults = run("baseline " + path("nowhere"));
  EXPECT_EQ(noResults.exitCode, 2);
  EXPECT_NE(noResults.err.find("no results in"), std::string::npos) << noResults.err;
  EXPECT_NE(run("baseline --help").out.find("Usage: cyclecert baseline OUT"), std::string::npos);
  EXPECT_NE(run("check --help").out.find("--expectations FILE"), std::string::npos);
  EXPECT_NE(run("fuzz --help").out.find("--expectations FILE"), std::string::npos);
}

TEST_F(ExpectationsCli, FuzzExpectsFailuresByKind) {
  const std::string common = "fuzz --engine mutant:start-not-returned --seed 1 --cases 40 --no-save --shrink-budget 0 ";
  const CliRun plain = run(common + "--out " + path("plain"));
  ASSERT_EQ(plain.exitCode, 1) << plain.out;
  const CliRun expected =
      run(common + "--out " + path("expected") + " --expectations " + write("e.txt", "kind:returns-to-start fail # the mutant's fault\n"));
  EXPECT_EQ(expected.exitCode, 0) << expected.out << expected.err;
  EXPECT_NE(expected.out.find(" 0 fail, "), std::string::npos) << expected.out;
  EXPECT_NE(expected.out.find("expected failure(s)"), std::string::npos) << expected.out;
  EXPECT_EQ(expected.err.find("FAIL returns-to-start"), std::string::npos) << "expected failures are not shrunk and kept";
}

TEST_F(ExpectationsCli, FuzzWarnsOfACaseSeedThatPassesNowAndFailsWithStrict) {
  // Case 0 of seed 1 is case seed 1: the reference passes it.
  const std::string file = write("e.txt", "fuzz-0000000000000001 fail # it failed once\n");
  const std::string command = "fuzz --engine reference --seed 1 --cases 1 --no-save --expectations " + file;
  const CliRun warned = run(command + " --out " + path("a"));
  EXPECT_EQ(warned.exitCode, 0) << warned.out << warned.err;
  EXPECT_NE(warned.err.find("unexpectedly passing: fuzz-0000000000000001 is pass now; " + file + ":1"), std::string::npos)
      << warned.err;
  EXPECT_NE(warned.out.find("1 unexpectedly passing"), std::string::npos) << warned.out;
  EXPECT_EQ(run(command + " --strict --out " + path("b")).exitCode, 1);
}

// ---- LinuxCNC ------------------------------------------------------------------------------------

std::string buildDir() {
  if (const char* dir = std::getenv("CYCLECERT_BUILD_DIR")) return dir;
  return fs::path(CYCLECERT_CLI).parent_path().string();
}

class LinuxCncExpectations : public CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    if (!cyclecert::LinuxCncEngine(buildDir()).available()) {
      GTEST_SKIP() << "rs274 is not in " << buildDir() << "/linuxcnc: run harness/engines/linuxcnc/fetch-rs274.sh "
                   << buildDir() << " (needs Debian's archive)";
    }
  }
  // The shipped file; --timeout 3: the case on which rs274 hangs is an engine failure sooner.
  CliRun check(const std::string& out, const std::string& expectations) const {
    return run("check --engine linuxcnc --timeout 3 --out " + path(out) + " --expectations " + expectations);
  }
  static std::string shipped() { return std::string(CYCLECERT_SOURCE_DIR) + "/harness/engines/linuxcnc/expectations.json"; }
};

TEST_F(LinuxCncExpectations, GreenWithTheShippedExpectations) {
  const CliRun green = check("out", shipped() + " --strict");
  EXPECT_EQ(green.exitCode, 0) << green.out << green.err;
  EXPECT_NE(green.out.find(" 0 fail, "), std::string::npos) << green.out;
  EXPECT_NE(green.out.find(" 0 engine failure(s), "), std::string::npos) << green.out;
}

TEST_F(LinuxCncExpectations, RedOnAFailureTheyDoNotList) {
  json e = json::parse(read(shipped()));
  ASSERT_GT(e["expectations"].size(), 10u);
  // A defect LinuxCNC is known for (the pass deeper than D), as if it were new.
  const std::string seeded = "fanuc-0i-f/g71/fuzz-linuxcnc-69ce2d0991639ccd";
  auto& entries = e["expectations"];
  const auto before = entries.size();
  for (auto it = entries.begin(); it != entries.end();) it = (*it)["case"] == seeded ? entries.erase(it) : it + 1;
  ASSERT_EQ(entries.size(), before - 1);
  const CliRun red = check("out", write("without-one.json", e.dump()));
  EXPECT_EQ(red.exitCode, 1) << red.out;
  EXPECT_NE(red.out.find(" 1 fail, "), std::string::npos) << red.out;
  EXPECT_NE(red.err.find("fail: " + seeded + ": depth-per-pass"), std::string::npos) << red.err;
}

}  // namespace
