// SVG picture of a toolpath (see toolpath_svg.h). Everything is transformed into pixel space here
// and written with fixed precision, so stroke widths and text sizes are in pixels.
#include "reports/svg/toolpath_svg.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <set>
#include <vector>

namespace cyclecert {

namespace {

// ---- canvas layout (pixels) -------------------------------------------------------------------

constexpr double kCanvasWidth = 900;
constexpr double kCanvasHeight = 600;
constexpr double kPlotLeft = 90;     // room for the diameter labels
constexpr double kPlotRight = 875;
constexpr double kPlotTop = 80;      // room for the title and the alarm
constexpr double kPlotBottom = 545;  // room for the legend
constexpr double kLegendY = 578;
constexpr double kOverlayLegendY = 562;  // with an overlay the legend has two rows: 562 and 584
constexpr double kLegendRowSpacing = 22;
constexpr std::size_t kMaxLegendLabel = 48;  // characters of an engine name in the legend
constexpr double kLabelSpacing = 14;  // minimum vertical distance between diameter labels
constexpr std::size_t kMaxDiameterLabels = 12;
// Size bounds (README "Limits"): a toolpath may hold a million moves (kMostMovesPerToolpath) and
// a judgement thousands of findings; the picture draws the first ones and says how many it left
// out, so that an SVG stays a few megabytes (the toolpath JSON and report.json hold everything).
constexpr std::size_t kMostMovesDrawn = 50'000;
constexpr std::size_t kMostFindingsDrawn = 50;

constexpr const char* kFinishColour = "#222222";
constexpr const char* kRoughColour = "#e08a00";
constexpr const char* kRapidColour = "#d62728";
constexpr const char* kFeedColour = "#1f4fd6";
constexpr const char* kAxisColour = "#666666";
constexpr const char* kAlarmColour = "#c00000";
constexpr const char* kHighlightColour = "#d400d4";
// The overlay (a second engine's toolpath): colours none of the other elements use, so that its
// rapids are not taken for the (orange, dashed) rough contour.
constexpr const char* kOverlayRapidColour = "#9467bd";
constexpr const char* kOverlayFeedColour = "#2ca02c";
constexpr const char* kRapidDash = "6 4";
constexpr const char* kRoughDash = "4 3";
constexpr const char* kAxisDash = "10 3 2 3";  // dash-dot

constexpr double kTwoPi = 2 * std::numbers::pi;

// ---- numbers ----------------------------------------------------------------------------------

bool isFinite(Point p) { return std::isfinite(p.z) && std::isfinite(p.x); }

// Fixed 3 decimals, locale independent; non-finite values are written as 0, -0 as 0, and
// absurdly large values (far off the canvas) are clamped so that the text stays short.
std::string num(double v) {
  if (!std::isfinite(v) || std::fabs(v) < 0.0005) v = 0;
  v = std::clamp(v, -1e9, 1e9);
  std::array<char, 64> buf{};
  auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v, std::chars_format::fixed, 3);
  if (ec != std::errc{}) return "0";
  return std::string(buf.data(), end);
}

// A value for people: at most 3 decimals, trailing zeros dropped ("54", "54.5").
std::string shortNum(double v) {
  std::string s = num(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (s.back() == '.') s.pop_back();
  return s;
}

// ---- arcs, in world coordinates (own helpers: only Segment fields are used) -------------------

double dist(Point a, Point b) { return std::hypot(a.z - b.z, a.x - b.x); }
bool samePoint(Point a, Point b) { return dist(a, b) <= kGeomEps; }
double angleOf(Point centre, Point p) { return std::atan2(p.x - centre.x, p.z - centre.z); }

// Angle reduced into [0, 2π).
double wrap(double a) {
  double r = std::fmod(a, kTwoPi);
  return r < 0 ? r + kTwoPi : r;
}

bool drawableArc(const Segment& s) {
  return s.isArc() && isFinite(s.center) && dist(s.center, s.from) > kGeomEps;
}

// Unsigned angle swept from `from` to `to` in the arc's direction, in (0, 2π]; equal end points
// mean a full circle.
double sweepMagnitude(const Segment& s) {
  const double a0 = angleOf(s.center, s.from);
  const double a1 = angleOf(s.center, s.to);
  const double d = s.kind == SegmentKind::ArcCCW ? wrap(a1 - a0) : wrap(a0 - a1);
  return d < 1e-12 ? kTwoPi : d;
}

// Whether the arc passes through the direction `angle` (seen from its centre).
bool arcContainsAngle(const Segment& s, double angle) {
  const double a0 = angleOf(s.center, s.from);
  const double d = s.kind == SegmentKind::ArcCCW ? wrap(angle - a0) : wrap(a0 - angle);
  return d <= sweepMagnitude(s);
}

// ---- bounds and the world→pixel view ----------------------------------------------------------

struct Box {
  bool empty = true;
  double zMin = 0, zMax = 0, xMin = 0, xMax = 0;

  void add(Point p) {
    if (!isFinite(p)) return;
    if (empty) {
      zMin = zMax = p.z;
      xMin = xMax = p.x;
      empty = false;
      return;
    }
    zMin = std::min(zMin, p.z);
    zMax = std::max(zMax, p.z);
    xMin = std::min(xMin, p.x);
    xMax = std::max(xMax, p.x);
  }

  void add(const Segment& s) {
    add(s.from);
    add(s.to);
    if (!drawableArc(s)) return;
    const double r = dist(s.center, s.from);
    for (int k = 0; k < 4; ++k) {  // the arc's apexes on both axes
      const double angle = k * std::numbers::pi / 2;
      if (arcContainsAngle(s, angle))
        add(Point{s.center.z + r * std::cos(angle), s.center.x + r * std::sin(angle)});
    }
  }
};

// Equal scales on both axes; the drawing is centred in the plot area.
class View {
 public:
  explicit View(Box box) {
    if (box.empty) box.add(Point{});
    double spanZ = box.zMax - box.zMin;
    double spanX = box.xMax - box.xMin;
    // A margin of 5% of the larger span (1 mm for a single point) keeps lines off the frame.
    const double pad = std::max(0.05 * std::max(spanZ, spanX), 1.0);
    spanZ += 2 * pad;
    spanX += 2 * pad;
    const double plotW = kPlotRight - kPlotLeft;
    const double plotH = kPlotBottom - kPlotTop;
    scale_ = std::min(plotW / spanZ, plotH / spanX);
    if (!std::isfinite(scale_) || scale_ <= 0) scale_ = 1;
    const double midZ = (box.zMin + box.zMax) / 2;
    const double midX = (box.xMin + box.xMax) / 2;
    offsetPx_ = (kPlotLeft + kPlotRight) / 2 - midZ * scale_;
    offsetPy_ = (kPlotTop + kPlotBottom) / 2 + midX * scale_;
  }

  double px(double z) const { return offsetPx_ + z * scale_; }
  double py(double x) const { return offsetPy_ - x * scale_; }  // X up: the y flip
  double length(double mm) const { return mm * scale_; }
  // Whether a world level is inside the plot area.
  bool zVisible(double z) const { return px(z) >= kPlotLeft && px(z) <= kPlotRight; }
  bool xVisible(double x) const { return py(x) >= kPlotTop && py(x) <= kPlotBottom; }

 private:
  double scale_ = 1;
  double offsetPx_ = 0;
  double offsetPy_ = 0;
};

// ---- path data ----------------------------------------------------------------------------------

std::string coords(const View& v, Point p) { return num(v.px(p.z)) + " " + num(v.py(p.x)); }

// One SVG elliptical-arc command to `to`. After the y flip, clockwise in the Z-right/X-up plot is
// clockwise on screen, which is SVG's positive-angle direction: sweep-flag 1 for CW, 0 for CCW.
std::string arcCommand(const View& v, double radius, bool largeArc, SegmentKind kind, Point to) {
  const std::string r = num(v.length(radius));
  const char* sweepFlag = kind == SegmentKind::ArcCW ? "1" : "0";
  return "A " + r + " " + r + " 0 " + (largeArc ? "1 " : "0 ") + sweepFlag + " " + coords(v, to);
}

// The drawing commands of one segment, without the initial move-to.
std::string segmentCommands(const View& v, const Segment& s) {
  if (!drawableArc(s)) return "L " + coords(v, s.to);
  const double r = dist(s.center, s.from);
  const double sweep = sweepMagnitude(s);
  if (sweep < kTwoPi - 1e-9) return arcCommand(v, r, sweep > std::numbers::pi, s.kind, s.to);
  // A full circle (or all but a hair of one): SVG draws nothing for an arc whose end points
  // coincide, so go via the diametrically opposite point.
  const Point opposite{2 * s.center.z - s.from.z, 2 * s.center.x - s.from.x};
  return arcCommand(v, r, false, s.kind, opposite) + " " + arcCommand(v, r, false, s.kind, s.to);
}

std::string segmentPathData(const View& v, const Segment& s) {
  return "M " + coords(v, s.from) + " " + segmentCommands(v, s);
}

// One path for a whole contour; a new sub-path starts wherever the segments are not connected.
std::string contourPathData(const View& v, const Contour& c) {
  std::string d;
  std::optional<Point> pen;
  for (const Segment& s : c.segments) {
    if (!pen || !samePoint(*pen, s.from)) d += (d.empty() ? "M " : " M ") + coords(v, s.from);
    d += " " + segmentCommands(v, s);
    pen = s.to;
  }
  return d;
}

// ---- elements -----------------------------------------------------------------------------------

struct Stroke {
  const char* colour;
  double width;
  const char* dash = nullptr;  // stroke-dasharray, none when null
};

std::string strokeAttributes(const Stroke& st) {
  std::string a = " fill=\"none\" stroke=\"" + std::string(st.colour) + "\" stroke-width=\"" +
                  num(st.width) + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
  if (st.dash) a += " stroke-dasharray=\"" + std::string(st.dash) + "\"";
  return a;
}

std::string pathElement(const std::string& cls, const std::string& d, const Stroke& st) {
  return "<path class=\"" + cls + "\" d=\"" + d + "\"" + strokeAttributes(st) + "/>\n";
}

std::string lineElement(const std::string& cls, double x1, double y1, double x2, double y2,
                        const Stroke& st) {
  return "<line class=\"" + cls + "\" x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" +
         num(x2) + "\" y2=\"" + num(y2) + "\"" + strokeAttributes(st) + "/>\n";
}

struct TextStyle {
  double size = 12;
  const char* colour = "#222222";
  const char* anchor = "start";
  bool bold = false;
};

std::string textElement(const std::string& cls, double x, double y, std::string_view content,
                        const TextStyle& ts) {
  std::string e = "<text class=\"" + cls + "\" x=\"" + num(x) + "\" y=\"" + num(y) +
                  "\" font-size=\"" + num(ts.size) + "\" fill=\"" + ts.colour +
                  "\" text-anchor=\"" + ts.anchor + "\"";
  if (ts.bold) e += " font-weight=\"bold\"";
  return e + ">" + svgEscape(content) + "</text>\n";
}

// ---- what is drawn ------------------------------------------------------------------------------

// Move i as a segment; an arc without a centre is drawn as a line.
Segment moveSegment(const Toolpath& path, std::size_t i) {
  const Move& m = path.moves[i];
  Segment s;
  s.kind = m.center ? m.shape : SegmentKind::Line;
  s.from = path.from(i);
  s.to = m.to;
  if (m.center) s.center = *m.center;
  return s;
}

// The points marked "A": each cycle's start point, or the toolpath's start when it has no cycles.
std::vector<Point> startPoints(const Toolpath& path) {
  std::vector<Point> points;
  for (const CycleRecord& c : path.cycles) points.push_back(c.start);
  if (points.empty()) points.push_back(path.start);
  return points;
}

Box drawingBounds(const PlotInput& in) {
  Box box;
  for (const Segment& s : in.finish.segments) box.add(s);
  for (const Segment& s : in.rough.segments) box.add(s);
  box.add(in.path.start);
  for (const auto& outline : in.stock) {
    for (Point p : outline) box.add(p);
  }
  for (const Highlight& h : in.highlights) {
    for (const auto& region : h.regions) {
      for (Point p : region) box.add(p);
    }
    for (const Segment& s : h.segments) box.add(s);
    for (Point p : h.points) box.add(p);
  }
  for (std::size_t i = 0; i < in.path.moves.size(); ++i) box.add(moveSegment(in.path, i));
  for (Point p : startPoints(in.path)) box.add(p);
  if (in.overlay && !in.overlay->moves.empty()) {  // an overlay without moves (an alarm) adds nothing
    box.add(in.overlay->start);
    for (std::size_t i = 0; i < in.overlay->moves.size(); ++i) box.add(moveSegment(*in.overlay, i));
  }
  return box;
}

std::string polygonElement(const View& v, const std::vector<Point>& outline, const std::string& cls,
                           const std::string& fill, const std::string& stroke, double opacity) {
  std::string points;
  for (Point p : outline) {
    if (isFinite(p)) points += coords(v, p) + " ";
  }
  if (points.empty()) return {};
  return "<polygon class=\"" + cls + "\" points=\"" + points + "\" fill=\"" + fill + "\" fill-opacity=\"" +
         num(opacity) + "\" stroke=\"" + stroke + "\" stroke-width=\"0.8\"/>\n";
}

std::string stockOutlines(const View& v, const std::vector<std::vector<Point>>& stock) {
  std::string out;
  for (const auto& outline : stock) out += polygonElement(v, outline, "stock", "#d9d9d9", "#b0b0b0", 0.5);
  return out;
}

// The label of a highlight that asks for it, beside its first drawable point (towards the plot's
// centre when the point is near the right edge, so that the text stays on the canvas).
std::string highlightLabel(const View& v, const Highlight& h) {
  if (!h.labelShown) return {};
  const auto p = std::find_if(h.points.begin(), h.points.end(), isFinite);
  if (p == h.points.end()) return {};
  const double x = v.px(p->z);
  const double y = v.py(p->x);
  const bool nearRight = x > kPlotRight - 200;
  return textElement("witness-label", nearRight ? x - 10 : x + 10, y - 10, h.label,
                     {12, kHighlightColour, nearRight ? "end" : "start", true});
}

// "and 950,000 more moves not drawn": a line at the plot's bottom left when `count` is beyond
// `drawn` (`row`: pixels above the plot's bottom), else nothing.
std::string notDrawnNote(std::size_t count, std::size_t drawn, const std::string& what, double row) {
  if (count <= drawn) return {};
  return textElement("not-drawn", kPlotLeft + 4, kPlotBottom - row,
                     "the first " + std::to_string(drawn) + " " + what + " drawn, and " +
                         std::to_string(count - drawn) + " more (every one is in the JSON)",
                     {11, "#555555", "start", false});
}

// Findings' witnesses in magenta, over everything else.
std::string highlightElements(const View& v, const std::vector<Highlight>& highlights) {
  if (highlights.empty()) return {};
  const char* colour = kHighlightColour;
  std::string out = "<g id=\"findings\">\n";
  for (std::size_t i = 0; i < std::min(highlights.size(), kMostFindingsDrawn); ++i) {
    const Highlight& h = highlights[i];
    out += "<g class=\"finding\"><title>" + svgEscape(h.label) + "</title>\n";
    for (const auto& region : h.regions) out += polygonElement(v, region, "witness-region", colour, colour, 0.35);
    for (const Segment& s : h.segments) out += pathElement("witness-segment", segmentPathData(v, s), {colour, 3.5});
    for (Point p : h.points) {
      if (isFinite(p)) {
        out += "<circle class=\"witness-point\" cx=\"" + num(v.px(p.z)) + "\" cy=\"" + num(v.py(p.x)) +
               "\" r=\"6\" fill=\"none\" stroke=\"" + std::string(colour) + "\" stroke-width=\"2.5\"/>\n";
      }
    }
    out += highlightLabel(v, h);
    out += "</g>\n";
  }
  out += notDrawnNote(highlights.size(), kMostFindingsDrawn, "findings", 16);
  return out + "</g>\n";
}

std::string axisLines(const View& v) {
  std::string out;
  const Stroke spindle{kAxisColour, 1, kAxisDash};
  const Stroke zZero{"#aaaaaa", 0.8, "2 4"};
  const TextStyle label{12, kAxisColour, "start", true};
  if (v.xVisible(0)) {  // the spindle axis, dash-dot
    out += lineElement("axis", kPlotLeft, v.py(0), kPlotRight, v.py(0), spindle);
    out += textElement("axis-label", kPlotRight + 4, v.py(0) + 4, "Z", label);
  }
  if (v.zVisible(0)) {  // the line z = 0, fainter
    out += lineElement("axis", v.px(0), kPlotTop, v.px(0), kPlotBottom, zZero);
    out += textElement("axis-label", v.px(0) + 4, kPlotTop + 10, "X", label);
  }
  return out;
}

std::string contourPath(const View& v, const Contour& c, const std::string& cls, const Stroke& st) {
  if (c.empty()) return {};
  return pathElement(cls, contourPathData(v, c), st);
}

// Every move of `path` as one <path> in a group with the given id.
std::string moveGroup(const View& v, const Toolpath& path, const char* id, const Stroke& rapid, const Stroke& feed) {
  std::string out = "<g id=\"" + std::string(id) + "\">\n";
  for (std::size_t i = 0; i < std::min(path.moves.size(), kMostMovesDrawn); ++i) {
    const bool isRapid = path.moves[i].kind == MoveKind::Rapid;
    out += pathElement(isRapid ? "rapid" : "feed", segmentPathData(v, moveSegment(path, i)),
                       isRapid ? rapid : feed);
  }
  out += notDrawnNote(path.moves.size(), kMostMovesDrawn, std::string(id) == "overlay" ? "overlay moves" : "moves",
                      std::string(id) == "overlay" ? 30 : 4);
  return out + "</g>\n";
}

// Under an overlay the first toolpath is drawn wider, the overlay thinner on top of it: where the
// two coincide the overlay's colour runs inside the first's.
Stroke rapidStroke(bool underOverlay) { return {kRapidColour, underOverlay ? 2.8 : 1.2, kRapidDash}; }
Stroke feedStroke(bool underOverlay) { return {kFeedColour, underOverlay ? 3.2 : 1.4}; }
const Stroke kOverlayRapid{kOverlayRapidColour, 1.3, kRapidDash};
const Stroke kOverlayFeed{kOverlayFeedColour, 1.5};

std::string toolpathMoves(const View& v, const Toolpath& path, bool underOverlay) {
  return moveGroup(v, path, "toolpath", rapidStroke(underOverlay), feedStroke(underOverlay));
}

std::string overlayMoves(const View& v, const Toolpath& overlay) {
  return moveGroup(v, overlay, "overlay", kOverlayRapid, kOverlayFeed);
}

// Where a pass number goes: just behind the start of the pass's first cut (opposite to the cut's
// direction on screen), so that it sits outside the cut and off the infeed line.
std::string passLabel(const View& v, Point from, Point to, int pass) {
  const double x = v.px(from.z);
  const double y = v.py(from.x);
  const double dx = v.px(to.z) - x;
  const double dy = v.py(to.x) - y;
  TextStyle style{11, kFeedColour, "middle", true};
  if (std::fabs(dx) >= std::fabs(dy)) {  // a cut along Z (G71): beside the start
    style.anchor = dx < 0 ? "start" : "end";
    return textElement("pass-label", dx < 0 ? x + 5 : x - 5, y + 4, std::to_string(pass), style);
  }
  // A cut along X (G72): above or below the start.
  return textElement("pass-label", x, dy > 0 ? y - 5 : y + 13, std::to_string(pass), style);
}

// The pass number at the first cutting feed of each pass.
std::string passLabels(const View& v, const Toolpath& path) {
  std::string out = "<g id=\"pass-labels\">\n";
  std::set<int> labelled;
  for (std::size_t i = 0; i < std::min(path.moves.size(), kMostMovesDrawn); ++i) {
    const Move& m = path.moves[i];
    if (m.kind != MoveKind::Feed || m.phase != MovePhase::Pass || !labelled.insert(m.pass).second) continue;
    out += passLabel(v, path.from(i), m.to, m.pass);
  }
  return out + "</g>\n";
}

std::string startMarkers(const View& v, const Toolpath& path) {
  std::string out;
  for (Point p : startPoints(path)) {
    out += "<circle class=\"start\" cx=\"" + num(v.px(p.z)) + "\" cy=\"" + num(v.py(p.x)) +
           "\" r=\"4\" fill=\"#000000\"/>\n";
    out += textElement("start-label", v.px(p.z) + 6, v.py(p.x) - 6, "A", {14, "#000000", "start", true});
  }
  return out;
}

// A distinct x level of the finish contour, with its left-most vertex (where the guide line ends).
struct Level {
  double x;
  double zLeft;
};

std::vector<Level> finishLevels(const Contour& finish) {
  std::vector<Level> levels;
  auto addVertex = [&](Point p) {
    if (!isFinite(p)) return;
    for (Level& l : levels) {
      if (std::fabs(l.x - p.x) < 1e-6) {
        l.zLeft = std::min(l.zLeft, p.z);
        return;
      }
    }
    levels.push_back({p.x, p.z});
  };
  for (const Segment& s : finish.segments) {
    addVertex(s.from);
    addVertex(s.to);
  }
  std::sort(levels.begin(), levels.end(), [](const Level& a, const Level& b) { return a.x > b.x; });
  return levels;
}

// Keeps labels at least kLabelSpacing px apart (top to bottom), then at most kMaxDiameterLabels,
// spread evenly over the range.
std::vector<Level> readableLevels(const View& v, const std::vector<Level>& levels) {
  std::vector<Level> spaced;
  for (const Level& l : levels) {
    if (spaced.empty() || v.py(l.x) - v.py(spaced.back().x) >= kLabelSpacing) spaced.push_back(l);
  }
  if (spaced.size() <= kMaxDiameterLabels) return spaced;
  std::vector<Level> kept;
  const std::size_t n = spaced.size();
  for (std::size_t k = 0; k < kMaxDiameterLabels; ++k)
    kept.push_back(spaced[k * (n - 1) / (kMaxDiameterLabels - 1)]);
  return kept;
}

std::string diameterLabels(const View& v, const Contour& finish) {
  std::string out = "<g id=\"diameters\">\n";
  const Stroke guide{"#bbbbbb", 0.6, "1 3"};
  const TextStyle style{11, "#333333", "end", false};
  for (const Level& l : readableLevels(v, finishLevels(finish))) {
    const double y = v.py(l.x);
    out += lineElement("diameter-guide", kPlotLeft - 4, y, v.px(l.zLeft), y, guide);
    out += textElement("diameter", kPlotLeft - 7, y + 4, "\u00D8" + shortNum(2 * l.x), style);
  }
  return out + "</g>\n";
}

// A label that fits the legend: long engine names ("process:python3 …") are cut with an ellipsis.
std::string legendText(const std::string& label, const char* fallback) {
  if (label.empty()) return fallback;
  if (label.size() <= kMaxLegendLabel) return label;
  std::size_t cut = kMaxLegendLabel - 1;
  while (cut > 0 && (static_cast<unsigned char>(label[cut]) & 0xC0) == 0x80) --cut;  // not inside a UTF-8 character
  return label.substr(0, cut) + "\u2026";
}

std::string legendEntry(double x, double y, const std::string& label, const Stroke& stroke) {
  return lineElement("legend-sample", x, y - 4, x + 30, y - 4, stroke) +
         textElement("legend-label", x + 36, y, label, {12, "#222222", "start", false});
}

// One toolpath's row of an overlay legend: its rapid and feed samples, then its name.
std::string legendToolpathRow(double x, double y, const std::string& label, const Stroke& rapid, const Stroke& feed) {
  return lineElement("legend-sample", x, y - 4, x + 24, y - 4, rapid) +
         lineElement("legend-sample", x + 30, y - 4, x + 54, y - 4, feed) +
         textElement("legend-label", x + 60, y, label + " (rapid, feed)", {12, "#222222", "start", false});
}

std::string legend(const PlotInput& in) {
  std::string out = "<g id=\"legend\">\n";
  if (!in.overlay) {
    struct Entry {
      const char* label;
      Stroke stroke;
    };
    const std::array<Entry, 4> entries{{{"finish contour", {kFinishColour, 2}},
                                        {"rough contour", {kRoughColour, 1, kRoughDash}},
                                        {"rapid", rapidStroke(false)},
                                        {"feed", feedStroke(false)}}};
    double x = kPlotLeft;
    for (const Entry& e : entries) {
      out += legendEntry(x, kLegendY, e.label, e.stroke);
      x += 160;
    }
    return out + "</g>\n";
  }
  // Two rows: the contours on the left, one row per toolpath on the right.
  const double y1 = kOverlayLegendY;
  const double y2 = kOverlayLegendY + kLegendRowSpacing;
  out += legendEntry(kPlotLeft, y1, "finish contour", {kFinishColour, 2});
  out += legendEntry(kPlotLeft, y2, "rough contour", {kRoughColour, 1, kRoughDash});
  const double x = kPlotLeft + 170;
  out += legendToolpathRow(x, y1, legendText(in.pathLabel, "toolpath"), rapidStroke(true), feedStroke(true));
  out += legendToolpathRow(x, y2, legendText(in.overlayLabel, "overlay"), kOverlayRapid, kOverlayFeed);
  return out + "</g>\n";
}

// `who` names the toolpath when there are two (empty otherwise); `y` is the text's baseline.
std::string alarmText(const Alarm& alarm, const std::string& who, double y) {
  std::string text = "ALARM " + (who.empty() ? std::string() : "(" + who + ") ") + alarm.code + ": " + alarm.message;
  if (alarm.line > 0) text += " (line " + std::to_string(alarm.line) + ")";
  return textElement("alarm", 20, y, text, {16, kAlarmColour, "start", true});
}

std::string alarmFrame() {
  return "<rect class=\"alarm-frame\" x=\"2\" y=\"2\" width=\"" + num(kCanvasWidth - 4) +
         "\" height=\"" + num(kCanvasHeight - 4) + "\" fill=\"none\" stroke=\"" + kAlarmColour +
         "\" stroke-width=\"4\"/>\n";
}

// The alarm(s) in red under the title, the canvas framed in red: the first toolpath's on the first
// line, the overlay's on the next.
std::string alarmBanners(const PlotInput& in) {
  const bool mine = in.path.alarm.has_value();
  const bool overlays = in.overlay && in.overlay->alarm;
  if (!mine && !overlays) return {};
  std::string out = alarmFrame();
  const std::string pathWho = in.overlay ? legendText(in.pathLabel, "toolpath") : std::string();
  if (mine) out += alarmText(*in.path.alarm, pathWho, 56);
  if (overlays) out += alarmText(*in.overlay->alarm, legendText(in.overlayLabel, "overlay"), mine ? 74 : 56);
  return out;
}

}  // namespace

std::string svgEscape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      case '\t': case '\n': case '\r': out += c; break;
      default: out += (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
    }
  }
  return out;
}

