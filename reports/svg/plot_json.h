#pragma once
// A plot's input (PlotInput) as JSON, so that a run can keep the picture of each failure in its
// results.jsonl and a report drawn later (`cyclecert report`) needs neither the engine nor the case:
//
// {"title": "…",
//  "finish": [segment], "rough": [segment],           segment: {"shape": "line"|"arc_cw"|"arc_ccw",
//                                                               "from": {x, z}, "to": {x, z}, "center"?: {x, z}}
//  "path": toolpath,                                   the canonical toolpath JSON (toolpath_json.h)
//  "stock": [[{x, z}, …], …],                          outlines
//  "highlights": [{"label", "regions": [[{x, z}…]…], "segments": [segment], "points": [{x, z}],
//                  "label_shown": bool}],
//  "overlay"?: toolpath, "path_label"?: "…", "overlay_label"?: "…"}
//
// x is the radius in mm, as everywhere. Reading names the field of a malformed plot (a JSON pointer).
#include <nlohmann/json.hpp>

#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

nlohmann::json plotToJson(const PlotInput& plot);
PlotInput plotFromJson(const nlohmann::json& j);  // throws ToolpathFormatError naming the field

}  // namespace cyclecert
