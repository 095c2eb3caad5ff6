// The `linuxcnc` engine: the FANUC → LinuxCNC translation (texts written by hand), the reading of
// rs274's canonical output (hand-written samples), and — where fetch-rs274.sh has put rs274 into
// BUILD/linuxcnc — a G71 case end to end, an alarm, and a batch that gives what single runs give.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>

#include "harness/engines/linuxcnc/linuxcnc_engine.h"
#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

SpecCase makeCase(const std::string& id, const std::string& program, const std::string& profile = "fanuc-0i-f",
                  std::vector<std::pair<std::string, double>> params = {}) {
  SpecCase c;
  c.file = id + ".json";
  c.id = id;
  c.profile = profile;
  c.program = program;
  c.params = std::move(params);
  return c;
}

// Type I G71, G01 head, allowances U0.4 W0.1 (specs/cases/fanuc-0i-f/g71/g01-head-stepped-shaft).
const char* kStepped = "G00 X36 Z2;\nG71 U2 R1;\nG71 P10 Q50 U0.4 W0.1 F0.2;\nN10 G01 X22;\nN20 Z-15;\n"
                       "N30 X30 Z-25;\nN40 Z-35;\nN50 X35;\n";

std::string translated(const SpecCase& c) {
  const LinuxCncTranslation t = translateForLinuxCnc(c);
  EXPECT_TRUE(t.program) << t.notApplicable;
  return t.program ? t.program->text : "";
}

std::string notApplicable(const SpecCase& c) {
  const LinuxCncTranslation t = translateForLinuxCnc(c);
  EXPECT_FALSE(t.program) << "translated:\n" << (t.program ? t.program->text : "");
  return t.notApplicable;
}

// G73.*: FANUC's pattern repeating cycle has no LinuxCNC counterpart (LinuxCNC's G73 drills): not
// applicable with that reason — before the parameters 5135–5137 a G73 case sets, and in system C,
// where the cycle is written G75 (and G73 is G71's roughing, which translates).
// A SINUMERIK case is not applicable, named as such (before: "cannot read the program: expected a
// number after address C", the FANUC reader's complaint about CYCLE95).
TEST(LinuxCncTranslate, SinumerikProgramsAreNotApplicable) {
  const std::string lcyc95 = "G0X30Z2\n_CNAME=\"L1\"\nR105=1 R108=2\nLCYC95\nM02\n";
  EXPECT_NE(notApplicable(makeCase("lcyc95", lcyc95, "sinumerik-802s")).find("a SINUMERIK program (sinumerik-802s)"),
            std::string::npos);
  const std::string cycle95 = "G0X30Z2\nCYCLE95(\"L1\", 2)\nM02\n";
  EXPECT_NE(notApplicable(makeCase("cycle95", cycle95, "sinumerik-802d")).find("LinuxCNC has no LCYC95/CYCLE95"),
            std::string::npos);
}

TEST(LinuxCncTranslate, G73IsNotApplicableBecauseLinuxCncsG73Drills) {
  const std::string g73 = "G00 X60 Z2;\nG73 U3 W0 R2;\nG73 P10 Q20 U0.4 W0.1 F0.2;\nN10 G01 X30 Z0;\nX40 Z-10;\n"
                          "Z-30;\nN20 X56;\n";
  const std::string reason = "LinuxCNC's G73 is a drilling cycle (chip-break peck)";
  EXPECT_NE(notApplicable(makeCase("g73", g73)).find(reason), std::string::npos);
  EXPECT_NE(notApplicable(makeCase("g73", g73)).find("line 2"), std::string::npos);
  EXPECT_NE(notApplicable(makeCase("g73-params", g73, "fanuc-0i-f", {{"5135", 3}, {"5137", 2}})).find(reason),
            std::string::npos);
  EXPECT_NE(notApplicable(makeCase("g73-gsk", g73, "gsk")).find(reason), std::string::npos);
  std::string g75 = "G90 G95;\n" + g73;
  for (std::size_t at; (at = g75.find("G73")) != std::string::npos;) g75.replace(at, 3, "G75");
  EXPECT_NE(notApplicable(makeCase("g75-gsc", g75, "fanuc-0i-f", {{"3401#7", 1}})).find(reason), std::string::npos);
  // System C's G73 is G71's roughing: it is translated, not refused as a pattern repeating cycle.
  std::string g73AsG71 = std::string("G90 G95;\n") + kStepped;
  for (std::size_t at; (at = g73AsG71.find("G71")) != std::string::npos;) g73AsG71.replace(at, 3, "G73");
  EXPECT_NE(translated(makeCase("g73-gsc-roughing", g73AsG71, "fanuc-0i-f", {{"3401#7", 1}})).find("G71.1"),
            std::string::npos);
}

