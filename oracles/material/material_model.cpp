#include "oracles/material/material_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

using Box = bg::model::box<BgPoint>;
using Interval = std::pair<double, double>;

constexpr double kTwoPi = 2 * std::numbers::pi;
constexpr double kShadowMargin = 1.0;  // mm: how far a model's shadows reach past the material

double normalizedAngle(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

// Narrows [t0, t1] to where alpha + beta·t lies in [lo, hi]; false when nothing is left.
bool clipLinear(double alpha, double beta, double lo, double hi, double& t0, double& t1) {
  if (beta == 0) return alpha >= lo && alpha <= hi;
  double ta = (lo - alpha) / beta, tb = (hi - alpha) / beta;
  if (ta > tb) std::swap(ta, tb);
  t0 = std::max(t0, ta);
  t1 = std::min(t1, tb);
  return t0 <= t1;
}

// The arc cut into sub-arcs at the points where its tangent is parallel to `away` (where it turns
// back along the cut axis), so that each sub-arc is a graph over the cut axis. Lines unchanged.
std::vector<Segment> splitWhereTangentIsAlong(const Segment& s, const DepthFrame& frame) {
  if (!s.isArc() || s.radius() <= kGeomEps) return {s};
  const double r = s.radius(), span = sweep(s);
  const double start = std::atan2(s.from.x - s.center.x, s.from.z - s.center.z);
  const double direction = span < 0 ? -1.0 : 1.0;
  // The tangent is parallel to `away` where the radius is perpendicular to it.
  const Point radial{frame.away().x, -frame.away().z};
  std::vector<double> offsets;  // angles from `start`, along the arc
  for (double sign : {-1.0, 1.0}) {
    const double angle = std::atan2(sign * radial.x, sign * radial.z);
    const double offset = normalizedAngle(direction * (angle - start));
    if (offset > 1e-12 && offset < std::abs(span) - 1e-12) offsets.push_back(offset);
  }
  std::sort(offsets.begin(), offsets.end());
  std::vector<Segment> pieces;
  Point from = s.from;
  for (double offset : offsets) {
    const double a = start + direction * offset;
    const Point at{s.center.z + r * std::cos(a), s.center.x + r * std::sin(a)};
    pieces.push_back({s.kind, from, at, s.center, s.sourceLine});
    from = at;
  }
  pieces.push_back({s.kind, from, s.to, s.center, s.sourceLine});
  return pieces;
}

// One piece of a move's shadow: a path that is a graph over the cut axis (a line, or a flattened
// sub-arc), and the region its rays sweep — the path, then the path moved by reach·away walked
// back.

struct ShadowPiece {
  std::vector<Point> path;
  double reach = 0;
  BgPolygon polygon;
};

std::optional<ShadowPiece> shadowOfGraph(std::vector<Point> path, const DepthFrame& frame,
                                         double reach, double sink) {
  if (std::abs(frame.cut(path.back()) - frame.cut(path.front())) <= kTidyDistance || !(reach > 0)) {
    return std::nullopt;  // a move along the depth axis sweeps no area
  }
  ShadowPiece piece;
  auto& ring = piece.polygon.outer();
  ring.reserve(2 * path.size() + 1);
  for (Point p : path) ring.push_back(toBg(p - sink * frame.away()));
  const Point shift = reach * frame.away();
  for (auto it = path.rbegin(); it != path.rend(); ++it) ring.push_back(toBg(*it + shift));
  bg::correct(piece.polygon);  // closes the ring and orients it clockwise
  piece.path = std::move(path);
  piece.reach = reach;
  return piece;
}

// The shadow's pieces, one per graph-shaped part of the move. Rays end `reach` beyond the move, or
// kShadowMargin beyond `farDepth` when that is nearer: past the material's far side there is
// nothing to remove, and shorter shadows keep small the envelope Boost's rescaling divides
// (region.h).
std::vector<ShadowPiece> shadowPieces(const Segment& move, const DepthFrame& frame, double reach,
                                      double chordTolerance,
                                      double farDepth = std::numeric_limits<double>::infinity(),
                                      double sink = 0) {
  std::vector<ShadowPiece> pieces;
  for (const Segment& part : splitWhereTangentIsAlong(move, frame)) {
    std::vector<Point> path = flatten(part, chordTolerance);
    double nearest = frame.depth(path.front());
    for (Point p : path) nearest = std::min(nearest, frame.depth(p));
    const double needed = std::min(reach, farDepth + kShadowMargin - nearest);
    if (auto piece = shadowOfGraph(std::move(path), frame, needed, sink)) {
      pieces.push_back(std::move(*piece));
    }
  }
  return pieces;
}

// Whether the shadow of a line a→b (a parallelogram) reaches more than kTidyDistance into the
// region: an edge of the region enters it, or it lies wholly inside the region. A cheap test that
// spares Boost's difference for the many feeds that cut only air (retracts, moves over ground
// already cut). In frame coordinates the parallelogram is c ∈ [ca, cb], 0 ≤ h ≤ reach with
// h = d − da − slope·(c − ca).
bool lineShadowMeets(Point a, Point b, const DepthFrame& frame, double reach,
                     const BgRegion& region) {
  double ca = frame.cut(a), da = frame.depth(a), cb = frame.cut(b), db = frame.depth(b);
  if (ca > cb) {
    std::swap(ca, cb);
    std::swap(da, db);
  }
  const double slope = (db - da) / (cb - ca);
  bool meets = false;
  auto edge = [&](const BgPoint& p, const BgPoint& q) {
    const double cp = frame.cut(fromBg(p)), dp = frame.depth(fromBg(p));
    const double cq = frame.cut(fromBg(q)), dq = frame.depth(fromBg(q));
    double t0 = 0, t1 = 1;
    meets = meets ||
            (clipLinear(cp, cq - cp, ca + kTidyDistance, cb - kTidyDistance, t0, t1) &&
             clipLinear(dp - da - slope * (cp - ca), (dq - dp) - slope * (cq - cp), kTidyDistance,
                        reach - kTidyDistance, t0, t1));
  };
  auto ringEdges = [&](const BgPolygon::ring_type& ring) {
    for (std::size_t i = 1; i < ring.size() && !meets; ++i) edge(ring[i - 1], ring[i]);
  };
  for (const BgPolygon& polygon : region) {
    ringEdges(polygon.outer());
    for (const auto& hole : polygon.inners()) ringEdges(hole);
  }
  if (meets) return true;
  // No edge enters: the parallelogram is wholly inside the region or wholly outside.
  return bg::within(toBg(0.5 * (a + b) + (reach / 2) * frame.away()), region);
}

BgRegion unionOf(const std::vector<BgPolygon>& polygons) {
  if (polygons.size() == 1) return {polygons.front()};
  BgRegion region;
  for (const BgPolygon& polygon : polygons) {
    BgRegion united;
    bg::union_(region, polygon, united);
    region = std::move(united);
  }
  tidy(region);
  return region;
}

// --- Crossing: where a chord a→b is more than ε inside a region -----------------------------

// A chord a → a + d of a move, with its bounding box.
struct Chord {
  Point a, d;
  double length, zMin, zMax, xMin, xMax;
  Chord(Point from, Point to)
      : a(from),
        d{to.z - from.z, to.x - from.x},
        length(std::sqrt(d.z * d.z + d.x * d.x)),
        zMin(std::min(from.z, to.z)),
        zMax(std::max(from.z, to.z)),
        xMin(std::min(from.x, to.x)),
        xMax(std::max(from.x, to.x)) {}
  Point at(double t) const { return {a.z + t * d.z, a.x + t * d.x}; }
};

// Where the chord (t ∈ [0, 1]) comes within ε of the edge p→q: where it meets the edge's capsule, a
// band of half-width ε along the edge and a disk at p (the disk at q comes with the next edge).
// Plain arithmetic: this runs for every edge of the material for every rapid.
void addNearIntervals(const Chord& chord, Point p, Point q, double epsilon,
                      std::vector<Interval>& near) {
  if (std::max(p.z, q.z) + epsilon < chord.zMin || std::min(p.z, q.z) - epsilon > chord.zMax ||
      std::max(p.x, q.x) + epsilon < chord.xMin || std::min(p.x, q.x) - epsilon > chord.xMax) {
    return;  // the capsule's box misses the chord's
  }
  const double rz = chord.a.z - p.z, rx = chord.a.x - p.x;
  const double dz = chord.d.z, dx = chord.d.x;
  // Disk of radius ε around p: |r + t·d|² ≤ ε².
  const double qa = dz * dz + dx * dx, qb = rz * dz + rx * dx;
  const double disc = qb * qb - qa * (rz * rz + rx * rx - epsilon * epsilon);
  if (disc >= 0) {
    const double root = std::sqrt(disc);
    const double t0 = std::max(0.0, (-qb - root) / qa), t1 = std::min(1.0, (-qb + root) / qa);
    if (t0 <= t1) near.push_back({t0, t1});
  }
  // Band along the edge: 0 ≤ s ≤ L and |h| ≤ ε in the edge's own coordinates (u along, n across).
  const double ez = q.z - p.z, ex = q.x - p.x;
  const double length = std::sqrt(ez * ez + ex * ex);
  if (length <= kGeomEps) return;
  const double uz = ez / length, ux = ex / length;
  double t0 = 0, t1 = 1;
  if (clipLinear(rz * uz + rx * ux, dz * uz + dx * ux, 0, length, t0, t1) &&
      clipLinear(rx * uz - rz * ux, dx * uz - dz * ux, -epsilon, epsilon, t0, t1)) {
    near.push_back({t0, t1});
  }
}

// The parts of [0, 1] no interval covers.
std::vector<Interval> gapsBetween(std::vector<Interval>& intervals) {
  std::sort(intervals.begin(), intervals.end());
  std::vector<Interval> gaps;
  double reached = 0;
  for (const Interval& i : intervals) {
    if (i.first > reached) gaps.push_back({reached, i.first});
    reached = std::max(reached, i.second);
  }
  if (reached < 1) gaps.push_back({reached, 1});
  return gaps;
}

template <typename Visit>
void forEachEdge(const BgRegion& region, Visit visit) {
  auto ringEdges = [&visit](const BgPolygon::ring_type& ring) {
    for (std::size_t i = 1; i < ring.size(); ++i) visit(fromBg(ring[i - 1]), fromBg(ring[i]));
  };
  for (const BgPolygon& polygon : region) {
    ringEdges(polygon.outer());
    for (const auto& hole : polygon.inners()) ringEdges(hole);
  }
}

// A chord's pieces deeper than ε inside the region. Away from every edge's ε-capsule the chord
// cannot cross the boundary, so each gap between the near intervals lies wholly inside or wholly
// outside: its midpoint decides.
void addChordCrossing(const BgRegion& region, const Box& envelope, const Chord& chord,
                      double epsilon, std::vector<Interval>& near, Crossing& crossing) {
  if (chord.length <= kGeomEps) return;
  const Box chordBox{{chord.zMin, chord.xMin}, {chord.zMax, chord.xMax}};
  if (bg::disjoint(chordBox, envelope)) return;
  near.clear();
  forEachEdge(region, [&](Point p, Point q) { addNearIntervals(chord, p, q, epsilon, near); });
  for (const Interval& gap : gapsBetween(near)) {
    if (bg::within(toBg(chord.at(0.5 * (gap.first + gap.second))), region)) {
      const Segment piece{SegmentKind::Line, chord.at(gap.first), chord.at(gap.second), {}, 0};
      crossing.pieces.push_back(piece);
      crossing.length += (gap.second - gap.first) * chord.length;
    }
  }
}

Crossing crossingWithin(const BgRegion& region, const Box& envelope, const Segment& move,
                        double epsilon, double chordTolerance) {
  Crossing crossing;
  if (region.empty()) return crossing;
  epsilon = std::max(epsilon, kTidyDistance);
  const std::vector<Point> points = flatten(move, chordTolerance);
  std::vector<Interval> near;
  for (std::size_t i = 1; i < points.size(); ++i) {
    addChordCrossing(region, envelope, Chord(points[i - 1], points[i]), epsilon, near, crossing);
  }
  return crossing;
}

Box envelopeOf(const BgRegion& region) {
  Box box;
  if (region.empty()) {
    bg::assign_inverse(box);  // intersects nothing
  } else {
    bg::envelope(region, box);
  }
  return box;
}

}  // namespace

