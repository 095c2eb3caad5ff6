#pragma once
// Type II roughing (pockets) for G71 and G72, in the cycle frame (cut along z, steps along x).
// The algorithm and its interpretations: reference/cycles/README.md, "Type II".
#include <string>
#include <vector>

#include "reference/model/cycle_family.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct Type2Cycle {
  CycleFamily family = CycleFamily::G71;  // G71 or G72: chooses the rule IDs the moves cite
  Point start;                 // A
  std::vector<Segment> shape;  // the finish shape A → B → … → C, head block first
  Point allowance;             // the rough profile is the shape shifted by it
  bool headIsRapid = true;     // block ns is G00
  double depthOfCut = 0, retract = 0, feed = 0;
  double clearance = 0;        // parameter 5134
  bool semiFinish = true;      // RF2 = 0
  bool followAlongCut = false; // R16 = 1
  bool noRepeatedPath = false; // NSP = 1
  bool levelByLevel = false;   // fanuc-0i-c pocket order

  int depthDirection() const;  // sign of B − A on x (the head block's infeed)
  int cutDirection() const;    // sign of C − A on z
};

std::vector<Move> planType2(const Type2Cycle& cycle);

// True when the rough profile goes deeper again after coming back (a pocket wall): with an
// allowance along the cut axis the tool may cut into a side wall (G71.T2.DW0, G72.T2).
bool type2HasPocketWall(const Type2Cycle& cycle);

}  // namespace cyclecert
