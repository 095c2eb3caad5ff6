#pragma once
// Regions of the cycle plane on Boost.Geometry, and the conversions between them and cyclecert's
// geometry: flattening arcs into chords, outlines to regions and back, erosion, difference.
//
// Conventions (used by every file of oracles/material):
// - A BgPoint is (z, x): get<0> = z (along the spindle, drawn to the right), get<1> = x (radius,
//   drawn up), so Boost's notion of clockwise is the plot's clockwise (Z right, X up), the same as
//   ArcCW.
// - Polygons are Boost's defaults: outer rings clockwise, holes counter-clockwise, closed (the
//   first point repeated at the end). Every function here returns regions in that orientation.
// - Arcs become equal chords between points on the arc, so a flattened arc lies on the arc's centre
//   side, at most `chordTolerance` (the sagitta) from it; lines stay exact. A flattened figure is
//   within chordTolerance of the true one (Hausdorff distance): a convex round of the part (centre
//   inside) loses material, a fillet (centre outside) gains some. Euclidean distances measured
//   between a flattened figure and an exact one are off by at most chordTolerance, between two
//   flattened figures by at most 2·chordTolerance (0 when both flatten the same arc, or the same
//   arc translated — the rough profile and a path along it: their chords are the same). Verdicts
//   add that to their ε. Distances along an axis are not so bounded: next to a point where the
//   arc's tangent is parallel to the axis, a chord strays up to √(r·chordTolerance/2) from the arc
//   along it (a round starting from a shoulder, measured along x) — thickestAbove() allows for it.
// - Boost's booleans (1.74) rescale their operands' common envelope onto 10⁷ integer steps to stay
//   robust, so the points they create are exact to about envelope/10⁷ (6e-6 mm for a 60 mm
//   envelope): slivers of that width appear where two figures share an edge. Verdicts need an ε
//   well above it (the oracles' 1e-3 mm is); the model keeps its shadows short (1 mm past the
//   material) so that the envelope stays the material's.
// - Regions are kept tidy: consecutive points closer than kTidyDistance merged, points within
//   kTidyDistance of the line through their neighbours (collinear points, spikes) dropped, and
//   rings thinner (2·area / perimeter) than kDustWidth or than the booleans' resolution
//   (kBooleanResolution × the region's size) dropped as noise.
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

using BgPoint = boost::geometry::model::d2::point_xy<double>;  // (z, x)
using BgPolygon = boost::geometry::model::polygon<BgPoint>;     // clockwise outer ring, closed
using BgRegion = boost::geometry::model::multi_polygon<BgPolygon>;

inline constexpr double kTidyDistance = 1e-10;  // mm: closer points merge, flatter corners vanish
inline constexpr double kDustWidth = 1e-9;      // mm: rings thinner than this are dropped
inline constexpr double kBooleanResolution = 1e-7;  // of a region's size: thinner rings are noise

inline BgPoint toBg(Point p) { return {p.z, p.x}; }
inline Point fromBg(const BgPoint& p) { return {p.x(), p.y()}; }

// The points of `s` from s.from to s.to (both exact): a line gives its two end points; an arc gives
// the fewest equal chords whose sagitta r·(1 − cos(φ/2)) is ≤ chordTolerance (at least one chord),
// every point on the arc. A degenerate arc (radius ≤ kGeomEps) gives {from, to}. An arc with
// from == to and a radius is a full circle (geometry.h's convention). Throws std::invalid_argument
// for non-finite coordinates, chordTolerance ≤ 0, or more than kMostChordsPerArc chords.
// (Chords much finer than this, bounding the error along the axes too, would fall below the
// booleans' resolution next to axis-parallel tangents and make Boost see self-intersections.)
std::vector<Point> flatten(const Segment& s, double chordTolerance);
// README "Limits": an arc of the largest radius the dimension words allow (999,999.999 mm) takes
// some 70,000 chords at the default chord tolerance (1 µm); a tolerance set too fine is refused.
inline constexpr double kMostChordsPerArc = 1e6;
// How many chords flatten(s, chordTolerance) makes: 1 for a line or a degenerate arc; what a caller
// may check against a budget before flattening (no bound applied here).
double chordsToFlatten(const Segment& s, double chordTolerance);
// An upper bound on chordsToFlatten(s, chordTolerance) that needs no angles (no atan2): the chords
// of a full circle of the arc's radius, each taken to span 4·sqrt(tolerance / 2r) (asin x ≥ x),
// doubled against rounding. At least 1.
double mostChordsToFlatten(const Segment& s, double chordTolerance);
// The same into `points` (cleared first): a caller flattening move after move keeps one buffer.
void flattenInto(std::vector<Point>& points, const Segment& s, double chordTolerance);

// Appends flatten(s) to `points`, without repeating a first point equal to the last one there.
void appendFlattened(std::vector<Point>& points, const Segment& s, double chordTolerance);

// The region enclosed by `outline` (closed implicitly; either orientation; repeated points and
// collinear points allowed). An outline enclosing no area (fewer than three distinct points, all
// collinear, or thinner than kDustWidth) gives the empty region. Throws std::invalid_argument with
// Boost's reason when the outline crosses itself, and for non-finite coordinates.
BgRegion regionFrom(const std::vector<Point>& outline);

// The same for an outline known not to cross itself (built so), without Boost's validity check,
// which costs more than the rest.
BgRegion regionFromSimpleOutline(const std::vector<Point>& outline);

// Every ring of `region` as a list of points without the closing repetition: for each polygon its
// outer ring (clockwise) then its holes (counter-clockwise). Draw with fill-rule evenodd.
std::vector<std::vector<Point>> outlinesOf(const BgRegion& region);

// `region` shrunk by `epsilon` (Minkowski erosion by a disk: boost::geometry::buffer with distance
// −epsilon, round joins at concave corners approximated by 72 chords per circle): every point of
// the result is at least ~epsilon inside `region`. Empty when nothing is left; `region` itself
// (tidied) when epsilon ≤ 0.
BgRegion eroded(const BgRegion& region, double epsilon);

// a ∖ b, tidied (no dust where a and b share an edge); `a` as it is when their envelopes do not
// meet.
BgRegion without(const BgRegion& a, const BgRegion& b);

// Merges near-duplicate points, drops collinear points, spikes and dust rings (see the top of this
// file). Booleans on tidy regions stay small; every function here returns tidy regions.
// `operandSize`: the size (largest side of the envelope) of the operands of the boolean that made
// `region`, which sets the booleans' resolution; 0 takes the region's own size.
void tidy(BgRegion& region, double operandSize = 0);

// a ∩ b. Boost's intersection can fail on nearly degenerate input (edges that nearly coincide, a
// corner on an edge) and return an operand instead of the result; a result outside a's envelope or
// larger than either operand is such a failure, and the intersection is then taken by another
// route, a ∖ (a ∖ b).
BgRegion checkedIntersection(const BgRegion& a, const BgRegion& b);

// Boost's booleans return "pinched" rings where what remains falls into pieces that meet at a
// point (a ring through the same point twice, or a vertex on another of its edges) — and then
// rejects them as invalid input to the next boolean. This cuts each pinched outer ring into its
// pieces (points within `tolerance` count as the same).
void splitPinches(BgRegion& region, double tolerance);

}  // namespace cyclecert