BgRegion shadowOf(const Segment& move, Point away, double reach, double chordTolerance) {
  std::vector<BgPolygon> polygons;
  for (ShadowPiece& piece : shadowPieces(move, DepthFrame(away), reach, chordTolerance)) {
    polygons.push_back(std::move(piece.polygon));
  }
  return unionOf(polygons);
}

Crossing crossingOf(const BgRegion& region, const Segment& move, double epsilon,
                    double chordTolerance) {
  return crossingWithin(region, envelopeOf(region), move, epsilon, chordTolerance);
}

MaterialModel::MaterialModel(BgRegion stock, Point away, double reach, double chordTolerance)
    : remaining_(std::move(stock)), frame_(away), reach_(reach), chordTolerance_(chordTolerance) {
  if (!(reach > 0) || !(chordTolerance > 0)) {
    throw std::invalid_argument("the material model needs a positive reach and chord tolerance");
  }
  updateEnvelope();
}

void MaterialModel::updateEnvelope() { envelope_ = envelopeOf(remaining_); }

double MaterialModel::farDepth() const {
  if (remaining_.empty()) return -std::numeric_limits<double>::infinity();
  const BgPoint lo = envelope_.min_corner(), hi = envelope_.max_corner();
  return std::max({frame_.depth({lo.x(), lo.y()}), frame_.depth({lo.x(), hi.y()}),
                   frame_.depth({hi.x(), lo.y()}), frame_.depth({hi.x(), hi.y()})});
}

