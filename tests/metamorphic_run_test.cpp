// The metamorphic relations run against an engine (harness/judge/metamorphic_run.h, `--metamorphic` on
// check, fuzz and diff): an engine with a fault the oracles do not see on the spec cases — it only
// shows on programs that start far from the part, which the relations write — fails a relation;
// a follow-up the engine fails on is an engine failure, one it answers "not applicable" to is
// skipped; relations that do not apply are counted; the reference holds every relation on every
// spec case a relation applies to; and fuzz shrinks a violation keeping its kind.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "check_run_fixture.h"
#include "harness/fuzz/fuzz_relations.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/judge/metamorphic_run.h"
#include "harness/run/check_run.h"
#include "oracles/metamorphic/relations.h"
#include "reference/gcode/parser.h"

namespace cyclecert {
namespace {

// The reference, with a fault on programs whose first move ends beyond z = 10 mm: what `fault` does
// to the planned toolpath. The spec cases below start at z ≤ 3, so the oracles never see it; the
// relation translate-z (Z + 12.5) writes such programs.
class FarFromThePartEngine : public Engine {
 public:
  enum Fault { DoubledFeeds, Crash, NotSupported };
  explicit FarFromThePartEngine(Fault fault) : fault_(fault), reference_(makeEngine("reference")) {}
  std::string name() const override { return "far-from-the-part"; }
  std::string description() const override { return "the reference, wrong beyond z = 10 mm"; }
  std::string version() const override { return "test"; }
  EngineResult run(const SpecCase& c) override {
    EngineResult r = reference_->run(c);
    if (r.kind != EngineResult::Planned || r.path.moves.empty() || r.path.moves.front().to.z <= 10) return r;
    switch (fault_) {
      case DoubledFeeds:
        for (Move& m : r.path.moves) {
          if (m.feed) *m.feed *= 2;
        }
        return r;
      case Crash: return EngineResult::failed("crashed (a test engine)");
      case NotSupported: return EngineResult::notApplicable("programs starting beyond z = 10 mm are not supported");
    }
    return r;
  }

