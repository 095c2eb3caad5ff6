// junit.xml from report.json's document (reports/junit): one testsuite per engine, one testcase per
// spec or regression case and per failing generated case, failures naming their rules, counts that
// add up, text escaped — and accepted by the JUnit schema Jenkins and GitLab use (xmllint).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "reports/junit/junit_xml.h"
#include "reports/model/report_model.h"

namespace cyclecert {
namespace {

using nlohmann::json;
using boost::property_tree::ptree;

json line(const std::string& engine, const std::string& id, const std::string& verdict, const std::string& detail,
          json findings = json::array()) {
  return {{"engine", engine}, {"case", id},        {"file", "specs/cases/" + id + ".json"}, {"rules", {"G71.A", "G71.B"}},
          {"verdict", verdict}, {"detail", detail}, {"findings", findings}, {"seconds", 0.5}, {"seed", nullptr}};
}

json sampleReport() {
  json fuzzFail = line("mutant:x.y", "fuzz-00000000000000aa", "fail", "retract: too far",
                       {{{"oracle", "retract"}, {"rules", {"G71.RETRACT"}}, {"move", 4}, {"message", "retract 2e"}}});
  fuzzFail["seed"] = 170;
  fuzzFail["reproduce"] = "cyclecert fuzz --engine 'mutant:x.y' --seed 170 --cases 1";
  fuzzFail["program"] = "G00 X8 Z0;\nM30;\n";
  json fuzzNa = line("mutant:x.y", "fuzz-00000000000000ab", "not-applicable", "cannot");
  fuzzNa["seed"] = 171;
  json fuzzPass = line("mutant:x.y", "fuzz-00000000000000ac", "pass", "");
  fuzzPass["seed"] = 172;
  const std::vector<json> lines = {
      line("reference", "fanuc-0i-f/g71/a", "pass", ""),
      line("mutant:x.y", "fanuc-0i-f/g71/a", "fail", "move 3: expected <x 1>, got \"x 2\" & more\x01",
           {{{"oracle", "no-gouge"}, {"rules", {"G71.NOGOUGE"}}, {"message", "cuts <into> the part"}}}),
      line("mutant:x.y", "gsk/g72/b", "engine-failure", "timeout after 10 s"),
      line("mutant:x.y", "gsk/g72/c", "not-applicable", "G72 not supported"),
      line("mutant:x.y", "gsk/g72/d", "fail", "alarm PS0062 expected"),
      fuzzFail, fuzzNa, fuzzPass};
  const std::vector<json> runs = {{{"command", "check"}, {"engine", "mutant:x.y"}, {"engine_version", "v1"},
                                   {"cyclecert_version", "0.1.0"}, {"git_revision", "abc"}, {"spec_suite_hash", "h"},
                                   {"started", "2025-01-01T00:00:00Z"}}};
  return buildReport(lines, runs, {{"G71.A", "G71", "001", "1", "A"}, {"G71.B", "G71", "001", "2", "B"}});
}

const ptree& suiteNamed(const ptree& doc, const std::string& name) {
  for (const auto& [tag, node] : doc.get_child("testsuites")) {
    if (tag == "testsuite" && node.get<std::string>("<xmlattr>.name") == name) return node;
  }
  throw std::runtime_error("no testsuite " + name);
}

ptree parse(const std::string& xml) {
  std::istringstream in(xml);
  ptree doc;
  boost::property_tree::read_xml(in, doc);
  return doc;
}

TEST(Junit, OneSuitePerEngineOneCasePerSpecCaseAndFuzzFailure) {
  const ptree doc = parse(junitXml(sampleReport()));
  EXPECT_EQ(doc.get<std::string>("testsuites.<xmlattr>.tests"), "6");
  EXPECT_EQ(doc.get<std::string>("testsuites.<xmlattr>.failures"), "3");
  EXPECT_EQ(doc.get<std::string>("testsuites.<xmlattr>.errors"), "1");
  const ptree& mutant = suiteNamed(doc, "mutant:x.y");
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.tests"), "5");  // 4 spec cases + the failing generated one
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.failures"), "3");
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.errors"), "1");
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.skipped"), "1");
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.time"), "2.500000");
  EXPECT_EQ(mutant.get<std::string>("<xmlattr>.timestamp"), "2025-01-01T00:00:00Z");
  std::map<std::string, const ptree*> cases;
  for (const auto& [tag, node] : mutant) {
    if (tag == "testcase") cases[node.get<std::string>("<xmlattr>.name")] = &node;
  }
  ASSERT_EQ(cases.size(), 5u);
  const ptree& a = *cases.at("fanuc-0i-f/g71/a");
  EXPECT_EQ(a.get<std::string>("<xmlattr>.classname"), "mutant:x_y.spec.g71");
  EXPECT_EQ(a.get<std::string>("<xmlattr>.time"), "0.500000");
  const std::string message = a.get<std::string>("failure.<xmlattr>.message");
  EXPECT_EQ(message.rfind("fails G71.NOGOUGE: move 3", 0), 0u) << message;
  EXPECT_NE(a.get<std::string>("failure").find("no-gouge: cuts <into> the part  [rules: G71.NOGOUGE]"), std::string::npos);
  // An unmet expectation without a finding fails every rule the case cites.
  EXPECT_EQ(cases.at("gsk/g72/d")->get<std::string>("failure.<xmlattr>.message"), "fails G71.A, G71.B: alarm PS0062 expected");
  EXPECT_EQ(cases.at("gsk/g72/b")->get<std::string>("error.<xmlattr>.message"), "engine failure: timeout after 10 s");
  EXPECT_EQ(cases.at("gsk/g72/c")->get<std::string>("skipped.<xmlattr>.message"), "not applicable: G72 not supported");
  const ptree& fuzz = *cases.at("fuzz-00000000000000aa");
  EXPECT_EQ(fuzz.get<std::string>("<xmlattr>.classname"), "mutant:x_y.fuzz");
  const std::string text = fuzz.get<std::string>("failure");
  EXPECT_NE(text.find("reproduce: cyclecert fuzz --engine 'mutant:x.y' --seed 170 --cases 1"), std::string::npos) << text;
  EXPECT_NE(text.find("G00 X8 Z0;"), std::string::npos) << text;
  bool fuzzCounted = false;
  for (const auto& [tag, p] : mutant.get_child("properties")) {
    if (p.get<std::string>("<xmlattr>.name") == "fuzz_cases") fuzzCounted = p.get<std::string>("<xmlattr>.value") == "3";
  }
  EXPECT_TRUE(fuzzCounted);
  EXPECT_EQ(suiteNamed(doc, "reference").get<std::string>("<xmlattr>.tests"), "1");
}

TEST(Junit, TextIsEscapedControlCharactersToo) {
  const std::string xml = junitXml(sampleReport());
  EXPECT_NE(xml.find("expected &lt;x 1&gt;, got &quot;x 2&quot; &amp; more?"), std::string::npos);
  EXPECT_EQ(xml.find('\x01'), std::string::npos);
}

// xmllint --schema against jenkinsci's junit-10.xsd (tests/data/junit); the file's exit code.
int xmllintSchema(const std::string& xml, const std::string& name) {
  const auto file = std::filesystem::temp_directory_path() / ("cyclecert-junit-" + std::to_string(::getpid()) + "-" + name);
  std::ofstream(file) << xml;
  const std::string command = "xmllint --noout --schema " + std::string(CYCLECERT_SOURCE_DIR) +
                              "/tests/data/junit/junit-10.xsd " + file.string() + " 2>&1";
  const int status = std::system(command.c_str());
  std::filesystem::remove(file);
  return WEXITSTATUS(status);
}

TEST(Junit, TheJenkinsSchemaAcceptsItAndRejectsABrokenOne) {
  if (std::system("command -v xmllint >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "xmllint is not installed (Debian: apt-get install libxml2-utils); junit.xml not validated";
  }
  EXPECT_EQ(xmllintSchema(junitXml(sampleReport()), "good.xml"), 0);
  EXPECT_EQ(xmllintSchema(junitXml(buildReport({}, {}, {})), "empty.xml"), 0);
  // The same document with a testcase that lacks its name must be refused, or the check proves nothing.
  std::string broken = junitXml(sampleReport());
  const auto at = broken.find(" name=\"fanuc-0i-f/g71/a\"");
  ASSERT_NE(at, std::string::npos);
  broken.erase(at, std::string(" name=\"fanuc-0i-f/g71/a\"").size());
  EXPECT_NE(xmllintSchema(broken, "broken.xml"), 0);
}

}  // namespace
}  // namespace cyclecert