// PROG.WHOLE: the reference draws the approach from the first positioning on; the translation starts
// at A, so a program that moves from a known position before its cycle is not applicable, while
// one whose only positioning is the move to A (in one block or two) still translates.
TEST(LinuxCncTranslate, MotionBeforeTheCycleIsNotApplicable) {
  EXPECT_NE(notApplicable(makeCase("approach", std::string("G00 X100 Z100;\n") + kStepped)).find("motion before the cycle"),
            std::string::npos);
  EXPECT_FALSE(translated(makeCase("x-then-z", std::string("G00 X36;\nZ2;\n") + (kStepped + 12))).empty());
  EXPECT_FALSE(translated(makeCase("after-g28", std::string("G28 U0 W0;\n") + kStepped)).empty());
}

std::string buildDir() {
  if (const char* dir = std::getenv("CYCLECERT_BUILD_DIR")) return dir;
  return std::filesystem::path(CYCLECERT_CLI).parent_path().string();
}

std::string skipMessage() {
  return "rs274 is not in " + buildDir() + "/linuxcnc: run harness/engines/linuxcnc/fetch-rs274.sh " + buildDir() +
         " (needs Debian's archive)";
}

// Every spec case, for the batch proof.
std::vector<SpecCase> specCases() {
  std::vector<SpecCase> cases;
  for (const std::string& f : findSpecCaseFiles(std::string(CYCLECERT_SOURCE_DIR) + "/specs/cases")) {
    cases.push_back(loadSpecCase(f));
  }
  return cases;
}

void expectSameResult(const EngineResult& batch, const EngineResult& single) {
  EXPECT_EQ(batch.kind, single.kind);
  EXPECT_EQ(batch.detail, single.detail);
  const Toolpath &a = batch.path, &b = single.path;
  EXPECT_EQ(a.start, b.start);
  EXPECT_EQ(a.plane, b.plane);
  ASSERT_EQ(a.moves.size(), b.moves.size());
  for (std::size_t k = 0; k < a.moves.size(); ++k) {
    EXPECT_EQ(a.moves[k].kind, b.moves[k].kind) << "move " << k;
    EXPECT_EQ(a.moves[k].shape, b.moves[k].shape) << "move " << k;
    EXPECT_EQ(a.moves[k].to, b.moves[k].to) << "move " << k;
    EXPECT_EQ(a.moves[k].center, b.moves[k].center) << "move " << k;
    EXPECT_EQ(a.moves[k].feed, b.moves[k].feed) << "move " << k;
    EXPECT_EQ(a.moves[k].phase, b.moves[k].phase) << "move " << k;
  }
  ASSERT_EQ(a.alarm.has_value(), b.alarm.has_value());
  if (a.alarm) {
    EXPECT_EQ(a.alarm->code, b.alarm->code);
    EXPECT_EQ(a.alarm->message, b.alarm->message);
    EXPECT_EQ(a.alarm->line, b.alarm->line);
  }
  EXPECT_EQ(a.warnings.size(), b.warnings.size());
}

// The suite's fixture: the rs274 tests skip with the fetch command when rs274 is not there.
class LinuxCnc : public ::testing::Test {
 protected:
  LinuxCncEngine& engine() {
    if (!engine_) engine_ = std::make_unique<LinuxCncEngine>(buildDir());
    return *engine_;
  }
  bool haveRs274() { return engine().available(); }

 private:
  std::unique_ptr<LinuxCncEngine> engine_;
};

// ---- Translation ---------------------------------------------------------------------------------

TEST_F(LinuxCnc, TranslatesTypeIG71WithAllowancesIntoTheShiftedProfile) {
  // A = (x 18, z 2); the profile is shifted by (Δw 0.1, Δu/2 0.2): A' = (18.2, 2.1), B' = (11.2, 2.1)…
  EXPECT_EQ(translated(makeCase("stepped", kStepped)),
            "(cyclecert: stepped)\n"
            "G18 G21 G90 G40 G94 G91.1 G7\n"
            "G0 X36 Z2\n"
            "o100 sub\n"
            "G1 X22.4 Z2.1\n"
            "G1 X22.4 Z-14.9\n"
            "G1 X30.4 Z-24.9\n"
            "G1 X30.4 Z-34.9\n"
            "G1 X35.4 Z-34.9\n"
            "o100 endsub\n"
            "(cyclecert: cycle)\n"
            "G71.1 Q100 X36.4 Z2.1 D0 I2 R1 F0.2\n"
            "(cyclecert: return)\n"
            "G0 X36\n"
            "G0 Z2\n"
            "(cyclecert: end)\n"
            "M2\n");
}

