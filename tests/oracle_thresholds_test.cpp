// Each oracle against hand-made toolpaths that violate it by a little (just over its threshold) and
// that satisfy it by a little (just under): exactly that oracle reports, naming the right move, or
// nothing reports at all. Every path starts from a correct path derived by hand from the steps of
// reference/cycles/README.md (copied from a spec case whose moves were derived by hand) and perturbs
// one move — or the few moves that follow it, so that only the property under test breaks.
//
// The tolerance the geometric oracles carry is JudgeSettings::tolerance() = ε + 2·chord tolerance =
// 0.001 + 2·0.001 = 0.003 mm. "Just over" is the threshold + 0.002, "just under" the threshold − 0.002
// (or as close below as the threshold allows, where it is smaller than 0.002).
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/spec/rule_catalogue.h"
#include "harness/spec/spec_case.h"

namespace cyclecert {
namespace {

const double kTol = JudgeSettings{}.tolerance();  // 0.003
constexpr double kBy = 0.002;                     // how far over or under a threshold

// --- building toolpaths by hand ---------------------------------------------------------------

Move rapid(double x, double z) {
  Move m;
  m.kind = MoveKind::Rapid;
  m.to = {z, x};
  return m;
}

Move feed(double x, double z, double f) {
  Move m;
  m.kind = MoveKind::Feed;
  m.to = {z, x};
  m.feed = f;
  return m;
}

Toolpath pathFrom(Point start, std::vector<Move> moves) {
  Toolpath t;
  t.profile = "fanuc-0i-f";
  t.start = start;
  t.moves = std::move(moves);
  return t;
}

std::vector<Finding> judgePath(const std::string& program, const Toolpath& path,
                               std::vector<std::pair<std::string, double>> params = {},
                               JudgeSettings settings = {}) {
  JudgeRequest request;
  request.program = {program, "hand-made.nc", "fanuc-0i-f", std::move(params), {}};
  request.settings = settings;
  return judge(judgeInputFor(request, path));
}

// Exactly one finding, by `oracle`, naming `move`.
void expectOnly(const std::vector<Finding>& findings, const std::string& oracle, std::optional<std::size_t> move) {
  ASSERT_EQ(findings.size(), 1u) << findingsText(findings);
  EXPECT_EQ(findings[0].oracle, oracle) << findingsText(findings);
  EXPECT_EQ(findings[0].move, move) << findingsText(findings);
  EXPECT_FALSE(findings[0].rules.empty());
}

// Findings by `oracle` only, one per move of `moves`, in that order.
void expectOnly(const std::vector<Finding>& findings, const std::string& oracle, const std::vector<std::size_t>& moves) {
  ASSERT_EQ(findings.size(), moves.size()) << findingsText(findings);
  for (std::size_t k = 0; k < moves.size(); ++k) {
    EXPECT_EQ(findings[k].oracle, oracle) << findingsText(findings);
    EXPECT_EQ(findings[k].move, moves[k]) << findingsText(findings);
  }
}

void expectNone(const std::vector<Finding>& findings) { EXPECT_TRUE(findings.empty()) << findingsText(findings); }

// The findings other than `oracle`'s: for perturbations that move a pass level on purpose, which
// pass-levels rightly reports too (it has its own tests below).
std::vector<Finding> besides(std::vector<Finding> findings, const std::string& oracle) {
  findings.erase(std::remove_if(findings.begin(), findings.end(), [&](const Finding& f) { return f.oracle == oracle; }),
                 findings.end());
  return findings;
}

// --- the programs and their correct paths -------------------------------------------------------

// G71 type I, G00 head (spec case fanuc-0i-f/g71/quad-upos-wpos-outer-negz). A = (x 25, z 3),
// Δd = 2, e = 0.5, F 0.25; shape (15, 3) → (15, −20) → (20, −30) → (24, −30); allowances
// (Δu/2, Δw) = (0.25, 0.2): rough profile B' (15.25, 3.2) → (15.25, −19.8) → taper → (20.25, −29.8)
// → C' (24.25, −29.8). On the taper z = −19.8 − 2·(x − 15.25). The implied stock is x ≤ 25 over
// z ∈ [−30, 3].
const char* kG71 =
    "G00 X50 Z3;\nG71 U2 R0.5;\nG71 P10 Q40 U0.5 W0.2 F0.25;\nN10 G00 X30;\nN20 G01 Z-20;\nN30 X40 Z-30;\nN40 X48;\n";
constexpr double kG71F = 0.25;
const Point kG71A{3, 25};

// Levels A'.x − k·Δd = 23.25, 21.25, 19.25, 17.25 (15.25 = B'.x is not strictly between).
Toolpath g71Path() {
  const double f = kG71F;
  return pathFrom(kG71A, {
                             rapid(25.25, 3.2),     // 0  STEP1 A → A'
                             rapid(23.25, 3.2),     // 1  STEP2 infeed Δd (G00 head: rapid)
                             feed(23.25, -29.8, f), // 2  pass 1 to C' (the level is above the taper)
                             feed(23.75, -29.3, f), // 3  STEP4 45° retract by e
                             rapid(23.75, 3.2),     // 4  STEP5 back to A'.z
                             rapid(21.25, 3.2),     // 5  STEP6 infeed Δd + e
                             feed(21.25, -29.8, f), // 6  pass 2
                             feed(21.75, -29.3, f), // 7
                             rapid(21.75, 3.2),     // 8
                             rapid(19.25, 3.2),     // 9
                             feed(19.25, -27.8, f), // 10 pass 3 ends on the taper
                             feed(19.75, -27.3, f), // 11
                             rapid(19.75, 3.2),     // 12
                             rapid(17.25, 3.2),     // 13
                             feed(17.25, -23.8, f), // 14 pass 4 ends on the taper
                             feed(17.75, -23.3, f), // 15
                             rapid(17.75, 3.2),     // 16
                             rapid(15.25, 3.2),     // 17 infeed to B'
                             feed(15.25, -19.8, f), // 18 STEP7 semi-finish along the rough profile
                             feed(20.25, -29.8, f), // 19
                             feed(24.25, -29.8, f), // 20 C'
                             rapid(25, -29.8),      // 21 STEP8 (DTP = 0): out to A.x
                             rapid(25, 3),          // 22 … and along z to A
                         });
}

// The same with RF1 = 1 (no semi-finish): after pass 4's rapid back, STEP8 from there.
Toolpath g71PathWithoutSemiFinish() {
  Toolpath t = g71Path();
  t.moves.resize(17);
  t.moves.push_back(rapid(25, 3.2));  // 17 out to A.x
  t.moves.push_back(rapid(25, 3));    // 18 along z to A
  return t;
}

// G72 type I (spec case fanuc-0i-f/g72/dtp-conventional-return). A = (x 45, z 1), Δd = 2.5, e = 0.5,
// F150; shape (45, 1) → B (45, −8) → (30, −8) → C (15, −2); allowances (0.1, 0.1): rough profile
// B' (45.1, −7.9) → (30.1, −7.9) → C' (15.1, −1.9); on the taper x = 30.1 − 2.5·(z + 7.9). The cut
// runs along −x, the infeed along −z; the retract is +e in x (back) and +e in z (out).
const char* kG72 = "G00 X90 Z1;\nG72 W2.5 R0.5;\nG72 P10 Q20 U0.2 W0.1 F150;\nN10 G00 Z-8;\nG01 X60;\nN20 X30 Z-2;\nM30;\n";
constexpr double kG72F = 150;
const Point kG72A{1, 45};

// Levels A'.z − k·Δd = −1.4, −3.9, −6.4 (−8.9 is past B'.z = −7.9).
Toolpath g72Path() {
  const double f = kG72F;
  return pathFrom(kG72A, {
                             rapid(45.1, 1.1),      // 0  A → A'
                             rapid(45.1, -1.4),     // 1  infeed Δd
                             feed(15.1, -1.4, f),   // 2  pass 1: the level is above C', the cut ends at C'.x
                             feed(15.6, -0.9, f),   // 3  45° retract
                             rapid(45.1, -0.9),     // 4  back to A'.x
                             rapid(45.1, -3.9),     // 5  infeed Δd + e
                             feed(20.1, -3.9, f),   // 6  pass 2 ends on the taper
                             feed(20.6, -3.4, f),   // 7
                             rapid(45.1, -3.4),     // 8
                             rapid(45.1, -6.4),     // 9
                             feed(26.35, -6.4, f),  // 10 pass 3
                             feed(26.85, -5.9, f),  // 11
                             rapid(45.1, -5.9),     // 12
                             rapid(45.1, -7.9),     // 13 infeed to B'
                             feed(30.1, -7.9, f),   // 14 semi-finish
                             feed(15.1, -1.9, f),   // 15 C'
                             rapid(15.1, 1.0),      // 16 STEP8 (DTP = 0): out to A.z
                             rapid(45.0, 1.0),      // 17 … and along x to A
                         });
}

// Moves move `i` (and, with `count`, the moves after it) by (dx, dz).
void shift(Toolpath& t, std::size_t i, double dx, double dz, std::size_t count = 1) {
  for (std::size_t k = i; k < i + count; ++k) t.moves[k].to = t.moves[k].to + Point{dz, dx};
}

// --- the correct paths ----------------------------------------------------------------------------

TEST(OracleThresholds, TheHandDerivedPathsPassEveryOracle) {
  expectNone(judgePath(kG71, g71Path()));
  expectNone(judgePath(kG71, g71PathWithoutSemiFinish(), {{"RF1", 1}}));
  expectNone(judgePath(kG72, g72Path()));
}

// --- no-gouge -------------------------------------------------------------------------------------
// no-gouge measures the length of a move inside the part region (beyond the rough profile) eroded by
// the tolerance: a move counts only where it is more than 0.003 inside. The perturbation pushes pass
// 3's end point along the cut axis past the taper it should stop on, so that the end lies a normal
// distance n inside: over n = 0.003 + 0.002 = 0.005 (the last 0.002 of depth lies in the eroded part,
// a piece 0.002·√5 ≈ 0.0045 mm long), under n = 0.003 − 0.002 = 0.001 (all of it within the
// tolerance). The G71 taper falls 2 mm in z per mm in x, so a push of δz along z goes δz/√5 deep:
// δz = n·√5. The retract and the rapid after it move with the end point, so that the retract stays
// exactly 45° by e and nothing else changes — but the retract now starts in the part too, and leaves
// it at 45° (0.002·√2 ≈ 0.0021 mm of it more than 0.003 inside): no-gouge names both moves.

TEST(OracleThresholds, NoGougeG71PassEndPastTheTaper) {
  for (const double depth : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(depth);
    Toolpath t = g71Path();
    shift(t, 10, 0, -depth * std::sqrt(5.0), 3);  // pass 3, its retract and its rapid back
    const auto findings = judgePath(kG71, t);
    if (depth > kTol) {
      expectOnly(findings, "no-gouge", std::vector<std::size_t>{10, 11});
      ASSERT_EQ(findings.size(), 2u);
      EXPECT_NE(findings[0].message.find("over 0.0044"), std::string::npos) << findings[0].message;
      EXPECT_FALSE(findings[0].witness.regions.empty());
    } else {
      expectNone(findings);
    }
  }
}

// G72: the rough taper (30.1, −7.9) → (15.1, −1.9) runs 2.5 mm of x per mm of z; its normal's x
// component is 1/√(1 + 2.5²) ≈ 0.371, so pass 2's end pushed δx further along the cut (−x) goes
// δx/√7.25 deep: δx = n·√7.25 for the same n as above. Its retract moves with it (and is named too).
TEST(OracleThresholds, NoGougeG72PassEndPastTheTaper) {
  for (const double depth : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(depth);
    Toolpath t = g72Path();
    shift(t, 6, -depth * std::sqrt(1 + 2.5 * 2.5), 0, 2);  // pass 2 and its retract
    const auto findings = judgePath(kG72, t);
    if (depth > kTol) expectOnly(findings, "no-gouge", std::vector<std::size_t>{6, 7});
    else expectNone(findings);
  }
}

// --- rapids-in-air --------------------------------------------------------------------------------
// rapids-in-air measures the length of a rapid inside the material still standing eroded by the
// tolerance. The perturbation: a rapid back along the cut axis at (just below) the pass level instead
// of at the retract's height. Pass 2 retracts at 45° as it must (move 7), then rapids down to δ below
// pass 2's level x = 21.25 (move 8, inserted) — into the layer 21.25 → 19.25 that pass 3 has yet to
// cut — and back along z there (move 9). Over δ = 0.005: the dip crosses 0.005 − 0.003 = 0.002 mm of
// the eroded material and the return some 32 mm (all of its run over the stock, z ≤ 3); under
// δ = 0.001 both stay within the tolerance of the surface pass 2 cut. (At exactly the pass level the
// rapid runs on that surface: in air.) Pass 3 then removes the whole layer, so nothing else changes.

TEST(OracleThresholds, RapidsInAirG71ReturnAlongZBelowThePassLevel) {
  for (const double depth : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(depth);
    Toolpath t = g71Path();
    t.moves.insert(t.moves.begin() + 8, rapid(21.25 - depth, -29.3));  // 8  down below the level
    t.moves[9].to.x = 21.25 - depth;                                     // 9  back along z in the layer
    const auto findings = judgePath(kG71, t);
    if (depth > kTol) {
      expectOnly(findings, "rapids-in-air", std::vector<std::size_t>{8, 9});
      ASSERT_EQ(findings.size(), 2u);
      EXPECT_NE(findings[0].message.find("crosses 0.002 mm"), std::string::npos) << findings[0].message;
      EXPECT_NE(findings[1].message.find("crosses 32.2"), std::string::npos) << findings[1].message;
      EXPECT_FALSE(findings[1].witness.regions.empty());
      ASSERT_TRUE(findings[1].witness.segment);
      EXPECT_NEAR(findings[1].witness.segment->to.x, 21.25 - depth, 1e-12);
    } else {
      expectNone(findings);
    }
  }
}

// G72, the same along x: after pass 1 (level z = −1.4) and its retract (move 3), a rapid down to δ
// below the level (move 4, inserted) — into the layer −1.4 → −3.9 — and back along x there (move 5)
// over the stock (x ≤ 45). Pass 2 and the semi-finish remove that layer.
TEST(OracleThresholds, RapidsInAirG72ReturnAlongXBelowThePassLevel) {
  for (const double depth : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(depth);
    Toolpath t = g72Path();
    t.moves.insert(t.moves.begin() + 4, rapid(15.6, -1.4 - depth));  // 4  down below the level
    t.moves[5].to.z = -1.4 - depth;                                   // 5  back along x in the layer
    const auto findings = judgePath(kG72, t);
    if (depth > kTol) expectOnly(findings, "rapids-in-air", std::vector<std::size_t>{4, 5});
    else expectNone(findings);
  }
}

// --- complete -------------------------------------------------------------------------------------
// complete measures the thickest material left above the target along the depth axis. Without the
// semi-finish (RF1 = 1) at most Δd + tolerance = 2.003 may remain: pass 4 (level 17.25, 2 above the
// rough profile's x = 15.25) is raised by δ, so 2 + δ remains above B'…: over δ = 0.005 (2.005),
// under δ = 0.001 (2.001). Its end moves along the taper (z = −19.8 − 2·(x − 15.25)), its retract
// and rapid back with it.

TEST(OracleThresholds, CompleteWithoutSemiFinishLeavesDeltaD) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g71PathWithoutSemiFinish();
    shift(t, 13, excess, 0, 4);             // infeed, pass 4, retract, rapid back: δ higher
    t.moves[14].to.z -= 2 * excess;         // pass 4 still ends on the taper
    t.moves[15].to.z -= 2 * excess;         // and its retract is still 45°
    const auto findings = besides(judgePath(kG71, t, {{"RF1", 1}}), "pass-levels");
    if (excess > kTol) {
      expectOnly(findings, "complete", std::nullopt);
      ASSERT_EQ(findings.size(), 1u);
      ASSERT_TRUE(findings[0].witness.point);
      EXPECT_NEAR(findings[0].witness.point->x, 17.25 + excess, 1e-6);  // on top of the layer over B'…
      EXPECT_GT(findings[0].witness.point->z, -19.8);
      EXPECT_FALSE(findings[0].witness.regions.empty());
    } else {
      expectNone(findings);
    }
  }
}

