#pragma once
// The alarms a block raises for its G codes alone, before anything moves (PROG.GROUP.* in
// specs/rules.json). The program runner throws them; the oracles' reading of a program records
// them, so both stop at the same block.
#include "reference/interpreter/modal_state.h"
#include <string>

#include "reference/model/alarms.h"
#include "reference/model/program.h"

namespace cyclecert {

// PROG.GROUP.UNKNOWN, PROG.GSYS.OTHER: PS0010 for a G word that is not a code of the system's list,
// naming what it is in the other G code systems, the parameter that selects them, and how this
// system writes it (system A's G91 → U/W, G33 → G32; system B's G50 → G92).
CycleAlarm improperGCode(const Block& b, const Word& g, const ModalState& s);

// The reason a code the reference does not plan is reported (its NotSupported text), with what the
// number means in the other G code systems (system A's G90 cycle is system B/C's absolute
// programming, --param 3401#6=1).
std::string notPlannedReason(const Block& b, const Word& g, const ModalState& s);

// The block's first G word outside the system's list, or nullptr.
const Word* firstUnknownGCode(const Block& b, GCodeSystem system);

// PROG.GROUP.COMP: with the modal state before and after the block's codes, throws PS0037 for a
// plane change while G41/G42 stays in force and PS0034 for G41/G42 start-up or G40 cancel in a
// block that moves along an arc.
void checkCompensationChange(const Block& b, const ModalState& before, const ModalState& after);

}  // namespace cyclecert
