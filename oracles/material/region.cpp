#include "oracles/material/region.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

using Ring = BgPolygon::ring_type;

bool isFinite(Point p) { return std::isfinite(p.z) && std::isfinite(p.x); }

void requireFinite(const Segment& s) {
  if (!isFinite(s.from) || !isFinite(s.to) || (s.isArc() && !isFinite(s.center))) {
    throw std::invalid_argument("cannot flatten a segment with non-finite coordinates");
  }
}

// Largest angle a chord may span so that its sagitta r·(1 − cos(φ/2)) = 2r·sin²(φ/4) stays within
// the tolerance (the sin² form keeps precision when tolerance ≪ r).
double largestChordAngle(double radius, double chordTolerance) {
  const double ratio = chordTolerance / (2 * radius);
  return ratio >= 1 ? 2 * std::numbers::pi : 4 * std::asin(std::sqrt(ratio));
}

// The chords an arc of this sweep (signed) and radius is flattened into (flatten, chordsToFlatten).
double chordsForSweep(double sweep, double radius, double chordTolerance) {
  return std::ceil(std::abs(sweep) / largestChordAngle(radius, chordTolerance));
}

bool within(const BgPoint& a, const BgPoint& b, double tolerance) {
  return std::abs(a.x() - b.x()) <= tolerance && std::abs(a.y() - b.y()) <= tolerance;
}

bool near(const BgPoint& a, const BgPoint& b) { return within(a, b, kTidyDistance); }

// Whether `b` adds nothing between `a` and `c`: it lies within `flatness` of the line a–c (a
// collinear point, or the tip of a spike — a and c coincide, or c lies back along a–b).
bool isFlat(const BgPoint& a, const BgPoint& b, const BgPoint& c, double flatness) {
  const double ux = c.x() - a.x(), uy = c.y() - a.y();
  const double length = std::sqrt(ux * ux + uy * uy);
  if (length <= kTidyDistance) return true;
  const double cross = ux * (b.y() - a.y()) - uy * (b.x() - a.x());
  return std::abs(cross) <= flatness * length;
}

// The ring's points (closing repetition excluded) with near-duplicates, collinear points and spikes
// removed, also across the closing point. `flatness`: how far off the line through its neighbours
// a point may stand and still count as on it.
std::vector<BgPoint> tidyPoints(const std::vector<BgPoint>& points, double flatness = kTidyDistance) {
  std::vector<BgPoint> out;
  out.reserve(points.size());
  for (const BgPoint& p : points) {
    while (true) {
      if (!out.empty() && near(out.back(), p)) break;
      if (out.size() >= 2 && isFlat(out[out.size() - 2], out.back(), p, flatness)) {
        out.pop_back();
        continue;
      }
      out.push_back(p);
      break;
    }
  }
  // The ring wraps around: the last point is followed by the first.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    const std::size_t n = out.size();
    if (near(out[n - 1], out[0]) || isFlat(out[n - 2], out[n - 1], out[0], flatness)) {
      out.pop_back();
      changed = true;
    } else if (isFlat(out[n - 1], out[0], out[1], flatness)) {
      out.erase(out.begin());
      changed = true;
    }
  }
  if (out.size() < 3) out.clear();
  return out;
}

// Whether a ring is too thin to be material: 2·area / perimeter below `width`.
bool isDust(const std::vector<BgPoint>& open, double width) {
  double twiceArea = 0, perimeter = 0;
  for (std::size_t i = 0; i < open.size(); ++i) {
    const BgPoint& a = open[i];
    const BgPoint& b = open[(i + 1) % open.size()];
    twiceArea += a.x() * b.y() - b.x() * a.y();
    perimeter += std::sqrt((b.x() - a.x()) * (b.x() - a.x()) + (b.y() - a.y()) * (b.y() - a.y()));
  }
  return std::abs(twiceArea) < width * perimeter;
}

double sizeOf(const bg::model::box<BgPoint>& box) {
  return std::max(box.max_corner().x() - box.min_corner().x(),
                  box.max_corner().y() - box.min_corner().y());
}

// Tidies a closed ring in place; leaves it empty when nothing of substance remains.
void tidyRing(Ring& ring, double dust) {
  std::vector<BgPoint> open(ring.begin(), ring.end());
  if (open.size() >= 2 && bg::equals(open.front(), open.back())) open.pop_back();
  // A boolean's output is only as exact as its resolution: a spike or a kink thinner than that
  // (Boost leaves such spikes where a cut ends on the line a later move follows) is noise, and a
  // ring with a spike is invalid input to the next boolean.
  open = tidyPoints(open, dust);
  ring.clear();
  if (open.empty() || isDust(open, dust)) return;
  ring.assign(open.begin(), open.end());
  ring.push_back(open.front());
}

}  // namespace

