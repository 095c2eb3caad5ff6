// `cyclecert report` and the report files `check` and `fuzz` leave: real failures of a mutant with
// their plots and reproduce commands, run.json (a record per run, --resume, merge), a killed run's
// torn last line, and clear errors for a directory without results.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "tests/cli_fixture.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// A mutant that retracts straight out instead of at 45°: the stepped cases fail, the alarm case passes.
const char* kMutant = "mutant:retract-angle";
const char* kCases[] = {"fanuc-0i-f/g71/quad-upos-wpos-outer-negz", "fanuc-0i-f/g71/g01-head-stepped-shaft",
                        "fanuc-0i-f/g71/ps0064-z-reverse"};

class ReportCli : public CliFixture {
 protected:
  void SetUp() override {
    CliFixture::SetUp();
    copySpecSuite({std::begin(kCases), std::end(kCases)});
  }

  CliRun check(const std::string& out, const std::string& extra = "") const {
    return run("check --engine " + std::string(kMutant) + " --specs " + path("specs") + " --no-regressions --out " + path(out) +
               " " + extra);
  }

};

TEST_F(ReportCli, ACheckRunLeavesItsReportWithPlotsOfTheFailures) {
  const CliRun r = check("out");
  ASSERT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.out.find("report of 3 result(s): 3 cases: "), std::string::npos) << r.out;
  int failures = 0;
  for (const json& line : jsonLines(path("out/results.jsonl"))) {
    if (line["verdict"] != "fail") {
      EXPECT_FALSE(line.contains("plot")) << line["case"];
      continue;
    }
    ++failures;
    ASSERT_TRUE(line.contains("plot")) << line["case"];
    const json& plot = line["plot"];
    EXPECT_EQ(plot["path_label"], kMutant);
    EXPECT_EQ(plot["overlay_label"], "expected");  // the case's hand-derived toolpath
    EXPECT_FALSE(plot["finish"].empty());
    EXPECT_FALSE(plot["stock"].empty());
    bool divergenceMarked = false;
    for (const json& h : plot["highlights"]) {
      const std::string label = h["label"];
      divergenceMarked |= h["label_shown"] == true && label.rfind("first divergence: move ", 0) == 0;
    }
    EXPECT_TRUE(divergenceMarked) << plot["highlights"].dump();
    EXPECT_EQ(line["reproduce"].get<std::string>().rfind("cyclecert diff --engine 'mutant:retract-angle' --vs 'reference' '", 0), 0u)
        << line["reproduce"];
  }
  EXPECT_GE(failures, 1);

  const json report = json::parse(read(path("out/report.json")));
  EXPECT_EQ(report["format"], "cyclecert-report/1");
  ASSERT_EQ(report["engines"].size(), 1u);
  const json& engine = report["engines"][0];
  EXPECT_EQ(engine["name"], kMutant);
  EXPECT_EQ(engine["version"], kMutant);
  EXPECT_EQ(engine["totals"]["cases"], 3);
  EXPECT_EQ(engine["totals"]["fail"], failures);
  EXPECT_FALSE(report["certification"]["nonconforming_rules"].empty());
  EXPECT_TRUE(std::regex_match(report["certification"]["git_revision"].get<std::string>(),
                               std::regex("[0-9a-f]{40}(\\+dirty)?|unknown")));
  EXPECT_TRUE(std::regex_match(report["certification"]["spec_suite_hash"].get<std::string>(), std::regex("[0-9a-f]{64}")));
  int plotted = 0;
  for (const json& c : engine["cases"]) plotted += c.contains("plot");
  EXPECT_EQ(plotted, failures);
  EXPECT_NE(read(path("out/junit.xml")).find("<testsuite name=\"mutant:retract-angle\" tests=\"3\""), std::string::npos);
  EXPECT_NE(read(path("out/index.html")).find("mutant:retract-angle"), std::string::npos);
  EXPECT_NE(r.out.find(path("out/index.html")), std::string::npos);

  // `report` regenerates the same document from the same files.
  const CliRun again = run("report " + path("out") + " --specs " + path("specs"));
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(json::parse(read(path("out/report.json"))), report);
}

