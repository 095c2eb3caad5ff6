// The G74.1 replay's intersections (oracles/material/tool_shape.h, consistentIntersection) where a
// region touches the other only along a nearly collinear edge. Boost's overlay (1.74) can return the
// whole touching polygon as the intersection there; `fuzz --cycles g74.1` found it as false
// findings of no-gouge (a blade sliding along a slanted flank "sweeps" the whole part) and complete
// (material behind S, outside the groove, "left inside" it). The operands below are the ones those
// cases built, to the bit (hexadecimal literals, local (w, u) frame: Point{z = w, x = u}).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "oracles/judgement.h"
#include "oracles/material/boost_geometry.h"
#include "oracles/material/tool_shape.h"

namespace cyclecert {
namespace {

namespace bg = boost::geometry;

// fuzz --cycles g74.1 --seed 7, shrunk: G74.1 X32.14 Z-14.33 P10000 Q23600 H-1.84 D-10.34 A30 L2;
// G74.1 R0.3 W0.02 I1.03 J1. The rough pass's first feed (move 47) runs the blade's start-side
// corner along the 30° near flank from (u 0, w 0) to (u 3.152332, w 1.82) — the programmed point
// from u 1.03 to 4.182332. Its sweep (with the shank back along −w) is the hexagon below; the part
// (the stock without the finish groove) begins on the same flank line, u = w·cot 30°, from S (within
// 2e-6: the band's corner) to N (3.186973, 1.84). The two touch along the flank and nowhere cross:
// below the start level the sweep lies on the groove's side of the flank (u ≥ w·cot 30°), above it
// (its shank, u 0 … 4.18, w < 0) in the air over the mouth (the mouth rises at 2° only behind S, at
// u < 0), so the intersection has no area to speak of — not the part's 22.227 mm².
const std::vector<Point> kBladeSweep = {
    {-0x1.cd57d8c7ab57ap+3, -0x1.8p-51},          {-0x1.cd57d8c7ab57ap+3, 0x1.07ae147ae1478p+0},
    {-0x1.931a6823d44d7p+3, 0x1.0bab55ceabc7cp+2}, {0x1.d1eb851eb8518p+0, 0x1.0bab55ceabc7cp+2},
    {0x1.d1eb851eb8518p+0, 0x1.937fa15fe6ebap+1},  {0x0p+0, -0x1.8p-51}};
const std::vector<Point> kPartBesideTheFlank = {
    {0x1.af4c50574b7fbp-21, 0x1.7583de6119df9p-20}, {0x1.d70a3d70a3d71p+0, 0x1.97eebf47a320ep+1},
    {0x1.d70a3d70a3d71p+0, 0x1.0b6c53a8f305ap+3},   {0x1.2ad5ff56cb8efp-2, 0x1.0b6c549904102p+3},
    {0x1.736d296d6cd54p-2, 0x1.4c6216384f2eap+3},   {0x1.6b851eb851eb8p+1, 0x1.4c6216384f2eap+3},
    {0x1.6b851eb851eb8p+1, -0x1.03d70a3d70a3ep+1},  {-0x1.225cac8b955ffp-4, -0x1.03d70a3d70a3ep+1}};

// fuzz --cycles g74.1 --seed 123689112662539606, shrunk: G74.1 X19.28 Z-17.96 P35100 Q44900 H-14.08
// D-9.52 B80 L44; G74.1 R0.57 A0.54 B0.41 (a pointed tool, J0). The mouth rises behind S at 44°; the
// r1 chamfer (0.54 each way, I10) runs from P0 = (u −0.388443, w −0.375116) on the mouth to
// (0, 0.54) on the near flank. After the last move the material left behind S (u < 0, between the
// mouth and the start level w 0, left of the chamfer line, out to the band's edge u −1.388443) is the
// part, outside the groove; the target (the rough profile closed straight up from P0 and from the far
// mouth) lies right of the chamfer line and of u = P0's. They share the chamfer line and P0 (within
// 3e-6): nothing of that material is inside the groove.
const std::vector<Point> kMaterialBehindS = {
    {-0x1.801d87051cf02p-2, -0x1.8dc3cf653ef5fp-2}, {0x1.41d863d8p-23, -0x1.d56f5ffdb0d0dp-3},
    {-0x1.0124cfa8p-20, -0x1.6371085f44fbbp+0},     {-0x1.573ef344bcffbp+0, -0x1.6371085f44fbbp+0}};
// And the band's 1 mm below the floor, the other piece of what is left.
const std::vector<Point> kMaterialBelowTheFloor = {
    {0x1.c28f5c2f6f4a4p+3, -0x1.6371085f44fbbp+0}, {0x1.c28f5c24e8eep+3, 0x1.def673e067bb8p+2},
    {0x1.e28f5c28f5c29p+3, 0x1.def673e067bb8p+2},  {0x1.e28f5c28f5c29p+3, -0x1.6371085f44fbbp+0}};
const std::vector<Point> kRoughGrooveTarget = {
    {-0x1.801e486b4f726p-2, -0x1.8dc4217d13eecp-2}, {-0x1.2cbc166a73ef1p+4, -0x1.8dc4217d13eecp-2},
    {-0x1.851a7371b0188p+3, 0x1.9ef673e067bb8p+2},  {0x1.90b98e3fba93fp+2, 0x1.9ef673e067bb8p+2},
    {0x1.98569de1e7478p+2, 0x1.8787dc06e065dp+2},   {0x1.c28f5c28f5c29p+3, 0x1.30a3d70a3d70ap+2},
    {0x1.c28f5c28f5c29p+3, 0x0p+0},                 {0x1.147ae147ae148p-1, 0x0p+0}};

TEST(GrooveOverlay, ABladeSlidingAlongTheFlankDoesNotSweepThePart) {
  const BgRegion swept = regionFrom(kBladeSweep), part = regionFrom(kPartBesideTheFlank);
  ASSERT_NEAR(bg::area(part), 22.227, 1e-3);
  const BgRegion crossed = consistentIntersection(swept, part);
  EXPECT_LT(bg::area(crossed), 1e-4);
  EXPECT_LT(thickestRing(crossed), 1e-4);
}

TEST(GrooveOverlay, MaterialBehindTheStartIsNotInsideTheGroove) {
  BgRegion left = regionFrom(kMaterialBehindS);
  left.push_back(regionFrom(kMaterialBelowTheFloor).front());
  const BgRegion target = regionFrom(kRoughGrooveTarget);
  ASSERT_GT(bg::area(left), 0.5);
  const BgRegion inside = consistentIntersection(left, target);
  EXPECT_LT(bg::area(inside), 1e-4);
  EXPECT_LT(thickestRing(inside), 1e-4);
}

// An intersection Boost gets right is kept as it is: two unit squares overlapping by half.
TEST(GrooveOverlay, AnOrdinaryIntersectionIsUnchanged) {
  const BgRegion a = regionFrom({{0, 0}, {1, 0}, {1, 1}, {0, 1}}), b = regionFrom({{0.5, 0}, {1.5, 0}, {1.5, 1}, {0.5, 1}});
  EXPECT_NEAR(bg::area(consistentIntersection(a, b)), 0.5, 1e-12);
}

// The two programs above, planned by the reference and judged: no finding. Before consistentIntersection
// the first had no-gouge on move 47 (22.227 mm² of the part) and the second complete (0.413161 mm
// "inside the groove's rough profile", the material behind S).
std::vector<Finding> judgedReference(const std::string& program) {
  const PlanRequest request{program, "groove.nc", "gsk", {}, {}};
  const ReadRequest read = readRequest(request);
  JudgeInput in;
  in.program = readProgramSpec(*read.program, *read.profile, read.params, ToolOffset{});
  in.path = planWithReference(request);
  return judge(in);
}

std::string text(const std::vector<Finding>& fs) {
  std::string s;
  for (const Finding& f : fs) s += f.oracle + ": " + f.message + "\n";
  return s;
}

TEST(GrooveOverlay, TheFuzzersCasesPassEveryOracle) {
  for (const char* program :
       {"G00 X26.58 Z-12.99 F0.1;\nG74.1 X32.14 Z-14.33 P10000 Q23600 H-1.84 D-10.34 A30 L2;\nG74.1 R0.3 W0.02 I1.03 J1;\n",
        "G00 X18.72 Z-14.25 F0.1;\nG74.1 X19.28 Z-17.96 P35100 Q44900 H-14.08 D-9.52 B80 L44;\nG74.1 R0.57 A0.54 B0.41;\n"}) {
    const std::vector<Finding> f = judgedReference(program);
    EXPECT_TRUE(f.empty()) << program << text(f);
  }
}

}  // namespace
}  // namespace cyclecert
