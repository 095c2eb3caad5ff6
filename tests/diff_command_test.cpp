// `cyclecert diff` as a user and a CI job meet it: two engines on one spec case or program, the exit
// codes (0 agree, 1 diverge or cannot compare, 2 bad usage or input), the first divergence with its
// move and context, the JSON, and the SVG overlay of both toolpaths.
#include <gtest/gtest.h>

#include "tests/cli_fixture.h"

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "harness/spec/rule_catalogue.h"

namespace {

using boost::property_tree::ptree;
using nlohmann::json;

class DiffCli : public CliFixture {};

std::string specCase(const std::string& id) { return cyclecert::defaultSpecsDir() + "/cases/" + id + ".json"; }
std::string corpus(const std::string& name) { return std::string(CYCLECERT_SOURCE_DIR) + "/corpus/" + name; }

// G71 type I with A = (x 25, z 3), 23 moves; move 3 is the first 45° retract, (21.25, −29.8) →
// (23.75, −29.3), which mutant:retract-angle makes straight out along x: (23.75, −29.8).
const std::string kCase = specCase("fanuc-0i-f/g71/quad-upos-wpos-outer-negz");

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The <g> elements with this id, and the <path> children of the first.
std::vector<ptree> groupPaths(const ptree& node, const std::string& id) {
  std::vector<ptree> out;
  for (const auto& [name, child] : node) {
    if (name == "<xmlattr>") continue;
    if (name == "g" && child.get<std::string>("<xmlattr>.id", "") == id) {
      for (const auto& [n, c] : child)
        if (n == "path") out.push_back(c);
      return out;
    }
    auto below = groupPaths(child, id);
    if (!below.empty()) return below;
  }
  return out;
}

TEST_F(DiffCli, HelpDescribesOptionsAndExitCodes) {
  const CliRun r = run("diff --help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* part : {"Usage: cyclecert diff --engine A --vs B", "--tolerance T", "--context N", "--svg OUT",
                           "--json", "--timeout S", "not applicable", "Exit: 0 the engines agree"}) {
    EXPECT_TRUE(contains(r.out, part)) << part;
  }
  EXPECT_EQ(run("help diff").out, r.out);
  EXPECT_TRUE(contains(run("--help").out, "  diff       run two engines"));
}

TEST_F(DiffCli, TheReferenceAgreesWithItselfOnACase) {
  const CliRun r = run("diff --engine reference --vs reference " + kCase);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "reference [A]  planned 23 moves")) << r.out;
  EXPECT_TRUE(contains(r.out, "reference [B]  planned 23 moves")) << r.out;
  EXPECT_TRUE(contains(r.out, "the engines agree (23 moves within 0.001 mm)")) << r.out;
}

TEST_F(DiffCli, AMutantDivergesAtTheRetractWithContextAndAnSvgOverlay) {
  const std::string svgFile = path("d.svg");
  const CliRun r = run("diff --engine reference --vs mutant:retract-angle " + kCase + " --context 2 --svg " + svgFile);
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "first divergence: move 3: reference feed line to (x 23.75, z -29.3)")) << r.out;
  EXPECT_TRUE(contains(r.out, "mutant:retract-angle feed line to (x 23.75, z -29.8)")) << r.out;
  // The table: moves 1…5, the diverging one marked.
  std::istringstream lines(r.out);
  std::vector<std::string> rows;
  for (std::string line; std::getline(lines, line);) {
    if (line.size() > 7 && (line.rfind("  ", 0) == 0 || line.rfind("> ", 0) == 0) && std::isdigit(static_cast<unsigned char>(line[6])))
      rows.push_back(line);
  }
  ASSERT_EQ(rows.size(), 5u) << r.out;
  EXPECT_EQ(rows[0].substr(0, 7), "      1");
  EXPECT_EQ(rows[2].substr(0, 7), ">     3");
  EXPECT_EQ(rows[4].substr(0, 7), "      5");
  EXPECT_TRUE(contains(r.out, "svg written to " + svgFile));

  const std::string svg = read(svgFile);
  ASSERT_TRUE(contains(svg, "<svg"));
  EXPECT_TRUE(contains(svg, "id=\"overlay\""));
  EXPECT_TRUE(contains(svg, "first divergence: move 3"));
  ptree doc;
  std::istringstream in(svg);
  ASSERT_NO_THROW(boost::property_tree::read_xml(in, doc)) << svg;
  EXPECT_EQ(groupPaths(doc, "toolpath").size(), 23u);
  EXPECT_EQ(groupPaths(doc, "overlay").size(), 23u);
  EXPECT_TRUE(contains(svg, "mutant:retract-angle (rapid, feed)"));
}

