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

// G74.1 axial trapezoid groove cycle (GSK, seed 002, G74_1.*; docs/g74_1.md). A G74.1 block with X
// or Z gives the groove (its words are checked, nothing moves); one without them cuts the groove
// the nearest such block before it gives.
bool isG74_1GrooveBlock(const Block& b);
void applyG74_1FirstBlock(const CycleCall& call);
CycleOutcome planG74_1(const CycleCall& call);

}  // namespace cyclecert