// Δd − 0.002 left: pass 4 lowered by 0.002 (1.998 remain above B'…; pass 4 itself cuts 2.002, still
// within depth-per-pass's Δd + 0.003).
TEST(OracleThresholds, CompleteWithoutSemiFinishBelowDeltaD) {
  Toolpath t = g71PathWithoutSemiFinish();
  shift(t, 13, -kBy, 0, 4);
  t.moves[14].to.z += 2 * kBy;
  t.moves[15].to.z += 2 * kBy;
  expectNone(besides(judgePath(kG71, t, {{"RF1", 1}}), "pass-levels"));
}

// With the semi-finish, at most the tolerance (0.003) may remain. The semi-finish's taper (move 19)
// runs δ too high along x — a parallel taper, reached by a short feed out along x (inserted as move
// 19) — so a layer δ thick along the depth axis remains on the whole taper: over δ = 0.005, under
// δ = 0.001. The moves along the depth axis have no shadow and remove nothing; nothing else changes.
TEST(OracleThresholds, CompleteWithSemiFinishLeavesTheTolerance) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g71Path();
    t.moves.insert(t.moves.begin() + 19, feed(15.25 + excess, -19.8, kG71F));  // 19 out by δ
    t.moves[20].to.x += excess;                                                 // 20 the taper, δ higher
    const auto findings = besides(judgePath(kG71, t), "pass-levels");
    if (excess > kTol) {
      expectOnly(findings, "complete", std::nullopt);
      ASSERT_EQ(findings.size(), 1u);
      ASSERT_TRUE(findings[0].witness.point);
      EXPECT_LT(findings[0].witness.point->z, -19.8);  // on the taper
      EXPECT_GT(findings[0].witness.point->z, -29.8);
    } else {
      expectNone(findings);
    }
  }
}

