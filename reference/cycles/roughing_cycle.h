#pragma once
// What G71 and G72 share: the two-block format with address sharing (G71.ADDR.SHARED, G72.FMT),
// modal Δd and e held in parameters 5132/5133 (G71.DD.MODAL, G71.E.MODAL, G72.DD), the address
// ranges (G72.RANGE), and the type I plan in the cycle frame.

#include "reference/cycles/cycle_call.h"
#include "reference/cycles/shape_program.h"
#include "reference/cycles/type1_roughing.h"

namespace cyclecert {

// A roughing cycle's dialect: its code and which plane address carries Δd in the first block.
struct RoughingFormat {
  std::string code;  // "G71", "G72"
  char depthOfCutAddress;
};

// The first block (no P/Q): Δd and e, written into parameters 5132/5133 for the rest of the program.
void applyFirstBlock(const CycleCall& call, const RoughingFormat& format);

// The second block's values, in physical mm.
struct SecondBlock {
  const Word* p = nullptr;
  const Word* q = nullptr;
  double allowanceFirst = 0;   // Δw (along the plane's 1st axis)
  double allowanceSecond = 0;  // Δu/2 on a diameter axis, Δu otherwise (along the 2nd axis)
  double feed = 0;
};

// Reads and range-checks the block with P and Q. Throws CycleAlarm (PS0061, PS0003, PS0011).
SecondBlock readSecondBlock(const CycleCall& call, const RoughingFormat& format);

// Type I parameters from the machine parameters in force: Δd (PS0062 if not positive), e, RF1, DTP.
void applyType1Parameters(const CycleCall& call, Type1Cycle& cycle);

// Moves of a plan in the cycle frame, mapped back to the plane (G72 plans with the axes exchanged).
std::vector<Move> movesInPlane(std::vector<Move> moves, bool transposeFrame);

}  // namespace cyclecert
