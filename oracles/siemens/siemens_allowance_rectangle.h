#pragma once
// The oracles' own reading of CYCLE95's axis-parallel allowances FALZ / FALX (CYCLE95.PARAMS and
// CYCLE95.ROUGH notes, interpretation: the profile grown by the rectangle ±FALZ × ±FALX, each
// allowance on the stock side of every element). Written apart from the reference's
// reference/siemens/siemens_axis_allowance.* (a different construction), so that the two readings
// catch each other's mistakes.
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

// `profile` (in the stock-removal frame: travel towards −z, the part below) grown by the rectangle
// ±allowance.z × ±allowance.x. Throws OffsetError (offset.h, Interference) where the grown sides of
// a groove do not meet on its elements (the groove narrower than 2·FALZ).
std::vector<Segment> grownByAllowanceRectangle(const std::vector<Segment>& profile, Point allowance);

}  // namespace cyclecert
