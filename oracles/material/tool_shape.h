#pragma once
// The cutting tool as the material model sees it. The roughing cycles' model (material_model.h)
// takes the tool as a point with a shadow: a feed removes everything beyond it towards the start
// side — the fast path, kept for G71/G72/G73 and SINUMERIK. A grooving tool (G74.1 with I) is a
// blade: a rectangle of width r across the feed, with its shank running back out of the material;
// a move removes (and may cross) exactly the region the rectangle sweeps — the Minkowski sum of the
// move and the rectangle — not a shadow.
#include <optional>
#include <utility>
#include <vector>

#include "oracles/material/material_model.h"
#include "oracles/material/region.h"

namespace cyclecert {

struct ToolShape {
  double width = 0;  // 0: a point; > 0: a blade this wide
  bool isPoint() const { return width <= 0; }
};

// A blade's rectangle placed on its programmed point: it spans `width` from the point along the unit
// vector `across` and `length` along the unit vector `back` (the shank, towards the air).
struct BladeFrame {
  Point across;
  Point back;
  double length = 0;
};

// The convex hull of `points` as a region (empty when they span no area).
BgRegion convexHullOf(const std::vector<Point>& points);

// A convex shape to sweep: its points (relative to the tool's programmed point), with its own
// hull's vertices and their edges' normals found once, so that each chord's hull is fed only the
// points that can lie on it — the same hull (convexHullOf), without the far half of a disc.
class SweptShape {
 public:
  explicit SweptShape(std::vector<Point> points);
  // (shape + from) ∪ (shape + to), in that order point by point, without the points that cannot
  // be on their hull, into `out`.
  void along(Point from, Point to, std::vector<Point>& out) const;

 private:
  static double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
  std::vector<Point> points_;
  // Per point on the shape's hull: the outward normals of the hull's edges before and after it
  // (empty when the shape spans no area: every point is fed).
  std::vector<std::optional<std::pair<Point, Point>>> edges_;
};

// The Minkowski sum of `move` (arcs as chords within chordTolerance) and the convex shape whose
// points (relative to the tool's programmed point) are `shape`: the union of the convex hulls of the
// shape at each chord's two ends.
BgRegion sweptConvexShape(const Segment& move, const SweptShape& shape, double chordTolerance);
BgRegion sweptConvexShape(const Segment& move, const std::vector<Point>& shape, double chordTolerance);

// The Minkowski sum of `move` (arcs as chords within chordTolerance) and the parallelogram spanned
// from the origin by a·da and b·db: the union of the convex hulls of the parallelogram at each
// chord's two ends. With a blade frame (a = width along `across`, b = length along `back`) it is the
// region the blade sweeps; with b = 0 it is a point's shadow of length a along da. Along an arc,
// each run of chords whose directions lie in one open cone between ±da and ±db is that union built
// directly (its outline is the chain moved by the two side corners), without a boolean per chord.
BgRegion sweptRegion(const Segment& move, Point da, double a, Point db, double b, double chordTolerance);

// a ∩ b (checkedIntersection, region.h), checked against both operands. Boost's overlay can take a
// polygon that touches the other only along a nearly collinear edge for one inside it (its
// coordinates snapped to a grid of about 1e-7 of the operands' size) and return it whole — a
// result reaching beyond b's envelope, or larger than b. Such a result is redone with b nudged by a
// few grid steps (at most 1e-5 of the size: far below any tolerance), the first consistent answer
// kept; when none is, the first result stands (reported, never hidden).
BgRegion consistentIntersection(const BgRegion& a, const BgRegion& b);

// How far a tool's move enters `region` beyond `epsilon`.
struct ToolCrossing {
  double amount = 0;          // mm for a point (the length inside), mm² for a blade (the area)
  double thickness = 0;       // a blade's: the thickest ring's 2·area/perimeter; a point's: its length
  BgRegion crossed;           // a blade's crossed region
  std::vector<Segment> pieces;  // a point's pieces inside
  bool any() const { return amount > 0; }
};

// How far a tool whose move sweeps `swept` enters `region`: swept ∩ region, counted where a ring of
// it is thicker (2·area/perimeter, about the depth it goes in for a long thin sliver) than epsilon;
// amount its area.
ToolCrossing sweptCrossing(const BgRegion& region, const BgRegion& swept, double epsilon);

// A point: crossingOf (material_model.h) with epsilon. A blade: sweptCrossing of the region the
// blade sweeps (sweptRegion with the blade's frame).
ToolCrossing toolCrossing(const BgRegion& region, const Segment& move, const ToolShape& tool, const BladeFrame& blade,
                          double epsilon, double chordTolerance);

// The thickest ring of `region` by 2·area/perimeter (0 when empty).
double thickestRing(const BgRegion& region);

}  // namespace cyclecert