// --- depth-per-pass -------------------------------------------------------------------------------
// depth-per-pass measures, along the depth axis, the layer each feed removes; at most Δd + tolerance.
// Pass 2's level is lowered by δ so that it cuts Δd + δ below pass 1 (and pass 3 cuts Δd − δ): over
// δ = 0.005 (2.005 > 2.003), under δ = 0.001. Its infeed, retract and rapid back move with it.

TEST(OracleThresholds, DepthPerPassG71) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g71Path();
    shift(t, 5, -excess, 0, 4);  // moves 5–8
    const auto findings = besides(judgePath(kG71, t), "pass-levels");
    if (excess > kTol) {
      expectOnly(findings, "depth-per-pass", 6);
      ASSERT_EQ(findings.size(), 1u);
      EXPECT_NE(findings[0].message.find("2.005"), std::string::npos) << findings[0].message;
    } else {
      expectNone(findings);
    }
  }
}

// G72: pass 1's level goes from z = −1.4 (2.4 below the stock's top face z = A.z = 1, since A' is
// Δw = 0.1 above A) to 1 − (Δd + δ) = −1.5 − δ: its layer is 2.5 + δ thick, over δ = 0.005 (2.505 >
// 2.503), under δ = 0.001. The level is still above C'.z = −1.9, so the pass still ends at C'.x;
// its retract and rapid back move with it, and pass 2 cuts 2.4 − δ.
// Over, the retract after pass 1 (move 3) is named as well, though it removes no material: see
// DISABLED_DepthPerPassNamesOnlyTheMoveThatRemovesTheLayer below.
Toolpath g72PathFirstPassLower(double by) {
  Toolpath t = g72Path();
  shift(t, 1, 0, -(0.1 + by), 4);  // infeed, pass 1, retract, rapid back
  return t;
}