namespace {

// Cheap tests before a boolean: a shadow whose box misses the material's, or a line's shadow that
// meets no material, removes nothing.
bool meetsMaterial(const ShadowPiece& shadow, const bg::model::box<BgPoint>& envelope, const DepthFrame& frame,
                   const BgRegion& remaining) {
  if (bg::disjoint(bg::return_envelope<bg::model::box<BgPoint>>(shadow.polygon), envelope)) return false;
  return shadow.path.size() != 2 || lineShadowMeets(shadow.path[0], shadow.path[1], frame, shadow.reach, remaining);
}

}  // namespace

namespace {

// Whether every point of `polygon` lies in the shadow of the line a→b (a parallelogram: convex, so
// its vertices decide), within `tolerance`.
bool insideLineShadow(const BgPolygon& polygon, Point a, Point b, const DepthFrame& frame, double reach,
                      double tolerance) {
  double ca = frame.cut(a), da = frame.depth(a), cb = frame.cut(b), db = frame.depth(b);
  if (ca > cb) {
    std::swap(ca, cb);
    std::swap(da, db);
  }
  const double slope = (db - da) / (cb - ca);
  for (const BgPoint& v : polygon.outer()) {
    const double c = frame.cut(fromBg(v)), h = frame.depth(fromBg(v)) - da - slope * (c - ca);
    if (c < ca - tolerance || c > cb + tolerance || h < -tolerance || h > reach + tolerance) return false;
  }
  return true;
}

}  // namespace

