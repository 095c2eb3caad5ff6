#pragma once
// A pointed tool's round nose in the G74.1 replay (docs/g74_1.md I26; groove_replay.h): the moves are
// judged by the nose centre (the control point − R·tip), the tool is the disc of radius R around it.
// A move sweeps the disc along it — the Minkowski sum of the move and the disc — which must not
// enter the true part (no-gouge), nor material still standing when it is a rapid (rapids-in-air);
// a feed removes that sweep and its shadow (the tool's body trailing behind the nose, as a point's
// shadow). The groove a nose can empty is the target opened by the disc (what discs inside it
// reach): its concave floor corners keep a fillet of R, as any compensated contour leaves them.
#include <vector>

#include "oracles/material/region.h"
#include "oracles/material/tool_shape.h"
#include "reference/model/geometry.h"

namespace cyclecert {

// The disc's polygon about the origin: inscribed, its sides' sagitta within chordTolerance.
std::vector<Point> noseDisc(double radius, double chordTolerance);

// The disc of radius R with its shadow of `shadowLength` along the unit vector `shadowDir` (0: the
// disc alone), as a shape to sweep along a move (sweptConvexShape, tool_shape.h): made once per
// replay, swept move after move.
SweptShape noseShape(double radius, Point shadowDir, double shadowLength, double chordTolerance);

// `region` opened by a disc of radius R: the union of the discs inside it.
BgRegion openedBy(const BgRegion& region, double radius);

}  // namespace cyclecert
