// Roughing under tool-nose radius compensation (G71.TNRC.ZERO): the cycle runs on the compensated
// path of the A→A' start-up, whose end the start-up vector moves off A's line. The oracles' implied
// stock begins on the depth axis' line through that end, so the reference's plan — passes from A's
// cut coordinate, the semi-finish from the compensated A' — passes every oracle. Numbers worked out
// by hand in the comments.
#include <gtest/gtest.h>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/spec/spec_case.h"
#include "oracles/material/boost_geometry.h"
#include "oracles/material_replay.h"

namespace cyclecert {
namespace {

Segment line(Point a, Point b) { return {SegmentKind::Line, a, b, {}, 0}; }
bool inside(const BgRegion& r, Point p) { return boost::geometry::within(toBg(p), r); }

// G00 X8 Z0; G42 with nose radius 0.2, tip 3 (−z, −x); N10 G00 X2; G01 Z-3; N20 X8 Z-5 (radius
// values). The start-up ends at A' = (z 0, x 1) plus r along the right normal of the next block
// (travelling −z: +x) plus r·tip: (0, 1) + (0, 0.2) + (−0.2, −0.2) = (−0.2, 1). The compensated
// body starts there; the slanted start-up runs from A = (0, 4) to it.
constexpr Point kStart{0, 4}, kStartUpEnd{-0.2, 1};

TEST(CompensatedRoughing, TheImpliedStockBeginsOnTheDepthLineThroughTheStartUpEnd) {
  CycleSpec c;
  c.code = "G71";
  c.start = kStart;
  c.shape = {line(kStart, kStartUpEnd), line(kStartUpEnd, {-3.2, 1}), line({-3.2, 1}, {-5.2, 4})};
  const BgRegion stock = impliedStockOf(c, {0, 1}, 100, 1e-4);
  // Between the slanted start-up (at x 1.2 it stands at z −0.2·2.8/3 = −0.187) and z −0.2: not
  // stock — the start-up block builds the offset up there, it is no part boundary.
  EXPECT_FALSE(inside(stock, {-0.195, 1.2}));
  EXPECT_FALSE(inside(stock, {-0.1, 3.9}));
  // Beyond the line z = −0.2, above the compensated shape and below A's level: stock.
  EXPECT_TRUE(inside(stock, {-0.21, 1.2}));
  EXPECT_TRUE(inside(stock, {-0.21, 3.9}));
  // Its area: z ∈ [−5.2, −0.2] under x 4, less the part: 5 × 3 less the taper's triangle 2 × 3 / 2.
  EXPECT_NEAR(boost::geometry::area(stock), 15 - 3, 1e-9);
}

SpecCase compensatedCase(const std::string& program) {
  return specCaseFrom(nlohmann::json{{"id", "fanuc-0i-f/g71/tnrc-start-up"},
                                     {"title", "G71 type I under G42, tip 3"},
                                     {"rules", {"G71.TNRC.ZERO"}},
                                     {"profile", "fanuc-0i-f"},
                                     {"program", program},
                                     {"tool", {{"nose_radius", 0.2}, {"tip", 3}}},
                                     {"expect", {{"oracles", "pass"}}},
                                     {"derivation", "hand-written: see the test's comments"}},
                      "test");
}

std::vector<Finding> judgedReferencePlan(const SpecCase& c) {
  return judge(judgeInputFor(judgeRequestFor(c), planSpecCase(c)));
}

// The last pass stands less than Δd above the compensated A'; the sliver between it, the slanted
// start-up and the line through the compensated A' was reported left standing (complete) before
// the stock began on that line.
TEST(CompensatedRoughing, TheReferencePassesEveryOracleWhenTheStartUpEndMovesAlongTheCut) {
  for (const char* program :
       {"G00 X8 Z0;\nG42;\nG71 U0.51 R0.01;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2;\nG01 Z-3;\nN20 X8 Z-5;\nG40;\nM30;\n",
        // A chamfer from A': the start-up end moves by r·(sin, cos of the chamfer's slope) less r.
        "G00 X8 Z0;\nG42;\nG71 U0.51 R0.01;\nG71 P10 Q20 U0 W0 F0.2;\nN10 G00 X2;\nN20 G01 X8 Z-5;\nG40;\nM30;\n"}) {
    const std::vector<Finding> findings = judgedReferencePlan(compensatedCase(program));
    EXPECT_TRUE(findings.empty()) << program << findingsText(findings);
  }
}

}  // namespace
}  // namespace cyclecert
