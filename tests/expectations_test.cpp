// Expectation files (harness/results/expectations.h): reading JSON and text, the errors on malformed files
// (file, line:column or JSON path, what was expected), matching results by case, rule and kind,
// unexpected passes, and the baseline written from results read back to the same entries.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "harness/results/expectations.h"
#include "harness/results/results_file.h"

namespace {

using cyclecert::CaseResult;
using cyclecert::Expectation;
using cyclecert::ExpectationMatcher;
using cyclecert::Expectations;
using cyclecert::ExpectationsError;
using cyclecert::ExpectationStatus;
using cyclecert::Finding;
using cyclecert::parseExpectations;
using nlohmann::json;

// The message of the error the text raises ("" when it reads).
std::string errorOf(const std::string& text, const std::string& file = "lcnc.json") {
  try {
    parseExpectations(text, file);
  } catch (const ExpectationsError& e) {
    return e.what();
  }
  return "";
}

CaseResult result(const std::string& id, const std::string& verdict, std::vector<Finding> findings = {},
                  std::vector<std::string> rules = {"G71.T1.STEP2"}) {
  CaseResult r;
  r.engine = "linuxcnc";
  r.caseId = id;
  r.verdict = verdict;
  r.rules = std::move(rules);
  r.findings = std::move(findings);
  return r;
}

Finding finding(const std::string& oracle, std::vector<std::string> rules) {
  Finding f;
  f.oracle = oracle;
  f.rules = std::move(rules);
  f.message = "a message";
  return f;
}

TEST(ExpectationsRead, JsonEntriesByCaseRuleAndKind) {
  const Expectations e = parseExpectations(R"({"expectations": [
    {"case": "gsk/g72/arc", "outcome": "fail", "reason": "passes from A"},
    {"rule": "G71.T1.RETRACT45", "outcome": "fail", "reason": "rapid retract"},
    {"kind": "engine-failure", "outcome": "engine-failure", "reason": "hangs"}]})",
                                           "x.json");
  ASSERT_EQ(e.entries.size(), 3u);
  EXPECT_EQ(e.entries[0].key, Expectation::Key::Case);
  EXPECT_EQ(e.entries[0].id, "gsk/g72/arc");
  EXPECT_EQ(e.entries[0].outcome, "fail");
  EXPECT_EQ(e.entries[0].reason, "passes from A");
  EXPECT_EQ(e.entries[0].source, "x.json: /expectations/0");
  EXPECT_EQ(e.entries[1].key, Expectation::Key::Rule);
  EXPECT_EQ(e.entries[2].key, Expectation::Key::Kind);
  EXPECT_EQ(e.entries[2].outcome, "engine-failure");
  // A bare array of entries reads too.
  EXPECT_EQ(parseExpectations(R"([{"case": "a", "outcome": "fail", "reason": "r"}])", "x.json").entries.size(), 1u);
}

TEST(ExpectationsRead, TextLinesWithCommentsAndPrefixes) {
  const Expectations e = parseExpectations(
      "# LinuxCNC\n\n  fanuc-0i-f/g71/x fail # passes counted from A # not Δd below\n"
      "rule:G71.T1.RETRACT45 fail #rapid retract\r\nkind:diverges fail # other dialect\n",
      "l.txt");
  ASSERT_EQ(e.entries.size(), 3u);
  EXPECT_EQ(e.entries[0].id, "fanuc-0i-f/g71/x");
  EXPECT_EQ(e.entries[0].reason, "passes counted from A # not Δd below");
  EXPECT_EQ(e.entries[0].source, "l.txt:3");
  EXPECT_EQ(e.entries[1].key, Expectation::Key::Rule);
  EXPECT_EQ(e.entries[1].id, "G71.T1.RETRACT45");
  EXPECT_EQ(e.entries[1].reason, "rapid retract");
  EXPECT_EQ(e.entries[2].key, Expectation::Key::Kind);
  EXPECT_EQ(e.entries[2].id, "diverges");
  EXPECT_TRUE(parseExpectations("\n# nothing yet\n", "l.txt").entries.empty());
}