TEST(OracleThresholds, DepthPerPassG72FirstPass) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    const auto findings = besides(judgePath(kG72, g72PathFirstPassLower(excess)), "pass-levels");
    if (excess > kTol) {
      ASSERT_FALSE(findings.empty());
      for (const Finding& f : findings) EXPECT_EQ(f.oracle, "depth-per-pass") << findingsText(findings);
      EXPECT_EQ(findings[0].move, 2u) << findingsText(findings);
      EXPECT_NE(findings[0].message.find("2.505"), std::string::npos) << findings[0].message;
    } else {
      expectNone(findings);
    }
  }
}

// Oracle weakness (left for the lead; enable when fixed): the 45° retract after pass 1 starts on the
// edge of the column x ∈ [15, 15.1] that pass 1 leaves standing beside C'.x (the implied stock
// reaches x = C.x = 15, the passes stop at C'.x = 15.1). MaterialModel::removedBy(retract) returns a
// zero-area polygon along that edge, (z −1.505, x 15.1) → (1, 15.1) → (1, 15.1), which thickestAbove
// measures at the column's full height: depth-per-pass reports "move 3 removes a layer 2.505 mm
// thick". In the correct path the same phantom layer reads 2.4 (under Δd, so unseen).
TEST(OracleThresholds, DepthPerPassNamesOnlyTheMoveThatRemovesTheLayer) {
  expectOnly(besides(judgePath(kG72, g72PathFirstPassLower(kTol + kBy)), "pass-levels"), "depth-per-pass", 2);
}

