#include "oracles/material/depth_frame.h"

#include <array>
#include <cstddef>
#include <utility>

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
  std::array<double, 2> offsets{};  // angles from `from`, along the arc (held in place: no allocation)
  std::size_t count = 0;
  for (double sign : {-1.0, 1.0}) {
    const auto offset = offsetAlongArc(angles, std::atan2(sign * frame.along().x, sign * frame.along().z));
    if (offset && *offset > 1e-12 && *offset < span - 1e-12) offsets[count++] = *offset;
  }
  if (count == 2 && offsets[1] < offsets[0]) std::swap(offsets[0], offsets[1]);  // in order along the arc
  Point from = s.from;
  for (std::size_t k = 0; k < count; ++k) {
    const double offset = offsets[k];
    const Point at = pointAt(s, angles, offset / span);
    pieces.push({s.kind, from, at, s.center, s.sourceLine});
    from = at;
  }
  pieces.push({s.kind, from, s.to, s.center, s.sourceLine});
  return pieces;
}

bool isGraphOverCutAxis(std::span<const Segment> path, const DepthFrame& frame) {
  OneWayAlongCut way;
  for (const Segment& s : path) {
    for (const Segment& piece : splitWhereTangentIsAlong(s, frame)) {
      if (!way.keeps(piece, frame)) return false;
    }
  }
  return true;
}

bool OneWayAlongCut::keeps(const Segment& piece, const DepthFrame& frame) {
  const double advance = frame.cut(piece.to) - frame.cut(piece.from);
  if (std::abs(advance) <= kTidyDistance) return true;  // a wall
  const int sign = advance > 0 ? 1 : -1;
  if (direction_ != 0 && sign != direction_) return false;
  direction_ = sign;
  return true;
}

}  // namespace cyclecert
