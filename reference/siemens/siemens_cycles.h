#pragma once
// SINUMERIK stock-removal cycles (seed 004): what the Siemens program runner hands the planners —
// the contour subprogram read into segments and the cycle's parameters — and what they give back.
// LCYC95 (802S/C, seed 004 §2, rules LCYC95.*) and CYCLE95 (802D, seed 004 §3, rules CYCLE95.*).
//
// The split: the Siemens front end (siemens_lexer/parser/program, the contour reader, the runner)
// reads the program, evaluates R parameters and string variables, finds the contour subprogram,
// builds its segments (CR= arcs, I/K centres, inserted CHF/CHR/RND) and calls a planner below; the
// planners know nothing of text. Coordinates are the plane's (z = longitudinal axis, x = radius),
// in mm.
#include <optional>
#include <string>
#include <vector>

#include "reference/model/geometry.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// R105 (LCYC95) / VARI (CYCLE95), values 1…12 (LCYC95.PARAMS table): longitudinal or face,
// external or internal, roughing, finishing or complete. Longitudinal machining feeds in along X
// (the transverse axis) and cuts along Z; face machining feeds in along Z and cuts along X.
enum class SiemensCut { Longitudinal, Face };
enum class SiemensSide { External, Internal };
enum class SiemensTechnology { Roughing, Finishing, Complete };

struct MachiningType {
  SiemensCut cut = SiemensCut::Longitudinal;
  SiemensSide side = SiemensSide::External;
  SiemensTechnology technology = SiemensTechnology::Roughing;
  friend bool operator==(const MachiningType&, const MachiningType&) = default;
};

// The table of LCYC95.PARAMS: 1 longitudinal external roughing, 2 face external roughing, 3
// longitudinal internal roughing, 4 face internal roughing, 5…8 the same finishing, 9…12 complete.
// Nothing for a value outside 1…12 or not whole.
std::optional<MachiningType> machiningTypeOf(double value);

// A contour subprogram (LCYC95.CONTOUR): lines and arcs (each at most a quarter circle) with the
// chamfers and rounds it inserts, in the programmed direction (which must be the finishing
// direction). `segments.front().from` is the contour's first programmed point.
struct SiemensContour {
  std::string name;               // "L42", as _CNAME or NPP names it
  std::string file;               // where it was read from ("L42.spf", or the case's subprograms)
  std::vector<Segment> segments;  // Segment::sourceLine: the line in `file`
};

// LCYC95's parameters (LCYC95.PARAMS), read from R105…R112 when the call is made.
struct Lcyc95Parameters {
  MachiningType type;          // R105
  double allowance = 0;        // R106, finishing allowance (unsigned)
  double maxInfeed = 0;        // R108, the largest infeed depth (the cycle computes the actual one)
  double infeedAngle = 0;      // R109, degrees
  double retract = 0;          // R110, after each roughing cut, in each axis
  double roughingFeed = 0;     // R111
  double finishingFeed = 0;    // R112
};

// CYCLE95(NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT) (CYCLE95.PARAMS); empty
// arguments take the cycle's defaults (the front end fills them in).
struct Cycle95Parameters {
  std::string contourName;     // NPP
  double infeed = 0;           // MID (unsigned)
  double allowanceZ = 0;       // FALZ
  double allowanceX = 0;       // FALX
  double allowance = 0;        // FAL, along the contour
  double roughingFeed = 0;     // FF1
  double undercutFeed = 0;     // FF2
  double finishingFeed = 0;    // FF3
  MachiningType type;          // VARI
  double dwell = 0;            // DT, seconds, chip breaking
  double interruptLength = 0;  // DAM, roughing interrupted after this length for chip breaking
  double retract = 0;          // _VRT, incremental, unsigned
};

// One call of a stock-removal cycle, as the runner makes it.
struct SiemensCycleCall {
  int line = 0;                  // the line of the call in the main program
  Point position;                // the tool's position when the cycle is called
  const SiemensContour* contour = nullptr;
  ToolOffset tool;               // the active tool's nose radius and tip (finishing compensates)
};

// What a planner gives back: the moves from `position` to the cycle's end (phase and rule IDs set
// as the FANUC planners set theirs), and where the tool ends. A controller alarm is thrown as
// CycleAlarm (reference/model/alarms.h) with the Siemens alarm number as its code.
struct SiemensCycleOutcome {
  std::vector<Move> moves;
  std::vector<Warning> warnings;
  Point end;
};

SiemensCycleOutcome planLcyc95(const SiemensCycleCall& call, const Lcyc95Parameters& p);
SiemensCycleOutcome planCycle95(const SiemensCycleCall& call, const Cycle95Parameters& p);

}  // namespace cyclecert