// G72: pass 2's level z = −3.9 goes δ deeper, Δd + δ = 2.5 + δ below pass 1's; its end stays on the
// taper (x = 30.1 − 2.5·(z + 7.9) grows by 2.5·δ). Pass 2 ends on the taper, so the step it leaves
// above the taper under pass 1 is 2.5 + δ high at its foot too, and the semi-finish (move 15) removes
// it: depth-per-pass rightly names both moves.
TEST(OracleThresholds, DepthPerPassG72PassEndingOnTheTaper) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g72Path();
    shift(t, 5, 0, -excess, 4);       // infeed, pass, retract, rapid back: δ deeper
    t.moves[6].to.x += 2.5 * excess;  // the taper at the deeper level
    t.moves[7].to.x += 2.5 * excess;
    const auto findings = besides(judgePath(kG72, t), "pass-levels");
    if (excess > kTol) expectOnly(findings, "depth-per-pass", std::vector<std::size_t>{6, 15});
    else expectNone(findings);
  }
}

// --- retract --------------------------------------------------------------------------------------
// Type I retracts at 45° by e (0.5) in cutting feed: each axis within the tolerance of e. The retract
// after pass 1 (move 3) goes e + δ back and out: over δ = 0.005, under δ = 0.001; the rapid back
// starts from there.

