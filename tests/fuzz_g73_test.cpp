// `cyclecert fuzz --cycles`: G73 cases (pattern repeating) — drawn only when asked for, so that the
// default run's cases stay as they were; covering shapes that are not monotone, d, Δi, Δk, the four
// quadrants and each invalid parameter with its alarm; written as the FANUC manual's two blocks
// (programs checked against hand-written text); answered by the reference as the rules say; the
// three G73 mutants caught by `check` on the spec cases and by the fuzzer; the verdict of a case the
// oracles refuse to judge; shrinking.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <sstream>

#include "harness/engines/engine.h"
#include "harness/engines/reference_plan.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/fuzz/regression_case.h"
#include "harness/run/check_run.h"
#include "harness/spec/spec_case.h"
#include "tests/cli_fixture.h"
#include "tests/fuzz_fixture.h"

namespace cyclecert {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 737373;
const FuzzCycles kG73 = {FuzzCycle::G73};

std::vector<FuzzCase> g73Sample(long n) { return fuzzSample(kSeed, n, kG73); }

std::string scratch(const std::string& name) { return scratchFolder("g73", name); }

TEST(FuzzCycles, NamesParse) {
  EXPECT_EQ(parseFuzzCycles("g73"), kG73);
  EXPECT_EQ(parseFuzzCycles("g71,g72"), kDefaultFuzzCycles);
  EXPECT_EQ(parseFuzzCycles("all"), (FuzzCycles{FuzzCycle::G71, FuzzCycle::G72, FuzzCycle::G73}));
  EXPECT_EQ(parseFuzzCycles("g73,g71,g73"), (FuzzCycles{FuzzCycle::G73, FuzzCycle::G71}));
  EXPECT_EQ(fuzzCyclesText({FuzzCycle::G71, FuzzCycle::G72, FuzzCycle::G73}), "g71,g72,g73");
  try {
    parseFuzzCycles("g71,g74");
    FAIL() << "g74 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown cycle 'g74' in 'g71,g74'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("g71, g72, g73 or all"), std::string::npos) << e.what();
  }
  EXPECT_THROW(parseFuzzCycles(""), std::invalid_argument);
}

// The default draws what it always drew; one of G71/G72 alone keeps every other draw of a case, so
// the G71 cases of the default run are the cases of a G71-only run with the same seeds.
TEST(FuzzCycles, OneOfG71AndG72KeepsTheOtherDraws) {
  int g71 = 0;
  for (long i = 0; i < 200; ++i) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i);
    const FuzzCase both = generateFuzzCase(seed);
    EXPECT_EQ(fuzzProgram(both), fuzzProgram(generateFuzzCase(seed, kDefaultCycleFormats, kDefaultFuzzCycles)));
    const FuzzCase only71 = generateFuzzCase(seed, kDefaultCycleFormats, {FuzzCycle::G71});
    const FuzzCase only72 = generateFuzzCase(seed, kDefaultCycleFormats, {FuzzCycle::G72});
    EXPECT_EQ(only71.cycle, 71);
    EXPECT_EQ(only72.cycle, 72);
    if (both.cycle == 71) {
      ++g71;
      EXPECT_EQ(fuzzProgram(both), fuzzProgram(only71));
    } else {
      EXPECT_EQ(fuzzProgram(both), fuzzProgram(only72));
    }
  }
  EXPECT_GT(g71, 50);
  EXPECT_LT(g71, 150);
}

TEST(FuzzCycles, G73WithTheOthersIsOneCaseInThree) {
  std::map<int, int> cycles;
  for (long i = 0; i < 900; ++i) {
    ++cycles[generateFuzzCase(fuzzCaseSeed(kSeed, i), kDefaultCycleFormats, parseFuzzCycles("g71,g72,g73")).cycle];
  }
  EXPECT_GT(cycles[73], 220);
  EXPECT_LT(cycles[73], 380);
  EXPECT_GT(cycles[71], 200);
  EXPECT_GT(cycles[72], 200);
}