std::vector<Point> flatten(const Segment& s, double chordTolerance) {
  std::vector<Point> points;
  flattenInto(points, s, chordTolerance);
  return points;
}

double chordsToFlatten(const Segment& s, double chordTolerance) {
  const double radius = s.radius();
  if (!s.isArc() || radius <= kGeomEps) return 1;
  return std::max(1.0, chordsForSweep(ArcAngles(s).sweep, radius, chordTolerance));
}

double mostChordsToFlatten(const Segment& s, double chordTolerance) {
  if (!s.isArc()) return 1;
  // 2π / (4·sqrt(tolerance / 2r)), doubled.
  return 1 + std::numbers::pi * std::sqrt(2 * s.radius() / chordTolerance);
}

namespace {

// Appends the segment's points flattened within chordTolerance (flatten), leaving out its first
// point (s.from) when `withFrom` is false: appendFlattened writes straight into the path it grows.
void appendFlattenedPoints(std::vector<Point>& points, const Segment& s, double chordTolerance, bool withFrom) {
  requireFinite(s);
  if (!(chordTolerance > 0) || !std::isfinite(chordTolerance)) {
    throw std::invalid_argument("the chord tolerance must be a positive number");
  }
  const double radius = s.radius();
  if (!s.isArc() || radius <= kGeomEps) {
    if (withFrom) points.push_back(s.from);
    points.push_back(s.to);
    return;
  }
  const ArcAngles angles(s);
  const double span = angles.sweep;  // signed: negative for clockwise
  const double chords = chordsForSweep(span, radius, chordTolerance);
  if (chords > kMostChordsPerArc) {
    throw std::invalid_argument("the chord tolerance " + std::to_string(chordTolerance) +
                                " mm is too small for an arc of radius " + std::to_string(radius) +
                                " mm: it would take more than 1,000,000 chords");
  }
  const int n = std::max(1, static_cast<int>(chords));
  if (points.empty()) points.reserve(static_cast<std::size_t>(n) + 1);  // a path appended to grows as vectors do
  if (withFrom) points.push_back(s.from);
  // Each point is the one before turned by the chord's angle about the centre: no sine or cosine
  // per point, and the rounding gathered over n ≤ 10⁶ turns stays within 10⁻⁹ of the radius.
  const double step = span / n, cosStep = std::cos(step), sinStep = std::sin(step);
  double cosA = std::cos(angles.start), sinA = std::sin(angles.start);
  for (int k = 1; k < n; ++k) {
    const double cosNext = cosA * cosStep - sinA * sinStep;
    sinA = sinA * cosStep + cosA * sinStep;
    cosA = cosNext;
    points.push_back({s.center.z + radius * cosA, s.center.x + radius * sinA});
  }
  points.push_back(s.to);
}

}  // namespace

void flattenInto(std::vector<Point>& points, const Segment& s, double chordTolerance) {
  points.clear();
  appendFlattenedPoints(points, s, chordTolerance, true);
}

void appendFlattened(std::vector<Point>& points, const Segment& s, double chordTolerance) {
  // Flattening starts at s.from: where the path already ends there, that point is not repeated.
  const bool joins = !points.empty() && nearlyEqual(points.back(), s.from, kTidyDistance);
  appendFlattenedPoints(points, s, chordTolerance, !joins);
}

namespace {

// The outline as a closed, clockwise, tidy polygon; nothing when nothing is left of it.
std::optional<BgPolygon> polygonFrom(const std::vector<Point>& outline, std::vector<BgPoint>& points) {
  points.reserve(outline.size());
  for (Point p : outline) {
    if (!isFinite(p)) throw std::invalid_argument("an outline point is not finite");
    points.push_back(toBg(p));
  }
  points = tidyPoints(points);
  if (points.empty()) return std::nullopt;
  BgPolygon polygon;
  polygon.outer().assign(points.begin(), points.end());
  bg::correct(polygon);  // closes the ring and makes it clockwise
  return polygon;
}

}  // namespace

BgRegion regionFrom(const std::vector<Point>& outline) {
  std::vector<BgPoint> points;
  const auto polygon = polygonFrom(outline, points);
  if (!polygon) return {};
  std::string reason;
  if (!bg::is_valid(*polygon, reason)) {
    throw std::invalid_argument("the outline is not a simple polygon: " + reason);
  }
  if (isDust(points, kDustWidth)) return {};
  return {*polygon};
}

BgRegion regionFromSimpleOutline(const std::vector<Point>& outline) {
  std::vector<BgPoint> points;
  const auto polygon = polygonFrom(outline, points);
  if (!polygon || isDust(points, kDustWidth)) return {};
  return {*polygon};
}

