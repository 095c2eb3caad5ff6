#pragma once
// Reading a block's motion: target position from X/Y/Z (absolute) and U/V/W (incremental) words,
// and, for G02/G03, the arc centre from R or I/J/K.
#include <optional>

#include "reference/interpreter/known_position.h"
#include "reference/interpreter/g_code_system.h"
#include "reference/interpreter/modal_state.h"
#include "reference/model/program.h"

namespace cyclecert {

// Converts a programmed length on an axis to physical mm (diameter axes halved, inch scaled).
double physicalLength(double programmed, bool diameterAxis, const ModalState& s);

// True when the block has any axis word (X Y Z U V W).
bool hasAxisWord(const Block& b);

// The position after the block's axis words (unchanged axes keep their value): X/Y/Z absolute, or
// incremental under G91 (PROG.GSYS.INCREMENTAL); U/V/W incremental.
AxisPosition targetPosition(const Block& b, const ModalState& s);

// The incremental address of an axis in G code system A: X → U, Y → V, Z → W (0 for another letter).
char incrementalAddressOf(char axis);

// Whether the block gives the axis ('X', 'Y', 'Z') an absolute coordinate (X under G90 or in
// system A), or moves it by an increment (U, or X under G91).
bool setsAxisAbsolutely(const Block& b, char axis, const ModalState& s);
bool movesAxisIncrementally(const Block& b, char axis, const ModalState& s);

// PROG.GSYS.INCREMENTAL: in G code systems B and C the manual writes increments as G91 X/Y/Z;
// U/V/W as incremental addresses depend on the machine. The block's first U/V/W word there (the
// program runner refuses it as not supported), or nullptr.
const Word* incrementalAddressOutsideItsSystem(const Block& b, const ModalState& s);

// What a block's axis words mean, decided by its group 00 command, the last one written when there
// are several (PROG.POSITION, PROG.GCODES, PROG.GROUP.LAST):
// a move (no such command, or G27's positioning), G04's dwell time, G28/G30's intermediate point,
// G53's machine coordinates, G50's coordinate setting, or G10/G65 data.
enum class AxisWordsMean { Motion, Dwell, ReferenceReturn, ReferenceCheck, MachineCoordinates, CoordinateSetting, Data };
AxisWordsMean axisWordsMeaning(const Block& b, GCodeSystem system);
// The meanings by which the tool moves: a move, G27's positioning, G28/G30's way through the
// intermediate point.
bool axisWordsMoveTheTool(AxisWordsMean meaning);

// Where the block leaves the tool in work coordinates as far as the program tells: the target of a
// move or of G27's positioning, G28/G30's intermediate point (the reference position beyond it
// is not modelled), the coordinates G50 sets; unchanged by a dwell, G53 or data. The program
// runner and the oracles' reading of a program both follow a block with this.
AxisPosition positionAfterBlock(const Block& b, const ModalState& s);

// PROG.POSITION: which axes' work coordinates are known after the block: an absolute word (not
// an X/Z word under G91 in G code system B/C: setsAxisAbsolutely) of a
// move, of G27's positioning or of G50's coordinate setting makes its axis known; G28/G30 (to a
// reference position, through the intermediate point) and G53 (machine coordinates) make the
// commanded axes unknown. The program runner and the oracles' reading of a program both use it.
void followKnownAxes(KnownPosition& known, const Block& b, AxisWordsMean meaning, const ModalState& s);

// A motion block as a plane segment from the current position; nothing when the block does not
// move in the plane. Throws CycleAlarm PS0023/PS0020 for an impossible arc.
std::optional<Segment> motionSegment(const Block& b, int motion, const ModalState& s);

}  // namespace cyclecert
