#pragma once
// The stock-removal frame (LCYC95 and CYCLE95 share it): every machining type 1…12 is planned as one
// case — cut along z towards −z, infeed along −x, the stock above the contour — and the moves are
// mapped back to the plane. Longitudinal machining is the plane itself; face machining exchanges z
// and x (LCYC95.PARAMS: "face machining feeds in along the longitudinal axis"); internal machining
// mirrors the depth axis (interpretation, see LCYC95.PARAMS notes in specs/rules.json).
#include <vector>

#include "reference/model/offset.h"
#include "reference/model/toolpath.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert {

struct StockRemovalFrame {
  bool transposed = false;  // face: the cut runs along X, the infeed along Z
  bool mirrored = false;    // internal: the depth direction is external's mirrored

  Point toFrame(Point plane) const;
  Point toPlane(Point frame) const;
  Segment toFrame(const Segment& plane) const;
  Segment toPlane(const Segment& frame) const;
  std::vector<Segment> toFrame(const std::vector<Segment>& plane) const;
  std::vector<Segment> toPlane(const std::vector<Segment>& frame) const;
  // A move planned in the frame, mapped to the plane in place (a copy would copy its rule IDs).
  void mapToPlane(Move& frameMove) const;

  // The side of the stock (where the tool runs) seen along the finishing direction, in the plane:
  // in the frame it is always the right (stock above, travel towards −z); each reflection swaps it.
  // Longitudinal external: G42, as offset.h's worked example.
  CompensationSide stockSideInPlane() const;
};

StockRemovalFrame frameOf(const MachiningType& type);

}  // namespace cyclecert