TEST_F(LinuxCnc, TranslatesG72WithAnArcAndTheDirectReturn) {
  // G72: Δd along Z; A = (x 30, z 2), allowance (Δw 0.1, Δu/2 0.1); the G03 arc's centre (z 0, x 20)
  // is shifted to (0.1, 20.1): I = 20.1 − 20.1 = 0, K = 0.1 − (−9.9) = 10 (radius, incremental).
  const SpecCase c = makeCase("facing",
                              "G00 X60 Z2;\nG72 W2 R0.5;\nG72 P10 Q30 U0.2 W0.1 F100;\nN10 G00 Z-10;\n"
                              "N20 G01 X40;\nN30 G03 X20 Z0 R10;\n",
                              "fanuc-0i-f", {{"DTP", 1}, {"5132", 1.5}});
  EXPECT_EQ(translated(c),
            "(cyclecert: facing)\n"
            "G18 G21 G90 G40 G94 G91.1 G7\n"
            "G0 X60 Z2\n"
            "o100 sub\n"
            "G0 X60.2 Z-9.9\n"
            "G1 X40.2 Z-9.9\n"
            "G3 X20.2 Z0.1 I0 K10\n"
            "o100 endsub\n"
            "(cyclecert: cycle)\n"
            "G72.1 Q100 X60.2 Z2.1 D0 I2 R0.5 F100\n"
            "(cyclecert: return)\n"
            "G0 X60 Z2\n"
            "(cyclecert: end)\n"
            "M2\n");
  const LinuxCncTranslation t = translateForLinuxCnc(c);
  ASSERT_TRUE(t.program);
  EXPECT_EQ(t.program->lines.at("G3 X20.2 Z0.1 I0 K10"), 6);  // an rs274 error there names case line 6
  EXPECT_EQ(t.program->lines.at("G72.1 Q100 X60.2 Z2.1 D0 I2 R0.5 F100"), 3);
  ASSERT_EQ(t.program->warnings.size(), 1u);
  EXPECT_NE(t.program->warnings[0].message.find("appended by cyclecert"), std::string::npos);
}

TEST_F(LinuxCnc, TypeIIUsesThePocketingCycleAndG17IsMappedOntoG18) {
  const std::string typeII = translated(makeCase(
      "pocket", "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q60 U0.4 W0 F0.2;\nN10 G00 X32 W0;\nN20 G01 Z-4;\n"
                "N30 X38 Z-7;\nN40 X26;\nN50 Z-13;\nN60 X38;\n"));
  EXPECT_NE(typeII.find("\nG71 Q100 X40.4 Z2 D0 I2 R0.5 F0.2\n"), std::string::npos) << typeII;

  const SpecCase g17 = makeCase("g17", "G17;\nG00 X64 Y21;\nG71 V2 R0.5;\nG71 P10 Q40 U0.2 V0.4 F0.2;\n"
                                       "N10 G00 Y12;\nN20 G01 X40;\nN30 X32 Y16;\nN40 Y20;\n");
  const LinuxCncTranslation t = translateForLinuxCnc(g17);
  ASSERT_TRUE(t.program) << t.notApplicable;
  EXPECT_EQ(t.program->plane, "G17");
  // G17: the 1st axis X (a diameter: 32 mm) is the canonical z, the 2nd axis Y the canonical x.
  EXPECT_EQ(t.program->start.z, 32);
  EXPECT_EQ(t.program->start.x, 21);
  EXPECT_NE(t.program->text.find("\nG0 X42 Z32\n"), std::string::npos) << t.program->text;
}

