#pragma once
// The oracles' material model on Boost.Geometry, in one include:
// - region.h: Bg types, flatten (arcs → chords within a tolerance), outlines ⇄ regions, eroded,
//   without, tidy; the conventions (orientation, the side of the chord error).
// - depth_frame.h: the cycle's depth and cut axes, from the `away` direction.
// - stock.h: bar, polygon and implied stocks; the part region for no-gouge.
// - material_model.h: shadows of feed moves, the MaterialModel replaying a toolpath, crossings.
// - thickness.h: how thick a region stands above a profile, for completeness.
#include "oracles/material/depth_frame.h"
#include "oracles/material/material_model.h"
#include "oracles/material/region.h"
#include "oracles/material/stock.h"
#include "oracles/material/thickness.h"
