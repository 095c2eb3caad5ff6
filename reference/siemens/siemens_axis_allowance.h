#pragma once
// CYCLE95's axis-parallel finishing allowances FALZ / FALX (CYCLE95.PARAMS, CYCLE95.ROUGH notes,
// interpretation): an allowance is left on the stock side of every element — FALZ on the faces
// (elements whose stock lies towards +z or towards −z), FALX above every element (the part lies
// below its profile). The profile is the contour-parallel profile grown by the rectangle
// ±FALZ × ±FALX (a Minkowski sum): each element moved by the rectangle's corner on its stock side (a
// face falling towards the axis — a groove's near wall — moves towards −z, never into the part), the
// gaps at convex corners closed along the rectangle's top edge, the overlaps at concave corners
// trimmed to their crossing. The part's face below the contour's first point is a wall facing +z:
// the profile begins at that point moved by (+FALZ, +FALX). In the stock-removal frame
// (siemens_roughing_frame.h: travel towards −z, the stock above and on the right of travel).
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

// `profile` grown by `allowance` (z: FALZ, x: FALX in the frame, both ≥ 0). Throws OffsetError
// (offset.h, Interference) when two elements meant to meet at a concave corner do not (the
// allowance wider than a groove).
std::vector<Segment> withAxisAllowances(const std::vector<Segment>& profile, Point allowance);

}  // namespace cyclecert
