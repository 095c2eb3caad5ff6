#pragma once
// A contour: connected segments in the cycle plane (physical coordinates, x = radius).
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

struct Contour {
  std::vector<Segment> segments;

  bool empty() const { return segments.empty(); }
  Point start() const { return segments.front().from; }
  Point end() const { return segments.back().to; }
  Contour shifted(Point by) const;
  Contour transposed() const;
};

}  // namespace cyclecert
