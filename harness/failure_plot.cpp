#include "harness/failure_plot.h"

#include "harness/judging.h"
#include "harness/reference_plan.h"

namespace cyclecert {

void addComparison(PlotInput& plot, const std::string& pathLabel, const PlotComparison& other) {
  plot.overlay = other.path;
  plot.pathLabel = pathLabel;
  plot.overlayLabel = other.label;
  if (!other.divergence) return;
  const std::size_t i = *other.divergence;
  Highlight marker;
  marker.label = "first divergence: move " + std::to_string(i);
  marker.labelShown = true;
  if (i < plot.path.moves.size()) marker.points.push_back(plot.path.moves[i].to);
  if (i < other.path.moves.size()) marker.points.push_back(other.path.moves[i].to);
  plot.highlights.push_back(marker);
}

std::optional<PlotInput> failurePlot(const SpecCase& c, const EngineResult& r, const std::string& engineName,
                                     const std::vector<Finding>& findings, double tolerance,
                                     const std::optional<PlotComparison>& other) {
  if (r.kind != EngineResult::Planned && r.kind != EngineResult::Alarmed) return std::nullopt;
  const std::string title = engineName + " \u2014 " + c.id;
  PlotInput plot;
  try {
    JudgeRequest request = judgeRequestFor(c);
    request.settings.epsilon = tolerance;
    plot = judgePlot(judgeInputFor(request, r.path), findings, title);
  } catch (const std::exception&) {
    // A program the oracles cannot read still has a path to show, on the cycles the engine recorded.
    plot = plotInputFor(r.path, title);
  }
  if (other) addComparison(plot, engineName, *other);
  return plot;
}

}  // namespace cyclecert
