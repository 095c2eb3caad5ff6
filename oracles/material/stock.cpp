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

namespace {

// The point of chord a → b where its cut coordinate is `c` (between theirs), exactly at `c`.
Point atCut(Point a, Point b, double c, const DepthFrame& frame) {
  const double ca = frame.cut(a), cb = frame.cut(b);
  const double t = (c - ca) / (cb - ca);
  return frame.point(c, frame.depth(a) + t * (frame.depth(b) - frame.depth(a)));
}

}  // namespace

BgRegion graphRegionWithin(const std::vector<Point>& profile, const DepthFrame& frame, double bottom, double lo,
                           double hi) {
  std::vector<Point> outline;
  const auto add = [&outline](Point p) {
    if (outline.empty() || !(outline.back() == p)) outline.push_back(p);
  };
  const auto inside = [&](Point p) { return frame.cut(p) >= lo && frame.cut(p) <= hi; };
  for (std::size_t i = 1; i < profile.size(); ++i) {
    const Point a = profile[i - 1], b = profile[i];
    const double ca = frame.cut(a), cb = frame.cut(b);
    if (std::max(ca, cb) < lo || std::min(ca, cb) > hi) continue;
    // Entering the band: from its near edge; leaving it: at its far edge.
    if (inside(a)) {
      add(a);
    } else {
      add(atCut(a, b, ca < lo ? lo : hi, frame));
    }
    if (inside(b)) {
      add(b);
    } else {
      add(atCut(a, b, cb > hi ? hi : lo, frame));
    }
  }
  if (outline.size() < 2) return {};
  const Point first = outline.front(), last = outline.back();
  outline.push_back(frame.atDepth(last, bottom));
  outline.push_back(frame.atDepth(first, bottom));
  return regionFromSimpleOutline(outline);
}

}  // namespace cyclecert
