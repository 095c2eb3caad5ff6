#pragma once
// FANUC Series 10/11 program format of G71/G72 (parameter 0001#1 FCV = 1): one block
// `G71 P(ns) Q(nf) U(Δu) W(Δw) I K D(Δd) F S T;` instead of the two blocks of the Series 0 format.
// U and W keep their meaning (Δu, Δw); D gives Δd in least input increments; e comes from
// parameter 5133 (rules G71.FS10.*).
#include <string>

#include "reference/cycles/cycle_call.h"

namespace cyclecert {

// The block with P and Q: reads D (and checks I, K) in the Series 10/11 format, or refuses a D
// under the Series 0 format. Δd is written into parameter 5132 like a first block's (G71.FS10.D).
// Throws CycleAlarm (PS0009, PS0007, PS0062, PS0003) or NotSupported (I, K).
void readSeries10Words(const CycleCall& call, const std::string& code);

}  // namespace cyclecert
