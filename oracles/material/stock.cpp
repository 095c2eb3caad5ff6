#include "oracles/material/stock.h"

#include <algorithm>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/depth_frame.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

std::vector<Point> flattenedPath(const std::vector<Segment>& segments, double chordTolerance) {
  std::vector<Point> points;
  for (const Segment& s : segments) appendFlattened(points, s, chordTolerance);
  return points;
}

// Whether the points never turn back along the cut axis (steps along the depth axis allowed).
bool isGraphOverCutAxis(const std::vector<Point>& points, const DepthFrame& frame) {
  int direction = 0;
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double step = frame.cut(points[i]) - frame.cut(points[i - 1]);
    if (std::abs(step) <= kTidyDistance) continue;
    const int sign = step > 0 ? 1 : -1;
    if (direction != 0 && sign != direction) return false;
    direction = sign;
  }
  return true;
}

// The quadrilateral under one chord, down to the bottom level.
BgRegion regionUnderChord(Point a, Point b, double bottom, const DepthFrame& frame) {
  return regionFrom({a, b, frame.atDepth(b, bottom), frame.atDepth(a, bottom)});
}

}  // namespace

BgRegion barStock(double diameter, double length, double frontZ) {
  if (!(diameter > 0) || !(length > 0)) return {};
  const double r = diameter / 2, back = frontZ - length;
  return regionFrom({{back, 0}, {back, r}, {frontZ, r}, {frontZ, 0}});
}

BgRegion polygonStock(const std::vector<Point>& outline) { return regionFrom(outline); }

BgRegion impliedStock(const std::vector<Segment>& finishShape, Point away, double chordTolerance) {
  if (finishShape.empty()) return {};
  const DepthFrame frame(away);
  std::vector<Point> outline = flattenedPath(finishShape, chordTolerance);
  const Point a = finishShape.front().from;
  // Above C, then back to A.
  outline.push_back(frame.atDepth(finishShape.back().to, frame.depth(a)));
  return regionFrom(outline);
}

BgRegion partRegion(const std::vector<Segment>& roughProfile, Point away, double reach,
                    double chordTolerance) {
  if (roughProfile.empty()) return {};
  const DepthFrame frame(away);
  std::vector<Point> profile = flattenedPath(roughProfile, chordTolerance);
  double deepest = frame.depth(profile.front());
  for (Point p : profile) deepest = std::min(deepest, frame.depth(p));
  const double bottom = deepest - std::max(reach, 0.0);

  if (isGraphOverCutAxis(profile, frame)) {
    const Point first = profile.front(), last = profile.back();
    profile.push_back(frame.atDepth(last, bottom));
    profile.push_back(frame.atDepth(first, bottom));
    return regionFrom(profile);
  }
  // A profile turning back along the cut axis: the union of the regions under each chord.
  BgRegion region;
  for (std::size_t i = 1; i < profile.size(); ++i) {
    const BgRegion under = regionUnderChord(profile[i - 1], profile[i], bottom, frame);
    if (under.empty()) continue;
    BgRegion united;
    bg::union_(region, under, united);
    region = std::move(united);
  }
  tidy(region);
  return region;
}

}  // namespace cyclecert