std::string renderToolpathSvg(const PlotInput& in) {
  const View view(drawingBounds(in));
  const std::string w = num(kCanvasWidth);
  const std::string h = num(kCanvasHeight);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + w + "\" height=\"" +
         h + "\" viewBox=\"0 0 " + w + " " + h + "\" font-family=\"sans-serif\">\n";
  out += "<title>" + svgEscape(in.title) + "</title>\n";
  out += "<rect class=\"background\" x=\"0\" y=\"0\" width=\"" + w + "\" height=\"" + h +
         "\" fill=\"#ffffff\"/>\n";
  out += stockOutlines(view, in.stock);
  out += axisLines(view);
  out += diameterLabels(view, in.finish);
  out += contourPath(view, in.rough, "rough", {kRoughColour, 1, kRoughDash});
  out += contourPath(view, in.finish, "finish", {kFinishColour, 2});
  out += toolpathMoves(view, in.path, in.overlay.has_value());
  if (in.overlay) out += overlayMoves(view, *in.overlay);
  out += passLabels(view, in.path);
  out += startMarkers(view, in.path);
  out += highlightElements(view, in.highlights);
  out += legend(in);
  out += textElement("title", 20, 30, in.title, {18, "#000000", "start", true});
  out += alarmBanners(in);
  return out + "</svg>\n";
}

}  // namespace cyclecert
