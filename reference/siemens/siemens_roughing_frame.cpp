#include "reference/siemens/siemens_roughing_frame.h"

namespace cyclecert {

namespace {
int reflections(const StockRemovalFrame& f) { return (f.transposed ? 1 : 0) + (f.mirrored ? 1 : 0); }
SegmentKind reflectedKind(SegmentKind k, int count) { return count % 2 == 0 ? k : reversedKind(k); }
}  // namespace

StockRemovalFrame frameOf(const MachiningType& type) {
  return {type.cut == SiemensCut::Face, type.side == SiemensSide::Internal};
}

Point StockRemovalFrame::toFrame(Point p) const {
  if (transposed) p = Point{p.x, p.z};
  if (mirrored) p.x = -p.x;
  return p;
}

Point StockRemovalFrame::toPlane(Point p) const {
  if (mirrored) p.x = -p.x;
  if (transposed) p = Point{p.x, p.z};
  return p;
}

namespace {

// A segment with its points mapped one way or the other; reflections turn an arc round.
template <typename MapPoint>
Segment mapped(const Segment& s, const StockRemovalFrame& f, MapPoint point) {
  Segment r = s;
  r.from = point(s.from);
  r.to = point(s.to);
  r.center = point(s.center);
  r.kind = reflectedKind(s.kind, reflections(f));
  return r;
}

template <typename MapSegment>
std::vector<Segment> mappedAll(const std::vector<Segment>& in, MapSegment segment) {
  std::vector<Segment> out;
  out.reserve(in.size());
  for (const Segment& s : in) out.push_back(segment(s));
  return out;
}

}  // namespace

Segment StockRemovalFrame::toFrame(const Segment& s) const {
  return mapped(s, *this, [this](Point p) { return toFrame(p); });
}

Segment StockRemovalFrame::toPlane(const Segment& s) const {
  return mapped(s, *this, [this](Point p) { return toPlane(p); });
}

std::vector<Segment> StockRemovalFrame::toFrame(const std::vector<Segment>& plane) const {
  return mappedAll(plane, [this](const Segment& s) { return toFrame(s); });
}

std::vector<Segment> StockRemovalFrame::toPlane(const std::vector<Segment>& frame) const {
  return mappedAll(frame, [this](const Segment& s) { return toPlane(s); });
}

void StockRemovalFrame::mapToPlane(Move& m) const {
  m.to = toPlane(m.to);
  if (m.center) m.center = toPlane(*m.center);
  m.shape = reflectedKind(m.shape, reflections(*this));
}

CompensationSide StockRemovalFrame::stockSideInPlane() const {
  return reflections(*this) % 2 == 0 ? CompensationSide::Right : CompensationSide::Left;
}

}  // namespace cyclecert