TEST_F(LinuxCnc, WhatLinuxCncCannotExpressIsNotApplicable) {
  EXPECT_NE(notApplicable(makeCase("rf1", kStepped, "fanuc-0i-f", {{"RF1", 1}})).find("RF1 (5105#1) = 1"),
            std::string::npos);
  EXPECT_NE(notApplicable(makeCase("tol", kStepped, "fanuc-0i-f", {{"5145", 0.2}})).find("5145 = 0.2"),
            std::string::npos);
  EXPECT_NE(notApplicable(makeCase("g42", std::string("G42;\n") + kStepped)).find("compensation"), std::string::npos);
  EXPECT_NE(notApplicable(makeCase("two", std::string(kStepped) + "G00 X36 Z2;\nG71 P10 Q50 U0.4 W0.1 F0.2;\n"))
                .find("one roughing cycle"),
            std::string::npos);
  EXPECT_NE(notApplicable(makeCase("g70", std::string(kStepped) + "G70 P10 Q50;\n")).find("G70"), std::string::npos);
  EXPECT_NE(notApplicable(makeCase("nocycle", "G00 X36 Z2;\nG01 Z-10 F0.2;\n")).find("no G71/G72"),
            std::string::npos);
  EXPECT_NE(notApplicable(makeCase("ps0063", "G00 X36 Z2;\nG71 U2 R1;\nG71 P10 Q99 U0.4 W0.1 F0.2;\nN10 G01 X22;\n"))
                .find("PS0063"),
            std::string::npos);
  SpecCase mdi = makeCase("mdi", kStepped);
  mdi.mdi = true;
  EXPECT_NE(notApplicable(mdi).find("MDI"), std::string::npos);
  // Parameters the translation carries are not a reason: Δd/e (5132/5133) and DTP; neither is a
  // parameter set to its default.
  EXPECT_TRUE(translateForLinuxCnc(makeCase("ok", kStepped, "fanuc-0i-f", {{"5133", 0.3}, {"DTP", 1}, {"RF1", 0}})).program);
}

// G71.FS10.*: the Series 10/11 one block (FCV = 1) says what the two blocks say — Δd by D in least
// input increments (D2000 = 2 mm), e by parameter 5133 — so it translates into the same LinuxCNC
// cycle as kStepped's `G71 U2 R1; G71 P10 Q50 U0.4 W0.1 F0.2`.
TEST_F(LinuxCnc, TranslatesTheSeries10OneBlockLikeTheTwoBlocks) {
  const std::string oneBlock = "G00 X36 Z2;\nG71 P10 Q50 U0.4 W0.1 D2000 F0.2;\nN10 G01 X22;\nN20 Z-15;\n"
                               "N30 X30 Z-25;\nN40 Z-35;\nN50 X35;\n";
  const std::string text = translated(makeCase("stepped", oneBlock, "fanuc-0i-f", {{"FCV", 1}, {"5133", 1}}));
  EXPECT_EQ(text, translated(makeCase("stepped", kStepped)));
  EXPECT_NE(text.find("\nG71.1 Q100 X36.4 Z2.1 D0 I2 R1 F0.2\n"), std::string::npos) << text;
  // G72 too: D1500 is Δd 1.5 mm along Z.
  const std::string face = translated(makeCase(
      "face", "G00 X60 Z2;\nG72 P10 Q30 U0.2 W0.1 D1500 F100;\nN10 G00 Z-10;\nN20 G01 X40;\nN30 G03 X20 Z0 R10;\n",
      "fanuc-0i-f", {{"FCV", 1}, {"5133", 0.5}, {"DTP", 1}}));
  EXPECT_NE(face.find("\nG72.1 Q100 X60.2 Z2.1 D0 I1.5 R0.5 F100\n"), std::string::npos) << face;
  // With FCV = 0 the D is FANUC's PS0009 before the shape is read: nothing to translate.
  EXPECT_NE(notApplicable(makeCase("fcv0", oneBlock)).find("PS0009"), std::string::npos);
}

// HAAS.G71.*: the Haas one block says what the two blocks say — Δd by D in mm (decimal point), e by
// parameter 5133 (Setting 73) — so it translates into kStepped's LinuxCNC cycle; R1 (type II) into
// the pocketing G71. G42 inside P…Q (HAAS.TNRC.SHAPE) is compensation: not applicable, as on FANUC.
TEST_F(LinuxCnc, TranslatesTheHaasOneBlockLikeTheTwoBlocks) {
  const std::string oneBlock = "G00 X36 Z2;\nG71 P10 Q50 U0.4 W0.1 D2. F0.2;\nN10 G01 X22;\nN20 Z-15;\n"
                               "N30 X30 Z-25;\nN40 Z-35;\nN50 X35;\n";
  const std::string text = translated(makeCase("stepped", oneBlock, "haas", {{"5133", 1}}));
  EXPECT_EQ(text, translated(makeCase("stepped", kStepped)));
  EXPECT_NE(text.find("\nG71.1 Q100 X36.4 Z2.1 D0 I2 R1 F0.2\n"), std::string::npos) << text;
  // Without 5133 the haas profile's Setting 73 default (1.27 mm) is e.
  EXPECT_NE(translated(makeCase("s73", oneBlock, "haas")).find(" I2 R1.27 F0.2\n"), std::string::npos);
  const std::string typeII = translated(makeCase(
      "r1", "G00 X40 Z2;\nG71 P10 Q50 U0.4 W0 D2. R1 F0.2;\nN10 G01 X30;\nN20 Z-10;\nN30 X34;\nN40 Z-20;\nN50 X38;\n",
      "haas", {{"5133", 0.5}}));
  EXPECT_NE(typeII.find("\nG71 Q100 X40.4 Z2 D0 I2 R0.5 F0.2\n"), std::string::npos) << typeII;
  const std::string why = notApplicable(makeCase(
      "g42", "G00 X36 Z2;\nG71 P10 Q50 U0.4 W0.1 D2. F0.2;\nN10 G42 G01 X22;\nN20 Z-15;\nN30 X35;\nG40;\n", "haas"));
  EXPECT_NE(why.find("G41/G42 at line 3"), std::string::npos) << why;
}