TEST(OracleThresholds, RetractG71TooLong) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g71Path();
    shift(t, 3, excess, excess);     // retract: back (+z) and out (+x) by e + δ
    t.moves[4].to.x += excess;       // the rapid back at the retract's height
    const auto findings = judgePath(kG71, t);
    if (excess > kTol) expectOnly(findings, "retract", 3);
    else expectNone(findings);
  }
}

// The retract out by e but back along the cut by e + δ (not quite 45°).
TEST(OracleThresholds, RetractG71NotQuite45Degrees) {
  for (const double excess : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(excess);
    Toolpath t = g71Path();
    shift(t, 7, 0, excess);  // pass 2's retract: back along +z by e + δ, out by e
    const auto findings = judgePath(kG71, t);
    if (excess > kTol) expectOnly(findings, "retract", 7);
    else expectNone(findings);
  }
}

// G72: the retract after pass 2 (move 7) is e − δ back (+x) and out (+z).
TEST(OracleThresholds, RetractG72TooShort) {
  for (const double shortfall : {kTol + kBy, kTol - kBy}) {
    SCOPED_TRACE(shortfall);
    Toolpath t = g72Path();
    shift(t, 7, -shortfall, -shortfall);
    t.moves[8].to.z -= shortfall;  // the rapid back at the retract's level
    const auto findings = judgePath(kG72, t);
    if (shortfall > kTol) expectOnly(findings, "retract", 7);
    else expectNone(findings);
  }
}

// The retract made as a rapid: not "in cutting feed".
TEST(OracleThresholds, RetractAsARapid) {
  Toolpath t = g71Path();
  t.moves[11] = rapid(19.75, -27.3);
  expectOnly(judgePath(kG71, t), "retract", 11);
}

// --- returns-to-start -----------------------------------------------------------------------------
// The end point is exact (no arc flattening is involved), so this oracle tolerates ε = 0.001, not the
// flattening tolerance: over = ε + 0.002 = 0.003 (and the 0.005 of a clearly wrong end), under =
// ε − 0.0005 (0.002 below ε would be negative). The last rapid (move 22) ends that far from A along
// +z, in air.

TEST(OracleThresholds, ReturnsToStart) {
  const double eps = JudgeSettings{}.epsilon;
  for (const double off : {eps + kBy, 0.005, eps - 0.0005}) {
    SCOPED_TRACE(off);
    Toolpath t = g71Path();
    t.moves[22].to.z += off;
    const auto findings = judgePath(kG71, t);
    if (off > eps) {
      expectOnly(findings, "returns-to-start", 22);
      ASSERT_EQ(findings.size(), 1u);
      ASSERT_TRUE(findings[0].witness.point);
      EXPECT_NEAR(findings[0].witness.point->z, 3 + off, 1e-12);
    } else {
      expectNone(findings);
    }
  }
}

TEST(OracleThresholds, ReturnsToStartG72) {
  Toolpath t = g72Path();
  t.moves[17].to.x -= 0.005;
  expectOnly(judgePath(kG72, t), "returns-to-start", 17);
}

// --- feeds ----------------------------------------------------------------------------------------
// Cutting moves run at the cycle's F exactly (the oracle allows only rounding: a relative 10⁻⁹).
// Over: F + 0.01 on one pass. Under: F written with a rounding error (F + 10⁻¹²), as an engine that
// converts units might. A cutting move without F is a finding too.

TEST(OracleThresholds, FeedsG71) {
  Toolpath t = g71Path();
  t.moves[6].feed = kG71F + 0.01;
  expectOnly(judgePath(kG71, t), "feeds", 6);

  t = g71Path();
  t.moves[6].feed = kG71F + 1e-12;
  expectNone(judgePath(kG71, t));

  t = g71Path();
  t.moves[19].feed.reset();
  expectOnly(judgePath(kG71, t), "feeds", 19);
}

TEST(OracleThresholds, FeedsG72) {
  Toolpath t = g72Path();
  t.moves[14].feed = kG72F + 0.01;  // the semi-finish
  expectOnly(judgePath(kG72, t), "feeds", 14);

  t = g72Path();
  t.moves[14].feed = kG72F * (1 + 1e-12);
  expectNone(judgePath(kG72, t));
}

// --- alarm ----------------------------------------------------------------------------------------
// The alarm oracle compares the engine's alarm (code and line) with what the documented checks
// require; it has no tolerance of its own, but the checks do: parameter 5146 allows the shape to move
// back along x by that much. "By a little" is therefore a shape that moves back 0.001 more or less
// than 5146 allows, and an alarm one line off.

