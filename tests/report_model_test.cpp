// report.json from hand-made results lines (reports/model): each case of a rule's verdict, the fuzz
// campaign's counts, a later line replacing an earlier one, the certification summary, and lines
// that are not results.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "reports/model/report_model.h"
#include "reports/svg/plot_json.h"

namespace cyclecert {
namespace {

using nlohmann::json;

const std::vector<ReportRule> kCatalogue = {
    {"G71.A", "G71", "001", "4.1", "rule A"}, {"G71.B", "G71", "001", "4.2", "rule B"},
    {"G71.C", "G71", "001", "4.3", "rule C"}, {"G71.D", "G71", "001", "4.4", "rule D"}};

json line(const std::string& engine, const std::string& id, const std::string& verdict, std::vector<std::string> rules,
          json findings = json::array()) {
  return {{"engine", engine}, {"case", id},          {"file", "specs/cases/" + id + ".json"},
          {"rules", rules},   {"verdict", verdict},   {"detail", verdict + " detail"},
          {"findings", findings}, {"seconds", 0.25}, {"seed", nullptr}};
}

json finding(const std::string& oracle, std::vector<std::string> rules) {
  return {{"oracle", oracle}, {"rules", rules}, {"move", 3}, {"message", oracle + " message"}, {"witness", json::object()}};
}

json fuzzLine(const std::string& engine, std::uint64_t seed, const std::string& verdict) {
  json l = line(engine, "fuzz-" + std::to_string(seed), verdict, {"G71.A"});
  l["file"] = "";
  l["seed"] = seed;
  return l;
}

const json& engineOf(const json& report, const std::string& name) {
  for (const json& e : report["engines"]) {
    if (e["name"] == name) return e;
  }
  ADD_FAILURE() << "no engine " << name << " in the report";
  static const json none = json::object();
  return none;
}

const json& ruleOf(const json& engine, const std::string& id) {
  for (const json& r : engine["rules"]) {
    if (r["id"] == id) return r;
  }
  ADD_FAILURE() << "no rule " << id;
  static const json none = json::object();
  return none;
}

std::string verdictOf(const json& report, const std::string& engine, const std::string& rule) {
  return ruleOf(engineOf(report, engine), rule).value("verdict", "");
}

TEST(ReportModel, AFindingFailsTheRulesItNamesAndTheCaseStillPassesTheOthers) {
  const json report = buildReport({line("e", "p/g71/a", "fail", {"G71.A", "G71.B"}, json::array({finding("retract", {"G71.B"})}))}, {},
                                  kCatalogue);
  EXPECT_EQ(verdictOf(report, "e", "G71.B"), "fail");
  EXPECT_EQ(ruleOf(engineOf(report, "e"), "G71.B")["failing"], json({"p/g71/a"}));
  EXPECT_EQ(verdictOf(report, "e", "G71.A"), "pass");
  EXPECT_EQ(ruleOf(engineOf(report, "e"), "G71.A")["cases"], json({"p/g71/a"}));
}

TEST(ReportModel, AnUnmetExpectationFailsEveryRuleTheCaseCites) {
  const json report = buildReport({line("e", "p/g71/a", "fail", {"G71.A", "G71.B"})}, {}, kCatalogue);
  EXPECT_EQ(verdictOf(report, "e", "G71.A"), "fail");
  EXPECT_EQ(verdictOf(report, "e", "G71.B"), "fail");
  EXPECT_EQ(verdictOf(report, "e", "G71.C"), "untested");
}

TEST(ReportModel, AFindingsRuleTheCaseDoesNotCiteFailsToo) {
  const json report = buildReport({line("e", "p/g71/a", "fail", {"G71.A"}, json::array({finding("feeds", {"G71.D"})}))}, {}, kCatalogue);
  const json& d = ruleOf(engineOf(report, "e"), "G71.D");
  EXPECT_EQ(d["verdict"], "fail");
  EXPECT_EQ(d["failing"], json({"p/g71/a"}));
  EXPECT_EQ(d["cases"], json::array());  // it cites A only
}

TEST(ReportModel, RuleVerdictsRankFailThenEngineFailureThenPassThenNotApplicable) {
  const json report = buildReport({line("e", "p/g71/fails-a", "fail", {"G71.A"}),
                                   line("e", "p/g71/crash-ab", "engine-failure", {"G71.A", "G71.B"}),
                                   line("e", "p/g71/pass-bc", "pass", {"G71.B", "G71.C"}),
                                   line("e", "p/g71/na-cd", "not-applicable", {"G71.C", "G71.D"})},
                                  {}, kCatalogue);
  EXPECT_EQ(verdictOf(report, "e", "G71.A"), "fail");            // over an engine failure
  EXPECT_EQ(verdictOf(report, "e", "G71.B"), "engine-failure");  // over a pass
  EXPECT_EQ(verdictOf(report, "e", "G71.C"), "pass");            // over not applicable
  EXPECT_EQ(verdictOf(report, "e", "G71.D"), "not-applicable");  // every case citing it was
  EXPECT_EQ(ruleOf(engineOf(report, "e"), "G71.B")["cases"], json({"p/g71/crash-ab", "p/g71/pass-bc"}));
}

TEST(ReportModel, EveryCatalogueRuleIsReportedAndAnUnknownCitedOneAfterThem) {
  const json report = buildReport({line("e", "p/g71/a", "pass", {"G71.A", "G99.NEW"})}, {}, kCatalogue);
  ASSERT_EQ(report["rules"].size(), 5u);
  EXPECT_EQ(report["rules"][0]["summary"], "rule A");
  EXPECT_EQ(report["rules"][4]["id"], "G99.NEW");
  EXPECT_EQ(report["rules"][4]["summary"], "not in specs/rules.json");
  EXPECT_EQ(engineOf(report, "e")["rules"].size(), 5u);
  EXPECT_EQ(verdictOf(report, "e", "G99.NEW"), "pass");
  EXPECT_EQ(verdictOf(report, "e", "G71.B"), "untested");
}

TEST(ReportModel, FuzzPassesAreCountedNotListed) {
  std::vector<json> lines;
  for (std::uint64_t seed = 1; seed <= 1000; ++seed) lines.push_back(fuzzLine("e", seed, seed % 100 == 0 ? "fail" : "pass"));
  lines.push_back(fuzzLine("e", 5000, "not-applicable"));
  lines.push_back(fuzzLine("e", 5001, "engine-failure"));
  lines.push_back(line("e", "p/g71/a", "pass", {"G71.A"}));
  const json runs = {{{"command", "fuzz"}, {"engine", "e"}, {"seed", 77}, {"started", "2025-01-01T00:00:00Z"}},
                     {{"command", "fuzz"}, {"engine", "e"}, {"seed", 78}, {"started", "2025-01-02T00:00:00Z"}},
                     {{"command", "check"}, {"engine", "e"}, {"started", "2025-01-03T00:00:00Z"}}};
  const json report = buildReport(lines, runs.get<std::vector<json>>(), kCatalogue);
  const json& e = engineOf(report, "e");
  EXPECT_EQ(e["fuzz"], json({{"cases", 1002}, {"pass", 990}, {"fail", 10}, {"not_applicable", 1}, {"engine_failure", 1},
                             {"seeds", {77, 78}}}));
  EXPECT_EQ(e["totals"], json({{"cases", 1}, {"pass", 1}, {"fail", 0}, {"not_applicable", 0}, {"engine_failure", 0}}));
  ASSERT_EQ(e["cases"].size(), 13u);  // the spec case and the twelve generated cases that did not pass
  for (const json& c : e["cases"]) {
    if (c["kind"] != "fuzz") continue;
    EXPECT_NE(c["verdict"], "pass");
    EXPECT_TRUE(c.contains("seed"));
  }
  EXPECT_EQ(ruleOf(e, "G71.A")["failing"].size(), 10u);
}

TEST(ReportModel, ALaterLineForTheSameCaseReplacesTheEarlierOne) {
  const json report = buildReport({line("e", "p/g71/a", "fail", {"G71.A"}), line("e", "p/g71/b", "pass", {"G71.B"}),
                                   line("e", "p/g71/a", "pass", {"G71.A"}), fuzzLine("e", 9, "fail"), fuzzLine("e", 9, "pass"),
                                   fuzzLine("e", 10, "pass"), fuzzLine("e", 10, "engine-failure"),
                                   line("other", "p/g71/a", "fail", {"G71.A"})},
                                  {}, kCatalogue);
  const json& e = engineOf(report, "e");
  EXPECT_EQ(e["totals"]["cases"], 2);
  EXPECT_EQ(e["totals"]["fail"], 0);
  // The replaced failures (p/g71/a, fuzz 9) no longer fail G71.A; fuzz 10's engine failure now counts.
  EXPECT_EQ(ruleOf(e, "G71.A")["failing"], json::array());
  EXPECT_EQ(verdictOf(report, "e", "G71.A"), "engine-failure");
  EXPECT_EQ(e["fuzz"]["cases"], 2);
  EXPECT_EQ(e["fuzz"]["pass"], 1);
  EXPECT_EQ(e["fuzz"]["engine_failure"], 1);
  ASSERT_EQ(e["cases"].size(), 3u);
  EXPECT_EQ(e["cases"][0]["id"], "p/g71/a");  // in the place of its first line
  EXPECT_EQ(e["cases"][2]["verdict"], "engine-failure");
  EXPECT_EQ(verdictOf(report, "other", "G71.A"), "fail");  // another engine's result is its own
}

TEST(ReportModel, CertificationSumsTheEnginesAndNamesTheLatestRun) {
  const json runs = {{{"command", "check"}, {"engine", "a"}, {"engine_version", "a 1.0"}, {"cyclecert_version", "0.1.0"},
                      {"git_revision", "old"}, {"spec_suite_hash", "h1"}, {"started", "2025-03-01T10:00:00Z"}},
                     {{"command", "check"}, {"engine", "b"}, {"engine_version", "b 2.0"}, {"cyclecert_version", "0.1.1"},
                      {"git_revision", "new"}, {"spec_suite_hash", "h2"}, {"started", "2025-03-02T10:00:00Z"}},
                     {{"command", "check"}, {"engine", "idle"}, {"engine_version", "i"}, {"started", "2025-02-01T10:00:00Z"}}};
  const json report = buildReport({line("a", "p/g71/x", "fail", {"G71.A"}), line("a", "p/g71/y", "pass", {"G71.B"}),
                                   line("b", "p/g71/x", "fail", {"G71.A"}), line("b", "p/g71/y", "not-applicable", {"G71.B"}),
                                   line("b", "p/g71/z", "engine-failure", {"G71.C"})},
                                  runs.get<std::vector<json>>(), kCatalogue);
  const json& c = report["certification"];
  EXPECT_EQ(report["format"], "cyclecert-report/1");
  EXPECT_EQ(c["totals"], json({{"cases", 5}, {"pass", 1}, {"fail", 2}, {"not_applicable", 1}, {"engine_failure", 1}}));
  EXPECT_EQ(c["git_revision"], "new");
  EXPECT_EQ(c["cyclecert_version"], "0.1.1");
  EXPECT_EQ(c["spec_suite_hash"], "h2");
  EXPECT_EQ(c["date"], "2025-03-02T10:00:00Z");
  EXPECT_EQ(c["engines"], json({{{"name", "a"}, {"version", "a 1.0"}},
                                {{"name", "b"}, {"version", "b 2.0"}},
                                {{"name", "idle"}, {"version", "i"}}}));  // a run without results is still named
  EXPECT_EQ(c["nonconforming_rules"], json({{{"rule", "G71.A"}, {"engines", {"a", "b"}}}}));
}

TEST(ReportModel, WithoutRunRecordsVersionsAreUnknown) {
  const json report = buildReport({line("e", "p/g71/a", "pass", {"G71.A"})}, {}, kCatalogue);
  EXPECT_EQ(report["certification"]["git_revision"], "unknown");
  EXPECT_TRUE(report["certification"]["date"].is_null());
  EXPECT_EQ(engineOf(report, "e")["version"], "unknown");
}

TEST(ReportModel, CaseKinds) {
  EXPECT_EQ(caseKind(line("e", "fanuc-0i-f/g71/a", "pass", {})), "spec");
  json kept = line("e", "fanuc-0i-f/g71/fuzz-linuxcnc-0123", "pass", {});
  EXPECT_EQ(caseKind(kept), "regression");
  json inRegressions = line("e", "fanuc-0i-f/g71/hand-made", "pass", {});
  inRegressions["file"] = "/src/corpus/regressions/fanuc-0i-f/g71/hand-made.json";
  EXPECT_EQ(caseKind(inRegressions), "regression");
  EXPECT_EQ(caseKind(fuzzLine("e", 3, "fail")), "fuzz");
}

TEST(ReportModel, AReportCaseKeepsWhatAPersonNeedsAndDropsTheWitness) {
  json l = fuzzLine("e", 42, "fail");
  l["findings"] = json::array({finding("retract", {"G71.B"})});
  l["program"] = "G00 X8 Z0;\n";
  l["reproduce"] = "cyclecert fuzz --engine 'e' --seed 42 --cases 1";
  const json report = buildReport({l}, {}, kCatalogue);
  const json& c = engineOf(report, "e")["cases"][0];
  EXPECT_EQ(c["seed"], 42);
  EXPECT_EQ(c["program"], "G00 X8 Z0;\n");
  EXPECT_EQ(c["reproduce"], l["reproduce"]);
  EXPECT_EQ(c["findings"], json({{{"oracle", "retract"}, {"rules", {"G71.B"}}, {"move", 3}, {"message", "retract message"}}}));
  const json spec = buildReport({line("e", "p/g71/a", "fail", {"G71.A"})}, {}, kCatalogue);
  EXPECT_FALSE(engineOf(spec, "e")["cases"][0].contains("seed"));
}

TEST(ReportModel, APlotIsKeptAndOneThatCannotBeDrawnIsLeftOutWithAWarning) {
  PlotInput plot;
  plot.title = "t";
  Move m;
  m.to = {1, 2};
  plot.path.moves = {m};
  json good = line("e", "p/g71/a", "fail", {"G71.A"});
  good["plot"] = plotToJson(plot);
  json bad = line("e", "p/g71/b", "fail", {"G71.A"});
  bad["plot"] = {{"title", "t"}, {"finish", "not segments"}};
  ReportBuilder builder(kCatalogue, {});
  builder.add(good);
  builder.add(bad);
  const json report = builder.build();
  EXPECT_EQ(engineOf(report, "e")["cases"][0]["plot"], good["plot"]);
  EXPECT_FALSE(engineOf(report, "e")["cases"][1].contains("plot"));
  ASSERT_EQ(builder.warnings().size(), 1u);
  EXPECT_NE(builder.warnings()[0].find("p/g71/b"), std::string::npos);
}

TEST(ReportModel, ALineThatIsNotAResultIsRejectedNamingTheField) {
  ReportBuilder builder(kCatalogue, {});
  const auto rejects = [&](const json& l, const std::string& field) {
    try {
      builder.add(l);
      ADD_FAILURE() << "accepted " << l.dump();
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  rejects(json::array(), "result object");
  json noEngine = line("e", "p/g71/a", "pass", {});
  noEngine.erase("engine");
  rejects(noEngine, "/engine");
  rejects(line("e", "p/g71/a", "passed", {}), "/verdict");
  json badSeed = line("e", "p/g71/a", "pass", {});
  badSeed["seed"] = "12";
  rejects(badSeed, "/seed");
  json badRules = line("e", "p/g71/a", "fail", {});
  badRules["rules"] = "G71.A";
  rejects(badRules, "/rules");
  EXPECT_TRUE(builder.build()["engines"].empty());
}

}  // namespace
}  // namespace cyclecert
