#pragma once
// How thick a region stands above a profile, measured along the depth axis — what the completeness
// oracle compares with Δd (or ε after the semi-finish pass).
#include <optional>
#include <vector>

#include "oracles/material/region.h"

namespace cyclecert {

struct Thickest {
  double thickness = 0;  // mm along the depth axis, ≥ 0
  Point where;           // the point of the region where it is reached
  Point beneath;         // the profile point below it (`where` − thickness·away)
};

// The largest distance, along the depth axis, from the profile up (along `away`) to a point of the
// region standing above it: each point of the region's boundary is measured against the nearest
// profile point beneath it at the same cut-axis coordinate. Only where the region spans some length
// of the profile along the cut axis: walls of the profile parallel to the depth axis are beneath
// nothing (material beside a shoulder is measured from the step below it), and material beyond the
// profile's ends (outside its span) or under it is not measured.
// The profile is flattened within chordTolerance — pass the tolerance the region's arcs were
// flattened with, so that chords coincide. Both boundaries are then piecewise linear, so the largest
// distance lies at the ends of the overlaps between region edges and profile chords.
// Resolution: the booleans place points to within ~size·10⁻⁷ (region.h), which beside a steep chord
// would read as thickness; so "some length", and the window within which the profile beneath a point
// is taken at its highest, are r = 10 × kBooleanResolution × the region's size (6e-5 mm for 60 mm).
// Thicknesses are exact for the flattened profile up to a slope·r where the region meets a chord
// of that slope. Nothing when no part of the region stands above the profile.
// Cost: O(region edges × profile chords each overlaps), no Boost boolean. Measuring the model's
// remaining material directly (without subtracting partRegion first) gives the same answer (to the
// booleans' resolution) far more cheaply.
std::optional<Thickest> thickestAbove(const BgRegion& region, const std::vector<Segment>& profile,
                                      Point away, double chordTolerance);

}  // namespace cyclecert