// fanuc-0i-f/g71/ps0064-z-reverse: N30 X26 Z-5 (line 6) moves back along z: PS0064 at line 6.
const char* kZReverse = "G00 X40 Z2;\nG71 U2 R0.5;\nG71 P10 Q40 U0.4 W0.1 F0.2;\nN10 G00 X20;\nN20 G01 Z-10;\nN30 X26 Z-5;\nN40 X38;\n";

Toolpath alarmPath(const std::string& code, int line) {
  Toolpath t;
  t.profile = "fanuc-0i-f";
  t.alarm = Alarm{code, "", line, ""};
  return t;
}

TEST(OracleThresholds, AlarmOnAnAllowedShape) {
  Toolpath t = alarmPath("PS0064", 4);
  t.start = kG71A;
  expectOnly(judgePath(kG71, t), "alarm", std::nullopt);
}

TEST(OracleThresholds, NoAlarmOnAForbiddenShape) {
  // A plausible path an engine that skipped the check might plan: one pass down to the shape's first
  // step, the semi-finish of its first segment, and the return to A = (20, 2), at F0.2.
  const Toolpath t = pathFrom({2, 20}, {rapid(20.2, 2.1), rapid(18.2, 2.1), feed(18.2, -9.9, 0.2), feed(18.7, -9.4, 0.2),
                                        rapid(18.7, 2.1), rapid(10.2, 2.1), feed(10.2, -9.9, 0.2), rapid(20, -9.9),
                                        rapid(20, 2)});
  const auto findings = judgePath(kZReverse, t);
  expectOnly(findings, "alarm", std::nullopt);
  ASSERT_EQ(findings.size(), 1u);
  EXPECT_NE(findings[0].message.find("PS0064"), std::string::npos) << findings[0].message;
}

TEST(OracleThresholds, AlarmCodeAndLine) {
  expectNone(judgePath(kZReverse, alarmPath("PS0064", 6)));
  expectOnly(judgePath(kZReverse, alarmPath("PS0064", 5)), "alarm", std::nullopt);  // one line early
  expectOnly(judgePath(kZReverse, alarmPath("PS0064", 7)), "alarm", std::nullopt);  // one line late
  expectOnly(judgePath(kZReverse, alarmPath("PS0329", 6)), "alarm", std::nullopt);  // the other axis
}

// fanuc-0i-f/g71/ps0329-within-5146: N50 X29.6 Z-13 (line 8) moves back 0.2 mm (radius) along x.
// 5146 = 0.2 + 0.001 allows it, 0.2 − 0.001 forbids it (PS0329 at line 8). The hand-derived path of
// that case (planned with 5146 = 0.5; 5146 changes nothing else).
const char* kDip = "G00 X36 Z2;\nG71 U2 R0.5;\nG71 P10 Q70 U0.4 W0.1 F0.2;\nN10 G00 X25;\nN20 G01 Z-8;\nN30 X30;\n"
                   "N40 Z-12;\nN50 X29.6 Z-13;\nN60 Z-16;\nN70 X34;\n";

TEST(OracleThresholds, AlarmAtTheEdgeOfParameter5146) {
  const double f = 0.2;
  const Toolpath planned = pathFrom({2, 18}, {
                                                 rapid(18.2, 2.1),      rapid(16.2, 2.1),
                                                 feed(16.2, -15.9, f),  feed(16.7, -15.4, f),
                                                 rapid(16.7, 2.1),      rapid(14.2, 2.1),
                                                 feed(14.2, -7.9, f),   feed(14.7, -7.4, f),
                                                 rapid(14.7, 2.1),      rapid(12.7, 2.1),
                                                 feed(12.7, -7.9, f),   feed(15.2, -7.9, f),
                                                 feed(15.2, -11.9, f),  feed(15.0, -12.9, f),
                                                 feed(15.0, -15.9, f),  feed(17.2, -15.9, f),
                                                 rapid(18.0, -15.9),    rapid(18.0, 2.0),
                                             });
  const Toolpath alarmed = alarmPath("PS0329", 8);
  const double within = 0.2 + 0.001, beyond = 0.2 - 0.001;
  expectNone(judgePath(kDip, planned, {{"5146", within}}));
  expectOnly(judgePath(kDip, alarmed, {{"5146", within}}), "alarm", std::nullopt);
  expectOnly(judgePath(kDip, planned, {{"5146", beyond}}), "alarm", std::nullopt);
  expectNone(judgePath(kDip, alarmed, {{"5146", beyond}}));
}

// --- flattening -----------------------------------------------------------------------------------
// Arcs are flattened within the chord tolerance and every verdict carries twice that: a correct path
// with arcs (seed 003 example 1 in FANUC form, planned by the reference) gives no finding, flattened
// coarsely (0.05 mm) or finely (0.0001 mm).