 private:
  Fault fault_;
  std::unique_ptr<Engine> reference_;
};

SpecCase specCase(const std::string& id) { return loadSpecCase(source("specs/cases/" + id + ".json")); }

const Finding* findingOf(const CaseResult& r, const std::string& kind) {
  for (const Finding& f : r.findings) {
    if (f.oracle == kind) return &f;
  }
  return nullptr;
}

const std::string kStepped = "fanuc-0i-f/g71/g01-head-stepped-shaft";  // G00 X36 Z2; G71 U2 R1; …

TEST(MetamorphicRun, AFaultOnlyARelationReachesFailsTheCaseWithTheRelationsFinding) {
  FarFromThePartEngine engine(FarFromThePartEngine::DoubledFeeds);
  const SpecCase c = specCase(kStepped);
  EXPECT_EQ(checkCase(engine, c).verdict, "pass");  // the oracles alone see nothing

  MetamorphicTally tally;
  const CaseResult r = checkCase(engine, c, &tally);
  EXPECT_EQ(r.verdict, "fail");
  const Finding* f = findingOf(r, "metamorphic:translate-z");
  ASSERT_NE(f, nullptr) << r.detail;
  EXPECT_EQ(f->rules, findRelation("translate-z")->rules);
  EXPECT_NE(f->message.find("feed"), std::string::npos) << f->message;                 // the first divergence
  EXPECT_NE(f->message.find("G00 X36 Z14.5;"), std::string::npos) << f->message;       // the follow-up program
  EXPECT_EQ(r.detail.rfind("metamorphic:", 0), 0u) << r.detail;
  EXPECT_NE(r.reproduce.find("--metamorphic"), std::string::npos) << r.reproduce;
  EXPECT_EQ(tally.byRelation.at("translate-z").violated, 1);
  EXPECT_EQ(tally.byRelation.at("mirror-z").held, 1);  // z ≤ 0 after the mirror: no fault there
  // The plot: the source's path on the source's contours, and the follow-up's mapped back over it
  // (z − 12.5), both labelled; they part at the feed, not in geometry.
  ASSERT_TRUE(r.plot);
  EXPECT_EQ((*r.plot)["path_label"], "source");
  EXPECT_EQ((*r.plot)["overlay_label"], "follow-up (translate-z), mapped back");
  ASSERT_EQ((*r.plot)["overlay"]["moves"].size(), (*r.plot)["path"]["moves"].size());
  for (const char* axis : {"x", "z"}) {
    EXPECT_NEAR((*r.plot)["overlay"]["moves"][0]["to"][axis].get<double>(),
                (*r.plot)["path"]["moves"][0]["to"][axis].get<double>(), 1e-9);
  }
  EXPECT_NE(r.plot->dump().find("first divergence: move"), std::string::npos);
}

TEST(MetamorphicRun, TheViolationCarriesBothProgramsAndBothPaths) {
  FarFromThePartEngine engine(FarFromThePartEngine::DoubledFeeds);
  const SpecCase c = specCase(kStepped);
  const EngineResult source = engine.run(c);
  const RelationsVerdict v = checkRelations(engine, c, source.path, c.tolerance);
  const auto it = std::find_if(v.violations.begin(), v.violations.end(),
                               [](const MetamorphicViolation& m) { return m.relation == "translate-z"; });
  ASSERT_NE(it, v.violations.end());
  EXPECT_NE(it->followUp.program.find("Z14.5"), std::string::npos) << it->followUp.program;
  EXPECT_EQ(it->followUp.profile, c.profile);
  ASSERT_FALSE(it->source.moves.empty());
  ASSERT_EQ(it->expected.moves.size(), it->source.moves.size());
  EXPECT_NEAR(it->expected.moves.front().to.z, it->source.moves.front().to.z + 12.5, 1e-9);
  ASSERT_TRUE(it->move);  // the first feed move: the doubled feed
  ASSERT_TRUE(it->actual.path.moves[*it->move].feed);
  EXPECT_NEAR(*it->actual.path.moves[*it->move].feed, 2 * *it->expected.moves[*it->move].feed, 1e-12);
  EXPECT_FALSE(relationsClean(v));
}

// The report draws a violation on the source: the follow-up's path mapped back by the inverse of
// the relation's point map, found by probing its expected path.
TEST(MetamorphicRun, TheWayBackInvertsEachRelationsMapOfPoints) {
  const SpecCase c = specCase(kStepped);
  const auto reference = makeEngine("reference");
  const Toolpath source = reference->run(c).path;
  const Program program = parseProgram(c.program, c.file);
  for (const Relation& r : allRelations()) {
    std::string whyNot;
    const auto f = r.transform(program, c.params, whyNot);
    if (!f) continue;
    const auto back = backMapOf(*f);
    ASSERT_TRUE(back) << r.id;
    const Toolpath expected = f->expectedPath(source);
    ASSERT_EQ(expected.moves.size(), source.moves.size()) << r.id;
    for (std::size_t i = 0; i < source.moves.size(); ++i) {
      EXPECT_TRUE(nearlyEqual(back->map(expected.moves[i].to), source.moves[i].to, 1e-9)) << r.id << " move " << i;
    }
    const bool mirrors = r.id == "mirror-z" || r.id == "mirror-x" || r.id == "transpose";
    EXPECT_EQ(back->mirrors, mirrors) << r.id;
    const bool moves = mirrors || r.id == "translate-z" || r.id == "translate-x" || r.id == "scale-k";
    EXPECT_EQ(back->identity, !moves) << r.id;
  }
}

TEST(MetamorphicRun, AFollowUpTheEngineFailsOnIsAnEngineFailureNotAViolation) {
  FarFromThePartEngine engine(FarFromThePartEngine::Crash);
  MetamorphicTally tally;
  const CaseResult r = checkCase(engine, specCase(kStepped), &tally);
  EXPECT_EQ(r.verdict, "engine-failure");
  EXPECT_NE(r.detail.find("crashed (a test engine)"), std::string::npos) << r.detail;
  EXPECT_NE(r.detail.find("translate-z"), std::string::npos) << r.detail;
  EXPECT_TRUE(r.findings.empty());
  EXPECT_EQ(tally.byRelation.at("translate-z").engineFailure, 1);
  EXPECT_EQ(tally.total().violated, 0);
}

TEST(MetamorphicRun, AFollowUpTheEngineDoesNotSupportIsSkippedAndCounted) {
  FarFromThePartEngine engine(FarFromThePartEngine::NotSupported);
  MetamorphicTally tally;
  const CaseResult r = checkCase(engine, specCase(kStepped), &tally);
  EXPECT_EQ(r.verdict, "pass") << r.detail;
  EXPECT_EQ(tally.byRelation.at("translate-z").notSupported, 1);
  EXPECT_EQ(tally.byRelation.at("translate-z").skipped(), 1);
  EXPECT_EQ(tally.byRelation.at("translate-z").run(), 0);
  EXPECT_GE(tally.total().held, 1);
}

TEST(MetamorphicRun, RelationsThatDoNotApplyAreSkippedAndCounted) {
  const auto reference = makeEngine("reference");
  // G72: the plane relations are G71 only.
  MetamorphicTally g72;
  EXPECT_EQ(checkCase(*reference, specCase("gsk/g72/first-infeed-g01"), &g72).verdict, "pass");
  EXPECT_EQ(g72.byRelation.at("plane-g17").doesNotApply, 1);
  EXPECT_EQ(g72.byRelation.at("plane-g19").doesNotApply, 1);
  // GSK (direct return): not a source for the relations into another dialect, written from 0i-F.
  EXPECT_EQ(g72.byRelation.at("haas-one-block").doesNotApply, 1);
  EXPECT_EQ(g72.total().run() + g72.total().skipped(), static_cast<long>(allRelations().size()));
  // A SINUMERIK program: only the relations that read its words (transformSiemens: translate-z,
  // translate-x, scale-k, r-ik) apply; the others are counted as not applying.
  std::vector<std::string> siemens = findSpecCaseFiles(source("specs/cases/sinumerik-802d"));
  ASSERT_FALSE(siemens.empty());
  MetamorphicTally cycle95;
  checkCase(*reference, loadSpecCase(siemens.front()), &cycle95);
  long readers = 0;
  for (const Relation& r : allRelations()) readers += r.transformSiemens ? 1 : 0;
  ASSERT_GT(readers, 0);
  EXPECT_EQ(cycle95.total().run() + cycle95.total().doesNotApply, static_cast<long>(allRelations().size()));
  EXPECT_GE(cycle95.total().doesNotApply, static_cast<long>(allRelations().size()) - readers);
  EXPECT_GT(cycle95.total().run(), 0) << "translate-z reads every SINUMERIK program";
  EXPECT_EQ(cycle95.byRelation.at("mirror-z").doesNotApply, 1);
  // The counts as one line and as JSON.
  EXPECT_NE(tallyText(g72).find(std::to_string(g72.total().run()) + " follow-ups run"), std::string::npos) << tallyText(g72);
  EXPECT_EQ(tallyJson(g72)["relations"]["plane-g17"]["skipped"], 1);
  EXPECT_EQ(tallyFromJson(tallyJson(g72)).total().held, g72.total().held);
}

// Every spec case the reference plans (or alarms on), under every relation that applies to it: the
// reference is judged against itself. A violation here is a reference defect or a relation's.
// Before the relations' limits (relationJudges, each relation's `outside`), 25 of these failed, all by the
// relations' limits, none a reference defect: haas-one-block from GSK sources (19: the direct
// return, DTP = 1) and from a 0i-C one (pocket order), PS0003 sources under metric-inch,
// param-default, fs10-one-block and haas-one-block (the rewritten word is then in range), and
// transpose on PS0322 sources (no G72 counterpart).
TEST(MetamorphicRun, TheReferenceHoldsEveryRelationOnEverySpecCase) {
  const auto reference = makeEngine("reference");
  MetamorphicTally tally;
  std::vector<std::string> violations;
  for (const std::string& file : findSpecCaseFiles(source("specs/cases"))) {
    const SpecCase c = loadSpecCase(file);
    const EngineResult r = reference->run(c);
    if (r.kind != EngineResult::Planned && r.kind != EngineResult::Alarmed) continue;
    const RelationsVerdict v = checkRelations(*reference, c, r.path, c.tolerance);
    tally.add(v.tally);
    for (const MetamorphicViolation& m : v.violations) violations.push_back(c.id + ": " + m.relation + ": " + m.divergence);
    if (v.engineFailure) violations.push_back(c.id + ": " + *v.engineFailure);
  }
  std::ostringstream list;
  for (const std::string& v : violations) list << v << "\n";
  EXPECT_TRUE(violations.empty()) << violations.size() << " violation(s):\n" << list.str();
  EXPECT_GT(tally.total().held, 300) << tallyText(tally);  // the relations do reach the spec cases
}

TEST(MetamorphicRun, FuzzShrinksAViolationKeepingItsKind) {
  FarFromThePartEngine engine(FarFromThePartEngine::DoubledFeeds);
  const fs::path out = fs::temp_directory_path() / ("cyclecert-metamorphic-fuzz-" + std::to_string(::getpid()));
  FuzzOptions options;
  options.seed = 7;
  options.cases = 60;
  options.outDir = (out / "oracles").string();
  std::ostringstream progress;
  const FuzzSummary oraclesAlone = runFuzz(engine, nullptr, options, progress);
  options.metamorphic = true;
  options.outDir = (out / "relations").string();
  const FuzzSummary withRelations = runFuzz(engine, nullptr, options, progress);
  fs::remove_all(out);

  EXPECT_GT(withRelations.fail, oraclesAlone.fail) << progress.str();
  const auto it = std::find_if(withRelations.failures.begin(), withRelations.failures.end(),
                               [](const FuzzFailure& f) { return isMetamorphicKind(f.kind); });
  ASSERT_NE(it, withRelations.failures.end()) << progress.str();
  EXPECT_GT(it->shrinkRuns, 0);
  EXPECT_FALSE(it->rules.empty());
  // The shrunk case still fails the same way.
  const SpecCase shrunk = fuzzSpecCase(it->shrunk, caseSeedTag(it->caseSeed));
  const FuzzVerdict again = judgeFuzzResultWithRelations(engine.run(shrunk), engine, nullptr, shrunk, 1e-3, nullptr);
  EXPECT_EQ(again.kind, it->kind) << again.detail;
  ASSERT_TRUE(again.violation);
  EXPECT_EQ(metamorphicKind(again.violation->relation), it->kind);
  EXPECT_GT(withRelations.metamorphic.total().run(), 0);
  EXPECT_GT(withRelations.metamorphic.total().skipped(), 0);
  EXPECT_NE(progress.str().find("--metamorphic"), std::string::npos);  // in the reproduce command
}

// `check --metamorphic` from the command line, with an engine in another process that has the
// same fault (tests/data/engines/far-from-the-part.py): exit 1 and a metamorphic finding; without
// --metamorphic the check passes.
TEST_F(CheckRun, MetamorphicOnTheCommandLine) {
  const std::string engine = "--engine 'process:python3 " + source("tests/data/engines/far-from-the-part.py") + " " +
                             cli() + "'";
  fs::copy_file(source("specs/rules.json"), dir_ / "specs/rules.json");
  const std::string common = " --specs " + (dir_ / "specs").string() + " --no-regressions --out ";
  const auto run = [&](const std::string& args) {
    return std::system((cli() + " check " + engine + common + args + " >" + (dir_ / "stdout.txt").string() + " 2>&1").c_str());
  };
  const int plain = run((dir_ / "plain").string());
  EXPECT_TRUE(WIFEXITED(plain) && WEXITSTATUS(plain) == 0) << source("") << plain;
  const int withRelations = run((dir_ / "out").string() + " --metamorphic");
  std::ifstream stdoutFile(dir_ / "stdout.txt");
  const std::string printed((std::istreambuf_iterator<char>(stdoutFile)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(WIFEXITED(withRelations) && WEXITSTATUS(withRelations) == 1) << printed;
  EXPECT_NE(printed.find("metamorphic relations: "), std::string::npos) << printed;
  bool found = false;
  for (const nlohmann::json& line : results()) {
    for (const auto& f : line["findings"]) found = found || f["oracle"] == "metamorphic:translate-z";
  }
  EXPECT_TRUE(found) << printed;
  std::ifstream counts(dir_ / "out/metamorphic.json");
  const nlohmann::json tally = nlohmann::json::parse(counts);
  EXPECT_GE(tally["relations"]["translate-z"]["violated"], 1);
  // The report carries the counts (report.json "metamorphic") and shows them; the plain run's does not.
  std::ifstream reportFile(dir_ / "out/report.json");
  const nlohmann::json report = nlohmann::json::parse(reportFile);
  ASSERT_TRUE(report.contains("metamorphic"));
  EXPECT_EQ(report["metamorphic"]["relations"]["translate-z"]["violated"], tally["relations"]["translate-z"]["violated"]);
  std::ifstream plainReport(dir_ / "plain/report.json");
  EXPECT_FALSE(nlohmann::json::parse(plainReport).contains("metamorphic"));
  std::ifstream html(dir_ / "out/index.html");
  const std::string page((std::istreambuf_iterator<char>(html)), std::istreambuf_iterator<char>());
  EXPECT_NE(page.find("<h2>Metamorphic relations</h2>"), std::string::npos);
  EXPECT_NE(page.find("<code>translate-z</code>"), std::string::npos);
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

std::string output(const std::string& command, int& exitCode) {
  FILE* pipe = ::popen(command.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, pipe)) out.append(buf, n);
  const int status = ::pclose(pipe);
  exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

// `diff --metamorphic`: each engine against itself. The mutant that reads a Haas program with the
// wrong controller's reader agrees with the reference on the 0i-F case, and fails haas-one-block.
TEST(MetamorphicDiff, ShowsEachEnginesRelationsAndFailsOnAViolation) {
  const std::string input = source("specs/cases/fanuc-0i-f/g71/css-g96-in-shape.json");
  int code = 0;
  const std::string plain = output(std::string(CYCLECERT_CLI) + " diff --engine mutant:pocket-order --vs reference " + input, code);
  EXPECT_EQ(code, 0) << plain;
  const std::string text =
      output(std::string(CYCLECERT_CLI) + " diff --engine mutant:pocket-order --vs reference " + input + " --metamorphic", code);
  EXPECT_EQ(code, 1) << text;
  EXPECT_NE(text.find("metamorphic:haas-one-block (HAAS.G71.FMT"), std::string::npos) << text;
  EXPECT_NE(text.find("metamorphic relations on reference: "), std::string::npos) << text;
  const std::string json = output(
      std::string(CYCLECERT_CLI) + " diff --engine mutant:pocket-order --vs reference " + input + " --metamorphic --json", code);
  const nlohmann::json j = nlohmann::json::parse(json);
  EXPECT_EQ(j["metamorphic"]["mutant:pocket-order"]["violations"][0]["relation"], "haas-one-block");
  EXPECT_EQ(j["metamorphic"]["mutant:pocket-order"]["violations"][0]["follow_up"]["profile"], "haas");
  EXPECT_TRUE(j["metamorphic"]["reference"]["violations"].empty());
  EXPECT_GT(j["metamorphic"]["reference"]["counts"]["held"], 10);
}

}  // namespace
}  // namespace cyclecert