void MaterialModel::apply(const Segment& move, MoveKind kind) {
  if (kind != MoveKind::Feed || remaining_.empty()) return;
  bool changed = false;
  for (const ShadowPiece& shadow : shadowPieces(move, frame_, reach_, chordTolerance_, farDepth(), kShadowSink)) {
    if (!meetsMaterial(shadow, envelope_, frame_, remaining_)) continue;  // cheap tests first: a shadow in air removes nothing
    BgRegion rest;
    bg::difference(remaining_, shadow.polygon, rest);
    Box operands = envelope_;
    bg::expand(operands, bg::return_envelope<Box>(shadow.polygon));
    const double size = std::max(operands.max_corner().x() - operands.min_corner().x(),
                                 operands.max_corner().y() - operands.min_corner().y());
    tidy(rest, size);
    const double resolution = std::max(kDustWidth, kBooleanResolution * size);
    splitPinches(rest, resolution);
    // Boost keeps a piece whose edges lie, within its resolution, on the shadow's edge even when the
    // whole piece is inside the shadow (a step left by a pass, then the semi-finish along the
    // profile it rests on): such a piece is cut material.
    if (shadow.path.size() == 2) {
      rest.erase(std::remove_if(rest.begin(), rest.end(),
                                [&](const BgPolygon& piece) {
                                  return insideLineShadow(piece, shadow.path[0], shadow.path[1], frame_, shadow.reach,
                                                          resolution);
                                }),
                 rest.end());
    }
    remaining_ = std::move(rest);
    changed = true;
  }
  if (changed) updateEnvelope();
}

double MaterialModel::area() const { return bg::area(remaining_); }

Crossing MaterialModel::crossing(const Segment& move, double epsilon) const {
  return crossingWithin(remaining_, envelope_, move, epsilon, chordTolerance_);
}

BgRegion MaterialModel::removedBy(const Segment& move) const {
  if (remaining_.empty()) return {};
  std::vector<BgPolygon> parts;
  for (const ShadowPiece& shadow : shadowPieces(move, frame_, reach_, chordTolerance_, farDepth(), kShadowSink)) {
    if (!meetsMaterial(shadow, envelope_, frame_, remaining_)) continue;
    for (BgPolygon& p : checkedIntersection(remaining_, {shadow.polygon})) parts.push_back(std::move(p));
  }
  BgRegion removed = unionOf(parts);
  tidy(removed);
  return removed;
}

}  // namespace cyclecert