std::vector<std::vector<Point>> outlinesOf(const BgRegion& region) {
  std::vector<std::vector<Point>> outlines;
  auto add = [&outlines](const Ring& ring) {
    std::vector<Point> points;
    points.reserve(ring.size());
    for (const BgPoint& p : ring) points.push_back(fromBg(p));
    if (points.size() >= 2 && points.front() == points.back()) points.pop_back();
    outlines.push_back(std::move(points));
  };
  for (const BgPolygon& polygon : region) {
    add(polygon.outer());
    for (const Ring& hole : polygon.inners()) add(hole);
  }
  return outlines;
}

BgRegion eroded(const BgRegion& region, double epsilon) {
  BgRegion result;
  if (!(epsilon > 0)) {
    result = region;
  } else if (!region.empty()) {
    namespace strategy = bg::strategy::buffer;
    const int pointsPerCircle = 72;
    bg::buffer(region, result, strategy::distance_symmetric<double>(-epsilon),
               strategy::side_straight(), strategy::join_round(pointsPerCircle),
               strategy::end_round(pointsPerCircle), strategy::point_circle(pointsPerCircle));
  }
  tidy(result);
  return result;
}

BgRegion without(const BgRegion& a, const BgRegion& b) {
  if (a.empty() || b.empty()) return a;
  using Box = bg::model::box<BgPoint>;
  Box envelope = bg::return_envelope<Box>(a);
  const Box envelopeB = bg::return_envelope<Box>(b);
  if (bg::disjoint(envelope, envelopeB)) return a;
  BgRegion result;
  bg::difference(a, b, result);
  bg::expand(envelope, envelopeB);
  tidy(result, sizeOf(envelope));
  return result;
}

namespace {

double distanceToSegment(const BgPoint& p, const BgPoint& a, const BgPoint& b, double& t) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  const double lengthSquared = ux * ux + uy * uy;
  t = lengthSquared > 0 ? ((p.x() - a.x()) * ux + (p.y() - a.y()) * uy) / lengthSquared : 0;
  t = std::clamp(t, 0.0, 1.0);
  const double dx = a.x() + t * ux - p.x(), dy = a.y() + t * uy - p.y();
  return std::sqrt(dx * dx + dy * dy);
}

// The loops of a ring that touches itself: a vertex on another of its edges (made a vertex of that
// edge too), or the same point twice; the ring is cut at each such point.
std::vector<std::vector<BgPoint>> loopsOf(std::vector<BgPoint> ring, double tolerance) {
  for (bool inserted = true; inserted;) {
    inserted = false;
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n && !inserted; ++i) {
      for (std::size_t j = 0; j < n && !inserted; ++j) {
        const std::size_t k = (j + 1) % n;
        if (i == j || i == k || within(ring[i], ring[j], tolerance) || within(ring[i], ring[k], tolerance)) continue;
        double t = 0;
        if (distanceToSegment(ring[i], ring[j], ring[k], t) <= tolerance && t > 0 && t < 1) {
          ring.insert(ring.begin() + static_cast<long>(k == 0 ? n : k), ring[i]);
          inserted = true;
        }
      }
    }
  }
  std::vector<std::vector<BgPoint>> loops;
  std::vector<BgPoint> path;
  for (const BgPoint& p : ring) {
    const auto seen = std::find_if(path.begin(), path.end(), [&](const BgPoint& q) { return within(p, q, tolerance); });
    if (seen == path.end()) {
      path.push_back(p);
      continue;
    }
    loops.emplace_back(seen, path.end());
    path.erase(seen + 1, path.end());
  }
  loops.push_back(std::move(path));
  return loops;
}

}  // namespace

