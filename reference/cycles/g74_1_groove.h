#pragma once
// G74.1's trapezoid groove (seed 002, G74_1.ADDR) in its own frame, as docs/g74_1.md §2–§5 and §7
// derive it: the profile chain from the mouth on the start side, down the near flank, along the
// floor, up the far flank to the mouth on the far side, with the corners r1…r4 cut as chamfers or
// rounds; the rough profile moved in by the allowances; the slice of the groove at a depth; the
// path of a grooving tool's programmed point along a profile.
//
// The frame: u is the distance from the groove start S along d's X direction (radius), w the depth
// below the start level towards the floor (along h's Z direction). A local point is a `Point` with
// z = w and x = u, so that the geometry helpers (arcs, intersections) serve unchanged.
#include <array>
#include <cstddef>
#include <stdexcept>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

// A local point at distance u along d and depth w.
inline Point grooveLocal(double u, double w) { return {w, u}; }

enum class GrooveCornerKind { Chamfer, Round };  // P's digit 0, 1

struct GrooveCorner {
  double size = 0;  // chamfer width or round radius (radius value, mm); 0: a sharp corner
  GrooveCornerKind kind = GrooveCornerKind::Chamfer;
};

// The corners in the seed's order: r1 (outer bottom at the start), r2 (outer bottom, other end),
// r3 (inner bottom near the start), r4 (inner bottom far from the start).
enum GrooveCornerIndex : std::size_t { kCornerR1 = 0, kCornerR2 = 1, kCornerR3 = 2, kCornerR4 = 3 };

// The groove as the two blocks give it, magnitudes in mm (the signs of h and d are the frame's).
struct GrooveShape {
  double depth = 0;       // |h| (radius)
  double floorWidth = 0;  // |d| / 2 (radius)
  double angleA = 90;     // ∠a, degrees
  double angleB = 90;     // ∠b
  double slope = 0;       // ∠p
  std::array<GrooveCorner, 4> corners{};
};

// The groove cannot be built or cut as given (docs/g74_1.md I9, I11, I17): the planner raises the
// cycle's alarm with this message.
class GrooveDoesNotFit : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Which part of the groove a segment of a profile belongs to, in the order of the chain.
enum class GroovePart { CornerR1, NearFlank, CornerR3, Floor, CornerR4, FarFlank, CornerR2 };

// A profile (finish, or rough with its allowances) in the local frame: the chain from P0 to Pend.
struct GrooveProfile {
  std::vector<Segment> chain;      // local points; the floor is always one segment
  std::vector<GroovePart> parts;   // the part of each segment
  Point start;                     // S (finish) or S' (rough): the near flank on the mouth
  double floorDepth = 0;           // w of the floor
  double floorFrom = 0, floorTo = 0;  // u of the floor's flat part (after r3, before r4)
  Point nearDirection, farDirection;  // unit directions of the near flank (down) and far flank (up)
};

// The finish profile (allowances 0) or the rough profile: each flank moved into the groove by
// flankAllowance (Δu/2) along u, the floor by floorAllowance (Δw) towards the mouth (I15).
// Throws GrooveDoesNotFit.
GrooveProfile buildGrooveProfile(const GrooveShape& g, double flankAllowance, double floorAllowance);

// The groove's width at depth w (0 < w ≤ floorDepth): u of its near and far boundary (flanks and
// floor corners; the mouth corners r1, r2 are not counted: I17). Above a flank's top, that top.
struct GrooveSlice {
  double nearU, farU;
};
GrooveSlice sliceAt(const GrooveProfile& p, double w);

// The deepest a tool of width r whose programmed point is at u (its blade spanning [u − r, u]) may
// go without cutting into the profile: the profile's depth under the blade's two corners, the
// smaller (the groove is convex below its mouth); 0 outside the groove. Mouth corners not counted.
double deepestUnderTheBlade(const GrooveProfile& p, double u, double toolWidth);

// The path of the programmed point of a grooving tool of width r (0: a pointed tool) along the
// profile (§7): the start side shifted by r along u, the floor from its start + r, the far side
// as it is. Local points.
std::vector<Segment> bladePath(const GrooveProfile& p, double toolWidth);

// The frame's placement in the plane: S, and the directions of h (Z) and d (X).
struct GrooveFrame {
  Point start;  // S = (Z, X/2)
  int depthSign = -1;  // sign of h
  int widthSign = -1;  // sign of d

  Point toPlane(Point local) const { return {start.z + depthSign * local.z, start.x + widthSign * local.x}; }
  // A local segment in the plane; an arc turns the other way when the frame mirrors (h·d < 0).
  Segment toPlane(const Segment& local) const;
};

}  // namespace cyclecert
