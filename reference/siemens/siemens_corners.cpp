#include "reference/siemens/siemens_corners.h"

#include <cmath>

#include "reference/model/alarms.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

Point unit(Point v) {
  const double n = std::hypot(v.z, v.x);
  return {v.z / n, v.x / n};
}

double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }
double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }

// How far from the corner along each element the chamfer or rounding starts: for a turn of φ
// between the directions, a chamfer of length c has legs c / (2 cos(φ/2)) (an isosceles triangle
// whose apex angle is π − φ), a rounding of radius r touches the elements r·tan(φ/2) from it.
double legOf(const CornerRequest& c, double turn) {
  switch (c.kind) {
    case CornerKind::ChamferLeg: return c.value;
    case CornerKind::ChamferLength: return c.value / (2 * std::cos(turn / 2));
    case CornerKind::Rounding: return c.value * std::tan(turn / 2);
  }
  return 0;
}

}  // namespace

std::optional<Segment> insertCorner(Segment& a, Segment& b, const CornerRequest& corner) {
  if (a.isArc() || b.isArc()) {
    throw NotSupported(corner.line, corner.text + " next to an arc: cyclecert inserts chamfers and roundings between two "
                                                  "lines only (write the element out as G1/G2/G3)");
  }
  const Point da = unit(a.to - a.from);
  const Point db = unit(b.to - b.from);
  const double turn = std::atan2(std::abs(cross(da, db)), dot(da, db));  // 0 … π
  if (turn <= 1e-9) return std::nullopt;  // in line: no corner
  if (turn >= M_PI - 1e-9) {
    throw NotSupported(corner.line, corner.text + " at a corner where the contour turns back on itself");
  }
  const double leg = legOf(corner, turn);
  if (leg > a.length() + kGeomEps || leg > b.length() + kGeomEps) {
    throw NotSupported(corner.line, corner.text + " needs " + shortDecimalText(leg) +
                                        " mm of each element; the controller shortens it then, which cyclecert does not model");
  }
  const Point corner0 = a.to;
  Segment between;
  between.sourceLine = corner.line;
  between.from = corner0 - leg * da;
  between.to = corner0 + leg * db;
  if (corner.kind == CornerKind::Rounding) {
    const bool left = cross(da, db) > 0;  // a turn to the left (counter-clockwise, Z right, X up)
    const Point normal = left ? Point{-da.x, da.z} : Point{da.x, -da.z};
    between.kind = left ? SegmentKind::ArcCCW : SegmentKind::ArcCW;
    between.center = between.from + corner.value * normal;
  }
  a.to = between.from;
  b.from = between.to;
  return between;
}

}  // namespace cyclecert
