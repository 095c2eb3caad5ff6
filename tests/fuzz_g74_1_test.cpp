// `cyclecert fuzz --cycles g74.1`: GSK G74.1 groove cases — drawn only when asked for; covering
// the four directions of h and d, the angles, the corners, layers, allowances, the tool width (and
// none), J0/1/2 and both units of P/Q; written as seed 002's two blocks (checked against
// hand-written text); planned by the reference without NotSupported, the valid ones without alarm
// (the groove fits the tool), each invalid one with exactly the alarm docs/g74_1.md §1 names; the
// three G74.1 mutants caught by `check` on the spec cases and differing from the reference on
// generated cases; shrinking.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>

#include "harness/engines/engine.h"
#include "harness/engines/reference_plan.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/fuzz/g74_1_case_generator.h"
#include "harness/run/check_run.h"
#include "harness/spec/spec_case.h"
#include "reference/model/alarms.h"
#include "tests/cli_fixture.h"
#include "tests/fuzz_fixture.h"

namespace cyclecert {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 741741;
const FuzzCycles kG74_1 = {FuzzCycle::G74_1};

std::vector<FuzzCase> grooveSample(long n) { return fuzzSample(kSeed, n, kG74_1); }

std::string scratch(const std::string& name) { return scratchFolder("g74_1", name); }

bool cites(const Move& m, const char* rule) { return std::find(m.rules.begin(), m.rules.end(), rule) != m.rules.end(); }

TEST(FuzzG74_1Cycles, NamesParseAndAllKeepsItsMeaning) {
  EXPECT_EQ(parseFuzzCycles("g74.1"), kG74_1);
  EXPECT_EQ(parseFuzzCycles("g74_1"), kG74_1);
  EXPECT_EQ(parseFuzzCycles("g71,g74_1,g74.1"), (FuzzCycles{FuzzCycle::G71, FuzzCycle::G74_1}));
  EXPECT_EQ(fuzzCyclesText(kG74_1), "g74.1");
  // "all" is the FANUC families it always was, so a seed keeps its cases.
  EXPECT_EQ(parseFuzzCycles("all"), (FuzzCycles{FuzzCycle::G71, FuzzCycle::G72, FuzzCycle::G73}));
  try {
    parseFuzzCycles("g74");
    FAIL() << "g74 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("g74.1 (or g74_1"), std::string::npos) << e.what();
  }
}

// Asked for with others, G74.1 is drawn in proportion (one case in three beside G71 and G72); asked
// for alone, every case is G74.1 on profile gsk.
TEST(FuzzG74_1Cycles, DrawnInProportionWithTheOthers) {
  std::map<int, int> cycles;
  for (long i = 0; i < 900; ++i) {
    ++cycles[generateFuzzCase(fuzzCaseSeed(kSeed, i), kDefaultCycleFormats, parseFuzzCycles("g71,g72,g74.1")).cycle];
  }
  EXPECT_GT(cycles[741], 220);
  EXPECT_LT(cycles[741], 380);
  EXPECT_GT(cycles[71] + cycles[72], 520);
  for (const FuzzCase& c : grooveSample(50)) {
    EXPECT_EQ(c.cycle, 741);
    EXPECT_EQ(c.profile, "gsk");
    EXPECT_EQ(fuzzCaseFolder(c), "gsk/g74_1");
  }
}

TEST(FuzzG74_1Generator, CoversDirectionsAnglesCornersLayersToolsPathTypesUnitsAndFaults) {
  std::map<std::string, int> seen;
  for (const FuzzCase& c : grooveSample(2000)) {
    const G74_1FuzzCase& g = c.groove;
    ++seen[std::string("h") + (g.depth < 0 ? "-" : "+") + " d" + (g.width < 0 ? "-" : "+")];
    ++seen["J" + std::to_string(g.pathType)];
    if (g.writeJ) ++seen["J0 written"];
    ++seen[g.stepsInMm ? "P/Q in mm" : "P/Q in increments"];
    ++seen[g.toolWidth > 0 ? "grooving tool" : "pointed tool"];
    if (g.angleA < 90) ++seen["sharp a"];
    if (g.angleB < 90) ++seen["sharp b"];
    if (g.angleA == 90 && g.angleB == 90) ++seen["straight flanks"];
    if (g.slope > 0) ++seen["slope"];
    if (g.layerDepth > 0 && g.layerDepth < std::abs(g.depth)) ++seen["several layers"];
    if (g.layerDepth >= std::abs(g.depth)) ++seen["V, one layer"];
    if (g.allowanceX != 0) ++seen["du"];
    if (g.allowanceZ != 0) ++seen["dw"];
    if (g.allowanceX < 0 || g.allowanceZ < 0) ++seen["negative allowance"];
    if (std::any_of(g.corners.begin(), g.corners.end(), [](int r) { return r > 0; })) {
      ++seen[g.cornerKinds < 0 ? "corners, no P" : g.cornerKinds == 0 ? "corners P0000" : "corners with rounds"];
    }
    ++seen["fault " + std::to_string(static_cast<int>(g.fault))];
    EXPECT_GT(g.radialStep, 0);
    EXPECT_GT(g.peck, 0);
    EXPECT_GE(g.retract, 0);
    if (g.fault == G74_1Fault::None || g.fault == G74_1Fault::SlopeNotBelowFlank) {
      EXPECT_LT(g.slope, g.fault == G74_1Fault::None ? g.angleA : 90);
    }
  }
  for (const char* what : {"h- d-", "h- d+", "h+ d-", "h+ d+", "J0", "J1", "J2", "J0 written", "P/Q in mm",
                           "P/Q in increments", "grooving tool", "pointed tool", "sharp a", "sharp b", "straight flanks",
                           "slope", "several layers", "V, one layer", "du", "dw", "negative allowance", "corners, no P",
                           "corners with rounds"}) {
    EXPECT_GE(seen[what], 20) << what;
  }
  for (int f = 1; f <= static_cast<int>(G74_1Fault::SlopeNotBelowFlank); ++f) {
    EXPECT_GE(seen["fault " + std::to_string(f)], 3) << "fault " << f;
  }
  EXPECT_GT(seen["fault 0"], 1700);  // one case in ten has a fault
  EXPECT_LT(seen["fault 0"], 1900);
}

// The program of a case built by hand, against the text seed 002's format gives: O0008's groove
// (X66 Z0 P30000 Q50000 H-10 D-20 A45 B60) with the example's 4 mm tool, Δv 4, allowances, J1 and
// corners; then in mm (182#7 = 1) and with each fault's spelling.
TEST(FuzzG74_1Generator, WritesSeed002sTwoBlocks) {
  FuzzCase c;
  c.cycle = 741;
  c.profile = "gsk";
  G74_1FuzzCase& g = c.groove;
  g.beforeX = 7000;
  g.beforeZ = 1000;
  g.startX = 6600;
  g.startZ = 0;
  g.depth = -1000;
  g.width = -2000;
  g.angleA = 45;
  g.angleB = 60;
  g.radialStep = 300;
  g.peck = 500;
  g.retract = 50;
  g.layerDepth = 400;
  g.allowanceX = 20;
  g.allowanceZ = -10;
  g.toolWidth = 400;
  g.pathType = 1;
  g.corners = {50, 0, 30, 0};
  g.cornerKinds = 0b0010;
  EXPECT_EQ(fuzzProgram(c),
            "G00 X70 Z10 F0.1;\n"
            "G74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\n"
            "G74.1 R0.5 V4 U0.2 W-0.1 I4 J1 A0.5 D0.3 P0010;\n"
            "M30;\n");
  EXPECT_EQ(describeFuzzCase(c),
            "G74.1, h − d −, |h| 10 |d| 20, ∠a 45 ∠b 60 ∠p 0, 2 corner(s) P0010, Δi 3 Δk 5 e 0.5, Δv 4, Δu 0.2 Δw "
            "-0.1, I 4, J1, P/Q in increments");
  EXPECT_FALSE(expectedAlarm(c));
  const SpecCase spec = fuzzSpecCase(c, "t");
  EXPECT_EQ(spec.id, "gsk/g74_1/fuzz-t");
  EXPECT_TRUE(spec.oraclesOnly);
  EXPECT_TRUE(spec.params.empty());
  g.stepsInMm = true;
  g.writeAngles = true;
  EXPECT_NE(fuzzProgram(c).find("G74.1 X66 Z0 P3 Q5 H-10 D-20 A45 B60 L0;\n"), std::string::npos) << fuzzProgram(c);
  const SpecCase inMm = fuzzSpecCase(c, "t");
  ASSERT_EQ(inMm.params.size(), 1u);
  EXPECT_EQ(inMm.params.front().first, "182#7");
  // Each fault's word, and the alarm it expects at its block.
  const struct {
    G74_1Fault fault;
    int variant;
    const char* text;
    const char* code;
    int line;
  } faults[] = {
      {G74_1Fault::DepthOut, 0, " H0 ", "PS0003", 2},
      {G74_1Fault::DepthOut, 1, " H-10000 ", "PS0003", 2},
      {G74_1Fault::DepthOut, 2, "Q5 D-20", "PS0003", 2},
      {G74_1Fault::WidthOut, 1, " D-10000 ", "PS0003", 2},
      {G74_1Fault::AngleAOut, 1, " A95 ", "PS0003", 2},
      {G74_1Fault::AngleBOut, 1, " B90.5 ", "PS0003", 2},
      {G74_1Fault::SlopeOut, 0, " L90;", "PS0003", 2},
      {G74_1Fault::StepNotPositive, 0, " P0 ", "PS0062", 2},
      {G74_1Fault::StepNotPositive, 1, " Q-5 ", "PS0062", 2},
      {G74_1Fault::StepTooLarge, 0, " P10000 ", "PS0003", 2},
      {G74_1Fault::MissingPeck, 0, "P3 H-10", "PS0061", 2},
      {G74_1Fault::WordNotTaken, 0, " R1;", "PS0009", 2},
      {G74_1Fault::RetractOut, 0, "G74.1 R100 ", "PS0003", 3},
      {G74_1Fault::LayerNotPositive, 1, " V-1 ", "PS0062", 3},
      {G74_1Fault::AllowanceOut, 1, " U0.2 W-10000 ", "PS0003", 3},
      {G74_1Fault::ToolWidthOut, 0, " I10000 ", "PS0003", 3},
      {G74_1Fault::PathTypeOut, 0, " J3 ", "PS0003", 3},
      {G74_1Fault::CornerOut, 0, " A100 ", "PS0003", 3},
      {G74_1Fault::CornerDigitOut, 1, " P11111;", "PS0003", 3},
  };
  for (const auto& f : faults) {
    g.fault = f.fault;
    g.faultVariant = f.variant;
    SCOPED_TRACE(f.text);
    EXPECT_NE(fuzzProgram(c).find(f.text), std::string::npos) << fuzzProgram(c);
    ASSERT_TRUE(expectedAlarm(c));
    EXPECT_EQ(expectedAlarm(c)->code, f.code);
    EXPECT_EQ(expectedAlarm(c)->line, f.line);
    EXPECT_FALSE(fuzzSpecCase(c, "t").oraclesOnly);
  }
  g.stepsInMm = false;
  g.fault = G74_1Fault::DecimalPoint;
  EXPECT_NE(fuzzProgram(c).find(" P30000. Q50000 "), std::string::npos) << fuzzProgram(c);
  EXPECT_EQ(expectedAlarm(c)->code, "PS0007");
  g.fault = G74_1Fault::StepTooLarge;
  EXPECT_NE(fuzzProgram(c).find(" P100000000 "), std::string::npos) << fuzzProgram(c);
}

// The reference plans every case (no NotSupported, no crash): each valid one without alarm (the
// generator fits the groove to the tool: GrooveDoesNotFit never comes), with its return to where the
// tool stood and the passes J asks for; each invalid one with exactly its alarm at its block.
TEST(FuzzG74_1Generator, TheReferencePlansEveryCaseAndAlarmsOnEachInvalidOne) {
  std::set<std::string> codes;
  int valid = 0;
  for (const FuzzCase& c : grooveSample(600)) {
    const SpecCase spec = fuzzSpecCase(c, "t");
    SCOPED_TRACE(spec.program);
    Toolpath t;
    try {
      t = planSpecCase(spec);
    } catch (const NotSupported& e) {
      ADD_FAILURE() << "not supported: " << e.what();
      continue;
    }
    if (const auto alarm = expectedAlarm(c)) {
      ASSERT_TRUE(t.alarm);
      EXPECT_EQ(t.alarm->code, alarm->code) << t.alarm->message;
      EXPECT_EQ(t.alarm->line, alarm->line) << t.alarm->message;
      EXPECT_TRUE(t.moves.empty());
      codes.insert(alarm->code);
      continue;
    }
    ++valid;
    ASSERT_FALSE(t.alarm) << t.alarm->code << " " << t.alarm->message;
    ASSERT_FALSE(t.moves.empty());
    EXPECT_LE(t.moves.size(), 5000u) << "a case of a few thousand moves at most";
    const Point before{c.groove.beforeZ / 100.0, c.groove.beforeX / 200.0};
    EXPECT_LT(distance(t.moves.back().to, before), 1e-9) << "the tool returns where it stood";
    const bool rough = std::any_of(t.moves.begin(), t.moves.end(), [](const Move& m) { return cites(m, "G74_1.STEP9"); });
    const bool finish = std::any_of(t.moves.begin(), t.moves.end(), [](const Move& m) { return cites(m, "G74_1.STEP10") && m.kind == MoveKind::Feed; });
    EXPECT_EQ(rough, c.groove.pathType != 2);
    EXPECT_EQ(finish, c.groove.pathType != 0);
  }
  EXPECT_GT(valid, 480);
  EXPECT_EQ(codes, (std::set<std::string>{"PS0003", "PS0007", "PS0009", "PS0061", "PS0062"}));
}

// Each G74.1 mutant fails G74.1 spec cases under `check` (their hand-derived toolpaths), and the
// oracles alone (no `--vs`: the groove oracles, no-gouge and rapids-in-air with the blade) find it on
// generated cases, the first failure shrunk to a G74.1 case kept with its folder.
TEST(FuzzG74_1, EveryG74_1MutantIsCaughtByCheckAndByTheOraclesOnGeneratedCases) {
  for (const char* name : {"mutant:g74_1-retract-to-bottom", "mutant:g74_1-radial-step-full", "mutant:g74_1-tool-width-ignored"}) {
    SCOPED_TRACE(name);
    auto engine = makeEngine(name);
    ASSERT_TRUE(engine);
    const SpecSuiteRun checked = checkTheSpecSuite(*engine, scratch("check"));
    EXPECT_GE(checked.summary.fail, 3) << checked.progress;

    FuzzOptions o;
    o.seed = kSeed;
    o.cases = 400;
    o.cycles = kG74_1;
    o.maxFailures = 1;
    o.shrinkBudget = 60;
    o.outDir = scratch("out");
    o.regressionsDir = scratch("regressions");
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(*engine, nullptr, o, progress);
    ASSERT_EQ(s.failures.size(), 1u) << progress.str();
    const FuzzFailure& f = s.failures.front();
    EXPECT_EQ(f.shrunk.cycle, 741);
    EXPECT_NE(progress.str().find("--cycles g74.1"), std::string::npos) << progress.str();
    ASSERT_FALSE(f.regressionFile.empty());
    EXPECT_NE(f.regressionFile.find("gsk/g74_1/"), std::string::npos) << f.regressionFile;
    EXPECT_NE(loadSpecCase(f.regressionFile).program.find("G74.1 "), std::string::npos);
    for (const std::string& dir : {o.outDir, o.regressionsDir}) fs::remove_all(dir);
  }
}

// The mutants leave every other cycle as the reference plans it (their edits touch G74.1 only).
TEST(FuzzG74_1, TheG74_1MutantsLeaveOtherCyclesAlone) {
  auto reference = makeEngine("reference");
  for (long i = 0; i < 40; ++i) {
    const SpecCase c = fuzzSpecCase(generateFuzzCase(fuzzCaseSeed(kSeed, i)), "t");
    const Toolpath want = reference->run(c).path;
    for (const char* name : {"mutant:g74_1-retract-to-bottom", "mutant:g74_1-radial-step-full", "mutant:g74_1-tool-width-ignored"}) {
      const Toolpath got = makeEngine(name)->run(c).path;
      ASSERT_EQ(got.moves.size(), want.moves.size()) << name << "\n" << c.program;
      for (std::size_t k = 0; k < got.moves.size(); ++k) EXPECT_LT(distance(got.moves[k].to, want.moves[k].to), 1e-12) << name;
    }
  }
}

// Shrinking a G74.1 failure keeps a G74.1 case: a property that fails on every groove with a
// grooving tool shrinks to one with the smallest values RapidCheck reaches.
TEST(FuzzG74_1, ShrinksToASmallerGroove) {
  auto engine = makeEngine("mutant:g74_1-tool-width-ignored");
  auto reference = makeEngine("reference");
  FuzzOptions o;
  o.seed = kSeed + 1;
  o.cases = 200;
  o.cycles = kG74_1;
  o.maxFailures = 1;
  o.shrinkBudget = 200;
  o.outDir = scratch("shrink");
  o.regressionsDir = "";
  std::ostringstream progress;
  const FuzzSummary s = runFuzz(*engine, reference.get(), o, progress);
  fs::remove_all(o.outDir);
  ASSERT_EQ(s.failures.size(), 1u) << progress.str();
  const FuzzFailure& f = s.failures.front();
  const FuzzCase original = generateFuzzCase(f.caseSeed, kDefaultCycleFormats, kG74_1);
  EXPECT_GT(f.shrunk.groove.toolWidth, 0) << "the fault needs a tool width";
  EXPECT_LE(std::abs(f.shrunk.groove.depth), std::abs(original.groove.depth));
  EXPECT_LE(std::abs(f.shrunk.groove.width), std::abs(original.groove.width));
  EXPECT_GT(f.shrinkRuns, 0);
}

class FuzzG74_1Cli : public CliFixture {};

TEST_F(FuzzG74_1Cli, CyclesG74_1RunsCleanOnTheReference) {
  const std::string out = path("g74_1-out");
  const CliRun r = run("fuzz --engine reference --cycles g74_1 --cases 200 --seed 3 --no-save --out " + out);
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("200 cases"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("0 fail"), std::string::npos) << r.out;
  EXPECT_NE(read(out + "/run.json").find("\"cycles\": \"g74.1\""), std::string::npos) << read(out + "/run.json");
  EXPECT_NE(run("fuzz --help").out.find("g74.1 (or"), std::string::npos);
}

}  // namespace
}  // namespace cyclecert
