#include "harness/judge/judging.h"

#include <sstream>

#include "harness/judge/siemens_reading.h"
#include "oracles/material_replay.h"
#include "reference/gcode/parser.h"
#include "reference/model/profile.h"
#include "reference/model/toolpath_json.h"

namespace cyclecert {

JudgeRequest judgeRequestFor(const SpecCase& c) {
  JudgeRequest r;
  r.program = planRequestFor(c);  // with the case's SINUMERIK subprograms
  r.stock = c.stock;
  r.settings.epsilon = c.tolerance;
  return r;
}

JudgeInput judgeInputFor(const JudgeRequest& request, Toolpath path) {
  const PlanRequest& p = request.program;
  JudgeInput in;
  if (const Profile& profile = requestedProfile(p); profile.dialect == Dialect::Siemens) {
    in.program = readSiemensProgramSpec(p, profile);
  } else {
    const ReadRequest read = readRequest(p, profile);
    in.program = readProgramSpec(*read.program, *read.profile, read.params, p.options.tool, p.options.mdi);
  }
  if (request.stock) {
    in.stock.kind = request.stock->bar ? Stock::Bar : Stock::Polygon;
    in.stock.diameter = request.stock->diameter;
    in.stock.length = request.stock->length;
    in.stock.frontZ = request.stock->frontZ;
    in.stock.outline = request.stock->outline;
  }
  in.path = std::move(path);
  in.settings = request.settings;
  return in;
}

std::string findingsText(const std::vector<Finding>& findings) {
  std::ostringstream s;
  for (const Finding& f : findings) {
    s << f.oracle;
    if (f.move) s << " (move " << *f.move << ")";
    s << ": " << f.message << "  [rules:";
    for (const auto& r : f.rules) s << " " << r;
    s << "]\n";
  }
  return s.str();
}

nlohmann::json findingsJson(const std::vector<Finding>& findings) {
  nlohmann::json out = nlohmann::json::array();
  for (const Finding& f : findings) {
    nlohmann::json j{{"oracle", f.oracle}, {"rules", f.rules}, {"message", f.message}};
    j["move"] = f.move ? nlohmann::json(*f.move) : nlohmann::json(nullptr);
    nlohmann::json witness = nlohmann::json::object();
    if (!f.witness.regions.empty()) {
      nlohmann::json regions = nlohmann::json::array();
      for (const auto& region : f.witness.regions) {
        nlohmann::json pts = nlohmann::json::array();
        for (Point p : region) pts.push_back(toJson(p));
        regions.push_back(pts);
      }
      witness["regions"] = regions;
    }
    if (f.witness.point) witness["point"] = toJson(*f.witness.point);
    if (f.witness.segment) witness["segment"] = {{"from", toJson(f.witness.segment->from)}, {"to", toJson(f.witness.segment->to)}};
    j["witness"] = witness;
    out.push_back(j);
  }
  return out;
}

PlotInput judgePlot(const JudgeInput& in, const std::vector<Finding>& findings, const std::string& title,
                    std::optional<std::size_t> materialAfterMove) {
  PlotInput plot;
  plot.title = title;
  plot.path = in.path;
  for (const CycleSpec& c : in.program.cycles) {
    for (const Segment& s : c.shape) {
      plot.finish.segments.push_back(s);
      plot.rough.segments.push_back(s.shifted(c.allowance));
    }
  }
  if (in.program.singleRoughingCycle()) {
    try {
      // The plot shows the stock the oracles used (a reach of 0 leaves the implied band at its shape).
      if (materialAfterMove) {
        if (auto outlines = materialAfter(in, *materialAfterMove)) plot.stock = std::move(*outlines);
      } else if (const auto replay = replayMaterial(in)) {
        plot.stock = outlinesOf(replay->stock);
      }
    } catch (const std::invalid_argument&) {
      // an unusable stock is reported by the oracles; the plot goes without it
    }
  }
  for (const Finding& f : findings) {
    Highlight h;
    h.label = f.oracle + (f.move ? ": move " + std::to_string(*f.move) : std::string()) + " — " + f.message;
    h.regions = f.witness.regions;
    if (f.witness.segment) h.segments.push_back(*f.witness.segment);
    if (f.witness.point) h.points.push_back(*f.witness.point);
    plot.highlights.push_back(h);
  }
  return plot;
}

}  // namespace cyclecert
