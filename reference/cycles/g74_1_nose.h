#pragma once
// G74.1 with a pointed tool under G41/G42 (seed 002: "该参数未输入时代表所用刀具为尖刀, 此时G41G42刀补
// 指令有效"; docs/g74_1.md I13, I26, I27): the cycle is planned for the nose centre inside the groove
// eroded by the nose radius R — the groove's chain offset into the groove by R, its floor-side
// chamfers and rounds the nose cannot touch made sharp, as an offset does — and every move is then
// the imaginary tip point: the centre shifted by R times the tip direction, as the other cycles'
// compensation (reference/model/offset.h) does.
#include "reference/cycles/g74_1_groove.h"
#include "reference/model/offset.h"

namespace cyclecert {

// The nose radius does not fit the groove (I27): the cycle's alarm is the interference alarm.
class NoseDoesNotFit : public GrooveDoesNotFit {
 public:
  using GrooveDoesNotFit::GrooveDoesNotFit;
};

// The profile (finish: allowances 0, or rough) that a nose of radius R > 0 follows, in the groove's
// frame, as a GrooveProfile the steps plan with a point: the path of the nose's lowest point (its
// centre + R along h: on the start level w = 0 when the nose touches it from above) — the groove's
// chain offset into the groove by R (offsetPath) and moved R along h, from the start level on the
// start side to the start level (or its end, when that lies deeper) on the far side, its end lines
// drawn on to the start level; `start` is the offset near flank's line there (A11 of a pointed tool,
// I12 with r = 0); its floor is the groove's floor, between the offset flanks.
// Throws GrooveDoesNotFit naming R and what it does not fit (I27).
GrooveProfile noseCentreProfile(const GrooveShape& g, double flankAllowance, double floorAllowance, double noseRadius);

// I26: the side of the groove's inside as its profile passes run (from the start side to the far
// side): on the left (G41) when h and d have the same sign, else on the right (G42).
CompensationSide grooveInsideSide(const GrooveFrame& frame);

}  // namespace cyclecert