TEST(FuzzG73Generator, CoversShapesDivisionsReliefsQuadrantsAndFaults) {
  std::map<std::string, int> seen;
  for (const FuzzCase& c : g73Sample(2000)) {
    ASSERT_EQ(c.cycle, 73);
    ++seen[std::string("quadrant ") + (c.mirrorCut ? "1" : "0") + (c.mirrorDepth ? "1" : "0")];
    ++seen[c.profile];
    ++seen[c.divisions == 1 ? "d = 1" : c.divisions >= 5 ? "d >= 5" : "d 2-4"];
    if (c.reliefDepth == 0) ++seen["no relief along x"];
    if (c.reliefCut == 0) ++seen["no relief along z"];
    if (c.reliefDepth > 0 && c.reliefCut > 0) ++seen["relief along both"];
    if (c.allowanceDepth == 0 && c.allowanceCut == 0) ++seen["no allowance"];
    if (c.finish) ++seen["G70"];
    ++seen["head G0" + std::to_string(c.headMotion)];
    if (c.headMotion == 0) {
      EXPECT_EQ(c.reliefCut, 0) << "a G00 block ns only without Δk";
    }
    ++seen["fault " + std::to_string(static_cast<int>(c.g73Fault))];
    bool down = false;
    for (const FuzzSegment& s : c.segments) {
      if (s.up < 0 && s.along > 0) down = true;
      if (s.kind == FuzzSegment::ConvexArc) ++seen[s.up < 0 ? "convex arc down" : "convex arc up"];
      if (s.kind == FuzzSegment::ConcaveArc) ++seen[s.up < 0 ? "concave arc down" : "concave arc up"];
      EXPECT_GE(s.along, 0);
      if (s.along == 0) {
        EXPECT_GE(s.up, 0) << "a step goes up only";
      }
    }
    if (down) ++seen["not monotone"];
    // The relief and the allowance point away from the part on every segment (G73.PASS.SHIFT): a
    // segment going down by u over a length a takes at most a·Δi/u along the cut axis, an arc going
    // down none (its vertical tangent).
    for (const FuzzSegment& s : c.segments) {
      if (s.up >= 0) continue;
      if (s.kind != FuzzSegment::Line) {
        EXPECT_EQ(c.reliefCut, 0) << "an arc going down with Δk";
        EXPECT_EQ(c.allowanceCut, 0) << "an arc going down with Δw";
      } else {
        EXPECT_LE(static_cast<long>(c.reliefCut) * -s.up, static_cast<long>(c.reliefDepth) * s.along);
        EXPECT_LE(static_cast<long>(c.allowanceCut) * -s.up, static_cast<long>(c.allowanceDepth) * s.along);
      }
    }
    // C is the shape's highest point.
    int depth = 0, top = 0;
    for (const FuzzSegment& s : c.segments) top = std::max(top, depth += s.up);
    EXPECT_EQ(depth, top);
  }
  for (const char* what :
       {"quadrant 00", "quadrant 01", "quadrant 10", "quadrant 11", "fanuc-0i-f", "fanuc-0i-c", "gsk", "d = 1",
        "d 2-4", "d >= 5", "no relief along x", "no relief along z", "relief along both", "no allowance", "G70",
        "head G00", "head G01", "fault 0", "fault 1", "fault 2", "fault 3", "fault 4", "convex arc down",
        "convex arc up", "concave arc down", "concave arc up", "not monotone"}) {
    EXPECT_GE(seen[what], 20) << what;
  }
  EXPECT_GT(seen["fault 0"], 1600);  // one case in ten has a fault
}

