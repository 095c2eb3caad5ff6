#pragma once
// Reads a contour subprogram (rules LCYC95.CONTOUR, SIEMENS.CONTOUR) into a SiemensContour: its
// first block gives the contour's first point (X and Z, absolute); every G1/G2/G3 block after it
// is an element; CHF=/CHR=/RND= insert a chamfer or rounding at the corner after their block. The
// subprogram ends at M02, M17 or RET. X is read in the diameter mode in force at the call (and any
// G22/G23, DIAMON/DIAMOF inside).
#include <string>

#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_motion.h"
#include "reference/siemens/siemens_program.h"

namespace cyclecert {

// Throws ParseError for a block a contour cannot hold (naming line and column), CycleAlarm 14040
// for an impossible arc, NotSupported for what cyclecert does not read yet. A subprogram without
// elements gives a contour without segments: the cycle raises alarm 10931 for it (LCYC95.ALARMS).
SiemensContour readSiemensContour(const std::string& name, const SiemensBlocks& blocks, SiemensModal modal);

}  // namespace cyclecert