TEST_F(ReportCli, TheReproduceCommandOfAFailingCaseShowsTheFailure) {
  ASSERT_EQ(check("out").exitCode, 1);
  std::string reproduce;
  for (const json& line : jsonLines(path("out/results.jsonl"))) {
    if (line["verdict"] == "fail") reproduce = line["reproduce"];
  }
  ASSERT_EQ(reproduce.rfind("cyclecert ", 0), 0u) << reproduce;
  const CliRun r = run(reproduce.substr(std::string("cyclecert ").size()));
  EXPECT_EQ(r.exitCode, 1) << r.err;  // the engines diverge
  EXPECT_NE(r.out.find("first divergence: move "), std::string::npos) << r.out;
}

TEST_F(ReportCli, EngineFailuresCarryAReproduceCommandAndAreErrorsInJunit) {
  const std::string engine = "process:sh " + std::string(CYCLECERT_SOURCE_DIR) + "/tests/data/engines/garbage.sh";
  const CliRun r = run("check --engine '" + engine + "' --specs " + path("specs") + " --no-regressions --out " + path("out"));
  ASSERT_EQ(r.exitCode, 1) << r.err;
  for (const json& line : jsonLines(path("out/results.jsonl"))) {
    EXPECT_EQ(line["verdict"], "engine-failure");
    EXPECT_FALSE(line.contains("plot"));  // there is no toolpath to draw
    EXPECT_EQ(line["reproduce"].get<std::string>().rfind("cyclecert diff --engine '" + engine + "' --vs 'reference' '", 0), 0u);
  }
  const json report = json::parse(read(path("out/report.json")));
  EXPECT_EQ(report["engines"][0]["totals"]["engine_failure"], 3);
  EXPECT_NE(read(path("out/junit.xml")).find("errors=\"3\""), std::string::npos);
}

TEST_F(ReportCli, RunJsonHasARecordPerRunResumeAppendsAndMergeJoins) {
  ASSERT_EQ(check("a").exitCode, 1);
  json runs = json::parse(read(path("a/run.json")))["runs"];
  ASSERT_EQ(runs.size(), 1u);
  const json& record = runs[0];
  EXPECT_EQ(record["command"], "check");
  EXPECT_EQ(record["engine"], kMutant);
  EXPECT_EQ(record["engine_version"], kMutant);
  EXPECT_FALSE(record.contains("vs"));
  EXPECT_FALSE(record.contains("seed"));
  EXPECT_TRUE(std::regex_match(record["started"].get<std::string>(), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  EXPECT_EQ(record["argv"][0], "cyclecert");
  EXPECT_EQ(record["argv"][1], "check");
  EXPECT_EQ(record["argv"][3], kMutant);

  ASSERT_EQ(check("a", "--resume").exitCode, 0);  // nothing left to run: every case is there
  runs = json::parse(read(path("a/run.json")))["runs"];
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1]["argv"].back(), "--resume");

  ASSERT_EQ(check("b").exitCode, 1);
  EXPECT_EQ(json::parse(read(path("b/run.json")))["runs"].size(), 1u);  // a fresh run starts the file again
  const CliRun merged = run("merge --out " + path("m") + " " + path("a") + " " + path("b"));
  ASSERT_EQ(merged.exitCode, 0) << merged.err;
  EXPECT_EQ(json::parse(read(path("m/run.json")))["runs"].size(), 3u);
  const CliRun report = run("report " + path("m") + " --specs " + path("specs"));
  ASSERT_EQ(report.exitCode, 0) << report.err;
  EXPECT_EQ(json::parse(read(path("m/report.json")))["engines"][0]["totals"]["cases"], 3);
}

