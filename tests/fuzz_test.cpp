// `cyclecert fuzz` and `merge`: the generator covers what the issue lists and is deterministic per
// seed; the reference passes every oracle on generated cases; every mutant is caught; a failure is
// shrunk, printed with a seed that reproduces it and kept as a spec case that `check` runs; a run
// resumes; shards merge into the unsharded run.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <sstream>

#include "harness/engines/engine.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/fuzz/regression_case.h"
#include "harness/run/check_run.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"
#include "oracles/metamorphic/path_compare.h"
#include "tests/cli_fixture.h"

namespace cyclecert {
namespace {

namespace fs = std::filesystem;

constexpr std::uint64_t kSeed = 424242;

std::vector<FuzzCase> sample(long n) {
  std::vector<FuzzCase> out;
  for (long i = 0; i < n; ++i) out.push_back(generateFuzzCase(fuzzCaseSeed(kSeed, i)));
  return out;
}

TEST(FuzzGenerator, TheSameSeedGivesTheSameCase) {
  for (long i = 0; i < 50; ++i) {
    const std::uint64_t seed = fuzzCaseSeed(kSeed, i);
    EXPECT_EQ(fuzzProgram(generateFuzzCase(seed)), fuzzProgram(generateFuzzCase(seed)));
  }
  EXPECT_NE(fuzzProgram(generateFuzzCase(1)), fuzzProgram(generateFuzzCase(2)));
  // Case 0 of a run is the run's seed itself: `--seed <case seed> --cases 1` reproduces a case.
  EXPECT_EQ(fuzzCaseSeed(kSeed, 0), kSeed);
}

// A case's tag names its results and files: 16 lowercase hex digits, leading zeros kept.
TEST(FuzzGenerator, ACaseSeedTagIsSixteenHexDigits) {
  EXPECT_EQ(caseSeedTag(0), "0000000000000000");
  EXPECT_EQ(caseSeedTag(5), "0000000000000005");
  EXPECT_EQ(caseSeedTag(0x9E3779B97F4A7C1AULL), "9e3779b97f4a7c1a");
  EXPECT_EQ(caseSeedTag(UINT64_MAX), "ffffffffffffffff");
  EXPECT_EQ(caseSeedTag(0xABCULL << 40), "000abc0000000000");
}

TEST(FuzzGenerator, CoversCyclesQuadrantsShapesAndParameterRanges) {
  std::map<std::string, int> seen;
  for (const FuzzCase& c : sample(3000)) {
    ++seen["G" + std::to_string(c.cycle)];
    ++seen[std::string("quadrant ") + (c.mirrorCut ? "1" : "0") + (c.mirrorDepth ? "1" : "0")];
    if (c.typeII) ++seen["type II"];
    ++seen[c.profile];
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const FuzzSegment& s = c.segments[i];
      if (s.kind == FuzzSegment::ConvexArc) ++seen["convex arc"];
      if (s.kind == FuzzSegment::ConcaveArc) ++seen["concave arc"];
      if (s.kind == FuzzSegment::Line && s.along > 0 && s.along == s.up) ++seen["chamfer"];
      if (s.kind == FuzzSegment::Line && s.along == 0 && s.up == 0) ++seen["zero length"];
      if (s.kind == FuzzSegment::Line && s.up < 0 && s.along > 0) ++seen["pocket wall"];
      if (s.along < 0) ++seen["turns back along the cut axis"];
      if (i > 0 && s.kind == FuzzSegment::Line && c.segments[i - 1].kind == FuzzSegment::Line &&
          s.along == c.segments[i - 1].along && s.up == c.segments[i - 1].up && (s.along || s.up)) {
        ++seen["collinear run"];
      }
      // A quarter arc after a line along the cut axis is tangent to it.
      if (i > 0 && s.kind != FuzzSegment::Line && c.segments[i - 1].kind == FuzzSegment::Line &&
          c.segments[i - 1].up == 0 && c.segments[i - 1].along > 0) {
        ++seen["tangent arc"];
      }
    }
    if (!c.typeII && std::any_of(c.segments.begin(), c.segments.end(), [](const FuzzSegment& s) { return s.up < 0; })) {
      ++seen["turns back along the depth axis"];
    }
    if (c.depthOfCut == 0) ++seen["Δd = 0"];
    if (c.headMotion == 2) ++seen["head block G02"];
    if (c.startAbove < 0) ++seen["A below C"];
    if (c.startAbove == c.allowanceDepth) ++seen["A on C's level"];
    if (c.allowanceDepth == 0 && c.allowanceCut == 0) ++seen["no allowance"];
    if (c.allowanceDepth > 0 && c.allowanceCut > 0) ++seen["both allowances"];
    for (const auto& [set, name] : {std::pair{c.rf1, "RF1"}, {c.dtp, "DTP"}, {c.r16, "R16"}, {c.nsp, "NSP"}, {c.rf2, "RF2"}}) {
      if (set) ++seen[name];
    }
  }
  for (const char* feature :
       {"G71", "G72", "quadrant 00", "quadrant 01", "quadrant 10", "quadrant 11", "type II", "fanuc-0i-f", "fanuc-0i-c",
        "gsk", "convex arc", "concave arc", "chamfer", "zero length", "pocket wall", "collinear run", "tangent arc",
        "turns back along the cut axis", "turns back along the depth axis", "Δd = 0", "head block G02", "A below C",
        "A on C's level", "no allowance", "both allowances", "RF1", "DTP", "R16", "NSP", "RF2"}) {
    EXPECT_GE(seen[feature], 5) << feature;
  }
}

// The shape program's F (ignored by roughing: G71.FST, G72.FST), tool-nose radius compensation and
// type II's clearance 5134 are drawn, and written into the program and the case.
TEST(FuzzGenerator, DrawsAnFInsideTheShapeCompensationAndTheClearance) {
  std::map<std::string, int> seen;
  long i = 0;
  for (const FuzzCase& c : sample(3000)) {
    const std::string program = fuzzProgram(c);
    const std::size_t ns = program.find("N10 "), nf = program.find('\n', program.find("N20 "));
    const std::string shape = program.substr(ns, nf - ns);
    if (shape.find(" F") != std::string::npos) ++seen["F in ns…nf"];
    EXPECT_EQ(c.shapeFeedAt >= 0, shape.find(" F") != std::string::npos) << program;
    const bool g41 = program.find("G41;") != std::string::npos, g42 = program.find("G42;") != std::string::npos;
    EXPECT_EQ(c.noseRadius > 0, g41 || g42) << program;
    if (g41) ++seen["G41"];
    if (g42) ++seen["G42"];
    if (c.noseRadius > 0) {
      EXPECT_NE(program.find("G40;"), std::string::npos) << program;
      EXPECT_LT(program.find(g41 ? "G41;" : "G42;"), program.find("G71 ") < program.find("G72 ") ? program.find("G71 ")
                                                                                                  : program.find("G72 "));
      const SpecCase spec = fuzzSpecCase(c, std::to_string(i));
      EXPECT_EQ(spec.raw["tool"]["nose_radius"], c.noseRadius / 100.0);
      if (c.finish) ++seen["compensated with G70"];
      ++seen["G" + std::to_string(c.cycle) + " compensated"];
    }
    if (c.clearance > 0) {
      EXPECT_TRUE(c.typeII);
      EXPECT_EQ(fuzzSpecCase(c, std::to_string(i)).raw["params"]["5134"], c.clearance / 100.0);
      ++seen["5134"];
    }
    ++i;
  }
  for (const char* feature : {"F in ns…nf", "G41", "G42", "compensated with G70", "G71 compensated", "G72 compensated", "5134"}) {
    EXPECT_GE(seen[feature], 20) << feature;
  }
}

TEST(FuzzGenerator, EveryCaseIsAValidSpecCaseTheReferenceAnswers) {
  const auto reference = makeEngine("reference");
  std::map<std::string, int> outcomes;
  long i = 0;
  for (const FuzzCase& c : sample(1000)) {
    const SpecCase spec = fuzzSpecCase(c, std::to_string(i++));
    EXPECT_NO_THROW(parseSpecCase(spec.raw.dump(), "round trip"));
    const EngineResult r = reference->run(spec);
    ++outcomes[kindName(r.kind)];
    EXPECT_TRUE(r.kind == EngineResult::Planned || r.kind == EngineResult::Alarmed) << spec.program << r.detail;
  }
  EXPECT_GT(outcomes["planned"], 700);
  EXPECT_GT(outcomes["alarm"], 20);  // the out-of-range draws
}

// ---- the cycle formats (--formats) -----------------------------------------------------------------

const CycleFormats kAllFormats = {CycleFormat::FanucTwoBlocks,   CycleFormat::Series10OneBlock,
                                  CycleFormat::HuazhongOneBlock, CycleFormat::HaasOneBlock,
                                  CycleFormat::SystemB,          CycleFormat::SystemC};
const CycleFormats kNewFormats = {CycleFormat::HaasOneBlock, CycleFormat::SystemB, CycleFormat::SystemC};

std::vector<FuzzCase> sampleOf(long n, const CycleFormats& formats) {
  std::vector<FuzzCase> out;
  for (long i = 0; i < n; ++i) out.push_back(generateFuzzCase(fuzzCaseSeed(kSeed, i), formats));
  return out;
}

// The format is drawn after everything else: a case drawn from several formats is the case the
// default run draws from its seed, with only what its format changes (so adding formats left the
// default run's cases, and their findings, as they were).
TEST(FuzzGenerator, AFormatDrawChangesOnlyWhatTheFormatWrites) {
  const std::vector<FuzzCase> plain = sample(1000), mixed = sampleOf(1000, kAllFormats);
  std::map<CycleFormat, int> seen;
  for (std::size_t i = 0; i < plain.size(); ++i) {
    const FuzzCase& a = plain[i];
    const FuzzCase& b = mixed[i];
    EXPECT_EQ(a.format, CycleFormat::FanucTwoBlocks);
    ++seen[b.format];
    EXPECT_EQ(a.segments.size(), b.segments.size()) << i;
    EXPECT_EQ(a.depthOfCut, b.depthOfCut) << i;
    EXPECT_EQ(a.retract, b.retract) << i;
    EXPECT_EQ(a.startAlong, b.startAlong) << i;
    if (b.format == CycleFormat::FanucTwoBlocks) {
      EXPECT_EQ(fuzzProgram(a), fuzzProgram(b)) << i;
    }
    if (b.format == CycleFormat::Series10OneBlock) {
      EXPECT_EQ(b.profile, a.profile == "gsk" ? "fanuc-0i-f" : a.profile) << i;
      EXPECT_EQ(b.typeII, a.typeII) << i;
      EXPECT_EQ(b.cycle, a.cycle) << i;
    }
  }
  for (CycleFormat f : kAllFormats) EXPECT_GT(seen[f], 120) << cycleFormatName(f);
}

// One line of the shape, Δd 1.25 mm, e 0.3 mm, allowances Δu/2 0.2 and Δw 0.05 mm, with G70: the
// case whose cycle blocks the format tests read by hand.
FuzzCase oneLineCase() {
  FuzzCase c;
  c.segments = {{FuzzSegment::Line, 500, 300}};
  c.b = 1000;
  c.startAbove = 100;
  c.depthOfCut = 125;
  c.retract = 30;
  c.allowanceDepth = 20;
  c.allowanceCut = 5;
  c.finish = true;
  return c;
}

// Hand-read blocks: Δd 1.25 mm is D1250 (least input increments, G71.FS10.D) with FCV = 1 and e in
// 5133; the Huazhong block carries U(Δd) R(e) and the allowances as X (diameter) and Z.
TEST(FuzzGenerator, WritesEachFormatsCycleBlock) {
  FuzzCase c = oneLineCase();
  EXPECT_NE(fuzzProgram(c).find("G71 U1.25 R0.3;\nG71 P10 Q20 U0.4 W0.05 F0.2;\n"), std::string::npos)
      << fuzzProgram(c);
  c.format = CycleFormat::Series10OneBlock;
  EXPECT_NE(fuzzProgram(c).find(";\nG71 P10 Q20 U0.4 W0.05 D1250 F0.2;\nN10 "), std::string::npos) << fuzzProgram(c);
  const SpecCase fs10 = fuzzSpecCase(c, "t");
  EXPECT_EQ(fs10.raw["params"]["FCV"], 1);
  EXPECT_EQ(fs10.raw["params"]["5133"], 0.3);
  EXPECT_EQ(fs10.raw["rules"][0], "G71.FS10.FMT");
  c.format = CycleFormat::HuazhongOneBlock;
  c.profile = "hnc";
  c.finish = false;
  EXPECT_NE(fuzzProgram(c).find(";\nG71 U1.25 R0.3 P10 Q20 X0.4 Z0.05 F0.2;\nN10 "), std::string::npos)
      << fuzzProgram(c);
  EXPECT_EQ(fuzzSpecCase(c, "t").raw["profile"], "hnc");
  EXPECT_NE(describeFuzzCase(c).find("hnc one-block format"), std::string::npos) << describeFuzzCase(c);
}

// Haas: D in mm with a decimal point (D1.25, D3.), R1 for type II, e in 5133, G42 in block ns;
// systems B/C: G90 G95 first, the two blocks (system C: G73/G74, G72 finishing), 3401#6 / #7.
TEST(FuzzGenerator, WritesTheHaasBlockAndTheProgramsInSystemsBAndC) {
  FuzzCase c = oneLineCase();
  c.format = CycleFormat::HaasOneBlock;
  c.profile = "haas";
  EXPECT_NE(fuzzProgram(c).find(";\nG71 P10 Q20 U0.4 W0.05 D1.25 F0.2;\nN10 G00 X2;"), std::string::npos)
      << fuzzProgram(c);
  const SpecCase haas = fuzzSpecCase(c, "t");
  EXPECT_EQ(haas.raw["params"]["5133"], 0.3);
  EXPECT_EQ(haas.raw["profile"], "haas");
  EXPECT_EQ(haas.raw["rules"][0], "HAAS.G71.FMT");
  c.depthOfCut = 300;
  c.noseRadius = 40;
  c.tip = tipIntoTheCut(c);
  const std::string compensated = fuzzProgram(c);
  EXPECT_NE(compensated.find(" D3. F0.2;\nN10 G42 G00 X2;\nN20 G40 G01 X8 Z-5;\nG70 P10 Q20;\nM30;"), std::string::npos)
      << compensated;
  EXPECT_EQ(compensated.find("G42;"), std::string::npos) << compensated;  // not before the cycle
  c.noseRadius = 0;
  c.typeII = true;
  c.allowanceCut = 0;
  EXPECT_NE(fuzzProgram(c).find(" D3. R1 F0.2;\nN10 G00 X2 W0;"), std::string::npos) << fuzzProgram(c);

  c.typeII = false;
  c.allowanceCut = 5;
  c.depthOfCut = 125;
  c.profile = "fanuc-0i-f";
  c.format = CycleFormat::SystemB;
  EXPECT_EQ(fuzzProgram(c).substr(0, 9), "G90 G95;\n") << fuzzProgram(c);
  EXPECT_NE(fuzzProgram(c).find(";\nG71 U1.25 R0.3;\nG71 P10 Q20 U0.4 W0.05 F0.2;\nN10 G00 X2;"), std::string::npos)
      << fuzzProgram(c);
  EXPECT_EQ(fuzzSpecCase(c, "t").raw["params"]["3401#6"], 1);
  EXPECT_EQ(fuzzSpecCase(c, "t").raw["rules"][0], "PROG.GSYS.B");
  c.format = CycleFormat::SystemC;
  c.typeII = true;
  c.allowanceCut = 0;
  const std::string inC = fuzzProgram(c);
  EXPECT_NE(inC.find(";\nG73 U1.25 R0.3;\nG73 P10 Q20 U0.4 W0 F0.2;\nN10 G00 X2 Z0;"), std::string::npos) << inC;
  EXPECT_EQ(inC.find(" W0;"), std::string::npos) << inC;  // no U/W increments in system C
  EXPECT_NE(inC.find("G72 P10 Q20;"), std::string::npos) << inC;
  EXPECT_EQ(fuzzSpecCase(c, "t").raw["params"]["3401#7"], 1);
  c.cycle = 72;
  EXPECT_NE(fuzzProgram(c).find(";\nG74 W1.25 R0.3;\nG74 P10"), std::string::npos) << fuzzProgram(c);
  EXPECT_NE(describeFuzzCase(c).find("G code system C"), std::string::npos) << describeFuzzCase(c);
}

// The program in system B or C, or in the Haas block, is the two-block program in other words: the
// reference plans the same toolpath from it (the two-block twin of a Haas case runs under profile
// haas, which reads both forms). Compensated Haas cases are not drawn (drawCompensation()).
TEST(FuzzGenerator, TheNewFormatsSayWhatTheTwoBlocksSay) {
  std::map<CycleFormat, int> compared;
  long i = 0;
  for (FuzzCase c : sampleOf(450, kNewFormats)) {
    const SpecCase spec = fuzzSpecCase(c, std::to_string(i));
    const EngineResult inFormat = makeEngine("reference")->run(spec);
    const CycleFormat format = c.format;
    c.format = CycleFormat::FanucTwoBlocks;
    const SpecCase twin = fuzzSpecCase(c, std::to_string(i++));  // its first block gives e
    const EngineResult twoBlocks = makeEngine("reference")->run(twin);
    ASSERT_EQ(inFormat.kind, twoBlocks.kind) << spec.program << inFormat.detail << "\n" << twin.program << twoBlocks.detail;
    EXPECT_FALSE(format == CycleFormat::HaasOneBlock && c.noseRadius > 0);
    if (inFormat.kind != EngineResult::Planned) continue;
    ++compared[format];
    const auto d = compareToolpaths(twoBlocks.path, inFormat.path, 1e-9);
    EXPECT_FALSE(d) << cycleFormatName(format) << ": " << *d << "\n" << spec.program << "\n" << twin.program;
  }
  for (CycleFormat f : kNewFormats) EXPECT_GT(compared[f], 100) << cycleFormatName(f);
}

TEST(FuzzGenerator, OneBlockCasesAreWhatTheirFormatCanSay) {
  for (const FuzzCase& c : sampleOf(1500, kAllFormats)) {
    const std::string program = fuzzProgram(c);
    if (c.format == CycleFormat::Series10OneBlock) {
      EXPECT_NE(c.profile, "gsk");
      EXPECT_NE(program.find(" D" + std::to_string(10 * c.depthOfCut) + " F0.2;"), std::string::npos) << program;
      EXPECT_EQ(program.substr(0, program.find("N10")).find(" R"), std::string::npos) << program;  // no R(e) block
    }
    if (c.format == CycleFormat::HuazhongOneBlock) {
      EXPECT_EQ(c.profile, "hnc");
      EXPECT_EQ(c.cycle, 71);
      EXPECT_FALSE(c.typeII);
      EXPECT_EQ(program.find("G70"), std::string::npos) << program;
    }
  }
}

// Huazhong documents no height check (no PS0322): A below C's level would be no alarm but the
// programmer's collision (the return to A runs through the part), so the hnc format never draws it
// (before: fuzz --formats all --seed 9 found a no-gouge on the reference, seed 2153864201484202247).
TEST(FuzzGenerator, HuazhongCasesStartAboveC) {
  int belowC = 0;
  for (const FuzzCase& c : sampleOf(4000, {CycleFormat::HuazhongOneBlock})) belowC += c.startAbove < 0;
  EXPECT_EQ(belowC, 0);
  int fanucBelowC = 0;  // the FANUC format keeps drawing it: PS0322 (G71.LIMIT.HEIGHT)
  for (const FuzzCase& c : sampleOf(4000, {CycleFormat::FanucTwoBlocks})) fanucBelowC += c.startAbove < 0;
  EXPECT_GT(fanucBelowC, 2);
}

// The reference plans every one-block case (or raises its alarm): none is refused as unsupported.
TEST(FuzzGenerator, TheReferenceAnswersEveryOneBlockCase) {
  const auto reference = makeEngine("reference");
  std::map<CycleFormat, std::map<std::string, int>> outcomes;
  long i = 0;
  const CycleFormats formats = {CycleFormat::Series10OneBlock, CycleFormat::HuazhongOneBlock, CycleFormat::HaasOneBlock,
                                CycleFormat::SystemB, CycleFormat::SystemC};
  for (const FuzzCase& c : sampleOf(1000, formats)) {
    const SpecCase spec = fuzzSpecCase(c, std::to_string(i++));
    const EngineResult r = reference->run(spec);
    ++outcomes[c.format][kindName(r.kind)];
    EXPECT_TRUE(r.kind == EngineResult::Planned || r.kind == EngineResult::Alarmed) << spec.program << r.detail;
  }
  for (CycleFormat f : formats) {
    EXPECT_GT(outcomes[f]["planned"], 130) << cycleFormatName(f);
  }
}

TEST(FuzzGenerator, FormatNamesParse) {
  EXPECT_EQ(parseCycleFormats("two-block"), kDefaultCycleFormats);
  EXPECT_EQ(parseCycleFormats("hnc,fs10,hnc"), (CycleFormats{CycleFormat::HuazhongOneBlock, CycleFormat::Series10OneBlock}));
  EXPECT_EQ(parseCycleFormats("all"), kAllFormats);
  EXPECT_EQ(cycleFormatsText(kAllFormats), "two-block,fs10,hnc,haas,gsys-b,gsys-c");
  EXPECT_EQ(parseCycleFormats("gsys-c,haas"), (CycleFormats{CycleFormat::SystemC, CycleFormat::HaasOneBlock}));
  for (const char* bad : {"", "fs11", "fs10,", "FS10"}) {
    try {
      parseCycleFormats(bad);
      ADD_FAILURE() << bad;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("two-block, fs10, hnc, haas, gsys-b, gsys-c or all"), std::string::npos)
          << e.what();
    }
  }
}

