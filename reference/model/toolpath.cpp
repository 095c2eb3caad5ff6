#include "reference/model/toolpath.h"

namespace cyclecert {

Segment Toolpath::segment(std::size_t i) const {
  const Move& m = moves[i];
  Segment s;
  s.kind = m.shape;
  s.from = from(i);
  s.to = m.to;
  if (m.center) s.center = *m.center;
  return s;
}

}  // namespace cyclecert
