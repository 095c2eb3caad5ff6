#pragma once
// The picture of a failing result, kept in results.jsonl so that a report drawn later needs neither
// the engine nor the case: the case's contours and stock, the engine's path, each finding's witness
// and, when there is something to compare with (the case's expected toolpath, or another engine's),
// that path over it with the first divergence ringed. `cyclecert diff` draws its overlay the same way.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/spec/spec_case.h"
#include "oracles/judgement.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

// A toolpath drawn over the engine's: whose it is, and the first move where the two part.
struct PlotComparison {
  std::string label;  // "expected", or the other engine's name
  Toolpath path;
  std::optional<std::size_t> divergence;
};

// Draws `other` over the plot's path, labels both and rings the end of each one's diverging move.
void addComparison(PlotInput& plot, const std::string& pathLabel, const PlotComparison& other);

// G74.1's grooving tool as its program gives it (docs/g74_1.md I12): the width r (I, mm) and the
// direction of d along X; the blade spans from the programmed point r towards −sign(d).
struct GroovingTool {
  double width = 0;
  int widthSign = -1;
};

// The grooving tool of each G74.1 cycle of the oracles' reading of a program (GrooveSpec), by the
// line of its second block (the line its cycle record carries); a cycle without I (a pointed tool)
// is left out. Empty for a program without G74.1.
std::vector<std::pair<int, GroovingTool>> groovingToolsOf(const ProgramSpec& program);

// The region a grooving tool's end face sweeps along move i of `path`: the move and the move moved
// by the blade's width, joined (an arc followed along its length).
std::vector<Point> sweptBlade(const Toolpath& path, std::size_t i, const GroovingTool& tool);

// The plot of engine `engineName`'s result `r` on case `c` with the findings it drew; nothing when
// the engine gave neither a toolpath nor an alarm (an engine failure, not applicable). A finding at
// a move of a G74.1 cycle cut with a grooving tool, or the first divergence from `other` there,
// also draws the blade's swept rectangle on that move of the engine's path.
std::optional<PlotInput> failurePlot(const SpecCase& c, const EngineResult& r, const std::string& engineName,
                                     const std::vector<Finding>& findings, double tolerance,
                                     const std::optional<PlotComparison>& other);

}  // namespace cyclecert