// The program of a case built by hand, against the text the manual's format gives (G73.FMT):
// outer, d 3, Δi 3 (a radius: U3), Δk 0.5, Δu/2 0.2 (U0.4), Δw 0.1; B (z 1, x 15), a line down
// and a convex arc up, a step up to C; A 0.5 above the blank's top and 0.2 ahead of it.
TEST(FuzzG73Generator, WritesTheManualsTwoBlocks) {
  FuzzCase c;
  c.cycle = 73;
  c.startAlong = 100;
  c.b = 1500;
  c.segments = {{FuzzSegment::Line, 1000, -200}, {FuzzSegment::ConvexArc, 500, 500}, {FuzzSegment::Line, 0, 300}};
  c.reliefDepth = 300;
  c.reliefCut = 50;
  c.divisions = 3;
  c.allowanceDepth = 20;
  c.allowanceCut = 10;
  c.startAbove = 50;
  c.startAhead = 20;
  c.headMotion = 1;
  c.finish = true;
  // Frame depths (radius): B 15, then 13, 18, C 21 = the top; A at 21 + 3 + 0.2 + 0.5 = 24.7. The
  // lowest point (13) is placed at radius 1 mm: X = 2·(depth − 12), so B X6, A X25.4, X2, X12, X18.
  // Along Z: A at 1 + 0.5 + 0.1 + 0.2 = 1.8; B at 1, then −9, −14, −14.
  EXPECT_EQ(fuzzProgram(c),
            "G00 X25.4 Z1.8;\n"
            "G73 U3 W0.5 R3;\n"
            "G73 P10 Q20 U0.4 W0.1 F0.2;\n"
            "N10 G01 X6 Z1;\n"
            "G01 X2 Z-9;\n"
            "G03 X12 Z-14 R5;\n"
            "N20 G01 X18 Z-14;\n"
            "G70 P10 Q20;\n"
            "M30;\n");
  EXPECT_EQ(describeFuzzCase(c), "G73, outer, cut forward, 3 segment(s), fanuc-0i-f, d 3, Δi 3 Δk 0.5, Δu/2 0.2 Δw 0.1, G70");
  // Inner, towards +Z: the reliefs and allowances change sign with their axis; the arc's sense flips twice.
  c.mirrorDepth = c.mirrorCut = true;
  c.finish = false;
  const std::string inner = fuzzProgram(c);
  EXPECT_NE(inner.find("G73 U-3 W-0.5 R3;\nG73 P10 Q20 U-0.4 W-0.1 F0.2;\n"), std::string::npos) << inner;
  EXPECT_NE(inner.find("G03 "), std::string::npos) << inner;
  // The faults, one at a time, and the alarm each expects.
  c.g73Fault = G73Fault::NoDivisions;
  EXPECT_NE(fuzzProgram(c).find("G73 U-3 W-0.5 R0;"), std::string::npos);
  EXPECT_EQ(expectedAlarm(c)->code, "PS0062");
  EXPECT_EQ(expectedAlarm(c)->line, 2);
  c.g73Fault = G73Fault::FractionalDivisions;
  EXPECT_NE(fuzzProgram(c).find(" R2.5;"), std::string::npos);
  c.g73Fault = G73Fault::MissingQ;
  EXPECT_NE(fuzzProgram(c).find("G73 P10 U-0.4"), std::string::npos);
  EXPECT_EQ(expectedAlarm(c)->line, 3);
  c.g73Fault = G73Fault::ArcHead;
  EXPECT_NE(fuzzProgram(c).find("N10 G02 "), std::string::npos);
  EXPECT_EQ(expectedAlarm(c)->line, 4);
  const SpecCase spec = fuzzSpecCase(c, "t");
  EXPECT_EQ(spec.id, "fanuc-0i-f/g73/fuzz-t");
  ASSERT_TRUE(spec.expectedAlarm);
  EXPECT_FALSE(spec.oraclesOnly);
  c.g73Fault = G73Fault::None;
  EXPECT_FALSE(expectedAlarm(c));
  EXPECT_TRUE(fuzzSpecCase(c, "t").oraclesOnly);
}

// The reference plans every valid case (d passes, each with its return to A, and the last at the
// allowance) and raises exactly the alarm of every invalid one.
TEST(FuzzG73Generator, TheReferenceAnswersEveryCaseAsTheRulesSay) {
  for (const FuzzCase& c : g73Sample(600)) {
    const SpecCase spec = fuzzSpecCase(c, "t");
    SCOPED_TRACE(spec.program);
    Toolpath t;
    ASSERT_NO_THROW(t = planSpecCase(spec));
    if (const auto alarm = expectedAlarm(c)) {
      ASSERT_TRUE(t.alarm);
      EXPECT_EQ(t.alarm->code, alarm->code);
      EXPECT_EQ(t.alarm->line, alarm->line);
      continue;
    }
    ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
    int returns = 0;
    for (const Move& m : t.moves) returns += std::find(m.rules.begin(), m.rules.end(), "G73.RETURN") != m.rules.end();
    EXPECT_EQ(returns, c.divisions);
  }
}