TEST(ExpectationsRead, MalformedJsonSaysWhereAndWhatWasExpected) {
  EXPECT_NE(errorOf("{\"expectations\": [\n  {\"case\": \"a\",, }]}").find("lcnc.json:2:"), std::string::npos)
      << errorOf("{\"expectations\": [\n  {\"case\": \"a\",, }]}");
  EXPECT_NE(errorOf("{\"expectations\": [\n  {\"case\": \"a\",, }]}").find("not valid JSON"), std::string::npos);
  EXPECT_EQ(errorOf(R"({"expectations": [{"case": "a", "outcome": "fail", "reason": "r"},
                                         {"case": "b", "outcome": "broken", "reason": "r"}]})"),
            "lcnc.json: /expectations/1/outcome: expected one of fail, engine-failure or not-applicable, got \"broken\"");
  EXPECT_EQ(errorOf(R"({"expectations": [{"case": "a", "outcome": "fail"}]})"),
            "lcnc.json: /expectations/0: missing \"reason\": expected a non-empty string saying why the failure is expected");
  EXPECT_NE(errorOf(R"([{"case": "a", "rule": "R", "outcome": "fail", "reason": "r"}])").find("lcnc.json: /0: expected exactly one of"),
            std::string::npos);
  EXPECT_NE(errorOf(R"([{"outcome": "fail", "reason": "r"}])").find("exactly one of \"case\""), std::string::npos);
  EXPECT_NE(errorOf(R"([{"case": "a", "outcom": "fail", "reason": "r"}])").find("/0/outcom: unknown field"), std::string::npos);
  EXPECT_NE(errorOf(R"({"expectation": []})").find("/expectation: unknown field"), std::string::npos);
  EXPECT_NE(errorOf(R"({"expectations": 3})").find("/expectations: expected an array of entries"), std::string::npos);
  EXPECT_NE(errorOf(R"([{"case": 7, "outcome": "fail", "reason": "r"}])").find("/0/case: expected a non-empty string, got 7"),
            std::string::npos);
  EXPECT_NE(errorOf("[3]").find("/0: expected an entry object"), std::string::npos);
}

TEST(ExpectationsRead, MalformedTextSaysLineColumnAndTheFormat) {
  EXPECT_EQ(errorOf("a fail # r\n  b failed # r\n", "l.txt"),
            "l.txt:2:5: expected an outcome (fail, engine-failure or not-applicable), got 'failed'");
  EXPECT_EQ(errorOf("a\n", "l.txt"),
            "l.txt:1:2: expected an outcome after 'a' (fail, engine-failure or not-applicable): `ID OUTCOME # reason`");
  EXPECT_EQ(errorOf("a fail\n", "l.txt"),
            "l.txt:1:7: expected a reason after '#' saying why the failure is expected: `a fail # reason`");
  EXPECT_EQ(errorOf("a fail #   \n", "l.txt"),
            "l.txt:1:8: expected a reason after '#' saying why the failure is expected: `a fail # reason`");
  EXPECT_EQ(errorOf("a fail because # r\n", "l.txt"),
            "l.txt:1:8: unexpected 'because': put the reason after '#' (`ID OUTCOME # reason`)");
  EXPECT_NE(errorOf("rule: fail # r\n", "l.txt").find("l.txt:1:1: expected an id after 'rule:'"), std::string::npos);
}

TEST(ExpectationsRead, TwoEntriesForOneCaseAreRefused) {
  EXPECT_EQ(errorOf("a fail # r\nb fail # r\na engine-failure # r\n", "l.txt"),
            "l.txt:3: case 'a' already has an entry at l.txt:1; keep one entry for it");
}

