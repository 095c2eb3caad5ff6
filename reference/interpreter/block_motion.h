#pragma once
// Reading a block's motion: target position from X/Y/Z (absolute) and U/V/W (incremental) words,
// and, for G02/G03, the arc centre from R or I/J/K.
#include <optional>

#include "reference/interpreter/known_position.h"
#include "reference/interpreter/modal_state.h"
#include "reference/model/program.h"

namespace cyclecert {

// Converts a programmed length on an axis to physical mm (diameter axes halved, inch scaled).
double physicalLength(double programmed, bool diameterAxis, const ModalState& s);

// True when the block has any axis word (X Y Z U V W).
bool hasAxisWord(const Block& b);

// The position after the block's axis words (unchanged axes keep their value).
AxisPosition targetPosition(const Block& b, const ModalState& s);

// What a block's axis words mean, decided by its group 00 command, the last one written when there
// are several (PROG.POSITION, PROG.GCODES, PROG.GROUP.LAST):
// a move (no such command, or G27's positioning), G04's dwell time, G28/G30's intermediate point,
// G53's machine coordinates, G50's coordinate setting, or G10/G65 data.
enum class AxisWordsMean { Motion, Dwell, ReferenceReturn, ReferenceCheck, MachineCoordinates, CoordinateSetting, Data };
AxisWordsMean axisWordsMeaning(const Block& b);
// The meanings by which the tool moves: a move, G27's positioning, G28/G30's way through the
// intermediate point.
bool axisWordsMoveTheTool(AxisWordsMean meaning);

// Where the block leaves the tool in work coordinates as far as the program tells: the target of a
// move or of G27's positioning, G28/G30's intermediate point (the reference position beyond it
// is not modelled), the coordinates G50 sets; unchanged by a dwell, G53 or data. The program
// runner and the oracles' reading of a program both follow a block with this.
AxisPosition positionAfterBlock(const Block& b, const ModalState& s);

// PROG.POSITION: which axes' work coordinates are known after the block: an absolute word of a
// move, of G27's positioning or of G50's coordinate setting makes its axis known; G28/G30 (to a
// reference position, through the intermediate point) and G53 (machine coordinates) make the
// commanded axes unknown. The program runner and the oracles' reading of a program both use it.
void followKnownAxes(KnownPosition& known, const Block& b, AxisWordsMean meaning);

// A motion block as a plane segment from the current position; nothing when the block does not
// move in the plane. Throws CycleAlarm PS0023/PS0020 for an impossible arc.
std::optional<Segment> motionSegment(const Block& b, int motion, const ModalState& s);

}  // namespace cyclecert