TEST_F(DiffCli, JsonGivesTheOutcomesTheMoveAndTheContext) {
  const CliRun r = run("diff --engine reference --vs mutant:retract-angle " + kCase + " --json");
  EXPECT_EQ(r.exitCode, 1) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["agree"], false);
  EXPECT_EQ(j["comparable"], true);
  EXPECT_EQ(j["tolerance"], 0.001);
  ASSERT_EQ(j["engines"].size(), 2u);
  EXPECT_EQ(j["engines"][0]["name"], "reference");
  EXPECT_EQ(j["engines"][1]["name"], "mutant:retract-angle");
  EXPECT_EQ(j["engines"][1]["outcome"], "planned");
  EXPECT_EQ(j["engines"][1]["moves"], 23);
  EXPECT_EQ(j["divergence"]["move"], 3);
  EXPECT_TRUE(contains(j["divergence"]["text"].get<std::string>(), "move 3"));
  ASSERT_EQ(j["context"].size(), 7u);  // moves 0…6 with the default context of 3
  EXPECT_EQ(j["context"][3]["move"], 3);
  EXPECT_NE(j["context"][3]["a"], j["context"][3]["b"]);
  EXPECT_EQ(j["context"][0]["a"], j["context"][0]["b"]);
  EXPECT_TRUE(j["svg"].is_null());
}

TEST_F(DiffCli, AProgramFromTheCorpus) {
  const std::string program = corpus("fanuc-g71-seed003-ex1.nc");
  CliRun r = run("diff --engine reference --vs reference " + program);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "(profile fanuc-0i-f, tolerance 0.001 mm)")) << r.out;
  EXPECT_TRUE(contains(r.out, "the engines agree")) << r.out;

  r = run("diff --engine reference --vs mutant:retract-angle " + program + " --svg " + path("p.svg"));
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "first divergence: move ")) << r.out;
  EXPECT_TRUE(contains(read(path("p.svg")), "id=\"overlay\""));

  // --param reaches both engines: RF1=1 drops the semi-finishing pass for the mutant as well.
  r = run("diff --engine reference --vs mutant:semifinish-skipped " + program + " --param RF1=1");
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
}

// A process engine gets the program as a whole valid spec case: examples/engine.py hands it to
// `cyclecert plan --case`, which reads it with the same checks as any case file.
TEST_F(DiffCli, AProcessEngineReceivesTheProgramAsAValidCase) {
  const std::string engine =
      "\"process:python3 " + std::string(CYCLECERT_SOURCE_DIR) + "/examples/engine.py " + CYCLECERT_CLI + "\"";
  const CliRun r = run("diff --engine reference --vs " + engine + " " + corpus("fanuc-g71-seed003-ex1.nc") + " --json");
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["agree"], true) << j.dump(2);
  EXPECT_EQ(j["engines"][1]["outcome"], "planned") << j.dump(2);
}

TEST_F(DiffCli, BothAlarmingAgreeAndAMissedAlarmDiverges) {
  const std::string alarmCase = specCase("fanuc-0i-f/g71/ps0062-dd-zero");
  CliRun r = run("diff --engine reference --vs reference " + alarmCase);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "alarm PS0062 at line")) << r.out;
  EXPECT_TRUE(contains(r.out, "the engines agree (both alarm")) << r.out;

  // mutant:alarm-missed tolerates the turn-back that PS0064 is about: a toolpath against an alarm.
  const std::string turnBack = specCase("fanuc-0i-f/g71/ps0064-z-reverse");
  r = run("diff --engine reference --vs mutant:alarm-missed " + turnBack + " --svg " + path("a.svg"));
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "first divergence: reference gave alarm PS0064 at line 6")) << r.out;
  EXPECT_TRUE(contains(r.out, "mutant:alarm-missed gave a toolpath of")) << r.out;
  const std::string svg = read(path("a.svg"));
  EXPECT_TRUE(contains(svg, "ALARM (reference) PS0064"));
  EXPECT_FALSE(contains(svg, "first divergence: move"));  // no move to mark
}

TEST_F(DiffCli, AnEngineThatIsNotApplicableCannotBeCompared) {
  // G75 (outer diameter grooving) is not planned by the reference: not applicable, so nothing to compare.
  const std::string g75 = write("g75.nc", "G00 X70 Z10;\nG75 R1;\nG75 X40 Z-20 P3000 Q5000 F0.1;\nM30;\n");
  const CliRun r = run("diff --engine reference --vs mutant:retract-angle " + g75);
  EXPECT_EQ(r.exitCode, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "not applicable: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "cannot compare the engines: reference is not applicable and mutant:retract-angle is not applicable"))
      << r.out;
}

TEST_F(DiffCli, UsageErrorsExitWith2) {
  CliRun r = run("diff --engine reference --vs nosuch " + kCase);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(contains(r.err, "unknown engine 'nosuch'")) << r.err;
  EXPECT_TRUE(contains(r.err, "mutant:retract-angle")) << r.err;  // the list of engines

  r = run("diff --engine reference --vs reference " + path("missing.nc"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(contains(r.err, path("missing.nc"))) << r.err;
  r = run("diff --engine reference --vs reference " + path("missing.json"));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(contains(r.err, path("missing.json"))) << r.err;

  EXPECT_EQ(run("diff --engine reference " + kCase).exitCode, 2);             // no --vs
  EXPECT_EQ(run("diff --engine reference --vs reference").exitCode, 2);       // no input
  EXPECT_EQ(run("diff --engine reference --vs reference " + kCase + " --context -1").exitCode, 2);
  EXPECT_EQ(run("diff --engine reference --vs reference " + kCase + " --bogus").exitCode, 2);
  r = run("diff --engine reference --vs reference " + kCase + " --profile nosuch");
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_TRUE(contains(r.err, "unknown profile 'nosuch'")) << r.err;
}

}  // namespace