TEST(ExpectationsRead, AMissingFileIsAnExpectationsError) {
  try {
    cyclecert::readExpectations("/nonexistent/expectations.json");
    FAIL() << "read a missing file";
  } catch (const ExpectationsError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/expectations.json"), std::string::npos) << e.what();
  }
}

TEST(ExpectationsMatch, ACaseEntryCoversItsCaseFailingThatWay) {
  const Expectations e = parseExpectations("a fail # dialect\nb engine-failure # hangs\n", "l.txt");
  ExpectationMatcher m(e);
  CaseResult a = result("a", "fail");
  EXPECT_EQ(m.apply(a), ExpectationStatus::Expected);
  ASSERT_TRUE(a.expectation);
  EXPECT_EQ(a.expectation->status, "expected-failure");
  EXPECT_EQ(a.expectation->reason, "dialect");
  EXPECT_EQ(a.expectation->source, "l.txt:1");
  // b is expected to hang; failing another way is new.
  CaseResult b = result("b", "fail");
  EXPECT_EQ(m.apply(b), ExpectationStatus::NewFailure);
  EXPECT_EQ(b.expectation->status, "new-failure");
  CaseResult c = result("c", "fail");
  EXPECT_EQ(m.apply(c), ExpectationStatus::NewFailure);
  CaseResult d = result("d", "pass");
  EXPECT_EQ(m.apply(d), ExpectationStatus::None);
  EXPECT_FALSE(d.expectation);
  ASSERT_EQ(m.unused().size(), 1u);
  EXPECT_EQ(m.unused()[0]->id, "b");
}

TEST(ExpectationsMatch, AnEntryWhoseCasePassesIsAnUnexpectedPass) {
  const Expectations e = parseExpectations("a fail # dialect\n", "l.txt");
  ExpectationMatcher m(e);
  CaseResult a = result("a", "pass");
  EXPECT_EQ(m.apply(a), ExpectationStatus::UnexpectedPass);
  EXPECT_EQ(a.expectation->status, "unexpected-pass");
  EXPECT_NE(cyclecert::unexpectedPassText(a).find("unexpectedly passing: a is pass now; l.txt:1"), std::string::npos);
  CaseResult na = result("a", "not-applicable");
  EXPECT_EQ(m.apply(na), ExpectationStatus::UnexpectedPass);
  EXPECT_TRUE(m.unused().empty());
}

TEST(ExpectationsMatch, ARuleEntryCoversTheRulesAFailureFails) {
  const Expectations e = parseExpectations("rule:G71.T1.RETRACT45 fail # rapid retract\n", "l.txt");
  ExpectationMatcher m(e);
  // The findings name the rules failed.
  CaseResult retract = result("a", "fail", {finding("retract", {"G71.T1.RETRACT45", "G72.RETRACT"})});
  EXPECT_EQ(m.apply(retract), ExpectationStatus::Expected);
  // A case citing the rule but failing another one is not covered.
  CaseResult other = result("b", "fail", {finding("no-gouge", {"G71.OP"})}, {"G71.T1.RETRACT45"});
  EXPECT_EQ(m.apply(other), ExpectationStatus::NewFailure);
  // Without findings naming rules, the failure stands against the rules it cites.
  CaseResult unmet = result("c", "fail", {}, {"G71.T1.RETRACT45"});
  EXPECT_EQ(m.apply(unmet), ExpectationStatus::Expected);
}

TEST(ExpectationsMatch, AKindEntryCoversAFindingsOracleOrTheFuzzKind) {
  const Expectations e = parseExpectations("kind:pass-levels fail # from A\nkind:diverges fail # dialect\n", "l.txt");
  ExpectationMatcher m(e);
  CaseResult levels = result("fuzz-01", "fail", {finding("retract", {}), finding("pass-levels", {})});
  EXPECT_EQ(m.apply(levels), ExpectationStatus::Expected);
  EXPECT_EQ(levels.expectation->reason, "from A");
  CaseResult diverges = result("fuzz-02", "fail");
  EXPECT_EQ(m.apply(diverges, "diverges"), ExpectationStatus::Expected);
  CaseResult gouge = result("fuzz-03", "fail", {finding("no-gouge", {})});
  EXPECT_EQ(m.apply(gouge, "no-gouge"), ExpectationStatus::NewFailure);
}

