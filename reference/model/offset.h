#pragma once
// Tool-nose radius compensation geometry (G40/G41/G42): the path of the nose centre rolled along a
// contour, and the path of the control point (the imaginary tool-nose point) that results.
// Depends on reference/model only, so the oracles can reuse it.
//
// Conventions (plane as in geometry.h: z right, x up, seen from +Y):
//  * Left/right are taken relative to the direction of travel at each point. For a direction
//    t = (tz, tx) the left normal is t turned +90° (counter-clockwise): (−tx, tz); the right normal
//    is (tx, −tz). G41 = tool on the left, G42 = tool on the right.
//  * Arcs: the same rule at every point of the arc. A CCW arc (G03) turns left, so its centre is
//    on its left; a CW arc (G02) has its centre on its right. Offsetting an arc on the side of its
//    centre shrinks the radius by r, on the other side grows it; the centre is kept.
//  * Imaginary tip directions, from the nose centre to the imaginary tip point, in units of r
//    (FANUC chart for X up, Z right): 1 (+z,+x), 2 (−z,+x), 3 (−z,−x), 4 (+z,−x), 5 (+z,0),
//    6 (0,+x), 7 (−z,0), 8 (0,−x), 0 and 9 (0,0) = the nose centre itself.
//
// Worked example — outer turning on top of a shaft, x = 10, moving towards the chuck (−z):
//   the direction of travel is (−1, 0); its left normal is (0, −1), i.e. −x, down into the part.
//   The tool is outside the part, above it, so it is on the RIGHT: G42. The right normal is (0, +1),
//   so the nose centre runs at x = 10 + r. With tip 3, direction (−1, −1), the imaginary tip point
//   runs at x = 10 + r − r = 10 (each point moved by −r along z, i.e. along the line): on lines
//   parallel to the axes the imaginary tip point runs on the programmed line itself (which is why
//   uncompensated programs are exact there), while on tapers and arcs it deviates
//   (tests/offset_test.cpp: Offset.AxisParallelLinesAreTracedExactly, Offset.ChamferTipPathDeviates).
//   Likewise a bore (inner turning) towards −z: the tool is inside the hole, below the surface (−x),
//   i.e. on the LEFT (G41), nose centre at x − r, tip 2 (−1, +1) puts the tip point back on x.
#include <stdexcept>
#include <string>
#include <vector>

#include "reference/model/geometry.h"
#include "reference/model/tool.h"

namespace cyclecert {

enum class CompensationSide { Left, Right };  // G41, G42

// Direction from the nose centre to the imaginary tool-nose point for tip 0…9, in units of the
// nose radius (see the chart above). Throws std::out_of_range for any other tip.
Point imaginaryTipDirection(int tip);

// Why a compensated path cannot be built.
enum class OffsetProblem {
  ArcVanishes,   // an arc's offset radius would be ≤ 0
  Interference,  // two pieces meant to meet at a concave corner do not intersect (FANUC's
                 // interference alarm: the nose radius is too large for the shape)
};

class OffsetError : public std::runtime_error {
 public:
  OffsetError(OffsetProblem problem, int segmentIndex, int sourceLine);
  OffsetProblem problem;
  int segmentIndex;  // index into the path given to offsetPath (for a corner: the segment after it)
  int sourceLine;    // that segment's sourceLine
};

// The nose-centre path of a circle of radius r ≥ 0 rolled along the connected `path` on `side`:
// each line moved along its normal, each arc's radius grown or shrunk (centre kept); at a convex
// corner (the offset pieces leave a gap) a connecting arc of radius r centred on the corner point
// (CCW on the right, CW on the left); at a concave corner both pieces trimmed to their
// intersection (the one nearest to the corner). Tangent-continuous joins add nothing. Zero-length
// pieces (in the input or after trimming) are dropped. Every piece keeps the sourceLine of the
// segment it comes from; corner arcs take the line of the segment after the corner. The ends of
// the path are not extended: the first piece starts r away from the path's start along its normal.
// Throws OffsetError (see OffsetProblem), std::invalid_argument for r < 0 or a gap in `path`.
std::vector<Segment> offsetPath(const std::vector<Segment>& path, double r, CompensationSide side);

// The path the control point (the imaginary tip) follows when `path` is machined with
// compensation: offsetPath(path, r, side) shifted by r·imaginaryTipDirection(tip).
std::vector<Segment> compensatedPath(const std::vector<Segment>& path, const ToolOffset& tool,
                                     CompensationSide side);

// Start-up as FANUC type A: the compensated position at the end of a start-up block that arrives
// at `p` before `next`: p + r·(normal of `next` at its start, on `side`) + r·imaginaryTipDirection.
Point startUpPoint(Point p, const Segment& next, const ToolOffset& tool, CompensationSide side);

// Small geometric helpers used above (and by the tests and oracles).
Point unitTangentAtStart(const Segment& s);  // direction of travel at `from`
Point unitTangentAtEnd(const Segment& s);    // direction of travel at `to`
Point sideNormal(Point unitTangent, CompensationSide side);
double distanceToSegment(Point p, const Segment& s);
// distanceToSegment of an arc whose angles are known (ArcAngles(arc)): the same distance, without
// working them out again for each point.
double distanceToSegment(Point p, const Segment& arc, const ArcAngles& angles);
double distanceToPath(Point p, const std::vector<Segment>& path);  // +∞ for an empty path
// distanceToPath(p, path) <= tolerance, answered without measuring the segments far from p.
bool nearPath(Point p, const std::vector<Segment>& path, double tolerance);

}  // namespace cyclecert