// PROG.GSYS.*: a program in G code system B or C (3401#6 GSB / #7 GSC) is read in its system
// (oracles/cycle_spec) and translates into the cycle its system A twin does: G90 absolute, G95
// feed per revolution, system C's G73 the stock removal in turning.
TEST_F(LinuxCnc, TranslatesGCodeSystemsBAndCLikeSystemA) {
  const std::string expected = translated(makeCase("stepped", kStepped));
  const std::string shape = "N10 G01 X22;\nN20 Z-15;\nN30 X30 Z-25;\nN40 Z-35;\nN50 X35;\n";
  EXPECT_EQ(translated(makeCase("stepped", "G90 G95;\nG00 X36 Z2;\nG71 U2 R1;\nG71 P10 Q50 U0.4 W0.1 F0.2;\n" + shape,
                                "fanuc-0i-f", {{"3401#6", 1}})),
            expected);
  EXPECT_EQ(translated(makeCase("stepped", "G90 G95;\nG00 X36 Z2;\nG73 U2 R1;\nG73 P10 Q50 U0.4 W0.1 F0.2;\n" + shape,
                                "fanuc-0i-f", {{"GSC", 1}})),
            expected);
  // In system C, G71 is metric input: the program has no roughing cycle.
  EXPECT_NE(notApplicable(makeCase("c-g71", kStepped, "fanuc-0i-f", {{"3401#7", 1}})).find("no G71/G72"),
            std::string::npos);
}

TEST_F(LinuxCnc, TheHuazhongOneBlockIsNotApplicable) {
  const std::string why = notApplicable(makeCase(
      "hnc", "G00 X36 Z2;\nG71 U2 R1 P10 Q50 X0.4 Z0.1 F0.2;\nN10 G01 X22;\nN20 Z-15;\nN30 X30 Z-25;\nN40 Z-35;\n"
             "N50 X35;\n",
      "hnc"));
  EXPECT_NE(why.find("Huazhong"), std::string::npos) << why;
  EXPECT_NE(why.find("HNC.G71.FST"), std::string::npos) << why;
}

// ---- Reading rs274's canonical output ------------------------------------------------------------

