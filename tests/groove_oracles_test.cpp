// The oracles on G74.1 (oracles/groove/, and alarm, feeds, no-gouge, rapids-in-air, complete for a
// groove): the oracles' own reading of the two blocks, checked against numbers worked out by hand
// from docs/g74_1.md §3–§5, and for each oracle a hand-made good path (no finding) and a hand-made
// faulty one (its finding). The paths are derived by hand below, never taken from the reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "oracles/judgement.h"

namespace cyclecert {
namespace {

ProgramSpec specOf(const std::string& program, bool mmSteps = true) {
  PlanRequest request{program, "groove.nc", "gsk", {}, {}};
  if (mmSteps) request.params.push_back({"182#7", 1});
  const ReadRequest read = readRequest(request);
  return readProgramSpec(*read.program, *read.profile, read.params, ToolOffset{});
}

// ---- the reading (docs/g74_1.md §8, O0008) ----

const char* kO0008 = "G00 X70 Z10 M3 S500;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5;\n";

TEST(GrooveSpec, ReadsO0008AsDocsSection8WorksItOut) {
  const ProgramSpec spec = specOf(kO0008, false);
  ASSERT_EQ(spec.grooves.size(), 1u);
  const GrooveSpec& g = spec.grooves.front();
  ASSERT_FALSE(g.forbiddenBy) << g.forbiddenBy->message;
  EXPECT_EQ(g.line, 3);
  EXPECT_EQ(g.grooveLine, 2);
  EXPECT_DOUBLE_EQ(g.start.z, 0);
  EXPECT_DOUBLE_EQ(g.start.x, 33);
  EXPECT_EQ(g.depthSign, -1);
  EXPECT_EQ(g.widthSign, -1);
  EXPECT_DOUBLE_EQ(g.depth, 10);
  EXPECT_DOUBLE_EQ(g.floorWidth, 10);
  EXPECT_NEAR(g.radialStep, 1.5, 1e-12);  // P30000 × 0.0001 = 3 mm diameter
  EXPECT_NEAR(g.peck, 5, 1e-12);
  EXPECT_DOUBLE_EQ(g.retract, 0.5);
  EXPECT_DOUBLE_EQ(g.toolWidth, 0);
  EXPECT_EQ(g.pathType, 0);
  EXPECT_DOUBLE_EQ(g.before.z, 10);
  EXPECT_DOUBLE_EQ(g.before.x, 35);
  // S (0, 0) → N (10, 10) → F (20, 10) → M2 (25.773503, 0) in (u, w).
  ASSERT_EQ(g.finish.chain.size(), 3u);
  EXPECT_NEAR(g.finish.chain[0].to.x, 10, 1e-9);
  EXPECT_NEAR(g.finish.chain[0].to.z, 10, 1e-9);
  EXPECT_NEAR(g.finish.chain[1].to.x, 20, 1e-9);
  EXPECT_NEAR(g.finish.chain[2].to.x, 25.773503, 1e-6);
  EXPECT_NEAR(g.finish.chain[2].to.z, 0, 1e-9);
  // M2 in the plane: X14.452995 Z0.
  EXPECT_NEAR(2 * g.toPlane(g.finish.chain[2].to).x, 14.452995, 1e-6);
}

TEST(GrooveSpec, TheRoughProfileMovesEachSideInByItsAllowance) {
  // U2 W1 on O0008: S' u 1; N' (1 + 9·cot45, 9) = (10, 9); F' (20 − 1 + 1·cot60, 9); M2' u
  // 19 + 10·cot60 = 24.773503 (∠p = 0).
  const ProgramSpec spec = specOf("G00 X70 Z10;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5 U2 W1;\n", false);
  ASSERT_EQ(spec.grooves.size(), 1u);
  const GrooveOutline& r = spec.grooves.front().rough;
  ASSERT_EQ(r.chain.size(), 3u);
  EXPECT_NEAR(r.chain[0].from.x, 1, 1e-9);
  EXPECT_NEAR(r.chain[0].to.x, 10, 1e-9);
  EXPECT_NEAR(r.chain[0].to.z, 9, 1e-9);
  EXPECT_NEAR(r.chain[1].to.x, 19 + 1 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(r.chain[2].to.x, 19 + 10 / std::sqrt(3.0), 1e-9);
  EXPECT_NEAR(spec.grooves.front().roughStart().x, 1, 1e-9);  // A11 = S' + r (r = 0)
}

TEST(GrooveSpec, AChamferAtR1StartsTheProfileOnTheMouthBeforeS) {
  // A1 (r1 = 1, P digit a = 0: a chamfer of equal legs, I10): from (u −1, w 0) on the mouth to 1 mm
  // down the 45° flank, (0.7071, 0.7071).
  const ProgramSpec spec = specOf("G00 X70 Z10;\nG74.1 X66 Z0 P30000 Q50000 H-10 D-20 A45 B60;\nG74.1 R0.5 A1;\n", false);
  const GrooveOutline& f = spec.grooves.front().finish;
  ASSERT_GE(f.chain.size(), 4u);
  EXPECT_NEAR(f.chain[0].from.x, -1, 1e-9);
  EXPECT_NEAR(f.chain[0].from.z, 0, 1e-9);
  EXPECT_NEAR(f.chain[0].to.x, std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(f.chain[0].to.z, std::sqrt(0.5), 1e-9);
}

TEST(GrooveSpec, TheAlarmsOfI6bAreReadFromTheProgram) {
  const auto alarmOf = [](const std::string& program) {
    const ProgramSpec spec = specOf(program);
    const std::optional<Alarm> a = spec.firstAlarm();
    return a ? a->code + "@" + std::to_string(a->line) : std::string("none");
  };
  const std::string before = "G00 X50 Z5 F0.1;\n";
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4 A95;\nG74.1 R0.5;\n"), "PS0003@2");   // ∠a > 90
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 Q2 H-4 D-4;\nG74.1 R0.5;\n"), "PS0061@2");          // no P
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H0 D-4;\nG74.1 R0.5;\n"), "PS0003@2");        // h = 0 (I3)
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R100;\n"), "PS0003@3");       // e > 99.9999
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5 V0;\n"), "PS0062@3");    // Δv = 0
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5 J3;\n"), "PS0003@3");
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5 K1;\n"), "PS0009@3");    // K not taken
  EXPECT_EQ(alarmOf(before + "G74.1 R0.5;\n"), "PS0061@2");                                     // no first block
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5 I5;\n"), "PS0062@3");    // blade 5 > floor 2
  EXPECT_EQ(alarmOf(before + "G74.1 X40 Z0 P1 Q2 H-4 D-4;\nG74.1 R0.5 I1;\n"), "none");
  // P in least increments with a decimal point (182#7 = 0): PS0007.
  const ProgramSpec inc = specOf(before + "G74.1 X40 Z0 P1. Q20000 H-4 D-4;\nG74.1 R0.5;\n", false);
  ASSERT_TRUE(inc.firstAlarm());
  EXPECT_EQ(inc.firstAlarm()->code, "PS0007");
}

// ---- the oracles on hand-made paths ----
//
// The groove: S = X40 Z0 (z 0, x 20), H-4 (feed towards −Z), D-8 (steps towards −X, floor 4 mm
// radius), flanks 90°, Δi 2 (steps of 1 mm radius), Δk 1.5, e 0.5, a 2 mm blade (I2), J0. In the
// groove's frame u = 20 − x, w = −z: the groove is u ∈ [0, 4], w ∈ [0, 4]. A11 = (u 2, w 0) = x 18
// (the blade's start-side edge on the near flank). The cycle starts u 2, 3 and Amf 4 (x 18, 17,
// 16), each pecking 1.5, 3, 4 with 0.5 retracts; then back to A11, the rough pass down the near
// flank at x 18, along the floor to x 16 and up the far flank; back to A11; back to the start.
const char* kGroove = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8;\nG74.1 R0.5 I2;\n";

struct PathBuilder {
  Toolpath path;
  PathBuilder() {
    path.profile = "gsk";
    path.start = {5, 25};
  }
  PathBuilder& rapid(double z, double x) { return add(MoveKind::Rapid, z, x); }
  PathBuilder& feed(double z, double x, double f = 0.1) {
    add(MoveKind::Feed, z, x);
    path.moves.back().feed = f;
    return *this;
  }
  PathBuilder& add(MoveKind kind, double z, double x) {
    Move m;
    m.kind = kind;
    m.to = {z, x};
    path.moves.push_back(m);
    return *this;
  }
  // One axial cycle at x from the level z0 down to z0 − depth in pecks of 1.5 with retracts of 0.5,
  // then back to z0.
  PathBuilder& cycle(double x, double z0 = 0, double depth = 4) {
    double reached = 0;
    while (reached + 1.5 < depth - 1e-9) {
      reached += 1.5;
      feed(z0 - reached, x);
      rapid(z0 - reached + 0.5, x);
    }
    feed(z0 - depth, x);
    return rapid(z0, x);
  }
};

Toolpath goodGroovePath() {
  PathBuilder b;
  b.rapid(0, 18).cycle(18).rapid(0, 17).cycle(17).rapid(0, 16).cycle(16);
  b.rapid(0, 18);                                     // STEP8: back to A11
  b.feed(-4, 18).feed(-4, 16).feed(0, 16);            // STEP9: the rough profile
  b.rapid(0, 18);                                     // back to A11
  b.rapid(5, 25);                                     // the return (I20)
  return b.path;
}

std::vector<Finding> judged(const std::string& program, const Toolpath& path) {
  JudgeInput in;
  in.program = specOf(program);
  in.path = path;
  return judge(in);
}

std::vector<Finding> of(const std::vector<Finding>& all, const std::string& oracle) {
  std::vector<Finding> out;
  std::copy_if(all.begin(), all.end(), std::back_inserter(out), [&](const Finding& f) { return f.oracle == oracle; });
  return out;
}

std::string text(const std::vector<Finding>& fs) {
  std::string s;
  for (const Finding& f : fs) s += f.oracle + ": " + f.message + "\n";
  return s;
}

TEST(GrooveOracles, EveryOracleJudgesG74_1WhereItApplies) {
  for (const char* id : {"alarm", "feeds", "no-gouge", "rapids-in-air", "complete", "groove-peck", "groove-retract",
                         "groove-radial-step", "groove-layer", "groove-returns"}) {
    const auto& all = allOracles();
    const auto it = std::find_if(all.begin(), all.end(), [&](const auto& o) { return o->id() == id; });
    ASSERT_NE(it, all.end()) << id;
    EXPECT_TRUE((*it)->judges(CycleFamily::G74_1)) << id;
  }
}

TEST(GrooveOracles, TheHandMadeGoodPathPassesEveryOracle) {
  const std::vector<Finding> f = judged(kGroove, goodGroovePath());
  EXPECT_TRUE(f.empty()) << text(f);
}

TEST(GrooveOracles, APeckDeeperThanDeltaKIsFound) {
  PathBuilder b;
  b.rapid(0, 18).feed(-2.5, 18).rapid(-2, 18).feed(-4, 18).rapid(0, 18);  // first peck 2.5 > Δk 1.5
  b.rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  b.feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> f = of(judged(kGroove, b.path), "groove-peck");
  ASSERT_EQ(f.size(), 1u) << text(f);
  EXPECT_EQ(f.front().move, 1u);
  EXPECT_NE(std::find(f.front().rules.begin(), f.front().rules.end(), "G74_1.STEP3"), f.front().rules.end());
}

// A retract e longer than Δk (R2, Q1.5) rises above the cycle's start after the first peck: it is
// still STEP4, and the next feed (Δk + e = 3.5) goes Δk deeper than reached (STEP5). Per cycle at x:
// feed to z −1.5, rapid back 2 to z 0.5 (in the air before the face), feed 3.5 to −3, rapid to −1,
// feed to Bmn −4 (−4.5 would pass it), rapid back to 0. Before, the rapid to 0.5 was read as the
// cycle's end (STEP6) and the next feed as a new cycle's 3.5 mm first peck (fuzz --cycles g74.1).
TEST(GrooveOracles, ARetractLongerThanThePeckIsStillARetract) {
  const std::string program = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8;\nG74.1 R2 I2;\n";
  PathBuilder b;
  b.rapid(0, 18);
  for (double x : {18.0, 17.0, 16.0}) {
    if (x != 18.0) b.rapid(0, x);
    b.feed(-1.5, x).rapid(0.5, x).feed(-3, x).rapid(-1, x).feed(-4, x).rapid(0, x);
  }
  b.rapid(0, 18).feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> f = judged(program, b.path);
  EXPECT_TRUE(f.empty()) << text(f);
}

TEST(GrooveOracles, ARetractTowardsTheBottomIsFound) {
  PathBuilder b;
  b.rapid(0, 18).feed(-1.5, 18).rapid(-2, 18).feed(-3, 18).rapid(-2.5, 18).feed(-4, 18).rapid(0, 18);
  b.rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  b.feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> all = judged(kGroove, b.path);
  const std::vector<Finding> f = of(all, "groove-retract");
  ASSERT_EQ(f.size(), 1u) << text(all);
  EXPECT_EQ(f.front().move, 2u);
  EXPECT_NE(f.front().message.find("towards the bottom"), std::string::npos) << f.front().message;
  // The blade goes down 0.5 into material no feed has cut: rapids-in-air sees it too.
  EXPECT_EQ(of(all, "rapids-in-air").size(), 1u) << text(all);
}

TEST(GrooveOracles, AFeedRetractIsFound) {
  PathBuilder b;
  b.rapid(0, 18).feed(-1.5, 18).feed(-1, 18).feed(-3, 18).rapid(-2.5, 18).feed(-4, 18).rapid(0, 18);
  b.rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  b.feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> f = of(judged(kGroove, b.path), "groove-retract");
  ASSERT_EQ(f.size(), 1u) << text(f);
  EXPECT_NE(f.front().message.find("cutting feed"), std::string::npos) << f.front().message;
}

TEST(GrooveOracles, ARadialStepOfDeltaIIsFound) {
  PathBuilder b;
  b.rapid(0, 18).cycle(18).rapid(0, 16).cycle(16);  // a step of 2 mm radius = Δi, not Δi/2
  b.rapid(0, 18).feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> all = judged(kGroove, b.path);
  const std::vector<Finding> f = of(all, "groove-radial-step");
  ASSERT_EQ(f.size(), 1u) << text(all);
  EXPECT_EQ(f.front().move, 7u);  // after the 1 + 6 moves of ① and the first cycle
  // The 2 mm blade still empties the groove: only the step is wrong.
  EXPECT_EQ(all.size(), 1u) << text(all);
}

TEST(GrooveOracles, TheReturnMustEndTheCycle) {
  Toolpath p = goodGroovePath();
  p.moves.pop_back();  // no return to X50 Z5
  const std::vector<Finding> f = of(judged(kGroove, p), "groove-returns");
  ASSERT_EQ(f.size(), 1u) << text(f);
  EXPECT_NE(f.front().message.find("not back at the point before it"), std::string::npos) << f.front().message;
}

TEST(GrooveOracles, AFeedAtAnotherFIsFound) {
  Toolpath p = goodGroovePath();
  p.moves[1].feed = 0.2;
  const std::vector<Finding> f = of(judged(kGroove, p), "feeds");
  ASSERT_EQ(f.size(), 1u) << text(f);
  EXPECT_EQ(f.front().move, 1u);
}

TEST(GrooveOracles, AGrooveLeftUnfinishedIsFound) {
  PathBuilder b;
  b.rapid(0, 18).cycle(18).rapid(0, 17).cycle(17).rapid(0, 18);  // no cycle at x 16, no rough pass
  b.rapid(5, 25);
  const std::vector<Finding> all = judged(kGroove, b.path);
  const std::vector<Finding> f = of(all, "complete");
  ASSERT_EQ(f.size(), 1u) << text(all);
  EXPECT_FALSE(f.front().witness.regions.empty());
  // What is left is the strip u ∈ [3, 4] (x 16…17), w ∈ [0, 4]: 2·area/perimeter = 8/10.
  EXPECT_NE(f.front().message.find("0.8 mm thick"), std::string::npos) << f.front().message;
}

TEST(GrooveOracles, APathGougingTheFarFlankIsFound) {
  PathBuilder b;
  b.rapid(0, 18).cycle(18).rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  b.feed(-4, 18).feed(-4, 15.5).feed(0, 15.5);  // the far flank 0.5 too far: the blade spans u 2.5…4.5
  b.rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> all = judged(kGroove, b.path);
  const std::vector<Finding> f = of(all, "no-gouge");
  ASSERT_EQ(f.size(), 2u) << text(all);  // along the floor and up the flank
  EXPECT_EQ(f[0].move, 23u);  // ① 1, three cycles of 6 and two steps, STEP8 1, the near flank 1
  EXPECT_EQ(f[1].move, 24u);
}

TEST(GrooveOracles, ABladeIsNotAPoint) {
  // The same peck cycles with the blade's programmed point at x 19 (u 1) instead of 18: the 2 mm
  // blade spans u −1…1 and cuts 1 mm into the near flank (a point at u 1 would not).
  PathBuilder b;
  b.rapid(0, 19).cycle(19).rapid(0, 18).cycle(18).rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  b.feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  const std::vector<Finding> all = judged(kGroove, b.path);
  EXPECT_FALSE(of(all, "no-gouge").empty()) << text(all);
}

// J1 with an r1 chamfer A1 on the same groove: the finish profile starts on the mouth at u −1 and
// chamfers down to (u 0, w 1) (I10). The blade's programmed point follows the start side shifted by
// r = 2 (§7): from A11 (u 2) along the mouth to P0 + r (u 1, x 19), down the chamfer to (u 2, w 1),
// down the flank to the floor, along it to u 4 and up the far flank. Rough and finish profiles are
// the same (no allowances), so both passes run that path.
const char* kChamfered = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8;\nG74.1 R0.5 I2 J1 A1;\n";

Toolpath chamferedPath(bool withPasses) {
  PathBuilder b;
  b.rapid(0, 18).cycle(18).rapid(0, 17).cycle(17).rapid(0, 16).cycle(16).rapid(0, 18);
  if (withPasses) {
    for (int pass = 0; pass < 2; ++pass) {  // STEP9 (rough), then STEP10 (finish; its start is A11 too)
      b.feed(0, 19).feed(-1, 18).feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18);
    }
  }
  b.rapid(5, 25);
  return b.path;
}

TEST(GrooveOracles, TheFinishProfilesChamferIsCut) {
  const std::vector<Finding> good = judged(kChamfered, chamferedPath(true));
  EXPECT_TRUE(good.empty()) << text(good);
  // Without the profile passes the chamfer's triangle (legs 1: 2·area/perimeter = 1/(2 + √2)) stands.
  const std::vector<Finding> all = judged(kChamfered, chamferedPath(false));
  const std::vector<Finding> f = of(all, "complete");
  ASSERT_EQ(f.size(), 1u) << text(all);
  EXPECT_NE(f.front().message.find("0.292893 mm thick"), std::string::npos) << f.front().message;
  EXPECT_NE(f.front().message.find("finish profile"), std::string::npos) << f.front().message;
}

// Two layers (V2): each layer's cycles cut 2 deep from its top, pecks 1.5 then to the bottom.
const char* kLayered = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8;\nG74.1 R0.5 V2 I2;\n";

Toolpath layeredPath(bool layerOneTooDeep, bool skipLayerOne) {
  PathBuilder b;
  b.rapid(0, 18);
  if (layerOneTooDeep) {
    b.cycle(18, 0, 3);
  } else {
    b.cycle(18, 0, 2);
  }
  if (!skipLayerOne) b.rapid(0, 17).cycle(17, 0, 2).rapid(0, 16).cycle(16, 0, 2).rapid(0, 18);  // STEP8: Cmf
  b.rapid(-2, 18);                                                                              // STEP2
  b.cycle(18, -2, 2).rapid(-2, 17).cycle(17, -2, 2).rapid(-2, 16).cycle(16, -2, 2);
  b.rapid(0, 16).rapid(0, 18);                                                                  // STEP8, last layer
  b.feed(-4, 18).feed(-4, 16).feed(0, 16).rapid(0, 18).rapid(5, 25);
  return b.path;
}

TEST(GrooveOracles, TheLayeredGoodPathPasses) {
  const std::vector<Finding> f = judged(kLayered, layeredPath(false, false));
  EXPECT_TRUE(f.empty()) << text(f);
}

TEST(GrooveOracles, ALayerDeeperThanDeltaVIsFound) {
  const std::vector<Finding> all = judged(kLayered, layeredPath(true, false));
  const std::vector<Finding> f = of(all, "groove-layer");
  ASSERT_EQ(f.size(), 1u) << text(all);
  EXPECT_NE(f.front().message.find("3 mm deep"), std::string::npos) << f.front().message;
}

TEST(GrooveOracles, ARapidThroughUncutMaterialInsideTheGrooveIsFound) {
  // Layer 1 cuts only at x 18 (u 0…2); layer 2's step to x 17 at z −2 drags the blade (u 1…3)
  // through the material u 2…3, w 0…2 that no peck has cut.
  const Toolpath p = layeredPath(false, true);
  const std::vector<Finding> all = judged(kLayered, p);
  const std::vector<Finding> f = of(all, "rapids-in-air");
  ASSERT_FALSE(f.empty()) << text(all);
  const Move& m = p.moves[*f.front().move];
  EXPECT_EQ(m.kind, MoveKind::Rapid);
  EXPECT_DOUBLE_EQ(m.to.x, 17);
  EXPECT_DOUBLE_EQ(m.to.z, -2);
}

// A pointed tool (no I): the point itself, A11 = S (x 20). Cycles at u 0…4 (x 20…16).
const char* kPointed = "G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8;\nG74.1 R0.5;\n";

TEST(GrooveOracles, APointedToolsGoodPathPassesAndAPeckIntoTheFloorIsAGouge) {
  PathBuilder b;
  b.rapid(0, 20);
  for (double x : {20.0, 19.0, 18.0, 17.0, 16.0}) {
    if (x != 20) b.rapid(0, x);
    b.cycle(x);
  }
  b.rapid(0, 20).feed(-4, 20).feed(-4, 16).feed(0, 16).rapid(0, 20).rapid(5, 25);
  std::vector<Finding> f = judged(kPointed, b.path);
  EXPECT_TRUE(f.empty()) << text(f);
  // The last feed of the cycle at x 18 goes to z −4.5: 0.5 into the floor.
  Toolpath bad = b.path;
  for (Move& m : bad.moves) {
    if (m.kind == MoveKind::Feed && m.to.x == 18 && m.to.z == -4) {
      m.to.z = -4.5;
      break;
    }
  }
  f = of(judged(kPointed, bad), "no-gouge");
  ASSERT_FALSE(f.empty());
  EXPECT_NE(f.front().message.find("over"), std::string::npos) << f.front().message;
}

TEST(GrooveOracles, AnEngineThatPlansWhatTheRulesForbidIsFound) {
  // A95: ∠a outside (0, 90] is PS0003 at the first block (I6b); the good path is no alarm.
  const std::vector<Finding> f =
      of(judged("G00 X50 Z5 F0.1;\nG74.1 X40 Z0 P2 Q1.5 H-4 D-8 A95;\nG74.1 R0.5 I2;\n", goodGroovePath()), "alarm");
  ASSERT_EQ(f.size(), 1u);
  EXPECT_NE(f.front().message.find("PS0003"), std::string::npos) << f.front().message;
}

}  // namespace
}  // namespace cyclecert
