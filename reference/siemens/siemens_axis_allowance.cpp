#include "reference/siemens/siemens_axis_allowance.h"

#include <cmath>
#include <optional>

#include "reference/model/offset.h"
#include "reference/siemens/siemens_roughing_undercut.h"

namespace cyclecert {

namespace {

double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }

Point unitOf(Point v) {
  const double n = std::hypot(v.z, v.x);
  return n > 0 ? Point{v.z / n, v.x / n} : Point{0, 0};
}

// The direction of travel at `p` on `s`.
Point tangentAt(const Segment& s, Point p) {
  if (!s.isArc()) return unitOf(s.to - s.from);
  const Point u = unitOf(p - s.center);
  return s.kind == SegmentKind::ArcCCW ? Point{-u.x, u.z} : Point{u.x, -u.z};
}

// The stock side's normal at `p` (the right of travel in the frame).
Point stockNormalAt(const Segment& s, Point p) { return sideNormal(tangentAt(s, p), CompensationSide::Right); }

int signWithin(double v) { return v > 1e-9 ? 1 : v < -1e-9 ? -1 : 0; }

// The rectangle's corner on the stock side of a piece whose stock-side normal keeps its signs
// along it: FALZ towards where the stock lies in z (none on a diameter, which faces across z); FALX
// always upwards — the part lies below its profile (the contour runs towards −z), so even a wall
// has stock above its top end, and the profile's last point, like every other, lies FALX higher.
Point cornerTowardsStock(const Segment& piece, Point allowance) {
  const Point n = stockNormalAt(piece, pointAt(piece, 0.5));
  return {allowance.z * signWithin(n.z), allowance.x};
}

// Each element split where its stock normal turns across an axis (an arc at its apexes).
std::vector<Segment> piecesOf(const std::vector<Segment>& profile) {
  std::vector<Segment> pieces;
  for (const Segment& s : profile) {
    if (hasNoLength(s)) continue;
    Point from = s.from;
    if (s.isArc()) {
      for (const Point& apex : apexesAlong(s)) {
        if (distance(apex, from) <= kGeomEps || distance(apex, s.to) <= kGeomEps) continue;
        pieces.push_back(portionOf(s, from, apex));
        from = apex;
      }
    }
    pieces.push_back(portionOf(s, from, s.to));
  }
  return pieces;
}

// Where the carriers of two pieces (a line's infinite line, an arc's full circle) cross. A line
// touching a circle (a rounding tangent to the line before it) crosses it once, at the foot of the
// centre: the tangency is decided on lengths in mm (kGeomEps), so it holds at every scale of the part.
std::vector<Point> lineCircle(Point a, Point d, Point c, double r) {
  const double A = dot(d, d);
  if (A <= 0) return {};
  const Point foot = a + (dot(c - a, d) / A) * d;
  const double offCentre = distance(foot, c);
  if (offCentre > r + kGeomEps) return {};
  const double halfChord = std::sqrt(std::max(0.0, r * r - offCentre * offCentre));
  const Point u = (1 / std::sqrt(A)) * d;
  return {foot + (-halfChord) * u, foot + halfChord * u};
}

std::vector<Point> carrierCrossings(const Segment& p, const Segment& q) {
  if (!p.isArc() && !q.isArc()) {
    const Point d1 = p.to - p.from, d2 = q.to - q.from;
    const double den = cross(d1, d2);
    if (std::abs(den) <= 1e-15) return {};
    return {p.from + (cross(q.from - p.from, d2) / den) * d1};
  }
  if (!p.isArc()) return lineCircle(p.from, p.to - p.from, q.center, q.radius());
  if (!q.isArc()) return lineCircle(q.from, q.to - q.from, p.center, p.radius());
  const double r1 = p.radius(), r2 = q.radius();
  const double d = distance(p.center, q.center);
  if (d <= 1e-12 || d > r1 + r2 + 1e-9 || d < std::abs(r1 - r2) - 1e-9) return {};
  const double along = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - along * along));
  const Point u = unitOf(q.center - p.center);
  const Point mid = p.center + along * u;
  const Point perp{-u.x, u.z};
  return {mid + h * perp, mid + (-h) * perp};
}