TEST_F(ReportCli, AKilledRunsTornLastLineIsSkippedAndNamed) {
  ASSERT_EQ(check("out").exitCode, 1);
  std::ofstream(path("out/results.jsonl"), std::ios::app) << R"({"engine": "mutant:retract-angle", "case": "fanu)";
  const CliRun r = run("report " + path("out") + " --specs " + path("specs"));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find(path("out/results.jsonl") + ":4: skipped"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("report of 3 result(s) (1 line(s) skipped)"), std::string::npos) << r.out;
  EXPECT_EQ(json::parse(read(path("out/report.json")))["certification"]["totals"]["cases"], 3);
}

TEST_F(ReportCli, WithoutResultsOrWithABrokenRunJsonItIsAClearError) {
  fs::create_directories(path("empty"));
  CliRun r = run("report " + path("empty"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(path("empty") + "/results.jsonl does not exist"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(path("empty/report.json")));
  EXPECT_EQ(run("report").exitCode, 2);
  EXPECT_EQ(run("report " + path("a") + " " + path("b")).exitCode, 2);
  EXPECT_EQ(run("report --frobnicate " + path("a")).exitCode, 2);

  ASSERT_EQ(check("out").exitCode, 1);
  write("out/run.json", "{\"runs\": [");
  r = run("report " + path("out") + " --specs " + path("specs"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("run.json: not JSON"), std::string::npos) << r.err;

  fs::remove(path("out/run.json"));  // results alone still make a report, with unknown versions
  r = run("report " + path("out") + " --specs " + path("specs"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(json::parse(read(path("out/report.json")))["certification"]["git_revision"], "unknown");
}

TEST_F(ReportCli, HelpNamesTheFiles) {
  const CliRun r = run("report --help");
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("Usage: cyclecert report OUT"), std::string::npos);
  EXPECT_NE(r.out.find("junit.xml"), std::string::npos);
  EXPECT_NE(run("--help").out.find("report "), std::string::npos);
}

TEST_F(ReportCli, FuzzKeepsThePlotOfEachShrunkFailureAndAReproduceForEveryFailure) {
  const CliRun r = run("fuzz --engine mutant:start-not-returned --seed 7 --cases 40 --shrink-budget 20 --no-save --out " +
                       path("out"));
  ASSERT_EQ(r.exitCode, 1) << r.err;
  int failures = 0, plots = 0;
  for (const json& line : jsonLines(path("out/results.jsonl"))) {
    if (line["verdict"] == "pass" || line["verdict"] == "not-applicable") {
      EXPECT_FALSE(line.contains("reproduce"));
      continue;
    }
    ++failures;
    const std::string seed = std::to_string(line["seed"].get<std::uint64_t>());
    EXPECT_EQ(line["reproduce"], "cyclecert fuzz --engine 'mutant:start-not-returned' --seed " + seed + " --cases 1");
    if (!line.contains("plot")) continue;
    ++plots;
    EXPECT_TRUE(line.contains("program"));  // the shrunk case's, which the plot draws
    EXPECT_NE(line["plot"]["title"].get<std::string>().find("fuzz-"), std::string::npos);
    EXPECT_FALSE(line["plot"]["highlights"].empty());  // the finding's witness
  }
  EXPECT_GE(failures, 2);
  EXPECT_GE(plots, 1);
  EXPECT_LT(plots, failures);  // only the first failure of each kind is shrunk and drawn
  EXPECT_NE(r.out.find("report of 40 result(s): fuzz 40 cases: "), std::string::npos) << r.out;
  const json report = json::parse(read(path("out/report.json")));
  const json& fuzz = report["engines"][0]["fuzz"];
  EXPECT_EQ(fuzz["cases"], 40);
  EXPECT_EQ(fuzz["fail"], failures);
  EXPECT_EQ(fuzz["seeds"], json({7}));
  EXPECT_EQ(report["engines"][0]["cases"].size(), static_cast<std::size_t>(40 - fuzz["pass"].get<int>()));
  EXPECT_EQ(json::parse(read(path("out/run.json")))["runs"][0]["seed"], 7);
}

}  // namespace