// A case the oracles refuse (G73 today) is not applicable, unless its expected alarm was met (pass)
// or, with --vs, the engines disagree (fail); an expected alarm not raised fails as "expected-alarm".
TEST(FuzzG73Verdicts, RefusedCasesAreComparedAndAlarmsJudged) {
  auto reference = makeEngine("reference");
  auto other = makeEngine("reference");
  auto relief = makeEngine("mutant:g73-relief-sign");
  auto divisions = makeEngine("mutant:g73-divisions");
  FuzzCase c = g73Sample(1).front();
  c.g73Fault = G73Fault::None;
  c.divisions = 3;
  c.reliefDepth = 200;
  const SpecCase valid = fuzzSpecCase(c, "t");
  const FuzzVerdict alone = judgeFuzzCase(*reference, nullptr, valid, 1e-3);
  EXPECT_NE(alone.verdict, "fail") << alone.detail;
  EXPECT_EQ(judgeFuzzCase(*reference, other.get(), valid, 1e-3).verdict, alone.verdict);
  const FuzzVerdict vs = judgeFuzzCase(*relief, reference.get(), valid, 1e-3);
  EXPECT_EQ(vs.verdict, "fail") << vs.detail;
  c.g73Fault = G73Fault::NoDivisions;  // R0: PS0062 from both; with R−1 too
  const SpecCase r0 = fuzzSpecCase(c, "t");
  EXPECT_EQ(judgeFuzzCase(*reference, nullptr, r0, 1e-3).verdict, "pass");
  c.g73Fault = G73Fault::FractionalDivisions;
  EXPECT_EQ(judgeFuzzCase(*divisions, nullptr, fuzzSpecCase(c, "t"), 1e-3).verdict, "pass");  // R1.5: PS0003 still
  // A mutant that raises no alarm where one is expected.
  c.g73Fault = G73Fault::None;
  c.divisions = 1;  // the mutant reads R0: PS0062 where the case expects a plan — judged by the oracles/--vs
  const FuzzVerdict missing = judgeFuzzCase(*divisions, reference.get(), fuzzSpecCase(c, "t"), 1e-3);
  EXPECT_EQ(missing.verdict, "fail") << missing.detail;
  SpecCase wrongAlarm = fuzzSpecCase(c, "t");
  wrongAlarm.oraclesOnly = false;  // as fuzzSpecCase writes a case with an expected alarm
  wrongAlarm.expectedAlarm = ExpectedAlarm{};
  wrongAlarm.expectedAlarm->code = "PS0061";
  wrongAlarm.expectedAlarm->line = 3;
  const FuzzVerdict unmet = judgeFuzzCase(*reference, nullptr, wrongAlarm, 1e-3);
  EXPECT_EQ(unmet.verdict, "fail");
  EXPECT_EQ(unmet.kind, "expected-alarm");
}

// The reference is clean on G73 cases through the whole fuzz run, compared with itself.
TEST(FuzzG73, TheReferenceRunsCleanOnG73Cases) {
  auto reference = makeEngine("reference");
  FuzzOptions o;
  o.seed = kSeed;
  o.cases = 400;
  o.cycles = kG73;
  o.outDir = scratch("reference");
  std::ostringstream progress;
  const FuzzSummary s = runFuzz(*reference, makeEngine("reference").get(), o, progress);
  fs::remove_all(o.outDir);
  EXPECT_EQ(s.run, 400);
  EXPECT_EQ(s.fail, 0) << progress.str();
  EXPECT_EQ(s.engineFailure, 0) << progress.str();
  EXPECT_GT(s.pass, 20) << progress.str();  // the alarm cases at least
}

