#pragma once
// G72.RANGE: the ranges the cycle addresses accept (increment system ISB; ISC is not modelled).
// A value outside its range raises the controller's alarm, never a crash.
#include <string_view>

#include "reference/model/program.h"

namespace cyclecert {

enum class CycleAddress { DepthOfCut, Retract, Allowance, SequenceNumber };

struct AddressRange {
  double min, max;
};

AddressRange rangeOf(CycleAddress role, bool inch);

// Checks a word of a G71/G72 block against the table. Δd below its minimum (zero or negative) is
// alarm PS0062 (illegal cutting amount); anything else outside its range is PS0003.
void checkCycleAddress(const Word& w, CycleAddress role, bool inch);

// HNC.G71.FMT: an address other than G U R P Q X Z F S T M in the block is PS0009 (CycleAlarm),
// naming the FANUC/Haas one-block formats for W, D, I, K. The oracles' reading checks it too.
void refuseAddressesOutsideHuazhongG71(const Block& b);

}  // namespace cyclecert
