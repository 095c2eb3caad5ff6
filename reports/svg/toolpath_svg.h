#pragma once
// A self-contained SVG 1.1 picture of one toolpath over its finish and rough contours, for people:
// Z to the right, X (radius) up, equal scales, on a fixed 900×600 px canvas.
//
// What it shows: the title; the alarm (code, message, line) in red when the toolpath has one; the
// finish contour (solid, dark) and the rough contour (thin, dashed, orange); every move as one
// <path> element inside <g id="toolpath"> (rapids dashed red, feeds solid blue, arcs as real SVG
// arcs); the pass number next to the first cutting feed of each pass; the cycle start point(s)
// marked "A" (each CycleRecord's start, else Toolpath::start); the spindle axis x = 0 (dash-dot)
// and the line z = 0 when in view; diameter labels "Ø54" for the x levels of the finish contour's
// vertices (at most 12, never overlapping); and a legend.
//
// With an overlay (a second toolpath over the same contours: `cyclecert diff` draws engine B over
// engine A), the overlay's moves go inside <g id="overlay"> (rapids dashed purple, feeds solid
// green), drawn thinner over a widened first toolpath so that where the two coincide both stay
// visible; the legend gets a second row and names both toolpaths (pathLabel, overlayLabel) with
// their rapid and feed samples; the overlay's alarm, if any, is written under the first's. Its
// start point and pass numbers are not drawn again. A highlight with `labelShown` writes its label
// beside its first point (the divergence marker "first divergence: move N"); other highlights keep
// the label as a tooltip only.
//
// Size (README "Limits"): the first 50,000 moves of a toolpath (and of an overlay) and the first 50
// highlights are drawn, and a grey line at the plot's bottom left says how many more there are.
//
// The document never contains NaN or infinity (non-finite coordinates are left out of the scaling
// and written as 0), and degenerate input (nothing to draw, a single point) still gives a valid
// document.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/contour.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// Something a finding points at, drawn over everything in a contrasting colour.
struct Highlight {
  std::string label;                             // e.g. "no-gouge: move 12"
  std::vector<std::vector<Point>> regions;       // filled
  std::vector<Segment> segments;                 // thick strokes
  std::vector<Point> points;                     // rings
  bool labelShown = false;                       // also write the label as text beside the first point
};

struct PlotInput {
  std::string title;
  Contour finish;
  Contour rough;  // the finish contour shifted by the allowances (drawn as given)
  Toolpath path;
  std::vector<std::vector<Point>> stock;  // stock outline(s), drawn under everything, lightly filled
  std::vector<Highlight> highlights;      // findings' witnesses
  // A second toolpath drawn over `path` (another engine's), and the legend's names for the two;
  // without an overlay the labels are not used and the picture is as above.
  std::optional<Toolpath> overlay;
  std::string pathLabel;
  std::string overlayLabel;
};

std::string renderToolpathSvg(const PlotInput& in);

// Escapes text for XML character data and attribute values: & < > " ' become entities; control
// characters that XML 1.0 forbids (all below 0x20 except tab, LF, CR) become '?'.
std::string svgEscape(std::string_view text);

}  // namespace cyclecert
