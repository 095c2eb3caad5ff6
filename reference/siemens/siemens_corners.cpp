#include "reference/siemens/siemens_corners.h"

#include <algorithm>
#include <cmath>

#include "reference/model/alarms.h"
#include "reference/model/number_text.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }
double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
Point unit(Point v) { return (1.0 / std::hypot(v.z, v.x)) * v; }

// An element next to a corner (at its end when `atEnd`, else at its start), with what every point
// at a distance from the corner needs worked out once: a chamfer's length next to an arc is searched
// for (legOfChamferLength), trying many legs on the same element.
struct CornerElement {
  CornerElement(const Segment& s, bool atEnd) : s(s), atEnd(atEnd), corner(atEnd ? s.to : s.from) {
    if (!s.isArc()) return;
    angles = ArcAngles(s);
    radius = s.radius();
    toCorner = unit(corner - s.center);
    across = {-toCorner.x, toCorner.z};
    leaving = atEnd ? -1.0 * unitTangentAtEnd(s) : unitTangentAtStart(s);
  }
  const Segment& s;
  bool atEnd;
  Point corner;
  // An arc's: its angles, radius, the direction from its centre to the corner and across it, and the
  // direction the element leaves the corner in.
  std::optional<ArcAngles> angles;
  double radius = 0;
  Point toCorner, across, leaving;
};

// Whether `p` lies on the element (within the geometry's tolerance, ends included).
constexpr double kOnElement = 1e-7;
bool onElement(Point p, const Segment& s) { return distanceToSegment(p, s) <= kOnElement; }
bool onArc(Point p, const CornerElement& arc) { return distanceToSegment(p, arc.s, *arc.angles) <= kOnElement; }

// The point of element `e` at straight distance `leg` from its corner (its end or its start): along
// a line, `leg` from the corner; on an arc, where the circle of radius `leg` round the corner meets
// the arc (interpretation, SIEMENS.CORNER: a chamfer's leg next to an arc is measured straight from
// the corner). Nothing when the element is shorter than that.
std::optional<Point> pointAtDistanceFromCorner(const CornerElement& e, double leg) {
  const Segment& s = e.s;
  const Point corner = e.corner;
  if (!s.isArc()) {
    const Point along = unit(e.atEnd ? s.from - s.to : s.to - s.from);
    if (leg > s.length() + kGeomEps) return std::nullopt;
    return corner + leg * along;
  }
  // The circle round the corner meets the arc's circle at two points, mirror images across the line
  // from the centre through the corner; the chamfer's end is the one on the element (of two — an arc
  // over a half circle — the one the element leaves the corner towards).
  const double r = e.radius;
  if (leg > 2 * r) return std::nullopt;
  const double along = r - leg * leg / (2 * r);  // from the centre towards the corner
  const double side = std::sqrt(std::max(0.0, r * r - along * along));
  std::optional<Point> found;
  for (const double sign : {1.0, -1.0}) {
    const Point p = s.center + along * e.toCorner + (sign * side) * e.across;
    if (!onArc(p, e)) continue;
    if (!found || dot(p - corner, e.leaving) > 0) found = p;
  }
  return found;
}

// SIEMENS.CORNER, CHF=: the chamfer's own length c. Between two lines it is the base of an
// isosceles triangle: legs c / (2 cos(φ/2)) for a turn of φ. Next to an arc the legs are equal
// straight distances from the corner (interpretation), found by bisection between c/2 (the chord
// is at most twice the leg) and the shorter element's chord. Nothing when the elements are too short.
std::optional<double> legOfChamferLength(const Segment& a, const Segment& b, double length, double turn) {
  if (!a.isArc() && !b.isArc()) return length / (2 * std::cos(turn / 2));
  const CornerElement before(a, true), after(b, false);
  const auto chord = [&](double leg) -> std::optional<double> {
    const auto pa = pointAtDistanceFromCorner(before, leg), pb = pointAtDistanceFromCorner(after, leg);
    if (!pa || !pb) return std::nullopt;
    return distance(*pa, *pb);
  };
  double low = length / 2, high = std::min(distance(a.from, a.to), distance(b.from, b.to));
  const auto longest = chord(high);
  if (high < low || !longest || *longest < length) return std::nullopt;
  for (int i = 0; i < 200 && high - low > 1e-13; ++i) {
    const double mid = (low + high) / 2;
    const auto c = chord(mid);
    if (c && *c < length) low = mid; else high = mid;
  }
  return high;
}

