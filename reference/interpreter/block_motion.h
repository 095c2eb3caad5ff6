#pragma once
// Reading a block's motion: target position from X/Y/Z (absolute) and U/V/W (incremental) words,
// and, for G02/G03, the arc centre from R or I/J/K.
#include <optional>

#include "reference/interpreter/modal_state.h"
#include "reference/model/program.h"

namespace cyclecert {

// Converts a programmed length on an axis to physical mm (diameter axes halved, inch scaled).
double physicalLength(double programmed, bool diameterAxis, const ModalState& s);

// True when the block has any axis word (X Y Z U V W).
bool hasAxisWord(const Block& b);

// The position after the block's axis words (unchanged axes keep their value).
AxisPosition targetPosition(const Block& b, const ModalState& s);

// A motion block as a plane segment from the current position; nothing when the block does not
// move in the plane. Throws CycleAlarm PS0023/PS0020 for an impossible arc.
std::optional<Segment> motionSegment(const Block& b, int motion, const ModalState& s);

}  // namespace cyclecert
