// no-gouge on a G74.1 pass along a slanted flank (issue 17): the blade's corner runs on the flank's
// line with the blade on the groove's side of it, so it sweeps none of the part — where Boost's
// intersection of the sweep with the part, whose edges then coincide along the flank, returned the
// whole part (92 mm², seed 73's case 9a3ed941a1b36233). The blade bound (groove_bounds.h,
// PartTop::liesBelow) proves it without the boolean.
#include <gtest/gtest.h>

#include <string>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "oracles/judgement.h"

namespace cyclecert {
namespace {

// S = X28.26 Z7.66 (radius 14.13); h 12.63 towards +Z, d 10.94, ∠b 49°, the mouth sloped ∠p 18°;
// J1 with W1.13, a 1.09 mm blade. In the groove's frame (u from S along d, w the depth) the finish
// far flank runs from the floor's far corner (5.47, 12.63) to the far mouth M2 (12.826, 4.168) —
// on the mouth line w = u·tan 18° — with dw/du = −8.462/7.356 = −1.150. The semi-finish pass up that
// flank (move 79 of the path) runs from (6.452, 11.5), the floor less W, to M2: 6.452 − 5.47 =
// 0.982 = 1.13 / 1.150 along the flank from its foot, so on the flank's line.
constexpr const char* kProgram =
    "G00 X38.12 Z0.65 F0.1;\nG74.1 X28.26 Z7.66 P2.18 Q3.97 H12.63 D10.94 B49 L18;\n"
    "G74.1 R1.17 W1.13 I1.09 J1 P1111;\nM30;\n";

TEST(GrooveFlankPass, ABladeRunningUpTheFarFlankSweepsNoneOfThePart) {
  const PlanRequest request{kProgram, "groove.nc", "gsk", {{"182#7", 1}}, {}};
  const ReadRequest read = readRequest(request);
  JudgeInput in;
  in.program = readProgramSpec(*read.program, *read.profile, read.params, ToolOffset{});
  in.path = planWithReference(request);  // the path under judgement; the expectation is the geometry above
  ASSERT_FALSE(in.path.alarm);
  ASSERT_GT(in.path.moves.size(), 79u);
  const Point from = in.path.from(79), to = in.path.moves[79].to;
  ASSERT_NEAR(to.z, 7.66 + 4.168, 1e-3) << "move 79 ends at M2";
  ASSERT_NEAR(from.z, 7.66 + 11.5, 1e-9) << "and starts at the floor less W";
  ASSERT_NEAR((to.z - from.z) / (to.x - from.x), -8.462 / 7.356, 2e-3) << "along the flank (Z the depth, X the radius u)";
  for (const Finding& f : judge(in)) {
    EXPECT_FALSE(f.oracle == "no-gouge" && f.move == 79) << f.message;
  }
}

}  // namespace
}  // namespace cyclecert
