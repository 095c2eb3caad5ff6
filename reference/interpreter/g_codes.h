#pragma once
// The G codes of a FANUC 0i-TF lathe that cyclecert reads, in G code systems A, B and C, and the
// Huazhong list (PROG.GCODES, PROG.GSYS.*, PROG.GROUP.* in specs/rules.json):
//  - several G codes of different groups in one block all act (PROG.GROUP.SHARE);
//  - several of one group: the last one specified is the one in effect (PROG.GROUP.LAST) — the
//    controller raises no alarm for it;
//  - a code the system's list does not hold is not a G code of the controller: PS0010
//    (PROG.GROUP.UNKNOWN).
// A code is looked up by the number written in the program and the system in force; what it does
// is its *function*, named by the code's number in system A (G73 in system C is function 710,
// stock removal in turning). One table serves the program runner and the oracles' reading of a
// program, so they cannot disagree on what a block's codes do.
#include <cstdint>
#include <string>

#include "reference/interpreter/g_code_system.h"
#include "reference/interpreter/modal_state.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/model/program.h"

namespace cyclecert {

// FANUC's group numbers (lathe).
enum class GGroup : std::uint8_t {
  OneShot = 0,            // 00: acts in its block only (G04, G10, G27–G30, G50, G53, G65, G70–G76)
  Motion = 1,             // 01: G00–G03, G32, and the single cycles (A: G90, G92, G94)
  SpindleSpeedMode = 2,   // 02: G96 constant surface speed, G97 its cancel
  Programming = 3,        // 03 (systems B/C): G90 absolute, G91 incremental
  FeedMode = 5,           // 05: feed per minute / per revolution (A: G98/G99, B/C: G94/G95)
  Units = 6,              // 06: inch, mm (A/B: G20/G21, C: G70/G71)
  NoseRadiusComp = 7,     // 07: G40, G41, G42
  DrillingCycle = 10,     // 10: G80, G83–G89
  CycleReturn = 11,       // 11 (systems B/C): G98 initial level, G99 R point level
  WorkCoordinates = 14,   // 14: G54–G59
  Plane = 16,             // 16: G17, G18, G19
};

// What the reference does with a code it knows.
enum class GSupport : std::uint8_t {
  Applied,     // its effect is modelled (or it has none on a turning toolpath: G80, G98/G99 return level)
  NotApplied,  // read, its effect not applied: a warning (G10, G65)
  NotPlanned,  // the program is reported as not supported (threading, other cycles)
};

// The functions systems B/C have and system A has not are named kOnlyInBC + their number in B.
inline constexpr int kOnlyInBC = 10000;
inline constexpr int kAbsoluteProgramming = kOnlyInBC + 900;   // B/C G90
inline constexpr int kIncrementalProgramming = kOnlyInBC + 910;  // B/C G91

struct GCode {
  int function;      // the code ×10 in system A (G74.1 → 741), or kOnlyInBC + its number ×10 in B
  GGroup group;
  GSupport support;
  const char* name;  // "threading", without the number (which depends on the system)
};

// PROG.GSYS.SELECT, the one place the system is chosen: the profile's, or for a profile that reads
// them (the FANUC ones) parameter 3401#7 GSC = 1 → C, else 3401#6 GSB = 1 → B, else A.
GCodeSystem gCodeSystemOf(const Profile& profile, const MachineParams& params);

// The modal state at the start of a program: power-on codes, the profile's units (PROG.UNITS) and
// G code system. The program runner and the oracles' readers start from it.
ModalState initialModalState(const Profile& profile, const MachineParams& params);

// "system A", "system B", "Huazhong".
std::string gCodeSystemName(GCodeSystem system);

// The entry for a code ×10 as written in a program of that system, or nullptr when it is not a G
// code of that list. Constant time: it is looked up for every G word of every block.
const GCode* findGCode(GCodeSystem system, int g10);
inline const GCode* findGCode(int g10) { return findGCode(GCodeSystem::A, g10); }

// "G04", "G74.1": a code ×10 as FANUC writes it.
std::string gCodeLabel(int g10);

// The number FANUC prints for a group ("01", "16").
int groupNumber(GGroup g);

// Applies one modal G code to the state (groups 01, 03, 06, 07, 14, 16); codes of other groups
// change nothing the reference models.
void applyModalGCode(const GCode& code, ModalState& s);

// Applies every G code of a block in the order written, in the state's system, so the last of a
// group is the one in force. Codes outside the system's list are skipped (the caller alarms).
void applyModalGCodes(const Block& b, ModalState& s);

// The function of the block's last group 00 code, or 0 when it has none: the one-shot command in
// effect.
int oneShotFunction(const Block& b, GCodeSystem system);

// True when one of the block's G words has that function (a system A number ×10) in the system.
bool hasGFunction(const Block& b, int function, GCodeSystem system);

// Applies the block's codes of one group in the order written (the last one is in force), in the
// state's system: a shape program ns…nf reads its group-03 G90/G91 so (PROG.GSYS.B).
void applyGroupCodes(const Block& b, GGroup group, ModalState& s);

// G72.NSNF.GCODES, PROG.GSYS.B: whether a code may stand in a shape program ns…nf, by its
// function in the program's system: positioning and interpolation (G00–G03), dwell, G96/G97, the
// feed modes (system A's G98/G99, B/C's G94/G95), nose-radius compensation G40–G42 (whether the
// profile tolerates them there is the caller's question) and B/C's absolute/incremental
// programming G90/G91 (the counterpart of system A's X/Z and U/W). Not B/C's G98/G99 (canned
// cycle return level). The reference's cycles and the oracles both ask it.
bool usableInShapeProgram(const GCode& code);

// PROG.GSYS.OTHER: what the code ×10 means in the other FANUC systems and the parameter that
// selects them ("; in G code system B (--param 3401#6=1) G77 is the outer diameter cutting cycle"),
// or "" when it means the same there or the system is not a FANUC one.
// byParameters: whether the profile reads 3401 (else the way names a FANUC profile too).
std::string otherSystemsMeaning(GCodeSystem system, int g10, bool byParameters);

}  // namespace cyclecert
