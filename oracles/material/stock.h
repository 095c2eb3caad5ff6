#pragma once
// The regions the oracles judge against: the stock a cycle starts from (a bar, a polygon, or the
// stock the cycle implies) and the part region that no move may enter.
// All in plane coordinates (z, x radius); arcs flattened within `chordTolerance` (region.h: chords
// lie on the arc's centre side, within the tolerance).
#include <vector>

#include "oracles/material/region.h"

namespace cyclecert {

// A bar of the given diameter: x ∈ [0, diameter/2], z ∈ [frontZ − length, frontZ]. Empty when the
// diameter or the length is not positive.
BgRegion barStock(double diameter, double length, double frontZ);

// The region an explicit outline encloses (regionFrom: either orientation; throws
// std::invalid_argument when it crosses itself).
BgRegion polygonStock(const std::vector<Point>& outline);

// The stock a cycle implies: the region bounded by the finish shape A → B → … → C and the line
// through A parallel to the cut axis, from A to the point of that line level with C ("above C"):
// everything between the start point's level and the shape, over the shape's span.
// `away` gives the frame (depth axis along it, cut axis across it; DepthFrame). Empty for an empty
// shape; std::invalid_argument when the outline crosses itself (a shape rising past A's level,
// which the rules forbid).
BgRegion impliedStock(const std::vector<Segment>& finishShape, Point away, double chordTolerance);

// The part grown by the allowances, for the no-gouge oracle: every point that has a point of the
// rough profile (the finish shape shifted by the allowance, from B' — or from A' for type II —
// to C') on its `away` side along the depth axis, down to `reach` beyond the profile's deepest
// point (a flat bottom). For a profile that is a graph over the cut axis (vertical walls allowed)
// this is the region between the profile and that bottom over the profile's span; a profile that
// turns back a little along the cut axis gives the union of every chord's region. Empty for an
// empty profile.
BgRegion partRegion(const std::vector<Segment>& roughProfile, Point away, double reach,
                    double chordTolerance);

}  // namespace cyclecert