namespace {

// Whether a ring (closing point excluded) touches itself: a vertex within `tolerance` of an edge
// that does not end at it or at a neighbour of it — the same point twice, or a vertex on another
// edge. A sweep along x meets each vertex only with the edges whose x-range (grown by the
// tolerance) holds it, so this costs O(n log n) for the rings the model makes, far less than
// is_valid (or an R-tree built per ring).
bool touchesItself(const std::vector<BgPoint>& ring, double tolerance) {
  const std::size_t n = ring.size();
  if (n < 4) return false;
  struct Edge {
    double minX, maxX, minY, maxY;
    std::size_t from;
  };
  std::vector<Edge> edges;
  edges.reserve(n);
  for (std::size_t j = 0; j < n; ++j) {
    const BgPoint& a = ring[j];
    const BgPoint& b = ring[(j + 1) % n];
    edges.push_back({std::min(a.x(), b.x()) - tolerance, std::max(a.x(), b.x()) + tolerance,
                     std::min(a.y(), b.y()) - tolerance, std::max(a.y(), b.y()) + tolerance, j});
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) { return a.minX < b.minX; });
  std::vector<std::size_t> byX(n);
  for (std::size_t i = 0; i < n; ++i) byX[i] = i;
  std::sort(byX.begin(), byX.end(), [&](std::size_t a, std::size_t b) { return ring[a].x() < ring[b].x(); });
  std::vector<const Edge*> active;  // edges whose x-range has begun and not yet ended
  std::size_t nextEdge = 0;
  for (const std::size_t i : byX) {
    const BgPoint& p = ring[i];
    for (; nextEdge < n && edges[nextEdge].minX <= p.x(); ++nextEdge) active.push_back(&edges[nextEdge]);
    std::erase_if(active, [&](const Edge* e) { return e->maxX < p.x(); });
    const std::size_t previous = (i + n - 1) % n, next = (i + 1) % n;
    for (const Edge* e : active) {
      const std::size_t j = e->from, k = (j + 1) % n;
      if (i == j || i == k || p.y() < e->minY || p.y() > e->maxY) continue;  // its own edges, or far
      double t = 0;
      if (distanceToSegment(p, ring[j], ring[k], t) > tolerance) continue;
      // Close to a neighbour's end only: a short edge, not a pinch.
      if ((t == 0 && j == next) || (t == 1 && k == previous)) continue;
      return true;
    }
  }
  return false;
}

}  // namespace

void splitPinches(BgRegion& region, double tolerance) {
  BgRegion out;
  for (BgPolygon& polygon : region) {
    std::vector<BgPoint> outer(polygon.outer().begin(), polygon.outer().end());
    if (outer.size() >= 2 && bg::equals(outer.front(), outer.back())) outer.pop_back();
    if (!touchesItself(outer, tolerance)) {
      out.push_back(std::move(polygon));
      continue;
    }
    const auto loops = loopsOf(std::move(outer), tolerance);
    if (loops.size() == 1) {
      out.push_back(std::move(polygon));
      continue;
    }
    // Each loop that encloses area with the ring's own orientation is a piece of its own; the
    // polygon's holes go to the piece that holds them.
    BgRegion pieces;
    for (const auto& loop : loops) {
      const std::vector<BgPoint> points = tidyPoints(loop);
      if (points.size() < 3) continue;
      BgPolygon piece;
      piece.outer().assign(points.begin(), points.end());
      piece.outer().push_back(points.front());
      if (bg::area(piece) <= 0) continue;  // a loop turning the other way encloses nothing of it
      pieces.push_back(std::move(piece));
    }
    for (const Ring& hole : polygon.inners()) {
      for (BgPolygon& piece : pieces) {
        if (bg::within(hole.front(), piece)) {
          piece.inners().push_back(hole);
          break;
        }
      }
    }
    for (BgPolygon& piece : pieces) out.push_back(std::move(piece));
  }
  region = std::move(out);
}

BgRegion checkedIntersection(const BgRegion& a, const BgRegion& b) {
  BgRegion result;
  bg::intersection(a, b, result);
  if (result.empty() || a.empty()) return result;
  using Box = bg::model::box<BgPoint>;
  const Box limit = bg::return_envelope<Box>(a), got = bg::return_envelope<Box>(result);
  const double slack = 1e-6 * std::max(1.0, sizeOf(limit));
  const bool inside = got.min_corner().x() >= limit.min_corner().x() - slack &&
                      got.min_corner().y() >= limit.min_corner().y() - slack &&
                      got.max_corner().x() <= limit.max_corner().x() + slack &&
                      got.max_corner().y() <= limit.max_corner().y() + slack;
  const double area = bg::area(result);
  if (inside && area <= std::min(bg::area(a), bg::area(b)) * (1 + 1e-9) + 1e-12) return result;
  // The same region by another route: what the difference leaves, taken from `a`.
  BgRegion rest, again;
  bg::difference(a, b, rest);
  bg::difference(a, rest, again);
  return again;
}

void tidy(BgRegion& region, double operandSize) {
  if (region.empty()) return;
  if (operandSize <= 0) operandSize = sizeOf(bg::return_envelope<bg::model::box<BgPoint>>(region));
  const double dust = std::max(kDustWidth, kBooleanResolution * operandSize);
  for (BgPolygon& polygon : region) {
    tidyRing(polygon.outer(), dust);
    if (polygon.outer().empty()) continue;
    for (Ring& hole : polygon.inners()) tidyRing(hole, dust);
    auto& holes = polygon.inners();
    holes.erase(std::remove_if(holes.begin(), holes.end(), [](const Ring& r) { return r.empty(); }),
                holes.end());
  }
  region.erase(std::remove_if(region.begin(), region.end(),
                              [](const BgPolygon& p) { return p.outer().empty(); }),
               region.end());
}

}  // namespace cyclecert
