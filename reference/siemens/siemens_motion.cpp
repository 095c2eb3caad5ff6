#include "reference/siemens/siemens_motion.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "reference/model/alarms.h"
#include "reference/model/program.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

// The end point's distance from the centre may differ from the start's by this much (mm), as the
// FANUC reader allows (reference/interpreter/block_motion.cpp).
constexpr double kArcRadiusTolerance = 0.01;

// SIEMENS.ARC (interpretation, as Siemens' circle end point monitoring describes it): an I/K end
// point off the circle by no more than kArcRadiusTolerance is taken as programmed correctly, and the
// centre is moved onto the chord's perpendicular bisector, at the start's radius from both ends, on
// the programmed centre's side (the chord's midpoint when the chord is longer than the diameter).
// The arc is then one circle: its end lies on it, so the roughing profile and the finishing path
// that offset it meet the next element where the program does.
Point centreWithBothEndsOnTheCircle(Point from, Point to, Point programmed) {
  if (std::abs(distance(from, programmed) - distance(to, programmed)) <= kGeomEps) return programmed;
  const double chord = distance(from, to);
  const Point mid = 0.5 * (from + to);
  const Point unit = (1.0 / chord) * (to - from);
  const Point normal{-unit.x, unit.z};  // the chord's direction turned by 90°
  const double half = chord / 2;
  const double r = distance(from, programmed);
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  const Point towardsProgrammed = programmed - mid;
  const double side = towardsProgrammed.z * normal.z + towardsProgrammed.x * normal.x >= 0 ? 1.0 : -1.0;
  return mid + (side * h) * normal;
}

}  // namespace

void applySiemensModal(const SiemensBlock& b, SiemensModal& m) {
  for (const SiemensWord& w : b.words) {
    if (w.address != "G") continue;
    const int g = gCode10(w.value);
    if (g == 0 || g == 10 || g == 20 || g == 30) m.motion = g / 10;
    if (g == 220) m.diameterX = false;
    if (g == 230) m.diameterX = true;
  }
  if (b.hasKeyword("DIAMON")) m.diameterX = true;
  if (b.hasKeyword("DIAMOF")) m.diameterX = false;
}

bool hasSiemensAxisWord(const SiemensBlock& b) { return b.find("X") || b.find("Z"); }

Point siemensTarget(const SiemensBlock& b, Point from, const SiemensModal& m) {
  Point to = from;
  if (const SiemensWord* z = b.find("Z")) to.z = z->value;
  if (const SiemensWord* x = b.find("X")) to.x = m.diameterX ? x->value / 2 : x->value;
  return to;
}

std::optional<Segment> siemensMotionSegment(const SiemensBlock& b, Point from, const SiemensModal& m,
                                            const std::string& file) {
  Segment seg;
  seg.sourceLine = b.line;
  seg.from = from;
  seg.to = siemensTarget(b, from, m);
  if (m.motion != 2 && m.motion != 3) {
    if (distance(seg.from, seg.to) <= kGeomEps) return std::nullopt;
    return seg;
  }
  seg.kind = m.motion == 2 ? SegmentKind::ArcCW : SegmentKind::ArcCCW;
  const SiemensWord* cr = b.find("CR");
  const SiemensWord* i = b.find("I");
  const SiemensWord* k = b.find("K");
  if (cr && (i || k)) {
    const SiemensWord* centre = i ? i : k;
    throw ParseError({file, b.line, centre->column}, "either CR= or I/K in an arc block, not both", centre->text);
  }
  if (cr) {
    // SIEMENS.ARC: CR=+r an arc of at most 180°, CR=-r more — FANUC's sign rule for R.
    const auto center = arcCenterFromRadius(seg.from, seg.to, cr->value, seg.kind);
    if (!center) {
      throw CycleAlarm(kSiemensCircleEndPointAlarm, b.line,
                       cr->text + " is shorter than half the chord (" + shortDecimalText(distance(seg.from, seg.to) / 2) +
                           " mm), or the end point equals the start");
    }
    seg.center = *center;
    return seg;
  }
  if (!i && !k) {
    throw ParseError({file, b.line, 1}, "CR= or I/K (the centre) in a G" + std::to_string(m.motion) + " block", b.text);
  }
  seg.center = seg.from + Point{k ? k->value : 0.0, i ? i->value : 0.0};
  const double r0 = distance(seg.from, seg.center);
  const double r1 = distance(seg.to, seg.center);
  if (std::abs(r0 - r1) > kArcRadiusTolerance || r0 <= kGeomEps) {
    throw CycleAlarm(kSiemensCircleEndPointAlarm, b.line,
                     "the end point is not on the circle (radius " + shortDecimalText(r0) + " mm at the start, " + shortDecimalText(r1) +
                         " mm at the end)");
  }
  seg.center = centreWithBothEndsOnTheCircle(seg.from, seg.to, seg.center);
  return seg;
}

}  // namespace cyclecert