TEST(OracleThresholds, FlatteningNeverProducesAFinding) {
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/fanuc-0i-f/g71/seed003-ex1-fanuc.json");
  const Toolpath path = planSpecCase(c);
  ASSERT_FALSE(path.alarm);
  bool hasArc = false;
  for (const Move& m : path.moves) hasArc = hasArc || m.shape != SegmentKind::Line;
  ASSERT_TRUE(hasArc);
  for (const double chord : {0.05, 0.0001}) {
    SCOPED_TRACE(chord);
    JudgeRequest request = judgeRequestFor(c);
    request.settings.chordTolerance = chord;
    const std::vector<Finding> findings = judge(judgeInputFor(request, path));
    EXPECT_TRUE(findings.empty()) << findingsText(findings);
  }
}

// --- weaknesses found while writing these tests (left for the lead; enable each when fixed) -------

// A pass that starts δ = 0.0005 mm (half of ε) inside the stock's front face z = 3 — after a rapid
// back and a rapid infeed that run 0.0005 inside it, which rapids-in-air rightly tolerates — leaves a
// skin 0.0005 mm wide along the cut axis between its level and the previous one. The next pass (move
// 14) removes that skin and depth-per-pass measures it at its full height, "a layer 4 mm thick",
// although it is far narrower than the tolerance (any δ > 0 does it; δ = 0 gives no finding).
// Neither the layer nor the leftover is eroded by the tolerance along the cut axis before its
// thickness is measured.
TEST(OracleThresholds, DepthPerPassIgnoresASkinNarrowerThanTheTolerance) {
  Toolpath t = g71Path();
  t.moves[8].to.z = 3 - 0.0005;
  t.moves[9].to.z = 3 - 0.0005;
  expectNone(judgePath(kG71, t));
}

// The same skin with RF1 = 1 (pass 4 starts 0.0005 inside the face, nothing removes the skin later):
// complete reports "4 mm of material stand above the rough profile at (z 2.9995, x 19.25)".
TEST(OracleThresholds, CompleteIgnoresASkinNarrowerThanTheTolerance) {
  Toolpath t = g71PathWithoutSemiFinish();
  t.moves[12].to.z = 3 - 0.0005;
  t.moves[13].to.z = 3 - 0.0005;
  expectNone(judgePath(kG71, t, {{"RF1", 1}}));
}

// "feeds: … rapids as rapids": no oracle checks that the infeeds follow the head block
// (G71.HEAD.G0G1, G71.T1.STEP2: rapid after a G00 head, cutting feed at F after a G01 head). The
// infeeds run at A'.z, in air, so rapids-in-air cannot see it either. Both swaps pass every oracle.
TEST(OracleThresholds, FeedsInfeedsFollowTheHeadBlock) {
  // G01 head (spec case g01-head-stepped-shaft, planned by the reference): infeeds 1, 5, 9, 13 as rapids.
  const SpecCase c = loadSpecCase(defaultSpecsDir() + "/cases/fanuc-0i-f/g71/g01-head-stepped-shaft.json");
  Toolpath p = planSpecCase(c);
  for (const std::size_t i : {1u, 5u, 9u, 13u}) {
    p.moves[i].kind = MoveKind::Rapid;
    p.moves[i].feed.reset();
  }
  EXPECT_FALSE(judge(judgeInputFor(judgeRequestFor(c), p)).empty());
  // G00 head: the infeeds 1, 5, 9, 13, 17 of the hand path as feeds at F.
  Toolpath q = g71Path();
  for (const std::size_t i : {1u, 5u, 9u, 13u, 17u}) {
    q.moves[i].kind = MoveKind::Feed;
    q.moves[i].feed = kG71F;
  }
  EXPECT_FALSE(judgePath(kG71, q).empty());
}

// pass-levels: a type I pass whose level is off the Δd grid below A' by just over the tolerance is
// reported; by just under it is not. (The depth-per-pass G71 perturbation lowers pass 2 by δ.)
TEST(OracleThresholds, PassLevelsOffTheGrid) {
  for (const double by : {kTol + kBy, kTol - kBy}) {
    Toolpath t = g71Path();
    shift(t, 5, -by, 0, 4);  // pass 2 (moves 5–8) lowered by δ, as in DepthPerPassG71
    std::vector<Finding> findings;
    for (const Finding& f : judgePath(kG71, t)) {
      if (f.oracle == "pass-levels") findings.push_back(f);
    }
    if (by > kTol) expectOnly(findings, "pass-levels", 6);
    else expectNone(findings);
  }
}

}  // namespace
}  // namespace cyclecert
