// The material a SINUMERIK call implies (oracles/material_replay.cpp), built without booleans where
// the shape allows (stockUpToLevel, stockAboveFaceTop, siemensAllowanceLayer): each region here is
// derived by hand from the rules (LCYC95.ROUGH note: the bar up to the profile's highest point, less
// what stands behind the part's face; a finishing call works on the allowance layer between the
// profile and the finishing path).
#include <gtest/gtest.h>

#include <algorithm>
#include <numbers>
#include <optional>
#include <string>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "oracles/material/boost_geometry.h"
#include "oracles/material_replay.h"
#include "tests/siemens_oracle_paths.h"

namespace cyclecert {
namespace {

using namespace siemens_test;

std::optional<MaterialReplay> replayOf(const std::string& program, const std::string& contour) {
  PlanRequest plan{program, "test.mpf", "sinumerik-802d", {}, {}};
  plan.subprograms.push_back({"L1", contour, "test#/subprograms/L1"});
  return replayMaterial(judgeInputFor(siemensRequest(program, "sinumerik-802d", contour), planWithReference(plan)));
}

double lowestX(const BgRegion& region) {
  double lowest = 1e9;
  for (const BgPolygon& polygon : region) {
    for (const BgPoint& p : polygon.outer()) lowest = std::min(lowest, p.y());
  }
  return lowest;
}

// L1 (x radius): (z 0, x 1.4), a chamfer up to (−0.1, 1.5), down to (−0.1, 1), along to (−1.1, 1),
// up to (−1.1, 1.5): a graph over z with a groove behind a raised start. The bar reaches the
// profile's highest point, x 1.5; the part's face stands at z 0 up to x 1.4, so the stock is what
// stands above x 1.4: the triangle over the chamfer (0.1 × 0.1 / 2 = 0.005) and the groove's top
// (1 × 0.1 = 0.1) — not the groove below 1.4 (which would make 0.505).
TEST(SiemensMaterial, TheStockBehindARaisedStartStandsAboveThePartsFace) {
  const std::string program =
      "T1 D1\nG0 X4.2 Z0.6\nCYCLE95(\"L1\", 0.5, 0, 0, 0, 0.1, 0.05, 0.05, 1, 0, 0, 0.1)\nM02\n";
  const std::string contour = "G1 X2.8 Z0\nG1 X3 Z-0.1\nG1 X2 Z-0.1\nG1 X2 Z-1.1\nG1 X3 Z-1.1\nRET\n";
  const std::optional<MaterialReplay> r = replayOf(program, contour);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(boost::geometry::area(r->stock), 0.105, 1e-9);
  EXPECT_NEAR(lowestX(r->stock), 1.4, 1e-9);
}

// A collar up to the profile's highest point: L1 (z0,x10) → (−5,10) → (−5,20) → (−10,20) → (−10,12)
// → (−20,12). The bar reaches x 20, the collar's top, which parts it in two: in front of the collar
// 5 × 10 = 50, behind it 10 × 8 = 80 (the collar's top itself holds none).
TEST(SiemensMaterial, ACollarUpToTheTopPartsTheStock) {
  const std::string program = "T1 D1\nG0 X44 Z2\nCYCLE95(\"L1\", 2, 0, 0, 0, 0.2, 0.1, 0.05, 1, 0, 0, 1)\nM02\n";
  const std::optional<MaterialReplay> r = replayOf(program, "G1 X20 Z0\nZ-5\nX40\nZ-10\nX24\nZ-20\nRET\n");
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->stock.size(), 2u);
  EXPECT_NEAR(boost::geometry::area(r->stock), 130, 1e-9);
  EXPECT_NEAR(lowestX(r->stock), 10, 1e-9);
}

// A finishing call (VARI 5, longitudinal external finishing) without allowances and without a
// nose radius: the profile is the contour, so is the finishing path — no allowance layer, no stock.
TEST(SiemensMaterial, AFinishingCallWithoutAllowancesHasNoStock) {
  const std::string program = "T1 D1\nG0 X24 Z2\nCYCLE95(\"L1\", 2, 0, 0, 0, 0.2, 0.1, 0.05, 5, 0, 0, 1)\nM02\n";
  const std::optional<MaterialReplay> r = replayOf(program, kL1);
  ASSERT_TRUE(r.has_value());
  EXPECT_TRUE(r->stock.empty());
}

// The same call with FAL 0.5: the layer between the contour grown by 0.5 on its stock side (offset.h:
// lines moved along their normal, an arc of 0.5 about a convex corner, concave corners trimmed) and
// the contour. L1 (z0,x10) → (−10,10) → (−10,16) → (−20,16) → (−20,20) is 30 mm long; its corners
// (−10,10) and (−20,16) are concave (the band loses a 0.5 × 0.5 square at each), (−10,16) convex (it
// gains a quarter disc of radius 0.5): 30 × 0.5 − 2 × 0.25 + π × 0.25 / 4, less the chords' sagitta
// (≤ 1e-3 mm along the quarter circle's 0.79 mm).
TEST(SiemensMaterial, AFinishingCallsAllowanceIsTheLayerAlongTheContour) {
  const std::string program = "T1 D1\nG0 X44 Z2\nCYCLE95(\"L1\", 2, 0, 0, 0.5, 0.2, 0.1, 0.05, 5, 0, 0, 1)\nM02\n";
  const std::optional<MaterialReplay> r = replayOf(program, kL1);
  ASSERT_TRUE(r.has_value());
  EXPECT_NEAR(boost::geometry::area(r->stock), 15 - 0.5 + std::numbers::pi / 16, 1e-3);
}

}  // namespace
}  // namespace cyclecert
