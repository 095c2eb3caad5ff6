#include "oracles/material/material_model.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <utility>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/thickness.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

using Box = bg::model::box<BgPoint>;
using Interval = std::pair<double, double>;

constexpr double kShadowMargin = 1.0;  // mm: how far a model's shadows reach past the material

// Narrows [t0, t1] to where alpha + beta·t lies in [lo, hi]; false when nothing is left.
bool clipLinear(double alpha, double beta, double lo, double hi, double& t0, double& t1) {
  if (beta == 0) return alpha >= lo && alpha <= hi;
  double ta = (lo - alpha) / beta, tb = (hi - alpha) / beta;
  if (ta > tb) std::swap(ta, tb);
  t0 = std::max(t0, ta);
  t1 = std::min(t1, tb);
  return t0 <= t1;
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
                                         double reach) {
  if (std::abs(frame.cut(path.back()) - frame.cut(path.front())) <= kTidyDistance || !(reach > 0)) {
    return std::nullopt;  // a move along the depth axis sweeps no area
  }
  ShadowPiece piece;
  auto& ring = piece.polygon.outer();
  ring.reserve(2 * path.size() + 1);
  for (Point p : path) ring.push_back(toBg(p));
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
                                      double farDepth = std::numeric_limits<double>::infinity()) {
  std::vector<ShadowPiece> pieces;
  for (const Segment& part : splitWhereTangentIsAlong(move, frame)) {
    std::vector<Point> path = flatten(part, chordTolerance);
    double nearest = frame.depth(path.front());
    for (Point p : path) nearest = std::min(nearest, frame.depth(p));
    const double needed = std::min(reach, farDepth + kShadowMargin - nearest);
    if (auto piece = shadowOfGraph(std::move(path), frame, needed)) {
      pieces.push_back(std::move(*piece));
    }
  }
  return pieces;
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

// The parts of [0, 1] no interval covers, into `gaps`.
void gapsBetween(std::vector<Interval>& intervals, std::vector<Interval>& gaps) {
  std::sort(intervals.begin(), intervals.end());
  gaps.clear();
  double reached = 0;
  for (const Interval& i : intervals) {
    if (i.first > reached) gaps.push_back({reached, i.first});
    reached = std::max(reached, i.second);
  }
  if (reached < 1) gaps.push_back({reached, 1});
}

// Working space of a crossing test, kept from chord to chord and move to move to spare allocations.
struct Scratch {
  std::vector<Point> points;
  std::vector<Interval> near, gaps, inside, insideAlso, both;
};

// Whether no point of the chord can be more than ε inside the region, without measuring: a region
// below a graph knows (RegionBelowGraph::staysWithin); nothing is sure of a region of rings.
bool surelyNotInside(const CrossingRegion&, const Chord&, double) { return false; }
bool surelyNotInside(const RegionBelowGraph& region, const Chord& chord, double epsilon) {
  return region.staysWithin(chord.a, chord.a + chord.d, epsilon);
}

// The parts of a chord (as intervals of t ∈ [0, 1]) deeper than ε inside the region, into
// `inside`. Away from every edge's ε-capsule the chord cannot cross the boundary, so each gap
// between the near intervals lies wholly inside or wholly outside: its midpoint decides.
// Whether the chord comes more than ε inside the region's box (a point more than ε inside the
// region does).
template <typename Region>
bool entersBoxOf(const Region& region, const Chord& chord, double epsilon) {
  return region.mayMeet(chord.zMin + epsilon, chord.zMax - epsilon, chord.xMin + epsilon, chord.xMax - epsilon);
}

template <typename Region>
void insideIntervals(const Region& region, const Chord& chord, double epsilon, Scratch& scratch,
                     std::vector<Interval>& inside) {
  inside.clear();
  if (!entersBoxOf(region, chord, epsilon) || surelyNotInside(region, chord, epsilon)) return;
  scratch.near.clear();
  region.forEachEdgeNear(chord.zMin - epsilon, chord.zMax + epsilon, chord.xMin - epsilon, chord.xMax + epsilon,
                         [&](Point p, Point q) { addNearIntervals(chord, p, q, epsilon, scratch.near); });
  gapsBetween(scratch.near, scratch.gaps);
  for (const Interval& gap : scratch.gaps) {
    if (region.contains(chord.at(0.5 * (gap.first + gap.second)))) inside.push_back(gap);
  }
}

// The common parts of two sorted lists of disjoint intervals, into `out`.
void common(const std::vector<Interval>& a, const std::vector<Interval>& b, std::vector<Interval>& out) {
  out.clear();
  for (std::size_t i = 0, j = 0; i < a.size() && j < b.size();) {
    const double lo = std::max(a[i].first, b[j].first), hi = std::min(a[i].second, b[j].second);
    if (lo < hi) out.push_back({lo, hi});
    (a[i].second < b[j].second ? i : j)++;
  }
}

// The pieces of `move` deeper than ε inside the region, and inside `also` when given (inside
// their intersection: a point is ε inside an intersection exactly when it is ε inside each).
// `regionOf()` gives the region, asked for only by a chord that comes into the box of `also`: a
// region made on demand (MaterialModel::crossing) is not made for a move clear of the stock.
template <typename RegionOf, typename Also = CrossingRegion>
Crossing crossingWithin(const Segment& move, double epsilon, double chordTolerance, RegionOf regionOf,
                        const Also* also = nullptr) {
  Crossing crossing;
  epsilon = std::max(epsilon, kTidyDistance);
  thread_local Scratch scratch;
  flattenInto(scratch.points, move, chordTolerance);
  const std::vector<Point>& points = scratch.points;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const Chord chord(points[i - 1], points[i]);
    if (chord.length <= kGeomEps || (also && !entersBoxOf(*also, chord, epsilon))) continue;
    insideIntervals(regionOf(), chord, epsilon, scratch, scratch.inside);
    const std::vector<Interval>* inside = &scratch.inside;
    if (also && !inside->empty()) {
      insideIntervals(*also, chord, epsilon, scratch, scratch.insideAlso);
      common(scratch.inside, scratch.insideAlso, scratch.both);
      inside = &scratch.both;
    }
    for (const Interval& piece : *inside) {
      crossing.pieces.push_back({SegmentKind::Line, chord.at(piece.first), chord.at(piece.second), {}, 0});
      crossing.length += (piece.second - piece.first) * chord.length;
    }
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
  return crossingOf(CrossingRegion(region), move, epsilon, chordTolerance);
}

Crossing crossingOf(const CrossingRegion& region, const Segment& move, double epsilon, double chordTolerance) {
  return crossingWithin(move, epsilon, chordTolerance, [&region]() -> const CrossingRegion& { return region; });
}

Crossing crossingOf(const RegionBelowGraph& region, const Segment& move, double epsilon, double chordTolerance) {
  return crossingWithin(move, epsilon, chordTolerance, [&region]() -> const RegionBelowGraph& { return region; });
}

MaterialModel::MaterialModel(BgRegion stock, Point away, double reach, double chordTolerance)
    : stock_(std::move(stock)), stockForCrossing_(stock_), frame_(away), reach_(reach), chordTolerance_(chordTolerance) {
  if (!(reach > 0) || !(chordTolerance > 0)) {
    throw std::invalid_argument("the material model needs a positive reach and chord tolerance");
  }
  stockEnvelope_ = envelopeOf(stock_);
  // The stock's top: the lower envelope of its edges seen from the other side (away reversed),
  // lowered to run by run of each ring that goes one way along the cut axis.
  const DepthFrame reversed({-frame_.away().z, -frame_.away().x});
  std::vector<Point> run;
  for (std::vector<Point>& ring : outlinesOf(stock_)) {
    if (ring.empty()) continue;
    ring.push_back(ring.front());
    run.assign(1, ring.front());
    int direction = 0;
    for (std::size_t i = 1; i < ring.size(); ++i) {
      const double advance = reversed.cut(ring[i]) - reversed.cut(ring[i - 1]);
      const int sign = std::abs(advance) <= kTidyDistance ? 0 : advance > 0 ? 1 : -1;
      if (sign != 0 && direction != 0 && sign != direction) {
        stockTop_.lower(run, reversed);
        run.assign(1, ring[i - 1]);
        direction = 0;
      }
      if (sign != 0) direction = sign;
      run.push_back(ring[i]);
    }
    stockTop_.lower(run, reversed);
  }
}

std::optional<double> MaterialModel::stockDeepestWithin(double c0, double c1) const {
  // Reversed, the cut coordinate and the depth change sign.
  std::optional<double> deepest;
  stockTop_.walk(
      -c1, -c0,
      [&](const CutEnvelope::Piece& p) {
        // A wall standing at an end of a range that has some width stands over none of it.
        if (p.c1 - p.c0 <= kTidyDistance && c1 - c0 > kTidyDistance) return;
        deepest = std::max(deepest.value_or(-INFINITY), -std::min(p.d0, p.d1));
      },
      [](double, double) {});
  return deepest;
}

void MaterialModel::apply(const Segment& move, MoveKind kind) {
  if (kind != MoveKind::Feed || stock_.empty()) return;
  bool lowered = false;
  for (const Segment& part : splitWhereTangentIsAlong(move, frame_)) {
    flattenInto(flattened_, part, chordTolerance_);
    lowered = cut_.lower(flattened_, frame_) || lowered;
  }
  if (lowered) {
    belowForCrossing_.reset();
    remaining_.reset();
  }
}

MaterialModel::FrameBox MaterialModel::inFrame(const Box& box) const {
  const BgPoint lo = box.min_corner(), hi = box.max_corner();
  const DepthFrame::Ranges r = frame_.rangesOf(lo.x(), hi.x(), lo.y(), hi.y());
  return {r.cMin, r.cMax, r.dMin, r.dMax};
}

// The frame box the stock stands in, 1 mm wider on every side (and below every feed): the region
// below the envelope is drawn within it, and its sides stay far from the material.
MaterialModel::FrameBox MaterialModel::frameBox() const {
  FrameBox box = inFrame(stockEnvelope_);
  for (const CutEnvelope::Piece& p : cut_.pieces()) box.dBottom = std::min({box.dBottom, p.d0, p.d1});
  box.cMin -= kShadowMargin;
  box.cMax += kShadowMargin;
  box.dBottom -= kShadowMargin;
  box.dTop += kShadowMargin;
  return box;
}

const BgRegion& MaterialModel::remaining() const {
  if (remaining_) return *remaining_;
  if (cut_.empty() || stock_.empty()) {
    remaining_ = stock_;
    return *remaining_;
  }
  const FrameBox box = frameBox();
  const BgRegion below = cut_.below(frame_, box.cMin, box.cMax, box.dBottom, box.dTop);
  BgRegion rest = checkedIntersection(stock_, below);
  Box operands = stockEnvelope_;
  bg::expand(operands, envelopeOf(below));
  const double size = std::max(operands.max_corner().x() - operands.min_corner().x(),
                               operands.max_corner().y() - operands.min_corner().y());
  tidy(rest, size);
  splitPinches(rest, std::max(kDustWidth, kBooleanResolution * size));
  remaining_ = std::move(rest);
  return *remaining_;
}

double MaterialModel::area() const { return bg::area(remaining()); }

const RegionBelowGraph& MaterialModel::belowForCrossing() const {
  if (!belowForCrossing_) {
    const FrameBox box = frameBox();
    belowForCrossing_.emplace(frame_, cut_.belowTop(box.cMin, box.cMax, box.dBottom, box.dTop), box.dBottom);
  }
  return *belowForCrossing_;
}

Crossing MaterialModel::crossing(const Segment& move, double epsilon) const {
  if (stock_.empty()) return {};
  const auto stock = [this]() -> const CrossingRegion& { return stockForCrossing_; };
  if (cut_.empty()) return crossingWithin(move, epsilon, chordTolerance_, stock);
  // Below the envelope first: a rapid in the air is found above it without measuring. The region
  // below is made again after the feeds lowered the envelope only for a move that comes into the
  // stock's box.
  return crossingWithin(move, epsilon, chordTolerance_, [this]() -> const RegionBelowGraph& { return belowForCrossing(); },
                        &stockForCrossing_);
}

std::vector<CutEnvelope::Piece> MaterialModel::topWithin(double c0, double c1) const {
  std::vector<CutEnvelope::Piece> top;
  top.reserve(3 * cut_.pieces().size() + 1);  // at most two a piece, one a gap
  cut_.walk(
      c0, c1,
      [&](const CutEnvelope::Piece& p) {
        if (p.c1 <= p.c0) return;
        const auto stockTop = stockDeepestWithin(p.c0, p.c1);
        if (!stockTop) return;  // no stock under this feed
        const double cap = *stockTop;
        if (p.d0 <= cap && p.d1 <= cap) return top.push_back(p);
        if (p.d0 >= cap && p.d1 >= cap) return top.push_back({p.c0, cap, p.c1, cap});
        const double c = p.c0 + (cap - p.d0) / (p.d1 - p.d0) * (p.c1 - p.c0);  // where it crosses the cap
        top.push_back({p.c0, std::min(p.d0, cap), c, cap});
        top.push_back({c, cap, p.c1, std::min(p.d1, cap)});
      },
      [&](double g0, double g1) {
        if (const auto stockTop = stockDeepestWithin(g0, g1)) top.push_back({g0, *stockTop, g1, *stockTop});
      });
  return top;
}

std::optional<CutEnvelope> MaterialModel::pointwiseTopWithin(double c0, double c1) const {
  // The stock's top: its reversed envelope's pieces turned back into this frame, left to right.
  std::vector<CutEnvelope::Piece> stock;
  stockTop_.walk(
      -c1, -c0,
      [&](const CutEnvelope::Piece& p) {
        if (p.c1 > p.c0) stock.push_back({-p.c1, -p.d1, -p.c0, -p.d0});
      },
      [](double, double) {});
  std::reverse(stock.begin(), stock.end());
  // The feeds' envelope over the stock only: beyond it there is no material to bound.
  std::vector<CutEnvelope::Piece> feeds;
  bool disjoint = true;
  for (const CutEnvelope::Piece& s : stock) {
    cut_.walk(
        s.c0, s.c1,
        [&](const CutEnvelope::Piece& p) {
          if (!(p.c1 > p.c0)) return;
          if (!feeds.empty() && p.c0 < feeds.back().c1 - kTidyDistance) disjoint = false;
          feeds.push_back(p);
        },
        [](double, double) {});
  }
  // Pieces of the envelope that overlap (a feed lowered as a graph that was none) bound nothing.
  if (!disjoint) return std::nullopt;
  CutEnvelope top;
  top.lower(stock);
  top.lower(feeds);
  return top;
}

std::optional<std::vector<CutEnvelope::Piece>> MaterialModel::topWithoutSkinsWithin(double c0, double c1,
                                                                                    double skin) const {
  const std::optional<CutEnvelope> found = pointwiseTopWithin(c0 - skin, c1 + skin);
  if (!found) return std::nullopt;
  return withoutSkinsOf(*found, c0, c1, skin);
}

std::vector<CutEnvelope::Piece> MaterialModel::withoutSkinsOf(const CutEnvelope& top, double c0, double c1,
                                                              double skin) {
  // The lowest of the top and its copies moved by ± skin (where a copy does not reach, the others
  // bound alone: looser, still above every point of the material without skins).
  CutEnvelope solid;
  if (skin > 0) {
    std::vector<CutEnvelope::Piece> moved;
    for (double by : {0.0, -skin, skin}) {
      moved.clear();
      for (const CutEnvelope::Piece& p : top.pieces()) moved.push_back({p.c0 + by, p.d0, p.c1 + by, p.d1});
      solid.lower(moved);
    }
  }
  std::vector<CutEnvelope::Piece> within;
  (skin > 0 ? solid : top).walk(
      c0, c1,
      [&](const CutEnvelope::Piece& p) {
        if (p.c1 > p.c0) within.push_back(p);
      },
      [](double, double) {});
  return within;
}

BgRegion MaterialModel::removedBy(const Segment& move) const {
  const BgRegion& material = remaining();
  if (material.empty()) return {};
  const Box envelope = envelopeOf(material);
  std::vector<BgPolygon> parts;
  for (const ShadowPiece& shadow : shadowPieces(move, frame_, reach_, chordTolerance_, inFrame(envelope).dTop)) {
    if (bg::disjoint(bg::return_envelope<Box>(shadow.polygon), envelope)) continue;
    for (BgPolygon& p : checkedIntersection(material, {shadow.polygon})) parts.push_back(std::move(p));
  }
  BgRegion removed = unionOf(parts);
  tidy(removed);
  return removed;
}

}  // namespace cyclecert
