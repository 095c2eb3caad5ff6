#include "reference/model/geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace cyclecert {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;

double angleOf(Point p, Point center) { return std::atan2(p.x - center.x, p.z - center.z); }

// sweep() of an arc whose end angles `a0` (from) and `a1` (to) are known: ArcAngles has the start's
// already (each angle is an atan2, a hot spot of the planners and the material replay).
double sweepFromAngles(const Segment& s, double a0, double a1) {
  // A closed arc (from == to) is a full circle.
  const bool full = nearlyEqual(s.from, s.to);
  if (s.kind == SegmentKind::ArcCCW) {
    const double d = normalizedAngle(a1 - a0);
    return (full || d == 0) ? kTwoPi : d;
  }
  const double d = normalizedAngle(a0 - a1);
  return -((full || d == 0) ? kTwoPi : d);
}

}  // namespace

double normalizedAngle(double a) {
  // std::fmod returns an `a` within ±2π unchanged (it is exact: a − n·2π with n = 0), and most
  // angles here are differences of two atan2 results, within ±2π: fmod is left for the others.
  if (!(std::abs(a) < kTwoPi)) a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

ArcAngles::ArcAngles(const Segment& arc)
    : start(angleOf(arc.from, arc.center)),
      sweep(arc.isArc() ? sweepFromAngles(arc, start, angleOf(arc.to, arc.center)) : 0) {}

std::optional<double> offsetAlongArc(const Segment& s, double a) { return offsetAlongArc(ArcAngles(s), a); }

std::optional<double> offsetAlongArc(const ArcAngles& arc, double a) {
  const double span = std::abs(arc.sweep);
  double off = arc.sweep > 0 ? normalizedAngle(a - arc.start) : normalizedAngle(arc.start - a);
  const double angularTol = 1e-9;
  if (off > kTwoPi - angularTol) off = 0;  // just before the start counts as the start
  if (off <= span + angularTol) return std::min(off, span);
  return std::nullopt;
}

// Coordinates are millimetres: no overflow for std::hypot to guard against, and it is slow.
double distance(Point a, Point b) { return std::sqrt((a.z - b.z) * (a.z - b.z) + (a.x - b.x) * (a.x - b.x)); }
bool nearlyEqual(Point a, Point b, double tol) {
  return std::abs(a.z - b.z) <= tol && std::abs(a.x - b.x) <= tol;
}

double Segment::radius() const { return isArc() ? distance(from, center) : 0.0; }

double Segment::length() const {
  return isArc() ? std::abs(sweep(*this)) * radius() : distance(from, to);
}

Segment Segment::shifted(Point by) const {
  Segment s = *this;
  s.from = from + by;
  s.to = to + by;
  s.center = center + by;
  return s;
}

SegmentKind reversedKind(SegmentKind k) {
  if (k == SegmentKind::ArcCW) return SegmentKind::ArcCCW;
  if (k == SegmentKind::ArcCCW) return SegmentKind::ArcCW;
  return k;
}

Segment Segment::reversed() const {
  Segment s = *this;
  std::swap(s.from, s.to);
  s.kind = reversedKind(kind);
  return s;
}

double sweep(const Segment& s) {
  if (!s.isArc()) return 0;
  return sweepFromAngles(s, angleOf(s.from, s.center), angleOf(s.to, s.center));
}

Point pointAt(const Segment& s, double t) {
  if (!s.isArc()) return s.from + t * (s.to - s.from);
  return pointAt(s, ArcAngles(s), t);
}

Point pointAt(const Segment& arc, const ArcAngles& angles, double t) {
  const double a = angles.start + t * angles.sweep;
  const double r = arc.radius();
  return {arc.center.z + r * std::cos(a), arc.center.x + r * std::sin(a)};
}

Segment transposed(const Segment& s) {
  Segment t = s;
  t.from = transposed(s.from);
  t.to = transposed(s.to);
  t.center = transposed(s.center);
  // Exchanging the axes mirrors the plane, so clockwise becomes counter-clockwise.
  t.kind = reversedKind(s.kind);
  return t;
}

std::vector<Point> intersectWithLevelX(const Segment& s, double level) {
  std::vector<Point> hits;
  if (!s.isArc()) {
    const double dx = s.to.x - s.from.x;
    if (std::abs(dx) <= kGeomEps) {
      if (std::abs(s.from.x - level) <= kGeomEps) hits = {s.from, s.to};
      return hits;
    }
    const double t = (level - s.from.x) / dx;
    if (t >= -kGeomEps && t <= 1 + kGeomEps) {
      const double tc = std::clamp(t, 0.0, 1.0);
      hits.push_back({s.from.z + tc * (s.to.z - s.from.z), level});
    }
    return hits;
  }
  const double r = s.radius();
  const double dx = level - s.center.x;
  if (std::abs(dx) > r + kGeomEps) return hits;
  const double h = std::sqrt(std::max(0.0, r * r - dx * dx));
  // At most two points, ordered along the arc in place (no vector: a hot spot of the planners).
  std::array<std::pair<double, Point>, 2> ordered;
  std::size_t count = 0;
  const ArcAngles angles(s);
  for (double sign : {-1.0, 1.0}) {
    const Point p{s.center.z + sign * h, level};
    if (auto off = offsetAlongArc(angles, angleOf(p, s.center))) ordered[count++] = {*off, p};
  }
  if (count == 2 && ordered[1].first < ordered[0].first) std::swap(ordered[0], ordered[1]);
  hits.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const Point p = ordered[k].second;
    if (hits.empty() || !nearlyEqual(hits.back(), p, 1e-12)) hits.push_back(p);
  }
  return hits;
}

