// G73 pattern repeating cycle (reference/cycles/g73.*, rules G73.*): each documented step on its
// own, then the cycle in a program. Expected values are derived by hand in the comments.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "reference/cycles/g73.h"
#include "reference/model/alarms.h"
#include "reference/model/params.h"

namespace cyclecert {
namespace {

Toolpath plan(const std::string& program, const std::string& profile = "fanuc-0i-f",
              std::vector<std::pair<std::string, double>> params = {}, RunOptions options = {}) {
  return planWithReference({program, "g73.nc", profile, std::move(params), options});
}

Segment line(Point from, Point to) {
  Segment s;
  s.from = from;
  s.to = to;
  return s;
}

// A = (x 30, z 2); B = (15, 0); (20, -10); C = (20, -30).
G73Cycle simpleCycle(int d) {
  G73Cycle c;
  c.start = {2, 30};
  c.headEnd = {0, 15};
  c.body = {line({0, 15}, {-10, 20}), line({-10, 20}, {-30, 20})};
  c.relief = {1, 3};       // Δk = 1, Δi = 3
  c.allowance = {0.1, 0.2};  // Δw = 0.1, Δu/2 = 0.2
  c.divisions = d;
  c.headIsRapid = false;
  c.feed = 0.2;
  return c;
}

// G73.PASS.SHIFT: ((d − k)/(d − 1))·(Δk, Δi) + (Δw, Δu/2): for d = 4, shares 1, 2/3, 1/3, 0.
TEST(G73PassShift, DividesTheReliefEquallyDownToTheAllowance) {
  const G73Cycle c = simpleCycle(4);
  EXPECT_TRUE(nearlyEqual(passShift(c, 1), {1.1, 3.2}));
  EXPECT_TRUE(nearlyEqual(passShift(c, 2), {0.1 + 2.0 / 3, 0.2 + 2.0}));
  EXPECT_TRUE(nearlyEqual(passShift(c, 3), {0.1 + 1.0 / 3, 0.2 + 1.0}));
  EXPECT_TRUE(nearlyEqual(passShift(c, 4), {0.1, 0.2}));
}

// G73.D1: one pass, at the allowance only.
TEST(G73PassShift, OneDivisionIsOnePassAtTheAllowance) {
  const G73Cycle c = simpleCycle(1);
  EXPECT_TRUE(nearlyEqual(passShift(c, 1), {0.1, 0.2}));
  const std::vector<Move> moves = planG73Passes(c);
  ASSERT_EQ(moves.size(), 5u);  // approach, head, two body segments, return
  EXPECT_TRUE(nearlyEqual(moves[0].to, {2.1, 30.2}));
  EXPECT_EQ(moves.back().phase, MovePhase::Return);
}

// G73.APPROACH, G73.HEAD, G73.PASS, G73.RETURN: per pass a rapid from A to the shifted start, the
// head in feed (G01), the body in feed, a rapid back to A.
TEST(G73Passes, EachPassIsApproachHeadBodyAndRapidBackToA) {
  const std::vector<Move> moves = planG73Passes(simpleCycle(2));
  ASSERT_EQ(moves.size(), 10u);
  // Pass 1, shift (1.1, 3.2).
  EXPECT_EQ(moves[0].kind, MoveKind::Rapid);
  EXPECT_EQ(moves[0].phase, MovePhase::Approach);
  EXPECT_TRUE(nearlyEqual(moves[0].to, {3.1, 33.2}));
  EXPECT_EQ(moves[1].kind, MoveKind::Feed);
  EXPECT_TRUE(nearlyEqual(moves[1].to, {1.1, 18.2}));
  EXPECT_EQ(moves[1].pass, 1);
  EXPECT_TRUE(nearlyEqual(moves[3].to, {-28.9, 23.2}));
  EXPECT_EQ(moves[4].kind, MoveKind::Rapid);
  EXPECT_TRUE(nearlyEqual(moves[4].to, {2, 30}));
  EXPECT_EQ(moves[4].phase, MovePhase::Pass);
  // Pass 2, shift (0.1, 0.2): starts with a rapid of pass 2, ends with the cycle's return.
  EXPECT_EQ(moves[5].phase, MovePhase::Pass);
  EXPECT_EQ(moves[5].pass, 2);
  EXPECT_TRUE(nearlyEqual(moves[5].to, {2.1, 30.2}));
  EXPECT_TRUE(nearlyEqual(moves[8].to, {-29.9, 20.2}));
  EXPECT_EQ(moves[9].phase, MovePhase::Return);
  EXPECT_TRUE(nearlyEqual(moves[9].to, {2, 30}));
  for (const Move& m : moves) {
    if (m.kind == MoveKind::Feed) {
      EXPECT_EQ(m.feed, 0.2);
    }
  }
}

// G73.HEAD: a G00 head block is followed by rapid.
TEST(G73Passes, AG00HeadIsARapid) {
  G73Cycle c = simpleCycle(1);
  c.headIsRapid = true;
  const std::vector<Move> moves = planG73Passes(c);
  EXPECT_EQ(moves[1].kind, MoveKind::Rapid);
  EXPECT_FALSE(moves[1].feed);
}

// G73.PASS.SHIFT: an arc keeps its radius; its centre moves with the shape.
TEST(G73Passes, ArcsAreTranslatedWithTheirCentres) {
  G73Cycle c = simpleCycle(2);
  Segment arc = line({-10, 20}, {-30, 20});
  arc.kind = SegmentKind::ArcCW;
  arc.center = {-20, 30};
  c.body[1] = arc;
  const std::vector<Move> moves = planG73Passes(c);
  ASSERT_EQ(moves[3].shape, SegmentKind::ArcCW);
  ASSERT_TRUE(moves[3].center);
  EXPECT_TRUE(nearlyEqual(*moves[3].center, {-18.9, 33.2}));
  EXPECT_TRUE(nearlyEqual(*moves[8].center, {-19.9, 30.2}));
}

const char* kSeed004 =
    "G0X70Z2;\nG73U5W0R4;\nG73P10Q11U0.2W0.1F0.1;\nN10G01X50Z0;\nG3X40Z-15R22;\nG2Z-45R25;\nN11G1Z-50;\nG70P10Q11;\n";

// G73.EX, G73.G70: seed 004's program plans G73 (4 passes of 6 moves) and G70 (5 moves).
TEST(G73InAProgram, Seed004PlansG73ThenG70) {
  const Toolpath t = plan(kSeed004);
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.cycles.size(), 2u);
  EXPECT_EQ(t.cycles[0].code, "G73");
  EXPECT_EQ(t.cycles[0].moveCount, 24u);
  EXPECT_EQ(t.cycles[1].code, "G70");
  EXPECT_EQ(t.cycles[1].moveCount, 5u);
  // Pass 1 starts at A + (Δw, Δi + Δu/2) = (2.1, 40.1).
  EXPECT_TRUE(nearlyEqual(t.moves[0].to, {2.1, 40.1}));
  // The last pass ends at C + allowance = (-49.9, 20.1), then back to A.
  EXPECT_TRUE(nearlyEqual(t.moves[22].to, {-49.9, 20.1}));
  EXPECT_TRUE(nearlyEqual(t.moves[23].to, {2, 35}));
}

// G73.FMT, G73.PARAMS: the first block's U (radius), W and R write 5135/5136/5137, which a later
// G73 without a first block uses.
TEST(G73InAProgram, TheFirstBlockIsModal) {
  const std::string shape = "N10 G01 X30 Z0;\nN20 X40 Z-10;\n";
  const Toolpath t = plan("G00 X60 Z2;\nG73 U3 W1 R2;\nG73 P10 Q20 U0 W0 F0.2;\n" + shape +
                          "G73 P10 Q20 U0 W0 F0.2;\nM30;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  ASSERT_EQ(t.cycles.size(), 2u);
  // Both cycles: first pass shifted by the whole relief (z 1, x 3 — U3 is a radius, not halved).
  EXPECT_TRUE(nearlyEqual(t.moves[t.cycles[0].firstMove].to, {3, 33}));
  EXPECT_TRUE(nearlyEqual(t.moves[t.cycles[1].firstMove].to, {3, 33}));
  EXPECT_EQ(t.cycles[1].moveCount, t.cycles[0].moveCount);
}

// G73.D.RANGE: R0 is PS0062 at the first block; R2.5 is PS0003; 5137 = 0 without R is PS0062.
TEST(G73InAProgram, DivisionsOutOfRangeAlarm) {
  const std::string rest = "G73 P10 Q20 U0 W0 F0.2;\nN10 G01 X30 Z0;\nN20 X40 Z-10;\n";
  Toolpath t = plan("G00 X60 Z2;\nG73 U3 R0;\n" + rest);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0062");
  EXPECT_EQ(t.alarm->line, 2);
  t = plan("G00 X60 Z2;\nG73 U3 R2.5;\n" + rest);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0003");
  t = plan("G00 X60 Z2;\n" + rest);
  ASSERT_TRUE(t.alarm);
  EXPECT_EQ(t.alarm->code, "PS0062");
  EXPECT_EQ(t.alarm->line, 2);
}

// G73.PARAMS: 5135/5136 are signed lengths, 5137 a whole number.
TEST(G73Params, ReliefsAreSignedAndDivisionsWhole) {
  MachineParams p;
  EXPECT_NO_THROW(p.set("5135", -2));
  EXPECT_EQ(p.get("5135"), -2);
  EXPECT_NO_THROW(p.set("5136", -1.5));
  EXPECT_THROW(p.set("5137", 2.5), std::invalid_argument);
  EXPECT_THROW(p.set("5137", -1), std::invalid_argument);
  EXPECT_THROW(p.set("5132", -1), std::invalid_argument);  // the other lengths stay unsigned
}

// G73.FS10.FMT: with FCV = 1 the one block's I, K, D are Δi, Δk, d; with FCV = 0 they are PS0009.
TEST(G73InAProgram, Series10OneBlock) {
  const std::string program = "G00 X60 Z2;\nG73 P10 Q20 U0 W0 I3 K1 D2 F0.2;\nN10 G01 X30 Z0;\nN20 X40 Z-10;\n";
  const Toolpath t = plan(program, "fanuc-0i-f", {{"FCV", 1}});
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_TRUE(nearlyEqual(t.moves[0].to, {3, 33}));
  // Pass 1: rapid (3, 33), head, body, rapid to A; pass 2 at shift 0 starts at A (no zero-length
  // rapid): head, body, return.
  EXPECT_EQ(t.moves.size(), 7u);
  const Toolpath refused = plan(program);
  ASSERT_TRUE(refused.alarm);
  EXPECT_EQ(refused.alarm->code, "PS0009");
  EXPECT_NE(refused.alarm->message.find("FCV"), std::string::npos) << refused.alarm->message;
  const Toolpath decimal = plan("G00 X60 Z2;\nG73 P10 Q20 I3 D2. F0.2;\nN10 G01 X30 Z0;\nN20 X40 Z-10;\n",
                                "fanuc-0i-f", {{"FCV", 1}});
  ASSERT_TRUE(decimal.alarm);
  EXPECT_EQ(decimal.alarm->code, "PS0007");
}

// G73.PLANE: in G19 (Y-Z: 1st axis Y, 2nd Z) V is Δk... the plane's incremental addresses carry the
// relief: W (2nd axis Z) is Δi and V (1st axis Y) is Δk.
TEST(G73InAProgram, PlansInTheYZPlane) {
  const Toolpath t = plan("G19;\nG00 Y2 Z30;\nG73 W3 V0 R2;\nG73 P10 Q20 W0 V0 F0.2;\nN10 G01 Y0 Z15;\nN20 Y-10 Z20;\n");
  ASSERT_FALSE(t.alarm) << t.alarm->message;
  EXPECT_EQ(t.plane, "G19");
  EXPECT_TRUE(nearlyEqual(t.moves[0].to, {2, 33}));
}

// G73.TNRC: with G42 and a nose radius the passes follow the compensated shape.
TEST(G73InAProgram, NoseRadiusCompensationShiftsTheShape) {
  RunOptions withRadius;
  withRadius.tool.noseRadius = 0.4;
  withRadius.tool.tip = 3;
  const std::string program = "G00 X60 Z2;\nG42;\nG73 U3 W0 R2;\nG73 P10 Q20 U0 W0 F0.2;\nN10 G01 X30 Z0;\nN20 Z-20;\n";
  const Toolpath plain = plan(program);
  const Toolpath compensated = plan(program, "fanuc-0i-f", {}, withRadius);
  ASSERT_FALSE(compensated.alarm) << compensated.alarm->message;
  ASSERT_EQ(compensated.cycles.size(), 1u);
  EXPECT_TRUE(compensated.cycles[0].compensated);
  EXPECT_FALSE(plain.cycles[0].compensated);
  EXPECT_FALSE(nearlyEqual(compensated.moves[1].to, plain.moves[1].to));
}

// G73.DIALECTS: the Haas and Huazhong G73 are not modelled: not supported, never planned wrongly.
TEST(G73InAProgram, OtherDialectsAreNotSupported) {
  EXPECT_THROW(plan("G00 X60 Z2;\nG73 P10 Q20 U0 W0 I3 K0 D2 F0.2;\nN10 G01 X30 Z0;\nN20 X40 Z-10;\n", "haas"),
               NotSupported);
}

// The oracles judge G73: tests/g73_oracles_test.cpp.

}  // namespace
}  // namespace cyclecert
