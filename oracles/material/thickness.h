#pragma once
// How thick a region stands above a profile, measured along the depth axis — what the completeness
// oracle compares with Δd (or ε after the semi-finish pass).
#include <optional>
#include <vector>

#include "oracles/material/depth_frame.h"
#include "oracles/material/region.h"

namespace cyclecert {

struct Thickest {
  double thickness = 0;  // mm along the depth axis, ≥ 0
  Point where;           // the point of the region where it is reached
  Point beneath;         // the profile point below it (`where` − thickness·away)
};

// The largest distance, along the depth axis, from the profile up (along `away`) to a point of the
// region standing above it: each point of the region's boundary is measured against the profile
// beneath it at the same cut-axis coordinate. Only where the region spans some length of the
// profile along the cut axis: walls of the profile parallel to the depth axis are beneath nothing
// (material beside a shoulder is measured from the step below it), and material beyond the
// profile's ends (outside its span) or under it is not measured.
//
// Tolerance. The profile is flattened within chordTolerance (pass the tolerance the region's arcs
// were flattened with). Next to a point where the profile is steep, flattening moves points by up
// to chordTolerance sideways, which reads as up to √(r·chordTolerance/2) of thickness along the
// depth axis (region.h). So "the profile beneath" a point at cut coordinate c is the highest the
// profile comes within c ± w (and at most w above the point), with w = 2·chordTolerance + the
// booleans' resolution (4 × kBooleanResolution × the region's size). Then, if every point of the
// exactly cut material stands at most T above the exact profile, the result is at most
// T + 2·chordTolerance (+ the resolution): a completeness verdict adds 2·chordTolerance to its ε
// and has no false finding. The price is the other way: where the profile rises along the cut axis
// with slope s, material may read up to s·w thinner than it is (nothing on flat ground, 0.002 on a
// 45° taper with chordTolerance 0.001).
// Both boundaries are piecewise linear, so the largest distance is found at the ends of the
// overlaps between region edges and profile chords (and w inside them). Nothing when no part of
// the region stands above the profile.
// Cost: O(region edges × profile chords each overlaps), no Boost boolean. Measuring the model's
// remaining material directly (without subtracting partRegion first) gives the same answer, far
// more cheaply.
std::optional<Thickest> thickestAbove(const BgRegion& region, const std::vector<Segment>& profile,
                                      Point away, double chordTolerance);

// The deepest the region comes over the cut coordinates [c0, c1]; nothing when it has no point
// there. One pass over its edges.
std::optional<double> deepestWithin(const BgRegion& region, const DepthFrame& frame, double c0, double c1);

}  // namespace cyclecert
