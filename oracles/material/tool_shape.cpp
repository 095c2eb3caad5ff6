#include "oracles/material/tool_shape.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

// Boost's convex hull (graham_andrew, 1.74) step by step on buffers kept between calls, with its own
// predicates (geometry::less and greater, side_by_triangle): the same hull, point for point, as
// bg::convex_hull — the unions after it see the same rings — without its containers' allocations
// per chord (a sweep takes one hull per chord).
struct HullBuffers {
  std::vector<BgPoint> lower, upper, lowerHull, upperHull;
};

using Side = bg::strategy::side::side_by_triangle<>;

// Graham–Andrew's half hull from `left` through `points` (sorted) to `right`: a point turning
// the wrong way (factor·side ≤ 0) drops the one before it.
void buildHalfHull(int factor, const std::vector<BgPoint>& points, std::vector<BgPoint>& hull, const BgPoint& left,
                   const BgPoint& right) {
  hull.clear();
  hull.push_back(left);
  const auto add = [&](const BgPoint& p) {
    hull.push_back(p);
    while (hull.size() >= 3) {
      const std::size_t n = hull.size();
      if (factor * Side::apply(hull[n - 3], hull[n - 1], hull[n - 2]) > 0) return;
      hull[n - 2] = hull[n - 1];
      hull.pop_back();
    }
  };
  for (const BgPoint& p : points) add(p);
  add(right);
}

}  // namespace

BgRegion convexHullOf(const std::vector<Point>& points) {
  thread_local HullBuffers b;
  BgRegion out;
  if (points.empty()) return out;
  // The extremes: the first least and the first greatest point (x, then y).
  const bg::less<BgPoint> less;
  const bg::greater<BgPoint> greater;
  BgPoint left = toBg(points.front()), right = left;
  for (std::size_t k = 1; k < points.size(); ++k) {
    const BgPoint p = toBg(points[k]);
    if (less(p, left)) left = p;
    if (greater(p, right)) right = p;
  }
  // The points left of the line left → right make the upper half, those right of it the lower;
  // those on it are on no hull.
  b.lower.clear();
  b.upper.clear();
  for (Point q : points) {
    const BgPoint p = toBg(q);
    const int side = Side::apply(left, right, p);
    if (side == 1) b.upper.push_back(p);
    if (side == -1) b.lower.push_back(p);
  }
  std::sort(b.lower.begin(), b.lower.end(), less);
  std::sort(b.upper.begin(), b.upper.end(), less);
  buildHalfHull(-1, b.lower, b.lowerHull, left, right);
  buildHalfHull(1, b.upper, b.upperHull, left, right);
  // Clockwise and closed: the upper half from left to right, then the lower back to left.
  BgPolygon hull;
  auto& ring = hull.outer();
  ring.reserve(b.upperHull.size() + b.lowerHull.size());
  ring.assign(b.upperHull.begin(), b.upperHull.end());
  ring.insert(ring.end(), std::next(b.lowerHull.rbegin()), b.lowerHull.rend());
  if (b.upperHull.size() + b.lowerHull.size() - 1 < 4) ring.push_back(ring.front());
  if (bg::area(hull) != 0) out.push_back(std::move(hull));
  bg::correct(out);
  return out;
}

namespace {

// `swept` := swept ∪ piece (the pieces of a sweep, in order along the move).
void uniteWith(BgRegion& swept, BgRegion piece) {
  if (swept.empty()) {
    swept = std::move(piece);
  } else if (!piece.empty()) {
    BgRegion merged;
    bg::union_(swept, piece, merged);
    swept = std::move(merged);
  }
}

double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }
int signOf(double v) { return (v > 0) - (v < 0); }

// Where a direction d lies against the parallelogram spanned by A and B: the signs of α and β in
// d = α·A + β·B. Both non-zero: d lies in one of the four open cones between ±A and ±B.
struct Cone {
  int alpha = 0, beta = 0;
  bool open() const { return alpha != 0 && beta != 0; }
  friend bool operator==(const Cone&, const Cone&) = default;
};

Cone coneOf(Point d, Point a, Point b) {
  const int det = signOf(cross(a, b));
  return {signOf(cross(d, b)) * det, signOf(cross(a, d)) * det};
}

// The parallelogram spanned by A and B swept along chords[first] … chords[last], every chord's
// direction in the open cone c: along such a run no side's extreme corner changes, so the union of
// the chords' hulls is the chain moved by one side corner, the parallelogram at the run's end, the
// chain moved back by the other side corner and the parallelogram at its start — a simple polygon
// (in the frame of A and B the chain is monotone in both coordinates and the two sides are graphs
// over it), with no boolean.
BgRegion parallelogramAlongRun(const std::vector<Point>& chords, std::size_t first, std::size_t last, Point a, Point b,
                               Cone c) {
  const auto corner = [&](int i, int j) { return static_cast<double>(i) * a + static_cast<double>(j) * b; };
  const int i0 = c.alpha < 0 ? 1 : 0, j0 = c.beta < 0 ? 1 : 0;  // the corner that leads backwards
  const Point start = corner(i0, j0), end = corner(1 - i0, 1 - j0);
  const Point side = corner(1 - i0, j0), otherSide = corner(i0, 1 - j0);
  std::vector<Point> outline;
  outline.reserve(2 * (last - first + 1) + 2);
  outline.push_back(chords[first] + start);
  for (std::size_t k = first; k <= last; ++k) outline.push_back(chords[k] + side);
  outline.push_back(chords[last] + end);
  for (std::size_t k = last + 1; k-- > first;) outline.push_back(chords[k] + otherSide);
  return regionFromSimpleOutline(outline);
}

}  // namespace

