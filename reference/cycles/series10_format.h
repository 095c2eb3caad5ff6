#pragma once
// The one-block forms of G71/G72: the block with P and Q also gives Δd with D, instead of a first
// block. Two dialects read it, their differences held as data (OneBlockDialect):
// - FANUC Series 10/11 program format (parameter 0001#1 FCV = 1): `G71 P Q U W I K D F S T;`, D in
//   least input increments (no decimal point), e from parameter 5133 (rules G71.FS10.*);
// - Haas (profile haas): `G71 P Q U W D I K F S T [R1];`, D in the program's units (decimal point),
//   I/K the rough-pass allowance, R1 type II (rules HAAS.G71.*).
#include <string>

#include "reference/cycles/cycle_call.h"

namespace cyclecert {

struct SecondBlock;

// How a dialect writes D, I, K and R in the block with P and Q.
struct OneBlockDialect {
  enum class DepthUnits { LeastInputIncrements, ProgramUnits };
  std::string name;          // "Series 10/11", "Haas"
  DepthUnits depthUnits;
  bool readsRoughAllowance;  // I/K: Haas's rough-pass allowance; Series 10/11's are not modelled
  bool r1SelectsTypeII;      // Haas: R1 in the block selects type II roughing
  bool zxPlaneOnly;          // Haas: "G18 Z-X plane must be active" (HAAS.G71.PLANE)
};

// The dialect of the call's profile and parameters, or nullptr when the block with P and Q is the
// Series 0 second block (FANUC with FCV = 0, GSK).
const OneBlockDialect* oneBlockDialect(const CycleCall& call);

// The block with P and Q: reads D (written into parameter 5132 like a first block's Δd,
// G71.FS10.D, HAAS.G71.D), I/K and R1 into `sb`, or refuses a D under the Series 0 format.
// Throws CycleAlarm (PS0009, PS0007, PS0062, PS0003) or NotSupported (Series 10/11 I, K; a Haas
// cycle outside G18).
void readOneBlockWords(const CycleCall& call, const std::string& code, SecondBlock& sb);

// G73.FS10.FMT: the Series 10/11 G73 block `G73 P Q U W I K D F S T;` (FCV = 1): I = Δi (radius) and
// K = Δk in the program's units, D = the number of divisions d (a whole number, no decimal point),
// written into parameters 5135/5136/5137 like a first G73 block's U, W, R. With FCV = 0 an I, K or D
// there is PS0009 naming FCV. Throws CycleAlarm (PS0009, PS0007, PS0062, PS0003).
void readG73OneBlockWords(const CycleCall& call);

}  // namespace cyclecert