namespace {

// Calls `f(offset along the arc, point)` for each apex strictly inside the arc, in the order of
// their angles (0, π/2, π, 3π/2): apexesAlong sorts them, extent needs no order (nor the two
// vectors apexesAlong returns through; extent is a hot spot of the planners).
template <class F>
void forEachApex(const Segment& arc, F&& f) {
  const double r = arc.radius();
  const ArcAngles angles(arc);
  for (int k = 0; k < 4; ++k) {
    const double a = k * std::numbers::pi / 2;
    if (auto off = offsetAlongArc(angles, a); off && *off > 0 && *off < std::abs(angles.sweep)) {
      f(*off, Point{arc.center.z + r * std::cos(a), arc.center.x + r * std::sin(a)});
    }
  }
}

}  // namespace

std::vector<Point> apexesAlong(const Segment& s) {
  std::vector<std::pair<double, Point>> found;
  if (!s.isArc()) return {};
  forEachApex(s, [&found](double off, Point p) { found.push_back({off, p}); });
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<Point> points;
  for (const auto& f : found) points.push_back(f.second);
  return points;
}

Extent extent(const Segment& s) {
  Extent e{std::min(s.from.z, s.to.z), std::max(s.from.z, s.to.z), std::min(s.from.x, s.to.x),
           std::max(s.from.x, s.to.x)};
  if (!s.isArc()) return e;
  forEachApex(s, [&e](double, Point p) {
    e.zMin = std::min(e.zMin, p.z);
    e.zMax = std::max(e.zMax, p.z);
    e.xMin = std::min(e.xMin, p.x);
    e.xMax = std::max(e.xMax, p.x);
  });
  return e;
}

Extent enclosingExtent(const Segment& s) {
  Extent e{std::min(s.from.z, s.to.z), std::max(s.from.z, s.to.z), std::min(s.from.x, s.to.x),
           std::max(s.from.x, s.to.x)};
  if (!s.isArc()) return e;
  const double r = s.radius();
  e.zMin = std::min(e.zMin, s.center.z - r);
  e.zMax = std::max(e.zMax, s.center.z + r);
  e.xMin = std::min(e.xMin, s.center.x - r);
  e.xMax = std::max(e.xMax, s.center.x + r);
  return e;
}

std::optional<Point> arcCenterFromRadius(Point from, Point to, double r, SegmentKind dir) {
  const double chord = distance(from, to);
  if (chord <= kGeomEps || !std::isfinite(r) || std::abs(r) * 2 < chord - 1e-6) return std::nullopt;
  const double half = chord / 2;
  const double h = std::sqrt(std::max(0.0, r * r - half * half));
  const Point mid = 0.5 * (from + to);
  const Point unit = (1.0 / chord) * (to - from);
  const Point right{unit.x, -unit.z};  // direction rotated by −90° (to the right of travel)
  // A clockwise arc of at most 180° has its centre to the right of the chord; R < 0 asks for the
  // larger arc, whose centre is on the other side.
  double side = dir == SegmentKind::ArcCW ? 1.0 : -1.0;
  if (r < 0) side = -side;
  return mid + (side * h) * right;
}

}  // namespace cyclecert
