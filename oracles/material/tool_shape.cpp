#include "oracles/material/tool_shape.h"

#include <algorithm>

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
  BgRegion crossed = checkedIntersection(swept, region);
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