// A vertex of the shape's own hull lies on the hull of its copies at from and to only where one of
// its two edges' outward normals n faces back (n·d ≤ 0, d = to − from: the copy at from) or forwards
// (n·d ≥ 0: the copy at to) — a normal between them would, and they span its normal cone. The rest
// (a disc's far half, the shape's inside) only cost the hull its sorting and side tests.
SweptShape::SweptShape(std::vector<Point> points) : points_(std::move(points)) {
  const BgRegion hull = convexHullOf(points_);
  if (hull.empty()) return;  // no area: every point is a candidate
  std::vector<Point> ring;
  for (const BgPoint& p : hull.front().outer()) ring.push_back(fromBg(p));
  ring.pop_back();  // the closing repetition
  Point centre{0, 0};
  for (Point p : ring) centre = centre + p;
  centre = (1.0 / static_cast<double>(ring.size())) * centre;
  const std::size_t n = ring.size();
  std::vector<Point> normals(n);  // of the edge from ring[k] to ring[k + 1], outwards
  for (std::size_t k = 0; k < n; ++k) {
    const Point a = ring[k], b = ring[(k + 1) % n];
    Point normal{b.x - a.x, a.z - b.z};
    if (dot(normal, 0.5 * (a + b) - centre) < 0) normal = -1.0 * normal;
    normals[k] = normal;
  }
  std::vector<std::size_t> byPoint(n);
  for (std::size_t k = 0; k < n; ++k) byPoint[k] = k;
  const auto less = [](Point a, Point b) { return a.z < b.z || (a.z == b.z && a.x < b.x); };
  std::sort(byPoint.begin(), byPoint.end(), [&](std::size_t a, std::size_t b) { return less(ring[a], ring[b]); });
  edges_.assign(points_.size(), std::nullopt);
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const auto it = std::lower_bound(byPoint.begin(), byPoint.end(), points_[i],
                                     [&](std::size_t k, Point p) { return less(ring[k], p); });
    if (it == byPoint.end() || !(ring[*it] == points_[i])) continue;  // not a vertex of the hull
    edges_[i] = std::pair{normals[(*it + n - 1) % n], normals[*it]};
  }
}

void SweptShape::along(Point from, Point to, std::vector<Point>& out) const {
  out.clear();
  const Point d = to - from;
  // Within a relative 1e-9 of facing sideways, a vertex counts as facing both ways.
  const auto faces = [&](Point normal, double sign) {
    return sign * dot(normal, d) >= -1e-9 * std::sqrt(dot(normal, normal) * dot(d, d));
  };
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (edges_.empty()) {
      out.push_back(from + points_[i]);
      out.push_back(to + points_[i]);
      continue;
    }
    if (!edges_[i]) continue;
    const auto [before, after] = *edges_[i];
    if (faces(before, -1) || faces(after, -1)) out.push_back(from + points_[i]);
    if (faces(before, 1) || faces(after, 1)) out.push_back(to + points_[i]);
  }
}

namespace {

// The convex shape swept along the chord from → to: the hull of the shape at both ends (`points`:
// a buffer kept between chords).
BgRegion hullAlongChord(Point from, Point to, const SweptShape& shape, std::vector<Point>& points) {
  shape.along(from, to, points);
  return convexHullOf(points);
}

// The convex shape swept along the chain of chords: the union of its hulls along each chord.
BgRegion sweptAlongChords(const std::vector<Point>& chords, const SweptShape& shape) {
  BgRegion swept;
  std::vector<Point> points;
  for (std::size_t k = 0; k + 1 < chords.size(); ++k) {
    uniteWith(swept, hullAlongChord(chords[k], chords[k + 1], shape, points));
  }
  tidy(swept);
  return swept;
}

}  // namespace

BgRegion sweptConvexShape(const Segment& move, const SweptShape& shape, double chordTolerance) {
  return sweptAlongChords(flatten(move, chordTolerance), shape);
}

BgRegion sweptConvexShape(const Segment& move, const std::vector<Point>& shape, double chordTolerance) {
  return sweptConvexShape(move, SweptShape(shape), chordTolerance);
}

