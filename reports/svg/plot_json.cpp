#include "reports/svg/plot_json.h"

#include "reference/model/toolpath_json.h"

namespace cyclecert {

using nlohmann::json;

namespace {

json segmentJson(const Segment& s) {
  json j{{"shape", shapeName(s.kind)}, {"from", toJson(s.from)}, {"to", toJson(s.to)}};
  if (s.isArc()) j["center"] = toJson(s.center);
  return j;
}

json pointsJson(const std::vector<Point>& points) {
  json out = json::array();
  for (const Point& p : points) out.push_back(toJson(p));
  return out;
}

json segmentsJson(const std::vector<Segment>& segments) {
  json out = json::array();
  for (const Segment& s : segments) out.push_back(segmentJson(s));
  return out;
}

json outlinesJson(const std::vector<std::vector<Point>>& outlines) {
  json out = json::array();
  for (const auto& ring : outlines) out.push_back(pointsJson(ring));
  return out;
}

[[noreturn]] void fail(const std::string& where, const std::string& expected) {
  throw ToolpathFormatError(where + ": expected " + expected);
}

const json& arrayAt(const json& j, const char* key, const std::string& where) {
  static const json empty = json::array();
  if (!j.contains(key)) return empty;
  if (!j[key].is_array()) fail(where + "/" + key, "an array");
  return j[key];
}

Segment segmentFromJson(const json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "a segment object");
  Segment s;
  const std::string shape = j.value("shape", std::string("line"));
  if (shape == "line") s.kind = SegmentKind::Line;
  else if (shape == "arc_cw") s.kind = SegmentKind::ArcCW;
  else if (shape == "arc_ccw") s.kind = SegmentKind::ArcCCW;
  else fail(where + "/shape", "\"line\", \"arc_cw\" or \"arc_ccw\"");
  for (const char* key : {"from", "to"}) {
    if (!j.contains(key)) fail(where + "/" + key, "a point (field missing)");
  }
  s.from = pointFromJson(j["from"], where + "/from");
  s.to = pointFromJson(j["to"], where + "/to");
  if (s.isArc()) {
    if (!j.contains("center")) fail(where + "/center", "a point for an arc (field missing)");
    s.center = pointFromJson(j["center"], where + "/center");
  }
  return s;
}

std::vector<Segment> segmentsFromJson(const json& j, const char* key, const std::string& where) {
  std::vector<Segment> out;
  const json& a = arrayAt(j, key, where);
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(segmentFromJson(a[i], where + "/" + key + "/" + std::to_string(i)));
  return out;
}

std::vector<Point> pointsFromJson(const json& a, const std::string& where) {
  if (!a.is_array()) fail(where, "an array of points");
  std::vector<Point> out;
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(pointFromJson(a[i], where + "/" + std::to_string(i)));
  return out;
}

std::vector<std::vector<Point>> outlinesFromJson(const json& j, const char* key, const std::string& where) {
  std::vector<std::vector<Point>> out;
  const json& a = arrayAt(j, key, where);
  for (std::size_t i = 0; i < a.size(); ++i) out.push_back(pointsFromJson(a[i], where + "/" + key + "/" + std::to_string(i)));
  return out;
}

// A toolpath inside the plot: its errors name the field from the plot's root.
Toolpath toolpathAt(const json& j, const char* key) {
  try {
    return toolpathFromJson(j[key]);
  } catch (const ToolpathFormatError& e) {
    const std::string what = e.what();
    throw ToolpathFormatError("/" + std::string(key) + (what.rfind('/', 0) == 0 ? what : ": " + what));
  }
}

}  // namespace

json plotToJson(const PlotInput& plot) {
  json highlights = json::array();
  for (const Highlight& h : plot.highlights) {
    highlights.push_back({{"label", h.label},
                          {"regions", outlinesJson(h.regions)},
                          {"segments", segmentsJson(h.segments)},
                          {"points", pointsJson(h.points)},
                          {"label_shown", h.labelShown}});
  }
  json j{{"title", plot.title},
         {"finish", segmentsJson(plot.finish.segments)},
         {"rough", segmentsJson(plot.rough.segments)},
         {"path", toJson(plot.path)},
         {"stock", outlinesJson(plot.stock)},
         {"highlights", highlights}};
  if (plot.overlay) {
    j["overlay"] = toJson(*plot.overlay);
    j["path_label"] = plot.pathLabel;
    j["overlay_label"] = plot.overlayLabel;
  }
  return j;
}

PlotInput plotFromJson(const json& j) {
  if (!j.is_object()) fail("(plot)", "a plot object");
  PlotInput plot;
  plot.title = j.value("title", std::string());
  plot.finish.segments = segmentsFromJson(j, "finish", "");
  plot.rough.segments = segmentsFromJson(j, "rough", "");
  if (j.contains("path")) plot.path = toolpathAt(j, "path");
  plot.stock = outlinesFromJson(j, "stock", "");
  const json& highlights = arrayAt(j, "highlights", "");
  for (std::size_t i = 0; i < highlights.size(); ++i) {
    const std::string where = "/highlights/" + std::to_string(i);
    const json& h = highlights[i];
    if (!h.is_object()) fail(where, "a highlight object");
    Highlight out;
    out.label = h.value("label", std::string());
    out.regions = outlinesFromJson(h, "regions", where);
    out.segments = segmentsFromJson(h, "segments", where);
    if (h.contains("points")) out.points = pointsFromJson(h["points"], where + "/points");
    out.labelShown = h.value("label_shown", false);
    plot.highlights.push_back(std::move(out));
  }
  if (j.contains("overlay")) {
    plot.overlay = toolpathAt(j, "overlay");
    plot.pathLabel = j.value("path_label", std::string());
    plot.overlayLabel = j.value("overlay_label", std::string());
  }
  return plot;
}

}  // namespace cyclecert
