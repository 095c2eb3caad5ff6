#pragma once
// The alarms a block raises for its G codes alone, before anything moves (PROG.GROUP.* in
// specs/rules.json). The program runner throws them; the oracles' reading of a program records
// them, so both stop at the same block.
#include "reference/interpreter/modal_state.h"
#include "reference/model/alarms.h"
#include "reference/model/program.h"

namespace cyclecert {

// PROG.GROUP.UNKNOWN: PS0010 for a G word that is not a code of the lathe's system A, naming the
// system A way to say it where there is one (G91 → U/W, G33 → G32).
CycleAlarm improperGCode(const Block& b, const Word& g);

// The block's first G word outside the table, or nullptr.
const Word* firstUnknownGCode(const Block& b);

// PROG.GROUP.COMP: with the modal state before and after the block's codes, throws PS0037 for a
// plane change while G41/G42 stays in force and PS0034 for G41/G42 start-up or G40 cancel in a
// block that moves along an arc.
void checkCompensationChange(const Block& b, const ModalState& before, const ModalState& after);

}  // namespace cyclecert
