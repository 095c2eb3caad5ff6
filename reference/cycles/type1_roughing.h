#pragma once
// Type I roughing (G71 and G72): the eight steps of seed 001 (G72.STEP1…8), which G71 follows
// with the axes exchanged (G71.T1.STEP1…8). The planner works in the *cycle frame*: it cuts along
// z and steps along x. G71 is already in that frame; G72 transposes its shape in and its moves out.
#include <string>
#include <vector>

#include "reference/model/cycle_family.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct Type1Cycle {
  CycleFamily family = CycleFamily::G71;  // G71 or G72: chooses the rule IDs the moves cite
  Point start;                  // A: cycle start = start of block ns
  Point headEnd;                // B: end of block ns
  std::vector<Segment> body;    // B → C: the finish shape after block ns
  Point allowance;              // (Δw, Δu/2) in the frame: the rough profile is the shape shifted by it
  bool headIsRapid = true;      // block ns is G00 (else G01)
  double depthOfCut = 0;        // Δd > 0
  double retract = 0;           // e ≥ 0
  double feed = 0;              // the cycle's F
  bool semiFinish = true;       // RF1 = 0
  bool directReturn = false;    // DTP = 1

  Point end() const { return body.empty() ? headEnd : body.back().to; }  // C
  int depthDirection() const;   // sign of B − A on the depth axis (x)
  int cutDirection() const;     // sign of C − B on the cut axis (z)
};

// The cycle's moves, in the cycle frame.
std::vector<Move> planType1(const Type1Cycle& cycle);

}  // namespace cyclecert
