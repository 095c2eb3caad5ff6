#pragma once
// The canned cycles the reference plans, one file each.
#include "reference/cycles/cycle_call.h"

namespace cyclecert {

// G71 outer/inner diameter roughing, FANUC 0i-F §4.2.1 (seed 000).
void applyG71FirstBlock(const CycleCall& call);
CycleOutcome planG71(const CycleCall& call);

// G70 finishing cycle (G70.EX).
CycleOutcome planG70(const CycleCall& call);

// G72 facing roughing (seed 001).
void applyG72FirstBlock(const CycleCall& call);
CycleOutcome planG72(const CycleCall& call);

// G73 pattern repeating cycle (seed 004, G73.*): reference/cycles/g73.h plans its passes.
void applyG73FirstBlock(const CycleCall& call);
CycleOutcome planG73(const CycleCall& call);

}  // namespace cyclecert
