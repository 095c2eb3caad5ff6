#include "oracles/material/depth_frame.h"

#include <algorithm>

#include "oracles/material/region.h"

namespace cyclecert {

SegmentPieces splitWhereTangentIsAlong(const Segment& s, const DepthFrame& frame) {
  SegmentPieces pieces;
  if (!s.isArc() || s.radius() <= kGeomEps) {
    pieces.push(s);
    return pieces;
  }
  const ArcAngles angles(s);
  const double span = std::abs(angles.sweep);
  // The tangent is parallel to `away` where the radius is perpendicular to it: along the cut axis.
  std::vector<double> offsets;  // angles from `from`, along the arc
  for (double sign : {-1.0, 1.0}) {
    const auto offset = offsetAlongArc(angles, std::atan2(sign * frame.along().x, sign * frame.along().z));
    if (offset && *offset > 1e-12 && *offset < span - 1e-12) offsets.push_back(*offset);
  }
  std::sort(offsets.begin(), offsets.end());
  Point from = s.from;
  for (double offset : offsets) {
    const Point at = pointAt(s, angles, offset / span);
    pieces.push({s.kind, from, at, s.center, s.sourceLine});
    from = at;
  }
  pieces.push({s.kind, from, s.to, s.center, s.sourceLine});
  return pieces;
}

bool isGraphOverCutAxis(std::span<const Segment> path, const DepthFrame& frame) {
  int direction = 0;
  for (const Segment& s : path) {
    for (const Segment& piece : splitWhereTangentIsAlong(s, frame)) {
      const double advance = frame.cut(piece.to) - frame.cut(piece.from);
      if (std::abs(advance) <= kTidyDistance) continue;  // a wall
      const int sign = advance > 0 ? 1 : -1;
      if (direction != 0 && sign != direction) return false;
      direction = sign;
    }
  }
  return true;
}

}  // namespace cyclecert