// Each G73 mutant fails the G73 spec cases under `check` (their hand-derived expectations) and is
// found by the default fuzz budget of G73 cases (with --vs reference while the oracles refuse G73;
// once they judge it, by them first), shrunk to a G73 case no larger, with a reproduce command that
// names the cycles; the kept regression case is a G73 case.
TEST(FuzzG73, EveryG73MutantIsCaughtByCheckAndByTheFuzzer) {
  auto reference = makeEngine("reference");
  for (const char* name : {"mutant:g73-divisions", "mutant:g73-relief-sign", "mutant:g73-last-pass-allowance"}) {
    SCOPED_TRACE(name);
    auto engine = makeEngine(name);
    ASSERT_TRUE(engine);
    const SpecSuiteRun checked = checkTheSpecSuite(*engine, scratch("check"));
    EXPECT_GE(checked.summary.fail, 3) << checked.progress;

    FuzzOptions o;
    o.seed = kSeed;
    o.cases = kDefaultFuzzCases;
    o.cycles = kG73;
    o.maxFailures = 1;
    o.shrinkBudget = 60;
    o.outDir = scratch("out");
    o.regressionsDir = scratch("regressions");
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(*engine, reference.get(), o, progress);
    ASSERT_EQ(s.failures.size(), 1u) << progress.str();
    const FuzzFailure& f = s.failures.front();
    EXPECT_EQ(f.shrunk.cycle, 73);
    EXPECT_LE(f.shrunk.segments.size(), generateFuzzCase(f.caseSeed, kDefaultCycleFormats, kG73).segments.size());
    EXPECT_NE(progress.str().find("--cycles g73"), std::string::npos) << progress.str();
    ASSERT_FALSE(f.regressionFile.empty());
    EXPECT_NE(f.regressionFile.find("/g73/"), std::string::npos) << f.regressionFile;
    const SpecCase kept = loadSpecCase(f.regressionFile);
    EXPECT_NE(kept.program.find("G73 "), std::string::npos) << kept.program;
    for (const std::string& dir : {o.outDir, o.regressionsDir}) fs::remove_all(dir);
  }
}

// The G73 mutants change G73 only: in G code system C, G73 is G71's roughing (its R is e, its U
// Δd), and a system C G75 is the pattern repeating cycle they change.
TEST(FuzzG73, TheG73MutantsReadTheProgramsGCodeSystem) {
  const SpecCase g71InSystemC =
      loadSpecCase(CYCLECERT_SOURCE_DIR "/specs/cases/fanuc-0i-f/program/gsys-c-g73-g71-metric.json");
  auto reference = makeEngine("reference");
  const Toolpath expected = reference->run(g71InSystemC).path;
  ASSERT_FALSE(expected.moves.empty());
  SpecCase g75 = loadSpecCase(CYCLECERT_SOURCE_DIR "/specs/cases/fanuc-0i-f/g73/d2-two-passes.json");
  g75.params.push_back({"3401#7", 1});
  g75.program = "G90 G95;\n" + g75.program;
  for (std::size_t at; (at = g75.program.find("G73")) != std::string::npos;) g75.program.replace(at, 3, "G75");
  const Toolpath g75Planned = reference->run(g75).path;
  ASSERT_FALSE(g75Planned.alarm);
  for (const char* name : {"mutant:g73-divisions", "mutant:g73-relief-sign"}) {
    SCOPED_TRACE(name);
    const EngineResult r = makeEngine(name)->run(g71InSystemC);
    EXPECT_FALSE(r.path.alarm);
    EXPECT_EQ(r.path.moves.size(), expected.moves.size());
    for (std::size_t i = 0; i < std::min(r.path.moves.size(), expected.moves.size()); ++i) {
      EXPECT_LE(distance(r.path.moves[i].to, expected.moves[i].to), 1e-9) << "move " << i;
    }
    const Toolpath mutated = makeEngine(name)->run(g75).path;
    bool differs = mutated.moves.size() != g75Planned.moves.size();
    for (std::size_t i = 0; !differs && i < mutated.moves.size(); ++i) {
      differs = distance(mutated.moves[i].to, g75Planned.moves[i].to) > 1e-6;
    }
    EXPECT_TRUE(differs) << "the system C G75 is G73: the mutant changes it";
  }
}

