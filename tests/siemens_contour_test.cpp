// The contour reader (issue 16, item 1; rules LCYC95.CONTOUR, SIEMENS.CONTOUR, SIEMENS.ARC,
// SIEMENS.CORNER, SIEMENS.DIAMETER): seed 004's contours L42 and L18 read into segments derived by
// hand from the seed's text, CR= and I/K arcs, and the chamfers and roundings CHF=/CHR=/RND=.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "reference/model/alarms.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_parser.h"

namespace cyclecert {
namespace {

SiemensContour contourOf(const std::string& text, bool diameterX = true) {
  SiemensModal modal;
  modal.motion = 1;
  modal.diameterX = diameterX;
  return readSiemensContour("L1", parseSiemensSubprogram(text, "L1.spf"), modal);
}

void expectSegment(const Segment& s, SegmentKind kind, Point from, Point to, int line) {
  EXPECT_EQ(s.kind, kind) << "line " << line;
  EXPECT_NEAR(s.from.z, from.z, 1e-9) << "line " << line;
  EXPECT_NEAR(s.from.x, from.x, 1e-9) << "line " << line;
  EXPECT_NEAR(s.to.z, to.z, 1e-9) << "line " << line;
  EXPECT_NEAR(s.to.x, to.x, 1e-9) << "line " << line;
  EXPECT_EQ(s.sourceLine, line);
}

// Seed 004 §二, L42.spf (the seed's OCR spaces in 'X20. 8' etc. removed), read under G23: X is a
// diameter, so x = X/2. The seed's chamfers "45 × 1.5" are written out as lines (X35→X38 over Z
// -45→-46.5, …), none as CHF=.
TEST(SiemensContour, SeedL42IsReadIntoItsElements) {
  const SiemensContour c = contourOf(
      "G1X0Z0\nG3X20.8Z-25.8K-15I0\nG2X31.6Z-39.5CR=8\nG1Z-45\nX35\nX38Z-46.5\nZ-58.5\nX35Z-60\nZ-65\nX39\nX42Z-66.5\nZ-75\nM02\n");
  ASSERT_EQ(c.segments.size(), 11u);
  // G3: from (0, 0) to (Z -25.8, X 20.8/2 = 10.4); programmed centre = start + (K -15, I 0) = (-15, 0),
  // radius 15; the end lies √(10.8² + 10.4²) = 14.993332 from it, 0.0067
  // off the circle: accepted, and the centre moved onto the chord's perpendicular bisector 15 from
  // both ends (SIEMENS.ARC): z² + x² = 225 and (z + 25.8)² + (x − 10.4)² = 225 on the programmed side
  // give (-14.999997, -0.009608).
  expectSegment(c.segments[0], SegmentKind::ArcCCW, {0, 0}, {-25.8, 10.4}, 2);
  EXPECT_NEAR(c.segments[0].center.z, -14.999997, 1e-6);
  EXPECT_NEAR(c.segments[0].center.x, -0.009608, 1e-6);
  // G2 CR=8 from (-25.8, 10.4) to (-39.5, 31.6/2 = 15.8): chord d = (-13.7, 5.4), |d| = √216.85 =
  // 14.725828; midpoint (-32.65, 13.1); the centre lies √(8² − 7.362914²) = 3.128498 off the chord,
  // to the right of it for a clockwise arc of at most 180°: along (5.4, 13.7)/|d| → (-31.502771,
  // 16.010561).
  expectSegment(c.segments[1], SegmentKind::ArcCW, {-25.8, 10.4}, {-39.5, 15.8}, 3);
  EXPECT_NEAR(c.segments[1].center.z, -31.502771, 1e-5);
  EXPECT_NEAR(c.segments[1].center.x, 16.010561, 1e-5);
  expectSegment(c.segments[2], SegmentKind::Line, {-39.5, 15.8}, {-45, 15.8}, 4);
  expectSegment(c.segments[3], SegmentKind::Line, {-45, 15.8}, {-45, 17.5}, 5);    // X35 → x 17.5
  expectSegment(c.segments[4], SegmentKind::Line, {-45, 17.5}, {-46.5, 19}, 6);    // chamfer 1.5 × 1.5
  expectSegment(c.segments[5], SegmentKind::Line, {-46.5, 19}, {-58.5, 19}, 7);
  expectSegment(c.segments[6], SegmentKind::Line, {-58.5, 19}, {-60, 17.5}, 8);    // chamfer back down
  expectSegment(c.segments[7], SegmentKind::Line, {-60, 17.5}, {-65, 17.5}, 9);
  expectSegment(c.segments[8], SegmentKind::Line, {-65, 17.5}, {-65, 19.5}, 10);   // X39 → x 19.5
  expectSegment(c.segments[9], SegmentKind::Line, {-65, 19.5}, {-66.5, 21}, 11);   // chamfer 1.5 × 1.5
  expectSegment(c.segments[10], SegmentKind::Line, {-66.5, 21}, {-75, 21}, 12);
  EXPECT_EQ(c.name, "L1");
  EXPECT_EQ(c.file, "L1.spf");
}

// Seed 004 §三, L18.spf under DIAMON.
TEST(SiemensContour, SeedL18IsReadIntoItsElements) {
  const SiemensContour c = contourOf(
      "G1X0Z0F0.2\nG03X20Z-10CR=10\nG1Z-16\nX27\nX30Z-17.5\nZ-30.5\nX40\nZ-35.5\nG02Z-50CR=20\nG1X50Z-58\nZ-70\nRET\n");
  ASSERT_EQ(c.segments.size(), 10u);
  // G03 CR=10 from (0, 0) to (-10, 10): the two centres 10 from both ends are (-10, 0) and (0, 10);
  // counter-clockwise by 90° (≤ 180°, CR positive) about (-10, 0): from angle 0° to 90°.
  expectSegment(c.segments[0], SegmentKind::ArcCCW, {0, 0}, {-10, 10}, 2);
  EXPECT_NEAR(c.segments[0].center.z, -10, 1e-9);
  EXPECT_NEAR(c.segments[0].center.x, 0, 1e-9);
  expectSegment(c.segments[1], SegmentKind::Line, {-10, 10}, {-16, 10}, 3);
  expectSegment(c.segments[2], SegmentKind::Line, {-16, 10}, {-16, 13.5}, 4);
  expectSegment(c.segments[3], SegmentKind::Line, {-16, 13.5}, {-17.5, 15}, 5);  // chamfer 1.5 × 1.5
  expectSegment(c.segments[4], SegmentKind::Line, {-17.5, 15}, {-30.5, 15}, 6);
  expectSegment(c.segments[5], SegmentKind::Line, {-30.5, 15}, {-30.5, 20}, 7);
  expectSegment(c.segments[6], SegmentKind::Line, {-30.5, 20}, {-35.5, 20}, 8);
  // G02 CR=20 from (-35.5, 20) to (-50, 20): chord 14.5, centre at z = -42.75 and 20 ± √(400 −
  // 7.25²) = 20 ± 18.639675; clockwise (leftwards) over ≤ 180° puts it above: x = 38.639675 (the
  // arc dips to x = 1.360325 below 20: the undercut of CYCLE95.UNDERCUT).
  expectSegment(c.segments[7], SegmentKind::ArcCW, {-35.5, 20}, {-50, 20}, 9);
  EXPECT_NEAR(c.segments[7].center.z, -42.75, 1e-9);
  EXPECT_NEAR(c.segments[7].center.x, 38.639675, 1e-6);
  expectSegment(c.segments[8], SegmentKind::Line, {-50, 20}, {-58, 25}, 10);
  expectSegment(c.segments[9], SegmentKind::Line, {-58, 25}, {-70, 25}, 11);
}

TEST(SiemensContour, ANegativeCrTakesTheArcOfMoreThanHalfACircle) {
  // From (0, 0) to (-10, 10) clockwise, CR=-10: of the centres (-10, 0) and (0, 10) the longer
  // clockwise arc (270°) is about (-10, 0).
  const SiemensContour c = contourOf("G1X0Z0\nG2X20Z-10CR=-10\nM17\n");
  ASSERT_EQ(c.segments.size(), 1u);
  EXPECT_NEAR(c.segments[0].center.z, -10, 1e-9);
  EXPECT_NEAR(c.segments[0].center.x, 0, 1e-9);
  // CR=+10, clockwise: the 90° arc about (0, 10).
  const SiemensContour shorter = contourOf("G1X0Z0\nG2X20Z-10CR=10\nM17\n");
  EXPECT_NEAR(shorter.segments[0].center.z, 0, 1e-9);
  EXPECT_NEAR(shorter.segments[0].center.x, 10, 1e-9);
}

TEST(SiemensContour, IAndKAreTheCentreRelativeToTheStartIAsARadius) {
  // From (-5, 10) (X20 diameter) to (-15, 20) (X40) counter-clockwise; K-10 I0 → centre (-15, 10):
  // 10 from both ends.
  const SiemensContour c = contourOf("G1X20Z-5\nG3X40Z-15K-10I0\nM17\n");
  EXPECT_NEAR(c.segments[0].center.z, -15, 1e-12);
  EXPECT_NEAR(c.segments[0].center.x, 10, 1e-12);
  // I is not halved under diameter programming: I5 moves the centre 5 mm in x.
  const SiemensContour i = contourOf("G1X0Z0\nG2X20Z0I5K0\nM17\n");
  EXPECT_NEAR(i.segments[0].center.x, 5, 1e-12);
}

TEST(SiemensContour, ImpossibleArcsAlarm14040) {
  try {
    contourOf("G1X0Z0\nG2X20Z-10CR=5\nM17\n");  // chord 14.14: no radius 5 arc
    FAIL() << "no alarm";
  } catch (const CycleAlarm& a) {
    EXPECT_EQ(a.alarm().code, "14040");
    EXPECT_EQ(a.alarm().line, 2);
  }
  try {
    contourOf("G1X0Z0\nG2X20Z-10K-3I0\nM17\n");  // radius 3 at the start, √(49 + 100) at the end
    FAIL() << "no alarm";
  } catch (const CycleAlarm& a) {
    EXPECT_EQ(a.alarm().code, "14040");
  }
}

// Under G22 (radius): X is x. A right-angle corner at (-10, 0) between a line along -Z and one
// along +X.
TEST(SiemensContour, ChamfersAndRoundingsAreInsertedBetweenTwoLines) {
  // CHR=2: legs of 2 along both lines.
  const SiemensContour chr = contourOf("G1X0Z0\nZ-10CHR=2\nX10\nM17\n", false);
  ASSERT_EQ(chr.segments.size(), 3u);
  expectSegment(chr.segments[0], SegmentKind::Line, {0, 0}, {-8, 0}, 2);
  expectSegment(chr.segments[1], SegmentKind::Line, {-8, 0}, {-10, 2}, 2);
  expectSegment(chr.segments[2], SegmentKind::Line, {-10, 2}, {-10, 10}, 3);
  // CHF=2√2: the chamfer's own length; a 90° turn gives legs 2√2 / (2 cos 45°) = 2.
  const SiemensContour chf = contourOf("G1X0Z0\nZ-10CHF=2.82842712474619\nX10\nM17\n", false);
  ASSERT_EQ(chf.segments.size(), 3u);
  expectSegment(chf.segments[1], SegmentKind::Line, {-8, 0}, {-10, 2}, 2);
  // RND=2: tangent 2·tan 45° = 2 from the corner; the turn is to the right (clockwise) and the
  // centre 2 to the right of the first line's direction (-1, 0), i.e. at (-8, 2).
  const SiemensContour rnd = contourOf("G1X0Z0\nZ-10RND=2\nX10\nM17\n", false);
  ASSERT_EQ(rnd.segments.size(), 3u);
  expectSegment(rnd.segments[1], SegmentKind::ArcCW, {-8, 0}, {-10, 2}, 2);
  EXPECT_NEAR(rnd.segments[1].center.z, -8, 1e-12);
  EXPECT_NEAR(rnd.segments[1].center.x, 2, 1e-12);
  // A corner where the contour turns by 45° (along -Z, then up at 45° to (-15, 5)): CHR=1 cuts 1
  // off each line, so the chamfer ends 1 along (-1, 1)/√2 from the corner (-10, 0).
  const SiemensContour obtuse = contourOf("G1X0Z0\nZ-10CHR=1\nX5Z-15\nM17\n", false);
  ASSERT_EQ(obtuse.segments.size(), 3u);
  EXPECT_NEAR(obtuse.segments[1].to.z, -10 - std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(obtuse.segments[1].to.x, std::sqrt(0.5), 1e-12);
}

// Next to an arc (SIEMENS.CORNER, interpretation): under G22 the line (0, 0) → (−10, 0) along −Z,
// then G3 to (−20, 10) with CR=10: centre (−20, 0) (the counter-clockwise one of the two 90° arcs),
// leaving the corner along +X — a right turn of 90°.
TEST(SiemensContour, ChamfersAndRoundingsAreInsertedNextToAnArc) {
  // RND=2: the centre lies 2 to the right of both: above the line (x = 2) and outside the arc's
  // circle (12 from (−20, 0)): (z + 20)² + 2² = 12², z = −20 + √140 = −8.167840… . It touches the
  // line below it at (−8.167840, 0) and the arc where the ray from (−20, 0) through it meets the
  // circle: (−20, 0) + 10·(√140, 2)/12 = (−10.139867…, 1.666667). A right turn: clockwise.
  const double fz = -20 + std::sqrt(140.0);
  const Point onArc{-20 + 10 * std::sqrt(140.0) / 12, 20.0 / 12};
  const SiemensContour rnd = contourOf("G1X0Z0\nZ-10RND=2\nG3X10Z-20CR=10\nM17\n", false);
  ASSERT_EQ(rnd.segments.size(), 3u);
  expectSegment(rnd.segments[0], SegmentKind::Line, {0, 0}, {fz, 0}, 2);
  expectSegment(rnd.segments[1], SegmentKind::ArcCW, {fz, 0}, onArc, 2);
  EXPECT_NEAR(rnd.segments[1].center.z, fz, 1e-9);
  EXPECT_NEAR(rnd.segments[1].center.x, 2, 1e-9);
  expectSegment(rnd.segments[2], SegmentKind::ArcCCW, onArc, {-20, 10}, 3);
  EXPECT_NEAR(rnd.segments[2].center.z, -20, 1e-9);
  EXPECT_NEAR(rnd.segments[2].center.x, 0, 1e-9);
  // CHR=2: 2 before the corner on the line, (−8, 0); on the arc the point 2 straight from the corner:
  // 10 − 2²/(2·10) = 9.8 from the centre towards the corner and √(10² − 9.8²) = √3.96 across, on the
  // arc's side (x > 0): (−10.2, 1.989975).
  const Point chamferEnd{-10.2, std::sqrt(3.96)};
  const SiemensContour chr = contourOf("G1X0Z0\nZ-10CHR=2\nG3X10Z-20CR=10\nM17\n", false);
  ASSERT_EQ(chr.segments.size(), 3u);
  expectSegment(chr.segments[1], SegmentKind::Line, {-8, 0}, chamferEnd, 2);
  expectSegment(chr.segments[2], SegmentKind::ArcCCW, chamferEnd, {-20, 10}, 3);
  // CHF= the length of that chamfer, √(2.2² + 3.96) = √8.8: the same legs of 2.
  const SiemensContour chf = contourOf("G1X0Z0\nZ-10CHF=" + std::to_string(std::sqrt(8.8)).substr(0, 8) + "\nG3X10Z-20CR=10\nM17\n", false);
  ASSERT_EQ(chf.segments.size(), 3u);
  EXPECT_NEAR(chf.segments[1].from.z, -8, 1e-5);
  EXPECT_NEAR(chf.segments[1].to.z, chamferEnd.z, 1e-5);
  EXPECT_NEAR(chf.segments[1].to.x, chamferEnd.x, 1e-5);
  // An arc before the corner: G2 from (0, 0) to (−10, 10), CR=10, centre (0, 10), arriving along +X;
  // then along −Z: a left turn. CHR=2 ends 2 along the line, (−12, 10), and on the arc at 9.8 from
  // (0, 10) towards the corner (−1, 0) and 1.989975 across, on the arc: (−9.8, 10 − 1.989975).
  const SiemensContour arcFirst = contourOf("G1X0Z0\nG2X10Z-10CR=10CHR=2\nG1Z-20\nM17\n", false);
  ASSERT_EQ(arcFirst.segments.size(), 3u);
  expectSegment(arcFirst.segments[0], SegmentKind::ArcCW, {0, 0}, {-9.8, 10 - std::sqrt(3.96)}, 2);
  expectSegment(arcFirst.segments[1], SegmentKind::Line, {-9.8, 10 - std::sqrt(3.96)}, {-12, 10}, 2);
}

TEST(SiemensContour, ContourErrorsNameTheirLine) {
  const auto lineOfError = [](const std::string& text) {
    try {
      contourOf(text);
    } catch (const ParseError& e) {
      return e.loc().line;
    } catch (const NotSupported& e) {
      return -e.line();
    }
    return 0;
  };
  EXPECT_EQ(lineOfError("G1X0\nZ-5\nM17\n"), 1);             // the first point needs X and Z
  EXPECT_EQ(lineOfError("G1X0Z0\nG0Z-5\nM17\n"), 2);         // G0 is no contour element
  EXPECT_EQ(lineOfError("G1X0Z0\nZ-5\nX10CHF=1\nM17\n"), 3);  // a chamfer after the last element
  EXPECT_EQ(lineOfError("G1X0Z0\nG2X10Z-5\nM17\n"), 2);      // an arc without CR or I/K
  EXPECT_EQ(lineOfError("G1X0Z0\nG2X10Z-5CR=5K1\nM17\n"), 2);  // both
  // A rounding that needs more than its element: tangent to the 1 mm line beyond its start (z 3.14).
  EXPECT_EQ(lineOfError("G1X0Z0\nZ-1RND=5\nG3X10Z-11CR=10\nM17\n"), -2);
  EXPECT_EQ(lineOfError("G1X0Z0\nG54Z-5\nM17\n"), 2);
}

}  // namespace
}  // namespace cyclecert
