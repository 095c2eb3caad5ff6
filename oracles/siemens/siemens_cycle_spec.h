#pragma once
// What a SINUMERIK stock-removal cycle call asks (LCYC95 on the 802S/C, CYCLE95 on the 802D), as
// the oracles read it: the call's position, contour and parameters — taken from the Siemens front
// end (the harness runs it with recording planners, harness/judge/siemens_reading.h), never from a
// planner's moves — and what the rules derive from them, in the stock-removal frame: the roughing
// profile, the computed start point, the equal infeed levels, CYCLE95's undercuts, the finishing path.
//
// The frame (LCYC95.PARAMS note): every machining type is judged as longitudinal external — cut
// along z towards −z, infeed along −x, the stock above the profile. Face machining exchanges z and x,
// internal machining mirrors the depth axis.
#include <string>
#include <vector>

#include "reference/model/cycle_family.h"
#include "reference/model/geometry.h"
#include "reference/model/tool.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert {

struct SiemensFrame {
  bool transposed = false;  // face: the cut runs along X, the infeed along Z
  bool mirrored = false;    // internal: the depth direction mirrored

  Point toFrame(Point plane) const;
  Point toPlane(Point frame) const;
  std::vector<Segment> toFrame(const std::vector<Segment>& plane) const;
  std::vector<Segment> toPlane(const std::vector<Segment>& frame) const;
};

// An undercut of the roughing profile (CYCLE95.UNDERCUT), in the frame: from the rim, where the
// profile turns back towards the depth axis, to where it is back at `top` — the lowest main level
// strictly above the rim (the level through a rim stops there) — (or to the profile's end). Its
// moves run at FF2.
struct SiemensUndercut {
  double rimZ = 0;  // the rim (the larger z)
  double endZ = 0;  // where the pocket ends (the smaller z)
  double top = 0;   // the level that passed over it
  double bottom = 0;
};

// The main roughing levels (LCYC95.DEPTH, interpretation): from the profile's highest point `top`
// down to its lowest `bottom` in the fewest equal steps not above R108 / MID — level k (0…count) is
// top − k·step, the last one `bottom`.
struct SiemensLevels {
  double top = 0, bottom = 0, step = 0;
  double count = 0;  // the number of steps (0: a flat profile)
  double level(double k) const { return k >= count ? bottom : top - k * step; }
  // The lowest level strictly above x (by more than tol); the top when none is.
  double levelAbove(double x, double tol) const;
  // Whether x is one of levels 1…count (within tol).
  bool isLevel(double x, double tol) const;
};
SiemensLevels equalLevels(double top, double bottom, double maxInfeed);

struct SiemensCycleSpec {
  // --- read from the program (the front end) ---
  CycleFamily family = CycleFamily::Lcyc95;
  int line = 0;                    // the call's line in the main program
  Point position;                  // the tool's position at the call (plane)
  MachiningType type;              // R105 / VARI
  std::string contourName, contourFile;
  std::vector<Segment> contour;    // the contour subprogram's segments (plane, programmed direction)
  double allowance = 0;            // R106 / FAL, along the contour
  double allowanceZ = 0;           // FALZ (0 for LCYC95)
  double allowanceX = 0;           // FALX (0 for LCYC95)
  double maxInfeed = 0;            // R108 / MID
  double infeedAngle = 0;          // R109, degrees from the infeed axis (CYCLE95: straight in)
  double retract = 0;              // R110 / _VRT, in each axis
  double roughingFeed = 0;         // R111 / FF1
  double undercutFeed = 0;         // FF2 (LCYC95 roughs no undercut)
  double finishingFeed = 0;        // R112 / FF3
  double interruptLength = 0;      // DAM (0: never interrupted; LCYC95 has none)
  double dwell = 0;                // DT, seconds at each interruption (unsigned)
  ToolOffset tool;

  // --- derived by describeSiemensCycle, in the frame ---
  SiemensFrame frame;
  std::vector<Segment> profile;     // contour + allowances: what roughing follows
  std::vector<Segment> finishPath;  // the contour finishing follows (nose-radius compensated)
  Point start;                      // the computed start (LCYC95.START)
  SiemensLevels levels;             // the main roughing levels
  std::vector<SiemensUndercut> undercuts;  // CYCLE95 only

  bool roughs() const { return type.technology != SiemensTechnology::Finishing; }
  bool finishes() const { return type.technology != SiemensTechnology::Roughing; }
  bool isCycle95() const { return family == CycleFamily::Cycle95; }
  // The rule IDs of a step: "LCYC95.ROUGH" or "CYCLE95.ROUGH" for step "ROUGH".
  std::string rule(const std::string& step) const { return std::string(cycleCode(family)) + "." + step; }
};

// Derives the frame geometry from the values read (LCYC95.START, LCYC95.DEPTH, CYCLE95.UNDERCUT,
// LCYC95.FINISH). Throws CycleAlarm 10931 when the allowance or the nose radius does not fit the
// contour (LCYC95.ALARMS).
void describeSiemensCycle(SiemensCycleSpec& c);

// Whether the feed from `from` to `to` (frame) runs in one of the cycle's undercuts: within its span
// along the cut axis and below the level that passed over it, or plunging along the depth axis down
// to that level (CYCLE95.UNDERCUT: these run at FF2).
bool inUndercut(const SiemensCycleSpec& c, Point from, Point to, double tol);

}  // namespace cyclecert
