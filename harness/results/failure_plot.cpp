#include "harness/results/failure_plot.h"

#include <algorithm>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

constexpr int kArcSteps = 16;  // points along an arc move's swept outline

// The G74.1 cycle record whose moves hold move i, if any.
const CycleRecord* grooveCycleHolding(const Toolpath& path, std::size_t i) {
  for (const CycleRecord& c : path.cycles) {
    if (c.code == "G74.1" && i >= c.firstMove && i < c.firstMove + c.moveCount) return &c;
  }
  return nullptr;
}

// The tool that made move i: its G74.1 cycle's (by the record's line); an engine that records no
// cycles made its moves with the program's only grooving tool, if it has one.
std::optional<GroovingTool> toolAt(const Toolpath& path, std::size_t i,
                                   const std::vector<std::pair<int, GroovingTool>>& tools) {
  if (const CycleRecord* c = grooveCycleHolding(path, i)) {
    for (const auto& [line, tool] : tools) {
      if (line == c->line) return tool;
    }
    return std::nullopt;
  }
  if (path.cycles.empty() && tools.size() == 1) return tools.front().second;
  return std::nullopt;
}

// The moves a failure points at: each finding's, and the first divergence from the path compared.
std::vector<std::size_t> witnessedMoves(const std::vector<Finding>& findings, const std::optional<PlotComparison>& other) {
  std::vector<std::size_t> moves;
  const auto add = [&](std::size_t i) {
    if (std::find(moves.begin(), moves.end(), i) == moves.end()) moves.push_back(i);
  };
  for (const Finding& f : findings) {
    if (f.move) add(*f.move);
  }
  if (other && other->divergence) add(*other->divergence);
  return moves;
}

// The swept blade at each witnessed move made with a grooving tool, drawn as one more highlight each.
void addSweptBlades(PlotInput& plot, const ProgramSpec& program, const Toolpath& path,
                    const std::vector<std::size_t>& moves) {
  const auto tools = groovingToolsOf(program);
  if (tools.empty()) return;
  for (const std::size_t i : moves) {
    if (i >= path.moves.size()) continue;
    const auto tool = toolAt(path, i, tools);
    if (!tool) continue;
    Highlight h;
    h.label = "the grooving tool's swept blade (I " + shortDecimalText(tool->width) + "): move " + std::to_string(i);
    h.regions.push_back(sweptBlade(path, i, *tool));
    plot.highlights.push_back(std::move(h));
  }
}

}  // namespace

std::vector<std::pair<int, GroovingTool>> groovingToolsOf(const ProgramSpec& program) {
  std::vector<std::pair<int, GroovingTool>> tools;
  for (const GrooveSpec& g : program.grooves) {
    if (g.toolWidth > 0) tools.push_back({g.line, GroovingTool{g.toolWidth, g.widthSign}});
  }
  return tools;
}

std::vector<Point> sweptBlade(const Toolpath& path, std::size_t i, const GroovingTool& tool) {
  const Segment s = path.segment(i);
  std::vector<Point> along;
  const int steps = s.kind == SegmentKind::Line ? 1 : kArcSteps;
  for (int k = 0; k <= steps; ++k) along.push_back(pointAt(s, static_cast<double>(k) / steps));
  const Point blade{0, -tool.widthSign * tool.width};
  std::vector<Point> region = along;
  for (auto p = along.rbegin(); p != along.rend(); ++p) region.push_back(*p + blade);
  return region;
}

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
    const JudgeInput input = judgeInputFor(request, r.path);
    plot = judgePlot(input, findings, title);
    addSweptBlades(plot, input.program, r.path, witnessedMoves(findings, other));
  } catch (const std::exception&) {
    // A program the oracles cannot read still has a path to show, on the cycles the engine recorded
    // (and no grooving tool they read to draw).
    plot = plotInputFor(r.path, title);
  }
  if (other) addComparison(plot, engineName, *other);
  return plot;
}

}  // namespace cyclecert