TEST_F(LinuxCnc, ParsesCanonicalMovesArcsAndMarkers) {
  const std::string out =
      "    1 N..... USE_LENGTH_UNITS(CANON_UNITS_MM)\n"
      "    7 N..... SELECT_PLANE(CANON_PLANE_XZ)\n"
      "   10 N..... STRAIGHT_TRAVERSE(18.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)\n"  // before the cycle
      "   11 N..... COMMENT(\"cyclecert: cycle\")\n"
      "   12 N..... SET_FEED_RATE(0.2000)\n"
      "   13 N..... STRAIGHT_TRAVERSE(18.0000, 0.0000, 2.0000, 0.0000, 0.0000, 0.0000)\n"  // zero length
      "   14 N..... STRAIGHT_TRAVERSE(18.2000, 0.0000, 2.1000, 0.0000, 0.0000, 0.0000)\n"
      "   15 N..... STRAIGHT_TRAVERSE(18.2000, 0.0000, 2.1000, 0.0000, 0.0000, 0.0000)\n"  // duplicate
      "(0.1,18.2) (2.1,18.2)\n"                                                         // a G7x diagnostic
      "   16 N..... STRAIGHT_FEED(-0.0000, 0.0000, 2.1000, 0.0000, 0.0000, 0.0000)\n"
      "   17 N..... STRAIGHT_FEED(-0.0000, 0.0000, -10.00004, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   18 N..... ARC_FEED(-15.0000, 5.0000, -10.0000, 5.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   19 N..... ARC_FEED(-20.0000, 0.0000, -20.0000, 5.0000, -1, 0.0000, 0.0000, 0.0000, 0.0000)\n"
      "   20 N..... ARC_FEED(-20.0000, -0.0000, -21.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)\n"  // zero
      "   21 N..... COMMENT(\"cyclecert: return\")\n"
      "   22 N..... STRAIGHT_TRAVERSE(18.0000, 0.0000, -20.0000, 0.0000, 0.0000, 0.0000)\n"
      "   23 N..... COMMENT(\"cyclecert: end\")\n"
      "   24 N..... STRAIGHT_TRAVERSE(0.0000, 0.0000, 0.0000, 0.0000, 0.0000, 0.0000)\n";  // after the end
  const CanonicalParse p = parseCanonical(out);
  ASSERT_EQ(p.error, "");
  EXPECT_TRUE(p.sawCycle);
  EXPECT_TRUE(p.sawEnd);
  EXPECT_EQ(p.path.start, (Point{2, 18}));
  ASSERT_EQ(p.path.moves.size(), 6u);
  const auto& m = p.path.moves;
  EXPECT_EQ(m[0].kind, MoveKind::Rapid);
  EXPECT_EQ(m[0].to, (Point{2.1, 18.2}));
  EXPECT_FALSE(m[0].feed);
  EXPECT_EQ(m[1].kind, MoveKind::Feed);
  EXPECT_EQ(m[1].to, (Point{2.1, 0}));
  EXPECT_FALSE(std::signbit(m[1].to.x)) << "-0.0000 is read as 0";
  EXPECT_EQ(m[1].feed, 0.2);
  EXPECT_EQ(m[2].to, (Point{-10, 0})) << "rounded to 4 decimals; the 9-number form (U V W) is read too";
  EXPECT_EQ(m[3].shape, SegmentKind::ArcCCW);
  EXPECT_EQ(m[3].to, (Point{-15, 5}));
  EXPECT_EQ(*m[3].center, (Point{-10, 5}));
  EXPECT_EQ(m[3].feed, 0.2);
  EXPECT_EQ(m[4].shape, SegmentKind::ArcCW);
  EXPECT_EQ(*m[4].center, (Point{-20, 5}));
  EXPECT_EQ(m[4].phase, MovePhase::None);
  EXPECT_EQ(m[5].phase, MovePhase::Return);
  EXPECT_EQ(m[5].kind, MoveKind::Rapid);
  EXPECT_EQ(m[5].to, (Point{-20, 18}));
}

TEST_F(LinuxCnc, GarbageCanonicalOutputIsAnError) {
  EXPECT_NE(parseCanonical("   5 N..... STRAIGHT_FEED(1.0000, nonsense, 2.0000)\n").error, "");
  EXPECT_NE(parseCanonical("   5 N..... SELECT_PLANE(CANON_PLANE_XZ)\n   6 N..... ARC_FEED(1.0, 2.0)\n").error, "");
  EXPECT_NE(parseCanonical("   5 N..... SELECT_PLANE(CANON_PLANE_XY)\n"
                           "   6 N..... ARC_FEED(1.0, 2.0, 0.0, 0.0, 1, 0.0, 0.0, 0.0, 0.0)\n")
                .error,
            "")
      << "an arc outside the XZ plane cannot be a lathe cycle's";
  const CanonicalParse empty = parseCanonical("executing\nsome text\n");
  EXPECT_EQ(empty.error, "");
  EXPECT_EQ(empty.calls, 0u);
  EXPECT_FALSE(empty.sawCycle);
}

// Found by tests/fuzz/linuxcnc_canon_fuzz.cpp: an ARC_FEED whose rotation is beyond a long was cast
// to long for the message (undefined behaviour; UBSan stopped there). The message shows the number.
TEST_F(LinuxCnc, AnArcOfAHugeRotationIsAnErrorShowingIt) {
  const std::string out = "   5 N..... SELECT_PLANE(CANON_PLANE_XZ)\n"
                          "   6 N..... ARC_FEED(1.0, 2.0, 0.0, 0.0, -2e21, 0.0, 0.0, 0.0, 0.0)\n";
  const std::string error = parseCanonical(out).error;
  EXPECT_NE(error.find("ARC_FEED with rotation -2e+21 (full turns)"), std::string::npos) << error;
}

TEST_F(LinuxCnc, ReadsRs274ErrorsAsAlarms) {
  const std::map<std::string, int> lines = {{"o100 endsub", 3}, {"G1 X22.4 Z2.1", 4}};
  const Alarm a = linuxCncAlarm("executing\n(2.1,18.2) (2.1,11.2)\nG7X error: Not monotonic\no100 endsub\n", lines);
  EXPECT_EQ(a.code, "LINUXCNC");
  EXPECT_EQ(a.message, "G7X error: Not monotonic");
  EXPECT_EQ(a.line, 3);
  const Alarm b = linuxCncAlarm("executing\nBad character 'u' used\nG71 Q100 U2executing", lines);
  EXPECT_EQ(b.message, "Bad character 'u' used");
  EXPECT_EQ(b.line, 0);
}

