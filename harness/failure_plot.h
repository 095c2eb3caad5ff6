#pragma once
// The picture of a failing result, kept in results.jsonl so that a report drawn later needs neither
// the engine nor the case: the case's contours and stock, the engine's path, each finding's witness
// and, when there is something to compare with (the case's expected toolpath, or another engine's),
// that path over it with the first divergence ringed. `cyclecert diff` draws its overlay the same way.
#include <optional>
#include <string>
#include <vector>

#include "harness/engines/engine.h"
#include "harness/spec_case.h"
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

// The plot of engine `engineName`'s result `r` on case `c` with the findings it drew; nothing when
// the engine gave neither a toolpath nor an alarm (an engine failure, not applicable).
std::optional<PlotInput> failurePlot(const SpecCase& c, const EngineResult& r, const std::string& engineName,
                                     const std::vector<Finding>& findings, double tolerance,
                                     const std::optional<PlotComparison>& other);

}  // namespace cyclecert
