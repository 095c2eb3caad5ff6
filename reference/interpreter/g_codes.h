#pragma once
// The G codes of a FANUC 0i-TF lathe (G code system A) that cyclecert reads, with their groups
// (PROG.GCODES, PROG.GROUP.* in specs/rules.json):
//  - several G codes of different groups in one block all act (PROG.GROUP.SHARE);
//  - several of one group: the last one specified is the one in effect (PROG.GROUP.LAST) — the
//    controller raises no alarm for it;
//  - a code the table does not hold is not a G code of the controller: PS0010 (PROG.GROUP.UNKNOWN).
// One table serves the program runner and the oracles' reading of a program, so they cannot
// disagree on what a block's codes do.
#include <cstdint>

#include "reference/interpreter/modal_state.h"
#include "reference/model/program.h"

namespace cyclecert {

// FANUC's group numbers (system A, lathe).
enum class GGroup : std::uint8_t {
  OneShot = 0,            // 00: acts in its block only (G04, G10, G27–G30, G50, G53, G65, G70–G76)
  Motion = 1,             // 01: G00–G03, G32, G90, G92, G94
  SpindleSpeedMode = 2,   // 02: G96 constant surface speed, G97 its cancel
  FeedMode = 5,           // 05: G98 per minute, G99 per revolution
  Units = 6,              // 06: G20 inch, G21 mm
  NoseRadiusComp = 7,     // 07: G40, G41, G42
  DrillingCycle = 10,     // 10: G80, G83–G89
  WorkCoordinates = 14,   // 14: G54–G59
  Plane = 16,             // 16: G17, G18, G19
};

// What the reference does with a code it knows.
enum class GSupport : std::uint8_t {
  Applied,     // its effect is modelled
  NotApplied,  // read, its effect not applied: a warning (G10, G65)
  NotPlanned,  // the program is reported as not supported (threading, other cycles)
};

struct GCode {
  int g10;           // the code ×10 (G74.1 → 741)
  GGroup group;
  GSupport support;
  const char* name;  // "G32 threading"
};

// The table's entry for a code ×10, or nullptr when it is not a G code of this controller.
// Constant time: it is looked up for every G word of every block.
const GCode* findGCode(int g10);

// The number FANUC prints for a group ("01", "16").
int groupNumber(GGroup g);

// Applies one modal G code to the state (groups 01, 06, 07, 14, 16); codes of other groups change
// nothing the reference models.
void applyModalGCode(int g10, ModalState& s);

// Applies every G code of a block in the order written, so the last of a group is the one in force.
void applyModalGCodes(const Block& b, ModalState& s);

// The block's last group 00 code (×10), or 0 when it has none: the one-shot command in effect.
int oneShotCode(const Block& b);

}  // namespace cyclecert
