// The oracles judge G73 (oracles/README.md, "G73"): the reader's G73 cycle, and each judgement
// catching a deliberately wrong G73 path — planned by the reference for a program that differs from
// the one judged (one division too few, the relief towards the part, no allowance), or the
// reference's path with moves taken out or changed. Expected figures are derived by hand below.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"

namespace cyclecert {
namespace {

// A = (z 2, x 30); B = (0, 15); (−10, 20); (−30, 20); C = (−30, 28). Δi = 3, Δk = 0, d = 2;
// Δu/2 = 0.2, Δw = 0.1: pass 1 shifted by (0.1, 3.2), pass 2 by (0.1, 0.2); the division step is 3.
std::string twoPasses(const std::string& firstBlock = "G73 U3 W0 R2;",
                      const std::string& secondBlock = "G73 P10 Q20 U0.4 W0.1 F0.2;") {
  return "G00 X60 Z2;\n" + firstBlock + "\n" + secondBlock + "\nN10 G01 X30 Z0;\nX40 Z-10;\nZ-30;\nN20 X56;\n";
}

// Seed 004: Δi = 5, d = 4 (step 5/3), with G70 after it.
std::string seed004(const std::string& firstBlock = "G73U5W0R4;") {
  return "G0X70Z2;\n" + firstBlock +
         "\nG73P10Q11U0.2W0.1F0.1;\nN10G01X50Z0;\nG3X40Z-15R22;\nG2Z-45R25;\nN11G1Z-50;\nG70P10Q11;\n";
}

JudgeRequest requestFor(const std::string& program) {
  JudgeRequest request;
  request.program = {program, "g73.nc", "fanuc-0i-f", {}, {}};
  return request;
}

Toolpath planned(const std::string& program) { return planWithReference(requestFor(program).program); }

std::vector<Finding> judged(const std::string& program, Toolpath path) {
  return judge(judgeInputFor(requestFor(program), std::move(path)));
}

bool reports(const std::vector<Finding>& findings, const std::string& oracle) {
  return std::any_of(findings.begin(), findings.end(), [&](const Finding& f) { return f.oracle == oracle; });
}

// The index of the first move after `from` that ends at A: the return of a pass.
std::size_t returnToStart(const Toolpath& path, Point a, std::size_t from = 0) {
  for (std::size_t i = from; i < path.moves.size(); ++i) {
    if (distance(path.moves[i].to, a) < 1e-9) return i;
  }
  return path.moves.size();
}

TEST(G73Reading, TheCycleIsAG73WithItsReliefDivisionsAndAllowances) {
  const JudgeInput in = judgeInputFor(requestFor(seed004()), planned(seed004()));
  ASSERT_EQ(in.program.cycles.size(), 1u);
  const CycleSpec& c = in.program.cycles.front();
  EXPECT_EQ(c.family, CycleFamily::G73);
  EXPECT_TRUE(c.patternRepeating());
  EXPECT_FALSE(c.forbiddenBy.has_value());
  EXPECT_TRUE(nearlyEqual(c.relief, {0, 5}));
  EXPECT_EQ(c.divisions, 4);
  EXPECT_TRUE(nearlyEqual(c.allowance, {0.1, 0.1}));
  EXPECT_NEAR(c.divisionStep(), 5.0 / 3, 1e-12);
  EXPECT_NEAR(c.layerLimit(), 5.0 / 3, 1e-12);
  EXPECT_TRUE(nearlyEqual(c.start, {2, 35}));
  EXPECT_TRUE(in.program.hasFinishingCycle);
}

// G73.PARAMS: without a first block, 5135/5136/5137; G73.FS10.FMT: I, K, D with FCV = 1.
TEST(G73Reading, ReliefAndDivisionsFromParametersAndTheSeries10Block) {
  JudgeRequest fromParams = requestFor(twoPasses("", "G73 P10 Q20 U0.4 W0.1 F0.2;"));
  fromParams.program.params = {{"5135", 2}, {"5136", 1}, {"5137", 3}};
  const CycleSpec a = judgeInputFor(fromParams, planWithReference(fromParams.program)).program.cycles.at(0);
  EXPECT_TRUE(nearlyEqual(a.relief, {1, 2}));
  EXPECT_EQ(a.divisions, 3);
  EXPECT_NEAR(a.divisionStep(), std::hypot(1.0, 2.0) / 2, 1e-12);

  JudgeRequest series10 = requestFor(twoPasses("", "G73 P10 Q20 U0.4 W0.1 I3 K1 D5 F0.2;"));
  series10.program.params = {{"FCV", 1}};
  const CycleSpec b = judgeInputFor(series10, planWithReference(series10.program)).program.cycles.at(0);
  EXPECT_TRUE(nearlyEqual(b.relief, {1, 3}));
  EXPECT_EQ(b.divisions, 5);
}

// G73.D.RANGE, G73.FS10.FMT, G73.ALARMS: the reader's own alarms, line by line.
TEST(G73Reading, TheDocumentedAlarms) {
  const auto alarmOf = [](const std::string& program, std::vector<std::pair<std::string, double>> params = {}) {
    JudgeRequest r = requestFor(program);
    r.program.params = std::move(params);
    Toolpath none;
    return judgeInputFor(r, none).program.firstAlarm();
  };
  const auto expectAlarm = [](const std::optional<Alarm>& a, const std::string& code, int line) {
    ASSERT_TRUE(a.has_value()) << code;
    EXPECT_EQ(a->code, code);
    EXPECT_EQ(a->line, line) << code;
  };
  expectAlarm(alarmOf(twoPasses("G73 U3 W0 R0;")), "PS0062", 2);
  expectAlarm(alarmOf(twoPasses("G73 U3 W0 R2.5;")), "PS0003", 2);
  expectAlarm(alarmOf(twoPasses("G73 U3 W0;")), "PS0062", 3);  // 5137 = 0 by default
  expectAlarm(alarmOf(twoPasses("G73 U3 R2;", "G73 P10 U0.4 F0.2;")), "PS0061", 3);
  expectAlarm(alarmOf(twoPasses("G73 U3 R2;", "G73 P10 Q99 U0.4 F0.2;")), "PS0063", 3);
  expectAlarm(alarmOf(twoPasses("", "G73 P10 Q20 U0.4 I3 D2 F0.2;")), "PS0009", 3);
  expectAlarm(alarmOf(twoPasses("", "G73 P10 Q20 U0.4 I3 D2. F0.2;"), {{"FCV", 1}}), "PS0007", 3);
  expectAlarm(alarmOf("G00 X60 Z2;\nG73 U3 R2;\nG73 P10 Q20 F0.2;\nN10 G02 X30 Z0 R20;\nN20 X40 Z-10;\n"), "PS0065", 4);
  EXPECT_FALSE(alarmOf(twoPasses()).has_value());
}

TEST(G73Judging, TheReferencePathsFindNothing) {
  for (const std::string& program : {seed004(), twoPasses(), twoPasses("G73 U2 W3 R3;")}) {
    const std::vector<Finding> findings = judged(program, planned(program));
    EXPECT_TRUE(findings.empty()) << program << findingsText(findings);
  }
}

// depth-per-pass: three divisions where the program asks four: passes 2.5 apart, not 5/3.
TEST(G73Judging, OneDivisionTooFewRemovesLayersThickerThanTheStep) {
  const std::vector<Finding> findings = judged(seed004(), planned(seed004("G73U5W0R3;")));
  EXPECT_TRUE(reports(findings, "depth-per-pass")) << findingsText(findings);
  EXPECT_FALSE(reports(findings, "no-gouge")) << findingsText(findings);
  EXPECT_FALSE(reports(findings, "complete")) << findingsText(findings);
}

// no-gouge: the relief applied towards the part (U−5): the first pass runs 4.9 mm inside it.
TEST(G73Judging, ReliefTowardsThePartGouges) {
  const std::vector<Finding> findings = judged(seed004(), planned(seed004("G73U-5W0R4;")));
  EXPECT_TRUE(reports(findings, "no-gouge")) << findingsText(findings);
}

// no-gouge: the last pass without the allowance runs on the shape, 0.2 (x) inside the part grown
// by the allowances (no G70: the roughing must leave the allowance).
TEST(G73Judging, LastPassWithoutTheAllowanceGouges) {
  const std::vector<Finding> findings = judged(twoPasses(), planned(twoPasses("G73 U3 W0 R2;", "G73 P10 Q20 F0.2;")));
  EXPECT_TRUE(reports(findings, "no-gouge")) << findingsText(findings);
}

// complete: the path stops after the first pass (on the blank's surface): the whole relief, 3 mm,
// stands above the rough profile.
TEST(G73Judging, AMissingLastPassLeavesTheReliefStanding) {
  Toolpath path = planned(twoPasses());
  const std::size_t firstReturn = returnToStart(path, {2, 30});
  ASSERT_LT(firstReturn + 1, path.moves.size());
  path.moves.resize(firstReturn + 1);
  const std::vector<Finding> findings = judged(twoPasses(), path);
  EXPECT_TRUE(reports(findings, "complete")) << findingsText(findings);
  EXPECT_FALSE(reports(findings, "returns-to-start")) << findingsText(findings);
}

// returns-to-start: the path ends at the end of the last pass, C shifted (z −29.9, x 28.2).
TEST(G73Judging, NoReturnToTheStartPoint) {
  Toolpath path = planned(twoPasses());
  ASSERT_TRUE(nearlyEqual(path.moves.back().to, {2, 30}));
  path.moves.pop_back();
  const std::vector<Finding> findings = judged(twoPasses(), path);
  EXPECT_TRUE(reports(findings, "returns-to-start")) << findingsText(findings);
}

// rapids-in-air: pass 2 approached by one rapid from A straight to (−9.9, 20.2), the end of its
// first body segment, 3 mm below pass 1's path there (x 23.2): through the layer still standing.
TEST(G73Judging, ARapidIntoTheLayerStillStanding) {
  Toolpath path = planned(twoPasses());
  const std::size_t secondApproach = returnToStart(path, {2, 30}) + 1;  // A → A + (0.1, 0.2)
  ASSERT_LT(secondApproach + 2, path.moves.size());
  Move& firstBodyEnd = path.moves[secondApproach + 2];
  ASSERT_TRUE(nearlyEqual(firstBodyEnd.to, {-9.9, 20.2}));
  firstBodyEnd.kind = MoveKind::Rapid;
  firstBodyEnd.feed.reset();
  path.moves.erase(path.moves.begin() + static_cast<long>(secondApproach),
                   path.moves.begin() + static_cast<long>(secondApproach + 2));
  const std::vector<Finding> findings = judged(twoPasses(), path);
  EXPECT_TRUE(reports(findings, "rapids-in-air")) << findingsText(findings);
}

// feeds: block ns is G01, so its shifted copy is a cutting feed (G73.HEAD); a rapid there, or a
// pass at another F than the cycle's, is reported.
TEST(G73Judging, TheHeadAsProgrammedAndThePassesAtTheCyclesFeed) {
  Toolpath rapidHead = planned(twoPasses());
  const std::size_t secondHead = returnToStart(rapidHead, {2, 30}) + 2;
  ASSERT_TRUE(nearlyEqual(rapidHead.moves.at(secondHead).to, {0.1, 15.2}));
  rapidHead.moves[secondHead].kind = MoveKind::Rapid;
  rapidHead.moves[secondHead].feed.reset();
  const std::vector<Finding> head = judged(twoPasses(), rapidHead);
  EXPECT_TRUE(reports(head, "feeds")) << findingsText(head);

  Toolpath slow = planned(twoPasses());
  slow.moves.at(secondHead + 1).feed = 0.1;
  const std::vector<Finding> feed = judged(twoPasses(), slow);
  EXPECT_TRUE(reports(feed, "feeds")) << findingsText(feed);
}

// G73.HEAD: a G00 block ns is followed as programmed even where its shifted copy meets the blank
// (Δk = 3: B shifted for pass 2 lies on the blank's front, reached through its corner); but a
// feed there is reported.
TEST(G73Judging, AG00HeadIsARapidWhereverItMeetsTheBlank) {
  const std::string program =
      "G00 X50 Z3;\nG73 U2 W3 R3;\nG73 P10 Q20 U0.2 W0.2 F0.25;\nN10 G00 X20 Z1;\nG01 Z-5;\nX30 Z-10;\nN20 X48;\n";
  EXPECT_TRUE(judged(program, planned(program)).empty());
  Toolpath fed = planned(program);
  ASSERT_EQ(fed.moves.at(1).kind, MoveKind::Rapid);
  fed.moves[1].kind = MoveKind::Feed;
  fed.moves[1].feed = 0.25;
  EXPECT_TRUE(reports(judged(program, fed), "feeds"));
}

// G70.EX after G73 with a G00 block ns: G70's rapid to B passes through the allowance in front of
// it (Δw = 0.1 here) as programmed; not a rapid through material the engine chose.
TEST(G73Judging, G70sG00HeadAfterG73) {
  const std::string program =
      "G00 X70 Z5;\nG73 U4 W3 R5;\nG73 P10 Q11 U0.2 W0.1 F0.1;\nN10 G00 X50 Z0;\nG3 X40 Z-15 R22;\nG2 Z-45 R25;\n"
      "N11 G1 Z-50;\nG70 P10 Q11;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

// Each oracle declares whether it judges G73: all but pass-levels, retract and pocket-entry.
// The part stands behind the shape on the side away from A, swept along an axis over whose other
// axis the shape is a graph — not along a Z-only relief: a turned chamfer going down then a face
// up, Δk = 0.01 only (B (0, 1.1), (−0.1, 1.0), C (−0.1, 1.6)); with d = 1 the one pass runs on the
// shape (no allowance), so nothing gouges (before: the part swept along Z took the face's edge for
// material, 0.09 mm).
TEST(G73Judging, ThePartIsBehindTheShapeWhateverTheReliefsDirection) {
  const std::string program =
      "G00 X3.22 Z0.02;\nG73 U0 W0.01 R1;\nG73 P10 Q20 U0 W0 F0.2;\nN10 G01 X2.2 Z0;\nG01 X2 Z-0.1;\n"
      "N20 G01 X3.2 Z-0.1;\nG70 P10 Q20;\n";
  EXPECT_TRUE(judged(program, planned(program)).empty());
}

// The blank is known only over the shape's span: a face B (0, 1.0) → C (0, 1.5) with Δk 0.01, Δw
// 0.01, Δu/2 0.01 leaves the blank's edge beyond C (x 1.5…1.51) where no pass reaches; the return
// from C to A crosses it — not material the program describes (before: rapids-in-air, 0.003 mm).
// And a chamfer from B (0, 1.0) with Δi 0.01, Δw 0.01 leaves blank ahead of B (z 0…0.01) that no
// pass reaches (before: complete, 0.003 mm).
TEST(G73Judging, TheBlankIsJudgedOverTheShapesSpanOnly) {
  const std::string face =
      "G00 X3.04 Z0.03;\nG73 U0 W0.01 R1;\nG73 P10 Q20 U0.02 W0.01 F0.2;\nN10 G01 X2 Z0;\nN20 G01 X3 Z0;\n"
      "G70 P10 Q20;\n";
  EXPECT_TRUE(judged(face, planned(face)).empty());
  const std::string chamfer =
      "G00 X2.24 Z0.37;\nG73 U0.01 W0 R1;\nG73 P10 Q20 U0 W0.01 F0.2;\nN10 G00 X2 Z0;\nN20 G01 X2.2 Z-0.1;\n"
      "G70 P10 Q20;\n";
  EXPECT_TRUE(judged(chamfer, planned(chamfer)).empty());
}

// The band the blank is known over runs along the relief: from the shape's end C (z 0.66, x 1.2)
// the relief's ray goes up at 45° (Δi = Δk = 0.01). Here the allowance (Δw 0.31, Δu/2 0.73)
// dwarfs the relief; the blank band taken along x (the part side) kept the blank's corner above C
// (z 0.66…0.97) that no 45° shadow of the finishing pass reaches, and the return from C to A
// crossed it (before: rapids-in-air, 0.0095 mm; found by `make run`'s G73 campaign). Along the
// relief, every point of the band lies on a ray from the shape: G70 leaves nothing standing.
TEST(G73Judging, TheBlankBandRunsAlongTheRelief) {
  const std::string program =
      "G00 X6.44 Z1.59;\nG73 U0.01 W0.01 R1;\nG73 P10 Q20 U1.46 W0.31 F0.2;\nN10 G01 X2 Z0.99;\nG01 X2.2 Z0.89;\n"
      "N20 G01 X2.4 Z0.66;\nG70 P10 Q20;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

// A shape segment parallel to the relief (slope 0.48/2.88 = Δi/Δk = 0.01/0.06): pass 1 runs along
// the finish shape's line, so the blank above the cone is nothing. The relief band's edge runs
// along that line too, collinear only to rounding, and Boost.Geometry's intersection returned the
// whole band as the blank (a parallelogram above the cone); depth-per-pass then read a layer of
// 2.86 mm at pass 1's face (found by `make run`'s G73 campaign, 3 of 55,600 cases). The band is now
// cut in the relief's own frame, where its edges are axis-parallel (withinCutBand).
TEST(G73Judging, AShapeSegmentAlongTheReliefLeavesNoBlankAboveIt) {
  const std::string program =
      "G00 X4 Z0.07;\nG73 U0.01 W0.06 R2;\nG73 P10 Q20 U0 W0 F0.2;\nN10 G01 X2.96 Z0;\nG01 X2 Z-2.88;\n"
      "N20 G01 X3.96 Z-2.88;\nG70 P10 Q20;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

// The same with no relief: the blank's frame is the allowance's (0.54, 0.54), a 45° cone runs along
// it (found on `fuzz --cycles g73 --seed 73` once the relief case was mended by drawing the band in;
// the booleans' rounding, 1e-7 of the band's size, swallowed that).
TEST(G73Judging, AShapeSegmentAlongTheAllowanceLeavesNoBlankAboveIt) {
  const std::string program =
      "G00 X15.5 Z5.62;\nG73 U0 W0 R1;\nG73 P10 Q20 U1.08 W0.54 F0.2;\nN10 G01 X7.14 Z2.95;\nG01 X2 Z0.38;\n"
      "G01 X2 Z0.38;\nN20 G01 X8.14 Z0.38;\nM30;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

// The cone X12.12 Z1.84 → X2 Z-3.22 (5.06 by 5.06: 45°) runs along the relief (1.15, 1.15); the
// allowance (W0.01, U0.1) stands 0.028 mm across it, so the blank holds a strip that thin along the
// cone. Every pass's and G70's feed along the cone shadows it along itself (the relief): in the model
// nothing removed the strip, and `complete` read 7.2 mm along the relief after G70 (found by `fuzz
// --cycles g73 --seed 1000`, 1 of 400,000, once the blank's band was cut exactly). G70 removes what
// stands beyond the shape on the part's side.
TEST(G73Judging, G70RemovesTheStripAlongAShapeSegmentParallelToTheRelief) {
  const std::string program =
      "G00 X20.84 Z4.03;\nG73 U1.15 W1.15 R2;\nG73 P10 Q20 U0.1 W0.01 F0.2;\nN10 G01 X12.12 Z1.84;\n"
      "G01 X2 Z-3.22;\nG01 X2 Z-3.48;\nG01 X4.1 Z-3.76;\nN20 G01 X13.12 Z-3.76;\nG70 P10 Q20;\nM30;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

// An inner shape whose first line (X12.06 Z-2.36 → X13.86 Z-1.46: 0.9 by 0.9) runs along the relief
// (−1.5, −1.5) and the allowance (−0.12, −0.12): the blank's edge there lies on the relief band's
// edge and on every pass's line at once. Cut exactly, the band's edge met the passes' shadows
// collinear only to rounding, and the material model's boolean kept the whole blank: `complete` read
// 2.12 mm left (fuzz --cycles g73 --seed 4242, 1 of 300,000). The band is drawn in by ten times the
// booleans' resolution.
TEST(G73Judging, ABlankEdgeOnTheBandAndThePassesIsRemoved) {
  const std::string program =
      "G00 X2 Z-5.1;\nG73 U-1.5 W-1.5 R5;\nG73 P10 Q20 U-0.24 W-0.12 F0.2;\nN10 G01 X12.06 Z-2.36;\n"
      "G01 X13.86 Z-1.46;\nG03 X11.76 Z-0.41 R1.05;\nN20 G01 X11.76 Z-0.41;\nM30;\n";
  const std::vector<Finding> findings = judged(program, planned(program));
  EXPECT_TRUE(findings.empty()) << findingsText(findings);
}

TEST(G73Judging, EachOracleDeclaresWhetherItJudgesG73) {
  for (const auto& oracle : allOracles()) {
    if (oracle->id().rfind("siemens-", 0) == 0) continue;  // the SINUMERIK oracles judge LCYC95/CYCLE95 only
    if (oracle->id().rfind("groove-", 0) == 0) continue;   // the groove oracles judge G74.1 only
    const bool skips = oracle->id() == "pass-levels" || oracle->id() == "retract" || oracle->id() == "pocket-entry";
    EXPECT_EQ(oracle->judges(CycleFamily::G73), !skips) << oracle->id();
    EXPECT_TRUE(oracle->judges(CycleFamily::G71)) << oracle->id();
    EXPECT_TRUE(oracle->judges(CycleFamily::G72)) << oracle->id();
  }
}

// The oracles that do not apply to G73 skip it: no pass levels, no 45° retract, no pocket entry.
TEST(G73Judging, PassLevelsRetractAndPocketEntryDoNotJudgeG73) {
  Toolpath path = planned(seed004("G73U5W0R3;"));
  const std::vector<Finding> findings = judged(seed004(), path);
  EXPECT_FALSE(reports(findings, "pass-levels"));
  EXPECT_FALSE(reports(findings, "retract"));
  EXPECT_FALSE(reports(findings, "pocket-entry"));
}

}  // namespace
}  // namespace cyclecert
