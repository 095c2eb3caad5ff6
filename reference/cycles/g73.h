#pragma once
// G73 — pattern repeating cycle (FANUC 0i-F, GSK; seed 004's example, rules G73.*). The whole finish
// shape A → B → C is followed d times, each pass shifted away from the part by a share of the total
// relief (Δi, Δk) on top of the finishing allowance (Δu/2, Δw); the last pass leaves the allowance.
// The planner works in plane coordinates (z = the plane's 1st axis, x = its 2nd).
#include <vector>

#include "reference/model/toolpath.h"

namespace cyclecert {

struct G73Cycle {
  Point start;                // A: the cycle start point = start of block ns
  Point headEnd;              // B: end of block ns
  std::vector<Segment> body;  // B → C: the shape after block ns
  Point relief;               // (Δk, Δi): the total relief along z and x (radius), signed
  Point allowance;            // (Δw, Δu/2): the finishing allowance, signed
  int divisions = 1;          // d ≥ 1: the number of rough passes
  bool headIsRapid = true;    // block ns is G00 (else G01)
  double feed = 0;            // the cycle's F
};

// G73.PASS.SHIFT, G73.D1: pass k of d (1-based) follows the shape shifted by
// (d − k)/(d − 1)·(Δk, Δi) + (Δw, Δu/2); with d = 1 the one pass is shifted by the allowance only.
Point passShift(const G73Cycle& cycle, int k);

// The cycle's moves: for each pass the rapid from A to the shifted start (G73.APPROACH), the
// shifted block ns as programmed (G73.HEAD), the shifted shape in cutting feed (G73.PASS) and the
// rapid back to A (G73.RETURN).
std::vector<Move> planG73Passes(const G73Cycle& cycle);

}  // namespace cyclecert