TEST(ExpectationsMatch, ACaseEntryWinsOverARuleEntryForItsReason) {
  const Expectations e = parseExpectations("rule:G71.T1.STEP2 fail # by rule\na fail # by case\n", "l.txt");
  ExpectationMatcher m(e);
  CaseResult a = result("a", "fail");
  m.apply(a);
  EXPECT_EQ(a.expectation->reason, "by case");
}

TEST(ExpectationsResults, TheResultLineCarriesTheExpectationAndOldLinesHaveNone) {
  CaseResult r = result("a", "fail");
  EXPECT_FALSE(json::parse(cyclecert::resultLine(r)).contains("expectation"));
  r.expectation = cyclecert::ResultExpectation{"expected-failure", "dialect", "l.txt:1"};
  const json line = json::parse(cyclecert::resultLine(r));
  EXPECT_EQ(line["expectation"], (json{{"status", "expected-failure"}, {"reason", "dialect"}, {"source", "l.txt:1"}}));
}

json resultJson(const std::string& id, const std::string& verdict, const std::string& detail, json findings = json::array()) {
  return {{"engine", "e"}, {"case", id}, {"verdict", verdict}, {"detail", detail}, {"findings", findings}};
}

TEST(ExpectationsBaseline, EveryFailureWithItsKindsAndFirstDetail) {
  const std::vector<json> lines = {
      resultJson("z", "fail", "move 1: expected rapid", {{{"oracle", "expectation"}}, {{"oracle", "retract"}}, {{"oracle", "retract"}}}),
      resultJson("p", "pass", ""),
      resultJson("h", "engine-failure", "rs274 timed out after 10 s"),
      resultJson("later-passes", "fail", "x"),
      resultJson("later-passes", "pass", ""),
      resultJson("n", "not-applicable", "G70")};
  const Expectations e = cyclecert::baselineOf(lines);
  ASSERT_EQ(e.entries.size(), 2u);
  EXPECT_EQ(e.entries[0].id, "h");
  EXPECT_EQ(e.entries[0].outcome, "engine-failure");
  EXPECT_EQ(e.entries[0].reason, "engine-failure: rs274 timed out after 10 s");
  EXPECT_EQ(e.entries[1].id, "z");
  EXPECT_EQ(e.entries[1].reason, "expectation, retract: move 1: expected rapid");
}

TEST(ExpectationsBaseline, WrittenJsonAndTextReadBackToTheSameEntries) {
  Expectations e;
  e.entries = {{Expectation::Key::Case, "fanuc-0i-f/g71/a", "fail", "quote \" and # hash", ""},
               {Expectation::Key::Rule, "G71.T1.RETRACT45", "fail", "rapid", ""},
               {Expectation::Key::Kind, "engine-failure", "engine-failure", "hangs", ""}};
  for (const auto& text : {cyclecert::expectationsJson(e), cyclecert::expectationsText(e)}) {
    const Expectations back = parseExpectations(text, "b");
    ASSERT_EQ(back.entries.size(), e.entries.size()) << text;
    for (std::size_t i = 0; i < e.entries.size(); ++i) {
      EXPECT_EQ(back.entries[i].key, e.entries[i].key) << text;
      EXPECT_EQ(back.entries[i].id, e.entries[i].id) << text;
      EXPECT_EQ(back.entries[i].outcome, e.entries[i].outcome) << text;
      EXPECT_EQ(back.entries[i].reason, e.entries[i].reason) << text;
    }
  }
  EXPECT_TRUE(parseExpectations(cyclecert::expectationsJson(Expectations{}), "b").entries.empty());
}

}  // namespace
