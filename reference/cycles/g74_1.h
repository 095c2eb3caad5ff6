#pragma once
// G74.1 — axial trapezoid groove cycle (GSK, seed 002 §3.23.7, rules G74_1.*): two blocks give the
// groove (X Z P Q H D A B L) and how to cut it (R V U W I J A B D E P); layers of axial peck cycles
// step across the groove, then a pass along the rough profile and/or the finish profile, and the
// tool goes back where it stood. docs/g74_1.md derives every point by hand; the planner follows
// its numbered steps (G74_1.STEP1…STEP10), one function each (g74_1_steps.cpp).
#include <optional>
#include <vector>

#include "reference/cycles/g74_1_groove.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// J: which passes the cycle makes (G74_1.ADDR).
enum class GroovePathType { RoughOnly = 0, RoughAndFinish = 1, FinishOnly = 2 };

// A pointed tool's nose under G41/G42 (I26): the cycle is planned for the nose centre in the groove
// eroded by `radius`, every move then shifted by `tipShift` (plane: R times the imaginary tip's
// direction) to the point the control follows.
struct GrooveNose {
  double radius = 0;
  Point tipShift;
};

// Everything the planner needs, in mm (radius values) in the plane.
struct G74_1Cycle {
  int line = 0;                    // the second G74.1 block (messages)
  Point before;                    // where the tool stands before the cycle (and returns to)
  GrooveFrame frame;               // S and the directions of h and d
  GrooveShape groove;
  double radialStep = 0;           // Δi/2 (Δi is a diameter)
  double peck = 0;                 // Δk
  double retract = 0;              // e
  std::optional<double> layerDepth;  // Δv; none: one layer (G74-like)
  double flankAllowance = 0;       // Δu/2
  double floorAllowance = 0;       // Δw
  double toolWidth = 0;            // r of a grooving tool (I); 0: a pointed tool
  std::optional<GrooveNose> nose;  // a pointed tool with a nose radius under G41/G42 (I26)
  GroovePathType pathType = GroovePathType::RoughOnly;
  double feed = 0;                 // the cutting feed in force
};

// The cycle's moves in plane coordinates. Throws GrooveDoesNotFit when the groove cannot be cut
// with this tool (the caller raises the cycle's alarm) and NotSupported above the plan size cap.
std::vector<Move> planG74_1Moves(const G74_1Cycle& cycle);

// The finish profile and the rough profile (I15) in the plane (the toolpath's cycle record draws them).
std::vector<Segment> g74_1FinishShape(const G74_1Cycle& cycle);
std::vector<Segment> g74_1RoughShape(const G74_1Cycle& cycle);

}  // namespace cyclecert