// SIEMENS.CORNER, CHF=/CHR=: a line from the point `leg` before the corner on `a` to the point `leg`
// after it on `b` (CHR: `leg` is the given width; CHF: legOfChamferLength).
Segment chamfer(Segment& a, Segment& b, const CornerRequest& corner, double leg) {
  const auto from = pointAtDistanceFromCorner(CornerElement(a, true), leg),
             to = pointAtDistanceFromCorner(CornerElement(b, false), leg);
  if (!from || !to) {
    throw NotSupported(corner.line, corner.text + " needs " + shortDecimalText(leg) +
                                        " mm of each element; the controller shortens it then, which cyclecert does not model");
  }
  Segment between;
  between.sourceLine = corner.line;
  between.from = *from;
  between.to = *to;
  a.to = *from;
  b.from = *to;
  return between;
}

// Where a circle centred at `center` touches element `s`: the foot of the perpendicular on a line,
// the point of an arc's circle on the ray from its centre through `center`.
Point tangentPoint(const Segment& s, Point center) {
  if (s.isArc()) return s.center + s.radius() * unit(center - s.center);
  const Point d = unit(s.to - s.from);
  return s.from + dot(center - s.from, d) * d;
}

// SIEMENS.CORNER, RND=: an arc of radius ρ tangent to both elements, on the inside of the turn. Its
// centre lies ρ from both, on the side the contour turns to: where the two elements offset by ρ to
// that side meet — offsetPath (reference/model/offset.h) trims such a concave corner to exactly that
// point. The elements end where the rounding touches them.
Segment rounding(Segment& a, Segment& b, const CornerRequest& corner, bool turnsLeft) {
  const auto refuse = [&] {
    throw NotSupported(corner.line, corner.text + " does not fit between its elements; the controller shortens it "
                                                  "then, which cyclecert does not model");
  };
  std::vector<Segment> offset;
  try {
    offset = offsetPath({a, b}, corner.value, turnsLeft ? CompensationSide::Left : CompensationSide::Right);
  } catch (const OffsetError&) {
    refuse();
  }
  if (offset.size() != 2) refuse();  // an element shorter than the rounding vanished
  const Point center = offset.front().to;
  const Point from = tangentPoint(a, center), to = tangentPoint(b, center);
  if (!onElement(from, a) || !onElement(to, b)) refuse();
  Segment between;
  between.sourceLine = corner.line;
  between.kind = turnsLeft ? SegmentKind::ArcCCW : SegmentKind::ArcCW;
  between.from = from;
  between.to = to;
  between.center = center;
  a.to = from;
  b.from = to;
  return between;
}

}  // namespace

std::optional<Segment> insertCorner(Segment& a, Segment& b, const CornerRequest& corner) {
  const Point da = unitTangentAtEnd(a);
  const Point db = unitTangentAtStart(b);
  const double turn = std::atan2(std::abs(cross(da, db)), dot(da, db));  // 0 … π
  if (turn <= 1e-9) return std::nullopt;  // tangent: no corner
  if (turn >= M_PI - 1e-9) {
    throw NotSupported(corner.line, corner.text + " at a corner where the contour turns back on itself");
  }
  switch (corner.kind) {
    case CornerKind::ChamferLeg: return chamfer(a, b, corner, corner.value);
    case CornerKind::ChamferLength: {
      const auto leg = legOfChamferLength(a, b, corner.value, turn);
      if (!leg) {
        throw NotSupported(corner.line, corner.text + " is longer than its elements allow; the controller shortens it "
                                                      "then, which cyclecert does not model");
      }
      return chamfer(a, b, corner, *leg);
    }
    case CornerKind::Rounding: return rounding(a, b, corner, cross(da, db) > 0);
  }
  return std::nullopt;
}

}  // namespace cyclecert
