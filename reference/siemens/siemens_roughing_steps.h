#pragma once
// The steps LCYC95 and CYCLE95 share (seed 004 §2 粗切削/精加工, §3 操作顺序): one function per
// documented step, planned in the stock-removal frame (siemens_roughing_frame.h: cut along z towards
// −z, infeed along −x, the stock above the profile). The two cycles differ in their parameter names,
// in how the infeed is made and in how the axes return at the end; StockRemoval says which.
#include <string>
#include <vector>

#include "reference/model/toolpath.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert {

// A stock-removal move's phase and pass, written in one place.
void stampPhase(Move& m, MovePhase phase, int pass);

// The rule IDs a cycle's moves cite, by step.
struct StockRemovalRules {
  std::string rough;      // LCYC95.ROUGH / CYCLE95.ROUGH
  std::string start;      // the computed start point
  std::string depth;      // the equal infeed steps
  std::string finish;     // LCYC95.FINISH / CYCLE95.FINISH
  std::string complete;   // LCYC95.COMPLETE / CYCLE95.COMPLETE
  std::string interrupt;  // CYCLE95.DAM (empty for LCYC95)
  std::string undercut;   // CYCLE95.UNDERCUT (empty for LCYC95)
};

// The main roughing levels from the profile's top down to its bottom, `top` first and `bottom`
// last: LCYC95.DEPTH's fewest equal steps not above the largest infeed (equalInfeedLevels). A faulty
// engine (harness/engines/mutants.cpp) plugs in another rule.
using RoughingLevelsRule = std::vector<double> (*)(double top, double bottom, double maxInfeed, int line);
std::vector<double> equalInfeedLevels(double top, double bottom, double maxInfeed, int line);

// One stock-removal cycle, in the frame.
struct StockRemoval {
  int line = 0;                     // the call's line (named by NotSupported)
  std::vector<Segment> profile;     // contour + finishing allowance: what roughing follows
  std::vector<Segment> finishPath;  // the contour as finishing follows it (nose-radius compensated)
  Point contourFront;               // the contour's first point (its own, not the profile's)
  Point clearance;                  // R110 / _VRT in each axis: the retract, and the start's distance
  double maxInfeed = 0;             // R108 / MID
  RoughingLevelsRule mainLevels = equalInfeedLevels;  // LCYC95.DEPTH
  double infeedAngle = 0;           // R109, degrees from the infeed axis (0: straight in)
  MoveKind infeedKind = MoveKind::Feed;
  double roughingFeed = 0;          // R111 / FF1
  double finishingFeed = 0;         // R112 / FF3
  double interruptLength = 0;       // DAM: a roughing cut is split after this length (0: never)
  double dwell = 0;                 // DT: seconds the tool dwells at each interruption
  bool axesReturnOneAfterTheOther = false;  // CYCLE95.ROUGH: at the end of roughing
  bool roughUndercuts = false;      // CYCLE95.UNDERCUT (LCYC95 leaves them to finishing)
  double undercutFeed = 0;          // FF2
  SiemensTechnology technology = SiemensTechnology::Roughing;
  StockRemovalRules rules;
};

// The cycle's start point, computed internally (LCYC95.START, interpretation): the clearance beyond
// the profile's extent on the entry side (largest z) and above its highest point (largest x).
Point computedStart(const std::vector<Segment>& profile, Point clearance);

// The actual infeed (LCYC95.DEPTH): the total depth divided into the fewest equal steps not above
// the largest infeed (at least one step for any depth). More than PROG.CAP.PASSES steps is
// NotSupported (roughing_cycle.h).
struct InfeedSteps {
  int count = 0;
  double depth = 0;
};
InfeedSteps equalInfeedSteps(double totalDepth, double maxInfeed, int line = 0);

// The moves from `position` (frame) to the cycle's end, in the frame.
std::vector<Move> planStockRemoval(const StockRemoval& cycle, Point position);

}  // namespace cyclecert
