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

Segment StockRemovalFrame::toFrame(const Segment& s) const {
  Segment r = s;
  r.from = toFrame(s.from);
  r.to = toFrame(s.to);
  r.center = toFrame(s.center);
  r.kind = reflectedKind(s.kind, reflections(*this));
  return r;
}

Segment StockRemovalFrame::toPlane(const Segment& s) const {
  Segment r = s;
  r.from = toPlane(s.from);
  r.to = toPlane(s.to);
  r.center = toPlane(s.center);
  r.kind = reflectedKind(s.kind, reflections(*this));
  return r;
}

std::vector<Segment> StockRemovalFrame::toFrame(const std::vector<Segment>& plane) const {
  std::vector<Segment> out;
  out.reserve(plane.size());
  for (const Segment& s : plane) out.push_back(toFrame(s));
  return out;
}

std::vector<Segment> StockRemovalFrame::toPlane(const std::vector<Segment>& frame) const {
  std::vector<Segment> out;
  out.reserve(frame.size());
  for (const Segment& s : frame) out.push_back(toPlane(s));
  return out;
}

Move StockRemovalFrame::toPlane(Move m) const {
  m.to = toPlane(m.to);
  if (m.center) m.center = toPlane(*m.center);
  m.shape = reflectedKind(m.shape, reflections(*this));
  return m;
}

CompensationSide StockRemovalFrame::stockSideInPlane() const {
  return reflections(*this) % 2 == 0 ? CompensationSide::Right : CompensationSide::Left;
}

}  // namespace cyclecert
