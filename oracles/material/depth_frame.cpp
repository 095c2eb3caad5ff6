#include "oracles/material/depth_frame.h"

#include <algorithm>
#include <numbers>

#include "oracles/material/region.h"

namespace cyclecert {

namespace {

double normalizedAngle(double a) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  a = std::fmod(a, kTwoPi);
  return a < 0 ? a + kTwoPi : a;
}

}  // namespace

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

bool isGraphOverCutAxis(const std::vector<Segment>& path, const DepthFrame& frame) {
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