// A shrunk failure of an alarm case keeps the alarm it must raise (not "every oracle passes").
TEST(FuzzG73, AnAlarmCaseIsKeptWithItsAlarm) {
  FuzzFailure f;
  f.caseSeed = 7;
  f.kind = "expected-alarm";
  f.detail = "…";
  f.shrunk = g73Sample(1).front();
  f.shrunk.g73Fault = G73Fault::MissingQ;
  const std::string dir = scratch("alarm-kept");
  const SpecCase kept = loadSpecCase(writeRegressionCase(dir, f, "process:x", "", {"G73.FMT"}, "cyclecert fuzz …"));
  fs::remove_all(dir);
  ASSERT_TRUE(kept.expectedAlarm);
  EXPECT_EQ(kept.expectedAlarm->code, "PS0061");
  EXPECT_EQ(kept.expectedAlarm->line, 3);
  EXPECT_FALSE(kept.oraclesOnly);
  EXPECT_NE(kept.derivation.find("the alarm its rule names"), std::string::npos) << kept.derivation;
}

class FuzzG73Cli : public CliFixture {};

TEST_F(FuzzG73Cli, CyclesOptionDrawsG73AndBadNamesExitWith2) {
  const std::string out = path("g73-out");
  const CliRun r = run("fuzz --engine reference --cycles g73 --cases 50 --seed 3 --no-save --out " + out);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(read(out + "/results.jsonl").find("G73"), std::string::npos);
  const CliRun bad = run("fuzz --engine reference --cycles g71,g74 --cases 1 --out " + path("bad"));
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("--cycles: unknown cycle 'g74'"), std::string::npos) << bad.err;
  EXPECT_NE(run("fuzz --help").out.find("--cycles LIST"), std::string::npos);
  // run.json records the cycles: resuming with others is another campaign, refused and named.
  EXPECT_NE(read(out + "/run.json").find("\"cycles\": \"g73\""), std::string::npos) << read(out + "/run.json");
  const CliRun other = run("fuzz --engine reference --cases 60 --seed 3 --no-save --resume --out " + out);
  EXPECT_EQ(other.exitCode, 2) << other.out << other.err;
  EXPECT_NE(other.err.find("cycles g73 in"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("g71,g72 in this run"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("(--cycles g73)"), std::string::npos) << other.err;
  const CliRun more = run("fuzz --engine reference --cycles g73 --cases 60 --seed 3 --no-save --resume --out " + out);
  EXPECT_EQ(more.exitCode, 0) << more.out << more.err;
  EXPECT_NE(more.out.find("50 already done"), std::string::npos) << more.out;
}

// run.json records --metamorphic: a resume with and without the relations is another campaign,
// refused and named (the relations judge the cases more strictly: the two would mix in one report).
TEST_F(FuzzG73Cli, ResumingWithoutTheRelationsARunMadeWithThemIsAnotherCampaign) {
  const std::string out = path("meta-out");
  const CliRun first = run("fuzz --engine reference --cycles g73 --cases 20 --seed 3 --no-save --metamorphic --out " + out);
  EXPECT_EQ(first.exitCode, 0) << first.out << first.err;
  EXPECT_NE(read(out + "/run.json").find("\"metamorphic\": true"), std::string::npos) << read(out + "/run.json");
  const CliRun other = run("fuzz --engine reference --cycles g73 --cases 40 --seed 3 --no-save --resume --out " + out);
  EXPECT_EQ(other.exitCode, 2) << other.out << other.err;
  EXPECT_NE(other.err.find("metamorphic on in"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("off in this run"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("(with --metamorphic)"), std::string::npos) << other.err;
  const CliRun more = run("fuzz --engine reference --cycles g73 --cases 40 --seed 3 --no-save --resume --metamorphic --out " + out);
  EXPECT_EQ(more.exitCode, 0) << more.out << more.err;
}

}  // namespace
}  // namespace cyclecert
