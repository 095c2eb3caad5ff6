// `cyclecert fuzz --cycles lcyc95,cycle95|siemens`: the SINUMERIK cases — drawn only when asked for;
// valid programs the reference plans without an alarm and invalid ones that raise the alarm they
// state, at the call; every machining type, undercuts, arcs and corners drawn; shrinking to a small
// case; the spec case with its contour subprogram; and the three Siemens mutants on hand-written
// programs (expected values worked out by hand in each test).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <map>
#include <set>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "harness/engines/engine.h"
#include "harness/engines/reference_plan.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/fuzz/siemens_case_generator.h"
#include "harness/run/check_run.h"
#include "harness/spec/spec_case.h"
#include "tests/fuzz_fixture.h"

namespace cyclecert {
namespace {

constexpr std::uint64_t kSeed = 160616;
const FuzzCycles kSiemens = {FuzzCycle::Lcyc95, FuzzCycle::Cycle95};

FuzzCase siemensCase(long i, const FuzzCycles& cycles = kSiemens) {
  return generateFuzzCase(fuzzCaseSeed(kSeed, i), kDefaultCycleFormats, cycles);
}

TEST(SiemensFuzzCycles, NamesParse) {
  EXPECT_EQ(parseFuzzCycles("siemens"), kSiemens);
  EXPECT_EQ(parseFuzzCycles("cycle95"), (FuzzCycles{FuzzCycle::Cycle95}));
  EXPECT_EQ(parseFuzzCycles("lcyc95,g71"), (FuzzCycles{FuzzCycle::Lcyc95, FuzzCycle::G71}));
  // "all" keeps its meaning (every FANUC family), so that `--cycles all` keeps a seed's cases.
  EXPECT_EQ(parseFuzzCycles("all"), (FuzzCycles{FuzzCycle::G71, FuzzCycle::G72, FuzzCycle::G73}));
  EXPECT_EQ(parseFuzzCycles("all,siemens").size(), 5u);
  EXPECT_EQ(fuzzCyclesText(kSiemens), "lcyc95,cycle95");
  try {
    parseFuzzCycles("lcyc95,cycle97");
    FAIL() << "cycle97 accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("unknown cycle 'cycle97'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("siemens"), std::string::npos) << e.what();
  }
}

// A run that asks for one cycle draws only it, on its profile.
TEST(SiemensFuzzCycles, OneCycleOnItsProfile) {
  for (long i = 0; i < 50; ++i) {
    const FuzzCase l = siemensCase(i, {FuzzCycle::Lcyc95});
    const FuzzCase c = siemensCase(i, {FuzzCycle::Cycle95});
    EXPECT_FALSE(l.siemens.cycle95);
    EXPECT_EQ(l.profile, "sinumerik-802s");
    EXPECT_TRUE(c.siemens.cycle95);
    EXPECT_EQ(c.profile, "sinumerik-802d");
  }
}

// Over a few hundred seeds: a valid case plans with no alarm and with roughing or finishing moves
// of its cycle; an invalid one raises exactly the alarm it states, at the call's line, before any
// move of the cycle. And the draws cover what the generator promises.
TEST(SiemensFuzzCases, ValidPlanAndInvalidRaiseTheirAlarm) {
  std::map<std::pair<bool, int>, int> types;  // (CYCLE95, type) → count
  std::map<SiemensFault, int> faults;
  int undercutsAtTheirOwnFeed = 0, arcs = 0, centreWords = 0, corners = 0, cornersNextToArcs = 0, compact = 0,
      notMultiple = 0;
  for (long i = 0; i < 400; ++i) {
    const FuzzCase f = siemensCase(i);
    SCOPED_TRACE("case " + std::to_string(i) + ": " + describeFuzzCase(f) + "\n" + fuzzProgram(f));
    const SpecCase c = fuzzSpecCase(f, "t" + std::to_string(i));
    ASSERT_EQ(c.subprograms.size(), 1u);
    EXPECT_EQ(c.subprograms.front().first, "L1");
    Toolpath path;
    ASSERT_NO_THROW(path = planSpecCase(c));
    const auto alarm = expectedAlarm(f);
    ++faults[f.siemens.fault];
    if (alarm) {
      ASSERT_TRUE(path.alarm.has_value());
      EXPECT_EQ(path.alarm->code, alarm->code);
      EXPECT_EQ(path.alarm->line, alarm->line);
      EXPECT_TRUE(c.expectedAlarm.has_value());
      continue;
    }
    EXPECT_FALSE(path.alarm.has_value()) << path.alarm->code << " " << path.alarm->message;
    const bool cycleMoves = std::any_of(path.moves.begin(), path.moves.end(), [](const Move& m) {
      return m.phase == MovePhase::Pass || m.phase == MovePhase::Finish;
    });
    EXPECT_TRUE(cycleMoves);
    const SiemensFuzzCase& s = f.siemens;
    ++types[{s.cycle95, s.type}];
    const bool undercut = std::any_of(s.segments.begin(), s.segments.end(), [](const SiemensSegment& g) { return g.up < 0; });
    if (s.cycle95 && undercut && s.undercutFeed != s.roughingFeed) ++undercutsAtTheirOwnFeed;
    for (std::size_t k = 0; k < s.segments.size(); ++k) {
      const SiemensSegment& g = s.segments[k];
      arcs += g.kind != SiemensSegment::Line;
      centreWords += g.kind != SiemensSegment::Line && g.centreWords;
      corners += g.corner != SiemensSegment::NoCorner;
      const bool arcAfter = k + 1 < s.segments.size() && s.segments[k + 1].kind != SiemensSegment::Line;
      cornersNextToArcs += g.corner != SiemensSegment::NoCorner && (g.kind != SiemensSegment::Line || arcAfter);
    }
    compact += s.compact;
    int height = 0, top = 0, bottom = 0;
    for (const SiemensSegment& g : s.segments) top = std::max(top, height += g.up), bottom = std::min(bottom, height);
    if ((top - bottom) % s.maxInfeed != 0) ++notMultiple;
  }
  for (bool cycle95 : {false, true}) {
    for (int type = 1; type <= 12; ++type) {
      const int drawn = types[std::pair{cycle95, type}];
      EXPECT_GT(drawn, 0) << (cycle95 ? "CYCLE95" : "LCYC95") << " type " << type;
    }
  }
  for (SiemensFault fault : {SiemensFault::MachiningType, SiemensFault::NoInfeedDepth, SiemensFault::AgainstDirection,
                             SiemensFault::ArcOverQuarter}) {
    EXPECT_GT(faults[fault], 0) << static_cast<int>(fault);
  }
  EXPECT_GT(undercutsAtTheirOwnFeed, 20);
  EXPECT_GT(arcs, 100);
  EXPECT_GT(centreWords, 20);
  EXPECT_GT(corners, 20);
  EXPECT_GT(cornersNextToArcs, 10);  // SIEMENS.CORNER next to an arc (the generator drew none before)
  EXPECT_GT(compact, 40);
  EXPECT_GT(notMultiple, 200);
}

// The written program, checked against text worked out by hand: LCYC95, type 1, a step and a line.
TEST(SiemensFuzzCases, ProgramAsWritten) {
  FuzzCase f;
  f.cycle = 95;
  f.profile = "sinumerik-802s";
  SiemensFuzzCase& s = f.siemens;
  s.type = 1;
  s.base = 1000;
  s.segments = {{SiemensSegment::Line, 0, 200}, {SiemensSegment::Line, 500, 0}, {SiemensSegment::ConvexQuarter, 100, 100}};
  s.segments[2].centreWords = true;
  s.maxInfeed = 150;
  s.retract = 100;
  s.startClear = 100;
  // The contour from radius 10 (base) at Z0: up the face to radius 12, along to Z-5, a convex quarter
  // (centre at Z-6 X(radius)12, I0 K-1) to radius 13 at Z-6. X words are diameters.
  EXPECT_EQ(siemensContourProgram(f), "G1 X20 Z0\nG1 X24 Z0\nG1 X24 Z-5\nG3 X26 Z-6 I0 K-1\nRET\n");
  // The start: 2 mm (R110 + 1 mm) beyond Z0 and above radius 13: X30 Z2.
  EXPECT_EQ(siemensMainProgram(f),
            "T1 D1\nG0 X30 Z2\n_CNAME=\"L1\"\nR105=1 R106=0 R108=1.5 R109=0\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n");
  // Face internal (type 4): the frame's z is the radius, its x the mirrored Z.
  s.type = 4;
  // z0 = 6 mm of contour + base − 1 mm: the contour's first point at radius 15, its end at radius 9.
  EXPECT_EQ(siemensContourProgram(f), "G1 X30 Z0\nG1 X30 Z-2\nG1 X20 Z-2\nG3 X18 Z-3 I-1 K0\nRET\n");
}

// Shrinking (RapidCheck's shrink tree, as `fuzz` walks it): a property that fails on every CYCLE95
// case with an undercut shrinks to a case of at most three segments.
TEST(SiemensFuzzCases, ShrinksToASmallCase) {
  const auto fails = [](const FuzzCase& f) {
    return f.siemens.cycle95 && std::any_of(f.siemens.segments.begin(), f.siemens.segments.end(),
                                            [](const SiemensSegment& g) { return g.up < 0; });
  };
  long i = 0;
  std::uint64_t seed = 0;
  for (;; ++i) {
    seed = fuzzCaseSeed(kSeed, i);
    const FuzzCase f = generateFuzzCase(seed, kDefaultCycleFormats, kSiemens);
    if (fails(f) && f.siemens.segments.size() >= 6) break;
    ASSERT_LT(i, 2000) << "no large CYCLE95 case with an undercut drawn";
  }
  rc::Shrinkable<FuzzCase> current = genFuzzCase(kDefaultCycleFormats, kSiemens)(rc::Random(seed), static_cast<int>(seed % 101));
  for (bool smaller = true; smaller;) {
    smaller = false;
    auto candidates = current.shrinks();
    while (auto candidate = candidates.next()) {
      if (fails(candidate->value())) {
        current = *candidate;
        smaller = true;
        break;
      }
    }
  }
  const FuzzCase shrunk = current.value();
  EXPECT_TRUE(fails(shrunk));
  EXPECT_LE(shrunk.siemens.segments.size(), 3u) << describeFuzzCase(shrunk);
  EXPECT_EQ(shrunk.siemens.type, 1);  // VARI shrinks to 1
}

// --- the mutants, on hand-written programs ---

SpecCase caseOf(const std::string& profile, const std::string& program, const std::string& contour) {
  return specCaseFrom({{"id", profile + "/test/mutant"},
                       {"title", "mutant test"},
                       {"rules", {"LCYC95.ROUGH"}},
                       {"profile", profile},
                       {"program", program},
                       {"subprograms", {{"L1", contour}}},
                       {"expect", {{"oracles", "pass"}}},
                       {"derivation", "hand-written"}},
                      "siemens_fuzz_test");
}

Toolpath runOn(const std::string& engine, const SpecCase& c) {
  EngineResult r = makeEngine(engine)->run(c);
  EXPECT_EQ(r.kind, EngineResult::Planned) << r.detail;
  return r.path;
}

// The step shaft (x radius): (x10,z0) → (10,-10) → (16,-10) → (16,-20) → (20,-20). R110 = 1, R108 = 3:
// start S = (21, 1); depth 10 in 4 equal steps of 2.5 (levels 17.5, 15, 12.5, 10).
const char* kStepShaft = "G1 X20 Z0\nZ-10\nX32\nZ-20\nX40\nRET\n";
const char* kLcyc95Rough =
    "G0 X50 Z2\n_CNAME=\"L1\"\nR105=1 R106=0 R108=3 R109=0\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n";

// siemens-retract-45: pass 1 cuts at 17.5 to (17.5,-20) and up the profile to (20,-20). The
// reference retracts R110 = 1 in each axis to (21,-19) and goes back to (21,1); the mutant retracts
// 1 mm at 45°, to (20 + 1/√2, −20 + 1/√2) = (20.70711, −19.29289), and back at that height to
// (20.70711, 1). Every other move ends where the reference's does.
TEST(SiemensMutants, Retract45) {
  const SpecCase c = caseOf("sinumerik-802s", kLcyc95Rough, kStepShaft);
  const Toolpath ref = runOn("reference", c), mutant = runOn("mutant:siemens-retract-45", c);
  ASSERT_EQ(ref.moves.size(), mutant.moves.size());
  const double h = 1 / std::sqrt(2.0);
  std::size_t retract = 0;
  while (retract < ref.moves.size() && !(ref.moves[retract].to.z == -19 && ref.moves[retract].to.x == 21)) ++retract;
  ASSERT_LT(retract + 1, ref.moves.size());
  EXPECT_EQ(ref.moves[retract].kind, MoveKind::Rapid);
  EXPECT_NEAR(mutant.moves[retract].to.z, -20 + h, 1e-9);
  EXPECT_NEAR(mutant.moves[retract].to.x, 20 + h, 1e-9);
  EXPECT_NEAR(ref.moves[retract + 1].to.z, 1, 1e-9);
  EXPECT_NEAR(ref.moves[retract + 1].to.x, 21, 1e-9);
  EXPECT_NEAR(mutant.moves[retract + 1].to.z, 1, 1e-9);
  EXPECT_NEAR(mutant.moves[retract + 1].to.x, 20 + h, 1e-9);
  // Four passes, four retracts (each followed by a move along Z but the last), all shortened.
  int differing = 0;
  for (std::size_t i = 0; i < ref.moves.size(); ++i) {
    const Point d = ref.moves[i].to - mutant.moves[i].to;
    if (std::abs(d.z) > 1e-9 || std::abs(d.x) > 1e-9) ++differing;
  }
  EXPECT_EQ(differing, 4 + 3);
}

// siemens-undercut-ff1: the groove of L1 (x radius) (10,0) → (10,-5) → (16,-5) → (16,-10) → (12,-10)
// → (12,-15) → (16,-15) → (16,-20) → (20,-20) is roughed after the passes at FF2 = 0.15 by the
// reference; the mutant cuts the same moves at FF1 = 0.3. Nothing else changes.
TEST(SiemensMutants, UndercutAtFf1) {
  const SpecCase c = caseOf("sinumerik-802d", "G0 X50 Z2\nCYCLE95(\"L1\", 3, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)\nM02\n",
                            "G1 X20 Z0\nZ-5\nX32\nZ-10\nX24\nZ-15\nX32\nZ-20\nX40\nRET\n");
  const Toolpath ref = runOn("reference", c), mutant = runOn("mutant:siemens-undercut-ff1", c);
  ASSERT_EQ(ref.moves.size(), mutant.moves.size());
  int undercutCuts = 0;
  for (std::size_t i = 0; i < ref.moves.size(); ++i) {
    const Move& r = ref.moves[i];
    const Move& m = mutant.moves[i];
    EXPECT_EQ(r.to.z, m.to.z);
    EXPECT_EQ(r.to.x, m.to.x);
    const bool undercut = std::find(r.rules.begin(), r.rules.end(), "CYCLE95.UNDERCUT") != r.rules.end();
    if (undercut && r.kind == MoveKind::Feed) {
      ++undercutCuts;
      EXPECT_DOUBLE_EQ(*r.feed, 0.15);
      EXPECT_DOUBLE_EQ(*m.feed, 0.3);
    } else {
      EXPECT_EQ(r.feed, m.feed);
    }
  }
  EXPECT_GT(undercutCuts, 3);
}

// Each Siemens mutant changes nothing on a FANUC case.
TEST(SiemensMutants, FanucCasesUnchanged) {
  const FuzzCase f = generateFuzzCase(fuzzCaseSeed(kSeed, 1));
  const SpecCase c = fuzzSpecCase(f, "fanuc");
  const Toolpath ref = runOn("reference", c);
  for (const char* name : {"mutant:siemens-retract-45", "mutant:siemens-undercut-ff1"}) {
    const Toolpath mutant = runOn(name, c);
    ASSERT_EQ(ref.moves.size(), mutant.moves.size()) << name;
    for (std::size_t i = 0; i < ref.moves.size(); ++i) EXPECT_EQ(ref.moves[i].to.z, mutant.moves[i].to.z) << name;
  }
}


// Each SINUMERIK mutant is caught by `check` on the spec cases and by the oracles alone in the
// default fuzz budget (2,000 cases, --cycles siemens): it fails more generated cases than the
// reference does on the same seed (the reference's own failures, where a contour begins by falling
// towards the axis, are issue 16's open disagreement), and its fault's oracle reports it.
TEST(SiemensMutants, EachIsCaughtByCheckAndByTheDefaultFuzzBudget) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("cyclecert-siemens-mutants-" + std::to_string(::getpid()));
  const auto failingCases = [&](Engine& engine, std::map<std::string, int>& byOracle) {
    FuzzOptions o;
    o.seed = 1;
    o.cases = kDefaultFuzzCases;
    o.cycles = kSiemens;
    o.shrinkBudget = 0;
    o.outDir = (dir / "fuzz").string();
    std::ostringstream progress;
    const FuzzSummary s = runFuzz(engine, nullptr, o, progress);
    std::ifstream results(dir / "fuzz" / "results.jsonl");
    long lines = 0;
    for (std::string line; std::getline(results, line); ++lines) {
      // The detail names each oracle that found something: "siemens-retract: …".
      const std::string detail = nlohmann::json::parse(line).value("detail", "");
      for (const char* oracle : {"siemens-retract", "siemens-infeed-steps", "siemens-feeds"}) {
        if (detail.find(std::string(oracle) + ":") != std::string::npos) ++byOracle[oracle];
      }
    }
    EXPECT_EQ(lines, s.run) << progress.str();
    fs::remove_all(o.outDir);
    return s.fail;
  };
  std::map<std::string, int> referenceOracles;
  auto reference = makeEngine("reference");
  const long referenceFails = failingCases(*reference, referenceOracles);
  const std::map<std::string, std::string> oracleOf = {{"mutant:siemens-retract-45", "siemens-retract"},
                                                       {"mutant:siemens-max-infeed", "siemens-infeed-steps"},
                                                       {"mutant:siemens-undercut-ff1", "siemens-feeds"}};
  for (const auto& [name, oracle] : oracleOf) {
    SCOPED_TRACE(name);
    auto engine = makeEngine(name);
    ASSERT_TRUE(engine);
    const SpecSuiteRun checked = checkTheSpecSuite(*engine, (dir / "check").string());
    EXPECT_GE(checked.summary.fail, 3) << checked.progress;
    std::map<std::string, int> byOracle;
    const long fails = failingCases(*engine, byOracle);
    EXPECT_GT(fails, referenceFails + 100);
    EXPECT_GT(byOracle[oracle], referenceOracles[oracle] + 100) << oracle;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cyclecert
