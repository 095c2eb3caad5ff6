#include "reference/model/contour.h"

namespace cyclecert {

Contour Contour::shifted(Point by) const {
  Contour c;
  c.segments.reserve(segments.size());
  for (const Segment& s : segments) c.segments.push_back(s.shifted(by));
  return c;
}

Contour Contour::transposed() const {
  Contour c;
  c.segments.reserve(segments.size());
  for (const Segment& s : segments) c.segments.push_back(cyclecert::transposed(s));
  return c;
}

}  // namespace cyclecert