// ---- rs274 itself (skipped when it has not been fetched) -----------------------------------------

TEST_F(LinuxCnc, PlansASimpleG71FromTheStartPointBackToIt) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  const EngineResult r = engine().run(makeCase("stepped", kStepped));
  ASSERT_EQ(r.kind, EngineResult::Planned) << r.detail << (r.path.alarm ? r.path.alarm->message : "");
  const Toolpath& p = r.path;
  EXPECT_EQ(p.start, (Point{2, 18}));
  ASSERT_GE(p.moves.size(), 5u);
  EXPECT_EQ(p.moves.front().kind, MoveKind::Rapid);
  EXPECT_EQ(p.moves.front().to, (Point{2.1, 18.2})) << "A → A' first";
  EXPECT_EQ(p.moves.back().to, (Point{2, 18})) << "ends at A (the appended return)";
  EXPECT_EQ(p.moves.back().phase, MovePhase::Return);
  bool reachedC = false;
  for (const Move& m : p.moves) {
    if (m.kind == MoveKind::Feed) {
      EXPECT_EQ(m.feed, 0.2);
    }
    EXPECT_LT(m.to.x, 18.2 + 1 + 1e-9) << "stays within the retract above A'";
    reachedC = reachedC || m.to == Point{-34.9, 17.7};
  }
  EXPECT_TRUE(reachedC) << "the last pass follows the rough profile to C'";
  ASSERT_EQ(p.cycles.size(), 1u);
  EXPECT_EQ(p.cycles[0].code, "G71");
  EXPECT_EQ(p.cycles[0].moveCount + 2, p.moves.size());
}

TEST_F(LinuxCnc, ErrorsComeBackAsAlarmsWithLinuxCncsMessage) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  // Z turns back after the head (PS0064 for FANUC): LinuxCNC's G7x says "Not monotonic".
  const EngineResult r = engine().run(makeCase(
      "reverse", "G00 X36 Z2;\nG71 U2 R1;\nG71 P10 Q40 U0.4 W0.1 F0.2;\nN10 G01 X22;\nN20 Z-15;\nN30 Z-10;\nN40 X35;\n"));
  ASSERT_EQ(r.kind, EngineResult::Alarmed) << r.detail;
  ASSERT_TRUE(r.path.alarm);
  EXPECT_EQ(r.path.alarm->code, "LINUXCNC");
  EXPECT_NE(r.path.alarm->message.find("Not monotonic"), std::string::npos) << r.path.alarm->message;
  EXPECT_EQ(r.path.alarm->line, 3);
}

TEST_F(LinuxCnc, ABatchGivesWhatSingleRunsGive) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  const std::vector<SpecCase> cases = {
      makeCase("stepped", kStepped),
      makeCase("reverse", "G00 X36 Z2;\nG71 U2 R1;\nG71 P10 Q40 U0.4 W0.1 F0.2;\nN10 G01 X22;\nN20 Z-15;\n"
                          "N30 Z-10;\nN40 X35;\n"),
      makeCase("rf1", kStepped, "fanuc-0i-f", {{"RF1", 1}}),
      makeCase("facing", "G00 X60 Z2;\nG72 W2 R0.5;\nG72 P10 Q30 U0.2 W0.1 F100;\nN10 G00 Z-10;\nN20 G01 X40;\n"
                         "N30 G03 X20 Z0 R10;\n"),
      makeCase("pocket", "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q60 U0.4 W0 F0.2;\nN10 G00 X32 W0;\nN20 G01 Z-4;\n"
                         "N30 X38 Z-7;\nN40 X26;\nN50 Z-13;\nN60 X38;\n"),
      makeCase("inner", "G00 X10 Z3;\nG71 U1.5 R0.5;\nG71 P10 Q30 U-0.4 W0.1 F0.15;\nN10 G00 X30;\n"
                        "N20 G01 Z-20;\nN30 X12 Z-30;\n"),
  };
  std::vector<EngineResult> single;
  for (const SpecCase& c : cases) single.push_back(engine().run(c));
  const std::size_t before = engine().processesStarted();
  const std::vector<EngineResult> batch = engine().runBatch(cases);
  // One process up to the alarm of case 2, one for the rest.
  EXPECT_EQ(engine().processesStarted() - before, 2u);
  ASSERT_EQ(batch.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].id);
    expectSameResult(batch[i], single[i]);
  }
  EXPECT_EQ(batch[0].kind, EngineResult::Planned);
  EXPECT_EQ(batch[1].kind, EngineResult::Alarmed);
  EXPECT_EQ(batch[2].kind, EngineResult::NotApplicable);
  EXPECT_EQ(batch[3].kind, EngineResult::Planned);
}