std::string scratch(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / ("cyclecert-fuzz-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(p);
  return p.string();
}

TEST(Fuzz, TheReferencePassesEveryOracleOnGeneratedCases) {
  auto engine = makeEngine("reference");
  FuzzOptions o;
  o.seed = kSeed;
  o.cases = 400;
  o.outDir = scratch("reference");
  std::ostringstream progress;
  const FuzzSummary s = runFuzz(*engine, nullptr, o, progress);
  fs::remove_all(o.outDir);
  EXPECT_EQ(s.run, 400);
  EXPECT_EQ(s.notApplicable, 0) << progress.str();  // every generated case is one the oracles judge
  EXPECT_EQ(s.fail, 0) << progress.str();
  EXPECT_EQ(s.engineFailure, 0) << progress.str();
}

// One-block cases through the fuzzer: the reference fails none (the Huazhong ones are not judged by
// the oracles yet: not applicable), a mutant is found on Series 10/11 cases, and the command that
// reproduces the failure names the formats.
TEST(Fuzz, OneBlockFormatsRunCleanOnTheReferenceAndTheReproduceCommandNamesThem) {
  auto reference = makeEngine("reference");
  FuzzOptions o;
  o.seed = kSeed;
  o.cases = 300;
  o.formats = {CycleFormat::Series10OneBlock, CycleFormat::HuazhongOneBlock};
  o.outDir = scratch("formats");
  std::ostringstream progress;
  const FuzzSummary s = runFuzz(*reference, nullptr, o, progress);
  fs::remove_all(o.outDir);
  EXPECT_EQ(s.fail, 0) << progress.str();
  EXPECT_EQ(s.engineFailure, 0) << progress.str();
  EXPECT_GT(s.pass, 100) << progress.str();

  auto mutant = makeEngine("mutant:pass-count");
  o.formats = {CycleFormat::Series10OneBlock};
  o.maxFailures = 1;
  o.shrinkBudget = 20;
  o.regressionsDir = "";
  o.outDir = scratch("formats-mutant");
  std::ostringstream found;
  const FuzzSummary m = runFuzz(*mutant, nullptr, o, found);
  fs::remove_all(o.outDir);
  ASSERT_EQ(m.failures.size(), 1u) << found.str();
  EXPECT_EQ(m.failures[0].shrunk.format, CycleFormat::Series10OneBlock);
  EXPECT_NE(found.str().find("--formats fs10"), std::string::npos) << found.str();
}

// The two fault classes the generator's later draws exist for are found by the fuzzer within a few hundred
// cases, by the oracle that judges them: roughing at the shape's F (feeds) and compensation to the
// wrong side (no-gouge).
TEST(Fuzz, TheShapeFeedAndCompensationFaultsAreFound) {
  for (const auto& [mutant, oracle] : {std::pair{"mutant:shape-feed-in-roughing", "feeds"},
                                      std::pair{"mutant:tnrc-sides-swapped", "no-gouge"}}) {
    SCOPED_TRACE(mutant);
    auto engine = makeEngine(mutant);
    FuzzOptions o;
    o.seed = 1;
    o.cases = 500;
    o.maxFailures = 1;
    o.shrinkBudget = 0;
    o.outDir = scratch(std::string("found-") + (mutant + 7));
    o.regressionsDir = "";
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(*engine, nullptr, o, progress);
    fs::remove_all(o.outDir);
    ASSERT_EQ(s.failures.size(), 1u) << progress.str();
    EXPECT_NE(progress.str().find("FAIL " + std::string(oracle)), std::string::npos) << progress.str();
  }
}

// Every mutant fails a generated case (the default budget is 2000 cases; each is caught long
// before), and the failure is shrunk, kept as a spec case, and that case fails `check` for the
// mutant and passes it for the reference.
TEST(Fuzz, EveryMutantIsFoundShrunkAndKeptAsARegression) {
  int mutants = 0;
  for (const auto& [name, description] : listEngines()) {
    if (name.rfind("mutant:", 0) != 0) continue;
    // The G73 faults are drawn with --cycles g73 (fuzz_g73_test.cpp: EveryG73MutantIsCaught…).
    if (name.rfind("mutant:g73-", 0) == 0) continue;
    // The SINUMERIK faults with --cycles siemens (siemens_fuzz_test.cpp: EverySiemensMutantIsCaught…).
    if (name.rfind("mutant:siemens-", 0) == 0) continue;
    // The G74.1 faults with --cycles g74.1 (fuzz_g74_1_test.cpp: EveryG74_1MutantIsCaught…).
    if (name.rfind("mutant:g74_1-", 0) == 0) continue;
    ++mutants;
    SCOPED_TRACE(name);
    auto engine = makeEngine(name);
    FuzzOptions o;
    o.seed = kSeed;
    o.cases = kDefaultFuzzCases;
    o.maxFailures = 1;
    o.shrinkBudget = 60;
    o.outDir = scratch("out-" + name.substr(7));
    o.regressionsDir = scratch("regressions-" + name.substr(7));
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(*engine, nullptr, o, progress);
    ASSERT_EQ(s.failures.size(), 1u) << description << " escaped " << s.run << " generated cases";
    const FuzzFailure& f = s.failures.front();
    EXPECT_NE(progress.str().find("reproduce: cyclecert fuzz --engine '" + name + "' --seed " + std::to_string(f.caseSeed)),
              std::string::npos)
        << progress.str();
    ASSERT_FALSE(f.regressionFile.empty());
    const SpecCase kept = loadSpecCase(f.regressionFile);
    EXPECT_TRUE(kept.oraclesOnly);
    EXPECT_LE(generateFuzzCase(f.caseSeed).segments.size() + 1, f.shrunk.segments.size() + 1 + 20);  // never grows
    EXPECT_LE(f.shrunk.segments.size(), generateFuzzCase(f.caseSeed).segments.size());
    // `check` runs the kept case: the mutant fails it, the reference passes it.
    CheckOptions co{scratch("no-specs"), o.regressionsDir, scratch("check-" + name.substr(7)), false};
    fs::create_directories(co.specsDir + "/cases");
    std::ostringstream checkProgress;
    EXPECT_EQ(runCheck(*engine, co, checkProgress).fail, 1) << checkProgress.str();
    auto reference = makeEngine("reference");
    const CheckSummary r = runCheck(*reference, co, checkProgress);
    EXPECT_EQ(r.pass, 1) << checkProgress.str();
    for (const std::string& dir : {o.outDir, o.regressionsDir, co.specsDir, co.outDir}) fs::remove_all(dir);
  }
  EXPECT_GE(mutants, 15);
}

TEST(Fuzz, ComparedWithASecondEngineADivergenceIsAFailure) {
  auto engine = makeEngine("mutant:retract-amount");
  auto reference = makeEngine("reference");
  // The same engine twice agrees with itself.
  FuzzOptions o;
  o.seed = kSeed;
  o.cases = 30;
  o.outDir = scratch("vs-self");
  std::ostringstream progress;
  EXPECT_EQ(runFuzz(*reference, makeEngine("reference").get(), o, progress).fail, 0) << progress.str();
  // Judged alone by the oracles the mutant fails; a divergence from the reference is found when
  // its own oracles pass — so compare a mutant the oracles also catch and check the kind named.
  o.outDir = scratch("vs-mutant");
  o.maxFailures = 1;
  o.shrinkBudget = 20;
  o.regressionsDir = scratch("vs-regressions");
  const FuzzSummary s = runFuzz(*engine, reference.get(), o, progress);
  ASSERT_EQ(s.failures.size(), 1u);
  EXPECT_FALSE(s.failures.front().kind.empty());
  for (const std::string& dir : {o.outDir, o.regressionsDir}) fs::remove_all(dir);
}

// A disagreement with the reference is kept as a case that must agree with the reference, run at
// check time — never as a copy of either engine's toolpath.
TEST(Fuzz, ADivergenceIsKeptAsAgreementWithTheReference) {
  FuzzFailure f;
  f.caseSeed = fuzzCaseSeed(kSeed, 3);
  f.kind = "diverges";
  f.detail = "move 2: reference …, process:x …";
  f.shrunk = generateFuzzCase(f.caseSeed);
  const std::string dir = scratch("agrees");
  const std::string file = writeRegressionCase(dir, f, "process:my engine", "reference", {"G71.QUAD"}, "cyclecert fuzz …");
  const SpecCase kept = loadSpecCase(file);
  ASSERT_TRUE(kept.agreesWith);
  EXPECT_EQ(*kept.agreesWith, "reference");
  EXPECT_FALSE(kept.expectedMoves);
  EXPECT_NE(file.find("fuzz-process-my-engine-"), std::string::npos) << file;
  CheckOptions co{scratch("agrees-specs"), dir, scratch("agrees-out"), false};
  fs::create_directories(co.specsDir + "/cases");
  std::ostringstream progress;
  EXPECT_EQ(runCheck(*makeEngine("reference"), co, progress).pass, 1) << progress.str();
  EXPECT_EQ(runCheck(*makeEngine("mutant:start-not-returned"), co, progress).fail, 1) << progress.str();
  for (const std::string& d : {dir, co.specsDir, co.outDir}) fs::remove_all(d);
}

class FuzzCli : public CliFixture {};

TEST_F(FuzzCli, HelpNamesEveryOption) {
  const CliRun r = run("fuzz --help");
  EXPECT_EQ(r.exitCode, 0);
  for (const char* option : {"--engine", "--vs", "--cases", "--time", "--seed", "--shard", "--out", "--regressions",
                             "--no-save", "--resume", "--max-failures"}) {
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  }
  EXPECT_EQ(run("merge --help").exitCode, 0);
}

TEST_F(FuzzCli, BadUsageExitsWith2) {
  EXPECT_EQ(run("fuzz").exitCode, 2);
  EXPECT_EQ(run("fuzz --engine nosuch").exitCode, 2);
  const CliRun shard = run("fuzz --engine reference --shard 3/2");
  EXPECT_EQ(shard.exitCode, 2);
  EXPECT_NE(shard.err.find("--shard"), std::string::npos) << shard.err;
  EXPECT_EQ(run("fuzz --engine reference --shard x").exitCode, 2);
  EXPECT_EQ(run("fuzz --engine reference --seed -1").exitCode, 2);
  EXPECT_EQ(run("fuzz --engine reference --cases 0").exitCode, 2);
  EXPECT_EQ(run("merge --out " + path("m")).exitCode, 2);
  EXPECT_EQ(run("merge --out " + path("m") + " " + path("nothing-here")).exitCode, 2);
}

TEST_F(FuzzCli, AFailurePrintsItsSeedAndTheCommandThatReproducesIt) {
  const CliRun r = run("fuzz --engine mutant:start-not-returned --seed 7 --cases 50 --max-failures 1 --shrink-budget 30 --out " +
                       path("out") + " --regressions " + path("regressions"));
  EXPECT_EQ(r.exitCode, 1);
  const auto at = r.err.find("reproduce: ");
  ASSERT_NE(at, std::string::npos) << r.err;
  std::string command = r.err.substr(at + 11, r.err.find('\n', at) - at - 11);
  command = command.substr(command.find(" fuzz ") + 1);
  // The command regenerates the same (unshrunk) case and fails it again.
  const CliRun again = run(command + " --no-save --out " + path("again"));
  EXPECT_EQ(again.exitCode, 1) << again.out << again.err;
  EXPECT_NE(again.out.find("1 fail"), std::string::npos) << again.out;
  EXPECT_NE(r.err.find("kept as " + path("regressions")), std::string::npos) << r.err;
}

TEST_F(FuzzCli, AnEngineThatAnswersGarbageFailsEveryCaseAndTheRunFinishes) {
  const CliRun r = run("fuzz --engine 'process:sh tests/data/engines/garbage.sh' --seed 2 --cases 12 --shrink-budget 3 "
                       "--no-save --out " + path("out"));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.out.find("12 engine failure(s)"), std::string::npos) << r.out;
  EXPECT_NE(r.err.find("FAIL engine-failure"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("invalid JSON reply"), std::string::npos) << r.err;
}

TEST_F(FuzzCli, ATimeBudgetStopsTheRunAndPrintsTheSeed) {
  const CliRun r = run("fuzz --engine reference --no-save --time 1 --out " + path("out"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("(reproduce the run with --seed "), std::string::npos) << r.err;
  // Stopped after about a second (one case more at most: under the sanitizers a case takes a while).
  const auto at = r.out.find(" cases in ");
  ASSERT_NE(at, std::string::npos) << r.out;
  const double seconds = std::stod(r.out.substr(at + 10));
  EXPECT_GE(seconds, 1.0) << r.out;
  EXPECT_LT(seconds, 3.0) << r.out;
}

TEST_F(FuzzCli, AKilledRunKeepsEveryResultWrittenAndResumes) {
  // SIGKILL after a second: no chance to flush anything at exit.
  const std::string fuzz = std::string(CYCLECERT_CLI) + " fuzz --engine reference --no-save --seed 3 --cases 100000 --out " +
                           path("out");
  ASSERT_NE(std::system(("sh -c '" + fuzz + " 2>/dev/null & pid=$!; sleep 2; kill -9 $pid; wait $pid' ").c_str()), -1);
  std::istringstream lines(read(path("out/results.jsonl")));
  long complete = 0;
  for (std::string line; std::getline(lines, line);) {
    try {
      if (nlohmann::json::parse(line).contains("case")) ++complete;
    } catch (const std::exception&) {  // the line the kill cut short
    }
  }
  EXPECT_GT(complete, 0);
  const CliRun r = run("fuzz --engine reference --no-save --seed 3 --cases " + std::to_string(complete + 5) +
                       " --resume --out " + path("out"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find(std::to_string(complete) + " already done"), std::string::npos) << r.out;
}

TEST_F(FuzzCli, AStoppedRunResumesWhereItStopped) {
  ASSERT_EQ(run("fuzz --engine reference --no-save --seed 5 --cases 40 --out " + path("out")).exitCode, 0);
  // A killed run's last line may be cut short: resume drops it and runs that case again.
  std::string results = read(path("out/results.jsonl"));
  std::ofstream(path("out/results.jsonl")) << results.substr(0, results.size() - 20);
  const CliRun r = run("fuzz --engine reference --no-save --seed 5 --cases 60 --resume --out " + path("out"));
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("21 cases"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("39 already done"), std::string::npos) << r.out;
  std::istringstream lines(read(path("out/results.jsonl")));
  std::set<std::string> ids;
  for (std::string line; std::getline(lines, line);) ids.insert(nlohmann::json::parse(line).at("case").get<std::string>());
  EXPECT_EQ(ids.size(), 60u);
}

TEST_F(FuzzCli, ShardsMergeIntoTheUnshardedRun) {
  ASSERT_EQ(run("fuzz --engine reference --no-save --seed 9 --cases 30 --out " + path("whole")).exitCode, 0);
  ASSERT_EQ(run("fuzz --engine reference --no-save --seed 9 --cases 30 --shard 1/2 --out " + path("s1")).exitCode, 0);
  ASSERT_EQ(run("fuzz --engine reference --no-save --seed 9 --cases 30 --shard 2/2 --out " + path("s2")).exitCode, 0);
  const CliRun m = run("merge --out " + path("merged") + " " + path("s1") + " " + path("s2") + " " + path("s2"));
  EXPECT_EQ(m.exitCode, 0) << m.err;
  EXPECT_NE(m.out.find("30 results, 15 duplicate(s) dropped"), std::string::npos) << m.out;
  const auto idsOf = [&](const std::string& file) {
    std::set<std::string> ids;
    std::istringstream lines(read(file));
    for (std::string line; std::getline(lines, line);) ids.insert(nlohmann::json::parse(line).at("case").get<std::string>());
    return ids;
  };
  EXPECT_EQ(idsOf(path("merged/results.jsonl")), idsOf(path("whole/results.jsonl")));
  EXPECT_EQ(idsOf(path("whole/results.jsonl")).size(), 30u);
}

}  // namespace
}  // namespace cyclecert

namespace cyclecert {
namespace {

// The first real engine: a short fuzz against LinuxCNC's rs274 answers every case (a toolpath, an
// alarm, or not applicable — never an engine failure) and finds what the README lists.
TEST(Fuzz, LinuxCncAnswersEveryGeneratedCaseAndIsFoundWanting) {
  if (!fs::exists(fs::path(CYCLECERT_CLI).parent_path() / "linuxcnc/usr/bin/rs274"))
    GTEST_SKIP() << "rs274 is not fetched (make rs274: harness/engines/linuxcnc/fetch-rs274.sh build)";
  auto engine = makeEngine("linuxcnc");
  FuzzOptions o;
  o.seed = 1;
  o.cases = 200;
  o.shrinkBudget = 30;
  o.outDir = scratch("linuxcnc");
  std::ostringstream progress;
  const FuzzSummary s = runFuzz(*engine, nullptr, o, progress);
  fs::remove_all(o.outDir);
  EXPECT_EQ(s.engineFailure, 0) << progress.str();
  EXPECT_GT(s.notApplicable, 0);
  std::set<std::string> kinds;
  for (const FuzzFailure& f : s.failures) kinds.insert(f.kind);
  EXPECT_TRUE(kinds.count("pass-levels")) << progress.str();  // the first pass at A's level (README)
}

}  // namespace
}  // namespace cyclecert