// Whether `x` lies on the piece `s` (on its carrier) between its ends.
bool liesOn(const Segment& s, Point x) {
  if (!s.isArc()) {
    const Point d = s.to - s.from;
    const double t = dot(x - s.from, d) / dot(d, d);
    return t >= -1e-9 && t <= 1 + 1e-9;
  }
  return offsetAlongArc(s, std::atan2(x.x - s.center.x, x.z - s.center.z)).has_value();
}

Segment lineBetween(Point a, Point b, int sourceLine) {
  Segment s;
  s.from = a;
  s.to = b;
  s.sourceLine = sourceLine;
  return s;
}

// Whether the line `next` goes on straight from the line `s` (a connector along an element's own
// line): one element, as the contour had it.
bool continuesInLine(const Segment& s, const Segment& next) {
  if (s.isArc() || next.isArc()) return false;
  const Point a = unitOf(s.to - s.from), b = unitOf(next.to - next.from);
  return std::abs(cross(a, b)) <= 1e-12 && dot(a, b) > 0;
}

class AxisAllowanceBuilder {
 public:
  explicit AxisAllowanceBuilder(Point allowance) : allowance_(allowance) {}

  std::vector<Segment> build(const std::vector<Segment>& profile) {
    const std::vector<Segment> pieces = piecesOf(profile);
    if (pieces.empty()) return profile;
    // The part's face below the contour's first point, a wall rising to it (stock towards +z): its
    // top moved by the rectangle's corner (+FALZ, +FALX) is where the profile begins.
    faceTop_ = pieces.front().from + allowance_;
    bool onTheFace = true;  // the walls the contour begins with at its first point's z are the face's
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      onTheFace = onTheFace && isWallAt(pieces[i], pieces.front().from.z);
      append(pieces[i].shifted(onTheFace ? allowance_ : cornerTowardsStock(pieces[i], allowance_)),
             static_cast<int>(i));
    }
    std::vector<Segment> out;
    for (Segment s : grown_) {
      if (hasNoLength(s)) continue;
      if (!out.empty()) s.from = out.back().to;
      if (!out.empty() && continuesInLine(out.back(), s)) {
        out.back().to = s.to;
        continue;
      }
      out.push_back(s);
    }
    return out;
  }

 private:
  static bool isWallAt(const Segment& s, double z) {
    return !s.isArc() && std::abs(s.from.z - z) <= kGeomEps && std::abs(s.to.z - z) <= kGeomEps;
  }

  // Every moved piece keeps its ends' heights + FALX, so where two meet their moved ends differ in z
  // only: a convex corner (the later piece moved less far towards +z) leaves a gap, closed along the
  // rectangle's top edge; a concave one an overlap, trimmed.
  void append(Segment next, int index) {
    const Point p = grown_.empty() ? faceTop_ : grown_.back().to;
    const Point q = next.from;
    if (q.z < p.z - kGeomEps) {
      grown_.push_back(lineBetween(p, q, next.sourceLine));
    } else if (q.z > p.z + kGeomEps && !grown_.empty()) {
      trimOverlap(grown_.back(), next, index);
    }
    grown_.push_back(next);
  }

  // A concave corner: both pieces trimmed to their crossing nearest the corner.
  static void trimOverlap(Segment& before, Segment& after, int index) {
    const Point near = pointAt(lineBetween(before.to, after.from, 0), 0.5);
    std::optional<Point> best;
    for (const Point& x : carrierCrossings(before, after)) {
      if (!liesOn(before, x) || !liesOn(after, x)) continue;
      if (!best || distance(x, near) < distance(*best, near)) best = x;
    }
    if (!best) throw OffsetError(OffsetProblem::Interference, index, after.sourceLine);
    before.to = *best;
    after.from = *best;
  }

  Point allowance_;
  Point faceTop_;
  std::vector<Segment> grown_;
};

}  // namespace

std::vector<Segment> withAxisAllowances(const std::vector<Segment>& profile, Point allowance) {
  if (allowance.z <= 0 && allowance.x <= 0) return profile;
  return AxisAllowanceBuilder(allowance).build(profile);
}

}  // namespace cyclecert
