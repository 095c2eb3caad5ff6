// SINUMERIK stock-removal pockets (issue 16's fuzz classes): the axis-parallel allowances FALZ /
// FALX on each element's stock side (reference/siemens/siemens_axis_allowance.*), and the pockets
// CYCLE95 roughs. Expectations derived by hand in the comments (CYCLE95.PARAMS, CYCLE95.ROUGH,
// CYCLE95.UNDERCUT notes in specs/rules.json).
#include <gtest/gtest.h>

#include <vector>

#include "reference/model/alarms.h"
#include "reference/siemens/siemens_axis_allowance.h"
#include "reference/siemens/siemens_cycles.h"
#include "tests/siemens_contours.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

std::vector<Point> cornersOf(const std::vector<Segment>& path) {
  std::vector<Point> points{path.front().from};
  for (const Segment& s : path) points.push_back(s.to);
  return points;
}

void expectCorners(const std::vector<Segment>& path, const std::vector<Point>& want) {
  const std::vector<Point> got = cornersOf(path);
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) {
    EXPECT_NEAR(got[i].z, want[i].z, 1e-9) << "corner " << i;
    EXPECT_NEAR(got[i].x, want[i].x, 1e-9) << "corner " << i;
  }
}

// A groove from z −5 to −10, 3 deep, in a collar of radius 6 (the frame of longitudinal external).
// FALZ 0.5 is left on the stock side of each wall: the wall at z −5 falls towards the axis with the
// collar (part) at +z, so its allowance lies towards −z: z −5.5; the wall at −10 rises with the part
// at −z: z −9.5; the face at z 0 (stock in front): z 0.5. The groove's bottom and the collar's top
// face across z: no FALZ on them (FALX 0). The profile: (0.5, 0) → (0.5, 6) → (−5.5, 6) → (−5.5, 3)
// → (−9.5, 3) → (−9.5, 6) → (−20, 6). (A uniform shift by +0.5 put the first wall at −4.5: inside
// the collar.)
TEST(SiemensAxisAllowance, FalzLiesOnTheStockSideOfEachWall) {
  const std::vector<Segment> groove =
      polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}}).segments;
  expectCorners(withAxisAllowances(groove, {0.5, 0}),
                {{0.5, 0}, {0.5, 6}, {-5.5, 6}, {-5.5, 3}, {-9.5, 3}, {-9.5, 6}, {-20, 6}});
}

// FALX 0.25 as well: the diameters move up by 0.25; the convex corners are closed along the
// rectangle (0.5 × 0.25), the concave ones trimmed: (0.5, 0) → (0.5, 6.25) → (−5.5, 6.25) →
// (−5.5, 3.25) → (−9.5, 3.25) → (−9.5, 6.25) → (−20, 6.25).
TEST(SiemensAxisAllowance, BothAllowancesGrowTheProfileByTheRectangle) {
  const std::vector<Segment> groove =
      polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}}).segments;
  expectCorners(withAxisAllowances(groove, {0.5, 0.25}),
                {{0.5, 0}, {0.5, 6.25}, {-5.5, 6.25}, {-5.5, 3.25}, {-9.5, 3.25}, {-9.5, 6.25}, {-20, 6.25}});
}

// A falling slope (a cone narrowing towards −z, its stock above and towards −z) moves by
// (−FALZ, +FALX); the rising slope after it by (+FALZ, +FALX). The V (0, 6) → (−4, 2) → (−8, 6)
// with FALZ 0.5, FALX 0.5: the falling line through (−0.5, 6.5) and (−4.5, 2.5), the rising one
// through (−3.5, 2.5) and (−7.5, 6.5): x = z + 7 and x = −z − 1 cross at (−4, 3). Before the falling line, the face (stock towards +z) at z 0.5
// from x 6 up: the profile begins at the rectangle's corner (0.5, 6.5) and runs along x 6.5 to the
// falling line's shifted start (−0.5, 6.5).
TEST(SiemensAxisAllowance, ASlopeFallingTowardsTheAxisMovesTowardsMinusZ) {
  const std::vector<Segment> v = polyline("V", {{0, 6}, {-4, 2}, {-8, 6}}).segments;
  expectCorners(withAxisAllowances(v, {0.5, 0.5}), {{0.5, 6.5}, {-0.5, 6.5}, {-4, 3}, {-7.5, 6.5}});
}

// Planned (CYCLE95 VARI 1, MID 2.5, FALZ 0.5): every roughing feed below the collar's top (x < 6)
// between the groove's walls stays between z −5.5 and −9.5 — the walls' allowances — and the
// groove's corners (−5.5, 3) and (−9.5, 3) are reached.
TEST(SiemensAxisAllowance, TheGroovePassesKeepFalzOffBothWalls) {
  const SiemensContour groove = polyline("G", {{0, 0}, {0, 6}, {-5, 6}, {-5, 3}, {-10, 3}, {-10, 6}, {-20, 6}});
  Cycle95Parameters p;
  p.contourName = "G";
  p.infeed = 2.5;
  p.allowanceZ = 0.5;
  p.roughingFeed = 0.2;
  p.undercutFeed = 0.05;
  p.finishingFeed = 0.1;
  p.type = machiningTypeOf(1).value();
  p.retract = 1;
  SiemensCycleCall call;
  call.line = 4;
  call.position = {5, 15};
  call.contour = &groove;
  const auto out = planCycle95(call, p);
  bool leftCorner = false, rightCorner = false;
  for (const Move& m : out.moves) {
    if (m.kind != MoveKind::Feed || m.to.x >= 6 - 1e-9 || m.to.z > -1) continue;
    EXPECT_LE(m.to.z, -5.5 + 1e-9) << m.to.z << " " << m.to.x;
    EXPECT_GE(m.to.z, -9.5 - 1e-9) << m.to.z << " " << m.to.x;
    leftCorner = leftCorner || nearlyEqual(m.to, {-5.5, 3}, 1e-9);
    rightCorner = rightCorner || nearlyEqual(m.to, {-9.5, 3}, 1e-9);
  }
  EXPECT_TRUE(leftCorner);
  EXPECT_TRUE(rightCorner);
}

}  // namespace
}  // namespace cyclecert
