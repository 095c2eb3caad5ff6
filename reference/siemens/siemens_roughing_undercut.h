#pragma once
// Undercuts (CYCLE95.UNDERCUT): where the roughing profile turns back towards the depth axis and
// rises again later — a pocket the axis-parallel passes cannot reach from the entry side. In the
// stock-removal frame (siemens_roughing_frame.h).
#include <optional>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

struct Undercut {
  double top = 0;              // the lowest roughing level that passed over the pocket (strictly above its rim): its stock lies below
  std::vector<Segment> down;   // the profile from where it turns back down to the pocket's lowest point
  std::vector<Segment> up;     // from the lowest point until the profile is back at `top` (or ends)
  double bottom() const;       // the lowest point's x
};

// The part of `s` between two of its points (an arc keeps its centre and direction).
Segment portionOf(const Segment& s, Point from, Point to);

// A portion of a profile element whose ends coincide: it has no length. (Segment::length reads an
// arc whose ends coincide as a full circle; no element of a roughing profile is one, so a portion
// of it with equal ends is a point: nothing to cut, nothing to emit.)
bool hasNoLength(const Segment& portion);

// Where the profile starts to descend on `s` (towards its end), CYCLE95.UNDERCUT's rim: its start
// when it leaves downwards or when `s` is an arc starting at its top (its start tangent along the
// cut axis, the circle falling away on both sides), the top of an arc inside it, or nothing.
std::optional<Point> descentStartOn(const Segment& s);

// The lowest of the levels (from the top down) strictly above `x` (the top when none is): the level
// through a rim stops there (its cleanup turns back with the profile), so only the levels above it
// pass over the pocket below.
double lowestLevelAbove(const std::vector<double>& levels, double x);

// The undercuts of `profile`, in order along it. `levels` are the roughing levels from the top down
// (the top of the profile first): a pocket's stock lies below the lowest level strictly above its rim
// (the level through a rim stops there).
std::vector<Undercut> findUndercuts(const std::vector<Segment>& profile, const std::vector<double>& levels);

}  // namespace cyclecert
