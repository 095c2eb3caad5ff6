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
// along it: each allowance towards where the stock lies in its axis (0 along an axis it faces
// across, e.g. FALZ on a diameter).
Point cornerTowardsStock(const Segment& piece, Point allowance) {
  const Point n = stockNormalAt(piece, pointAt(piece, 0.5));
  return {allowance.z * signWithin(n.z), allowance.x * signWithin(n.x)};
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

// Where the carriers of two pieces (a line's infinite line, an arc's full circle) cross.
std::vector<Point> lineCircle(Point a, Point d, Point c, double r) {
  const Point f = a - c;
  const double A = dot(d, d), B = 2 * dot(f, d), C = dot(f, f) - r * r;
  const double disc = B * B - 4 * A * C;
  if (A <= 0 || disc < -1e-12) return {};
  const double root = std::sqrt(std::max(0.0, disc));
  return {a + ((-B - root) / (2 * A)) * d, a + ((-B + root) / (2 * A)) * d};
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
    startBeforeTheFace(pieces.front());
    bool onTheFace = true;  // the walls the contour begins with at its first point's z are the face's
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      onTheFace = onTheFace && isWallAt(pieces[i], pieces.front().from.z);
      append(pieces[i], onTheFace ? allowance_ : cornerTowardsStock(pieces[i], allowance_),
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
  // The part's face below the contour's first point, a wall rising to it (stock towards +z): moved
  // by FALZ, it is where the profile begins when the first element's own corner lies elsewhere.
  void startBeforeTheFace(const Segment& first) {
    Segment face = lineBetween(first.from + Point{0, -1}, first.from, first.sourceLine);
    last_ = face;
    lastShift_ = allowance_;
    grown_.clear();
    faceEnd_ = first.from + lastShift_;
  }

  static bool isWallAt(const Segment& s, double z) {
    return !s.isArc() && std::abs(s.from.z - z) <= kGeomEps && std::abs(s.to.z - z) <= kGeomEps;
  }

  void append(const Segment& piece, Point shift, int index) {
    Segment next = piece.shifted(shift);
    const Point corner = piece.from;
    const Point p = grown_.empty() ? faceEnd_ : grown_.back().to;
    const Point q = next.from;
    if (distance(p, q) > kGeomEps) {
      const Point turn = tangentAt(last_, last_.to) + tangentAt(piece, piece.from);
      if (dot(q - p, turn) > 0) {
        closeGap(p, q, corner, piece, shift);
      } else if (!grown_.empty()) {
        trimOverlap(grown_.back(), next, index);
      } else {
        // The first element's corner lies behind the face: it begins where it crosses the face.
        next.from = q;
      }
    }
    grown_.push_back(next);
    last_ = piece;
    lastShift_ = shift;
  }

  // A convex corner: along the rectangle from one corner to the other, through the corner
  // between them on the stock side when both axes change.
  void closeGap(Point p, Point q, Point corner, const Segment& piece, Point shift) {
    if (std::abs(q.z - p.z) > kGeomEps && std::abs(q.x - p.x) > kGeomEps) {
      const Point outward = stockNormalAt(last_, last_.to) + stockNormalAt(piece, piece.from);
      const Point viaA = corner + Point{shift.z, lastShift_.x};
      const Point viaB = corner + Point{lastShift_.z, shift.x};
      const Point via = dot(viaA - corner, outward) >= dot(viaB - corner, outward) ? viaA : viaB;
      if (!grown_.empty()) grown_.push_back(lineBetween(p, via, piece.sourceLine));  // else: the face
      grown_.push_back(lineBetween(via, q, piece.sourceLine));
      return;
    }
    const bool alongTheFace = grown_.empty() && std::abs(q.z - p.z) <= kGeomEps;
    if (!alongTheFace) grown_.push_back(lineBetween(p, q, piece.sourceLine));
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
  Segment last_;
  Point lastShift_;
  Point faceEnd_;
  std::vector<Segment> grown_;
};

}  // namespace

std::vector<Segment> withAxisAllowances(const std::vector<Segment>& profile, Point allowance) {
  if (allowance.z <= 0 && allowance.x <= 0) return profile;
  return AxisAllowanceBuilder(allowance).build(profile);
}

}  // namespace cyclecert