BgRegion sweptRegion(const Segment& move, Point da, double a, Point db, double b, double chordTolerance) {
  const Point sideA = a * da, sideB = b * db;
  const SweptShape shape({{0, 0}, sideA, sideA + sideB, sideB});
  const std::vector<Point> chords = flatten(move, chordTolerance);
  // One chord (a line): its hull, no union to spare. A segment (a or b zero) has no open cones.
  if (chords.size() <= 2 || !(a > 0 && b > 0)) return sweptAlongChords(chords, shape);
  // An arc's chords: each run in one open cone swept at once; a chord along a side, by its hull.
  BgRegion swept;
  std::vector<Point> points;
  for (std::size_t k = 0; k + 1 < chords.size();) {
    const Cone c = coneOf(chords[k + 1] - chords[k], sideA, sideB);
    std::size_t last = k + 1;
    if (!c.open()) {
      uniteWith(swept, hullAlongChord(chords[k], chords[last], shape, points));
    } else {
      while (last + 1 < chords.size() && coneOf(chords[last + 1] - chords[last], sideA, sideB) == c) ++last;
      uniteWith(swept, parallelogramAlongRun(chords, k, last, sideA, sideB, c));
    }
    k = last;
  }
  tidy(swept);
  return swept;
}

namespace {

using Box = bg::model::box<BgPoint>;

// Whether `result` lies within `region`'s envelope (within 1e-6 of its size, as checkedIntersection).
bool withinTheEnvelopeOf(const BgRegion& result, const BgRegion& region) {
  const Box inner = bg::return_envelope<Box>(result), outer = bg::return_envelope<Box>(region);
  const double size = std::max(outer.max_corner().x() - outer.min_corner().x(), outer.max_corner().y() - outer.min_corner().y());
  const double slack = 1e-6 * std::max(1.0, size);
  return inner.min_corner().x() >= outer.min_corner().x() - slack && inner.min_corner().y() >= outer.min_corner().y() - slack &&
         inner.max_corner().x() <= outer.max_corner().x() + slack && inner.max_corner().y() <= outer.max_corner().y() + slack;
}

// A result of a ∩ b that lies within both operands' envelopes and is no larger than either.
bool consistentWith(const BgRegion& result, const BgRegion& a, const BgRegion& b) {
  return result.empty() || (withinTheEnvelopeOf(result, a) && withinTheEnvelopeOf(result, b) &&
                            bg::area(result) <= std::min(bg::area(a), bg::area(b)) * (1 + 1e-9) + 1e-12);
}

BgRegion translated(const BgRegion& region, double dx, double dy) {
  BgRegion out = region;
  for (BgPolygon& p : out) {
    for (BgPoint& q : p.outer()) q = BgPoint(q.x() + dx, q.y() + dy);
    for (auto& hole : p.inners()) {
      for (BgPoint& q : hole) q = BgPoint(q.x() + dx, q.y() + dy);
    }
  }
  return out;
}

}  // namespace

BgRegion consistentIntersection(const BgRegion& a, const BgRegion& b) {
  BgRegion first = checkedIntersection(a, b);
  // checkedIntersection's answer (by its first route, or by the one it falls back on unchecked) is kept
  // when it lies within both envelopes.
  if (first.empty() || (withinTheEnvelopeOf(first, a) && withinTheEnvelopeOf(first, b))) return first;
  const Box box = bg::return_envelope<Box>(b);
  const double size = std::max({1.0, box.max_corner().x() - box.min_corner().x(), box.max_corner().y() - box.min_corner().y()});
  for (double step : {1e-7, 1e-6, 1e-5}) {
    for (const auto& [dx, dy] : {std::pair{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}}) {
      const BgRegion nudged = translated(b, step * size * dx, step * size * dy);
      BgRegion again = checkedIntersection(a, nudged);
      if (consistentWith(again, a, nudged)) return again;
    }
  }
  return first;
}

double thickestRing(const BgRegion& region) {
  double thickest = 0;
  for (const BgPolygon& p : region) {
    const double perimeter = bg::perimeter(p);
    if (perimeter > 0) thickest = std::max(thickest, 2 * bg::area(p) / perimeter);
  }
  return thickest;
}

ToolCrossing sweptCrossing(const BgRegion& region, const BgRegion& swept, double epsilon) {
  ToolCrossing out;
  BgRegion crossed = consistentIntersection(swept, region);
  BgRegion thick;
  for (BgPolygon& p : crossed) {
    BgRegion one{p};
    if (thickestRing(one) > epsilon) thick.push_back(std::move(p));
  }
  if (thick.empty()) return out;
  out.amount = bg::area(thick);
  out.thickness = thickestRing(thick);
  out.crossed = std::move(thick);
  return out;
}

ToolCrossing toolCrossing(const BgRegion& region, const Segment& move, const ToolShape& tool, const BladeFrame& blade,
                          double epsilon, double chordTolerance) {
  ToolCrossing out;
  if (region.empty()) return out;
  if (tool.isPoint()) {
    const Crossing c = crossingOf(region, move, epsilon, chordTolerance);
    out.amount = out.thickness = c.length;
    out.pieces = c.pieces;
    return out;
  }
  return sweptCrossing(region, sweptRegion(move, blade.across, tool.width, blade.back, blade.length, chordTolerance),
                       epsilon);
}

}  // namespace cyclecert
