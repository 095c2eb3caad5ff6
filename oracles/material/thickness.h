#pragma once
// How thick a region stands above a profile, measured along the depth axis — what the completeness
// oracle compares with Δd (or ε after the semi-finish pass).
#include <optional>
#include <vector>

#include "oracles/material/cut_envelope.h"
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
// Tolerance. A profile that is a graph over the cut axis is measured exactly, its arcs as arcs
// (one that turns back along it, against chords within chordTolerance). The region's points may
// stand up to chordTolerance sideways of where they belong (pass the tolerance its arcs were
// flattened with, or a finer one when its vertices lie on the arcs exactly); next to a point where
// the profile is steep, that reads as thickness along the depth axis. So "the profile beneath" a point at cut
// coordinate c is the highest the profile comes within c ± w (and at most w above the point), with
// w = 2·chordTolerance + the booleans' resolution (4 × kBooleanResolution × the region's size).
// The price is the other way: where the profile rises along the cut axis with slope s, material
// may read up to s·w thinner than it is (nothing on flat ground, 0.002 on a 45° taper with
// chordTolerance 0.001).
// The region's boundary is piecewise linear; its distance above a line of the profile is largest at
// the ends of their overlap (and w inside them), above an arc also where the arc's tangent is
// parallel to the edge. Nothing when no part of the region stands above the profile.
// Cost: O(region edges × profile pieces each overlaps), no Boost boolean. Measuring the model's
// remaining material directly (without subtracting partRegion first) gives the same answer, far
// more cheaply.
std::optional<Thickest> thickestAbove(const BgRegion& region, const std::vector<Segment>& profile,
                                      Point away, double chordTolerance);

// The same measure for material that stands at most up to `top` (frame coordinates, pieces with
// c0 < c1) at each cut coordinate: only the top is measured. For a profile that is a graph over
// the cut axis it bounds thickestAbove of the material left beyond the part (MaterialModel::
// topWithin gives its top): beneath a graph, a point lower at the same cut coordinate stands no
// thicker; the region measures up to a few µm more only through its noise (chords of the part's
// arcs, points the booleans round). The resolution is the top's own. No Boost, no region.
std::optional<Thickest> thickestBeneath(const std::vector<CutEnvelope::Piece>& top, const std::vector<Segment>& profile,
                                        Point away, double chordTolerance);

// Whether thickestBeneath is more than `limit`: the oracles' question, answered without measuring
// the top's edges that stand no more than `limit` above the lowest of the profile beneath them.
bool standsThickerThan(const std::vector<CutEnvelope::Piece>& top, const std::vector<Segment>& profile, Point away,
                       double chordTolerance, double limit);

}  // namespace cyclecert
