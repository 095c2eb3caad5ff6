#include "oracles/groove/groove_nose.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/tool_shape.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

constexpr double kPi = 3.14159265358979323846;

// The disc's polygon, inscribed: its sides' sagitta R·(1 − cos(π/n)) within the chord tolerance.
std::vector<Point> discAround(Point centre, double radius, double chordTolerance) {
  const double step = std::acos(std::clamp(1 - chordTolerance / radius, -1.0, 1.0));
  const int n = std::clamp(static_cast<int>(std::ceil(kPi / std::max(step, 1e-6))), 12, 720);
  std::vector<Point> points;
  points.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2 * kPi * k / n;
    points.push_back(centre + Point{radius * std::cos(a), radius * std::sin(a)});
  }
  return points;
}

}  // namespace

std::vector<Point> noseDisc(double radius, double chordTolerance) { return discAround({0, 0}, radius, chordTolerance); }

SweptShape noseShape(double radius, Point shadowDir, double shadowLength, double chordTolerance) {
  std::vector<Point> shape = noseDisc(radius, chordTolerance);
  if (shadowLength > 0) {
    const std::size_t n = shape.size();
    for (std::size_t i = 0; i < n; ++i) shape.push_back(shape[i] + shadowLength * shadowDir);
  }
  return SweptShape(std::move(shape));
}

BgRegion openedBy(const BgRegion& region, double radius) {
  const BgRegion inner = eroded(region, radius);
  if (inner.empty()) return inner;
  namespace strategy = bg::strategy::buffer;
  const int pointsPerCircle = 72;
  BgRegion result;
  bg::buffer(inner, result, strategy::distance_symmetric<double>(radius), strategy::side_straight(),
             strategy::join_round(pointsPerCircle), strategy::end_round(pointsPerCircle),
             strategy::point_circle(pointsPerCircle));
  tidy(result);
  return checkedIntersection(result, region);
}

}  // namespace cyclecert