TEST_F(LinuxCnc, EverySpecCaseGivesTheSameResultInOneBatchAsAlone) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  const std::vector<SpecCase> cases = specCases();
  ASSERT_GT(cases.size(), 20u);
  std::vector<EngineResult> single;
  for (const SpecCase& c : cases) single.push_back(engine().run(c));
  const std::size_t before = engine().processesStarted();
  const std::vector<EngineResult> batch = engine().runBatch(cases);
  const std::size_t batchProcesses = engine().processesStarted() - before;
  std::size_t ran = 0, alarms = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(cases[i].id);
    expectSameResult(batch[i], single[i]);
    ran += single[i].kind == EngineResult::Planned || single[i].kind == EngineResult::Alarmed;
    alarms += single[i].kind == EngineResult::Alarmed;
  }
  EXPECT_GT(ran, 10u);
  // One process, plus one more after each case rs274 stopped in with an error.
  EXPECT_LE(batchProcesses, alarms + 1);
}

TEST_F(LinuxCnc, TimeoutAndOutputCapAreEngineFailures) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  LinuxCncOptions hurried;
  hurried.timeoutSeconds = 1e-6;
  LinuxCncEngine slow(buildDir(), hurried);
  const EngineResult late = slow.run(makeCase("stepped", kStepped));
  EXPECT_EQ(late.kind, EngineResult::Failed);
  EXPECT_NE(late.detail.find("timed out"), std::string::npos) << late.detail;

  LinuxCncOptions capped;
  capped.outputCap = 200;
  LinuxCncEngine chatty(buildDir(), capped);
  const EngineResult flood = chatty.run(makeCase("stepped", kStepped));
  EXPECT_EQ(flood.kind, EngineResult::Failed);
  EXPECT_NE(flood.detail.find("more than 200 bytes"), std::string::npos) << flood.detail;
}

// A case on which rs274 hangs (kept in corpus/regressions), between two that plan: in one batch the
// timeout lands on that case alone, and the others get what they get when run alone.
TEST_F(LinuxCnc, ACaseThatHangsInABatchGetsTheTimeoutAndTheOthersTheirResults) {
  if (!haveRs274()) GTEST_SKIP() << skipMessage();
  LinuxCncOptions quick;
  quick.timeoutSeconds = 1;
  LinuxCncEngine engine(buildDir(), quick);
  const SpecCase hangs =
      loadSpecCase(std::string(CYCLECERT_SOURCE_DIR) + "/corpus/regressions/fanuc-0i-f/g71/fuzz-linuxcnc-41467b9476da404d.json");
  const SpecCase before = makeCase("before", kStepped), after = makeCase("after", kStepped);
  const std::vector<EngineResult> batch = engine.runBatch({before, hangs, after});
  ASSERT_EQ(batch.size(), 3u);
  EXPECT_EQ(batch[1].kind, EngineResult::Failed);
  EXPECT_NE(batch[1].detail.find("timed out"), std::string::npos) << batch[1].detail;
  for (const std::size_t i : {0u, 2u}) {
    const EngineResult alone = engine.run(i == 0 ? before : after);
    EXPECT_EQ(batch[i].kind, alone.kind) << batch[i].detail;
    EXPECT_EQ(batch[i].path.moves.size(), alone.path.moves.size());
  }
}

TEST_F(LinuxCnc, WithoutRs274TheEngineFailsWithTheFetchCommand) {
  LinuxCncEngine missing("/nonexistent-build");
  EXPECT_FALSE(missing.available());
  const EngineResult r = missing.run(makeCase("stepped", kStepped));
  EXPECT_EQ(r.kind, EngineResult::Failed);
  EXPECT_NE(r.detail.find("fetch-rs274.sh /nonexistent-build"), std::string::npos) << r.detail;
  EXPECT_EQ(missing.version(), "linuxcnc-uspace (not fetched)");
  // Not-applicable cases need no rs274.
  EXPECT_EQ(missing.run(makeCase("rf1", kStepped, "fanuc-0i-f", {{"RF1", 1}})).kind, EngineResult::NotApplicable);
}

}  // namespace
}  // namespace cyclecert
