#include "oracles/material/tool_shape.h"

#include <algorithm>
#include <utility>

#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

BgRegion convexHullOf(const std::vector<Point>& points) {
  bg::model::multi_point<BgPoint> cloud;
  for (Point p : points) cloud.push_back(toBg(p));
  BgPolygon hull;
  bg::convex_hull(cloud, hull);
  BgRegion out;
  if (bg::area(hull) != 0) out.push_back(hull);
  bg::correct(out);
  return out;
}

BgRegion sweptConvexShape(const Segment& move, const std::vector<Point>& shape, double chordTolerance) {
  const std::vector<Point> chords = flatten(move, chordTolerance);
  BgRegion swept;
  for (std::size_t k = 0; k + 1 < chords.size(); ++k) {
    std::vector<Point> points;
    for (Point c : shape) {
      points.push_back(chords[k] + c);
      points.push_back(chords[k + 1] + c);
    }
    BgRegion hull = convexHullOf(points);
    if (swept.empty()) {
      swept = std::move(hull);
    } else if (!hull.empty()) {
      BgRegion merged;
      bg::union_(swept, hull, merged);
      swept = std::move(merged);
    }
  }
  tidy(swept);
  return swept;
}

BgRegion sweptRegion(const Segment& move, Point da, double a, Point db, double b, double chordTolerance) {
  return sweptConvexShape(move, {{0, 0}, a * da, a * da + b * db, b * db}, chordTolerance);
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
  const BgRegion swept = sweptRegion(move, blade.across, tool.width, blade.back, blade.length, chordTolerance);
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

}  // namespace cyclecert
