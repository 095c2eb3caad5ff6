#pragma once
// The G74.1 programs the metamorphic relations transform (GSK's axial trapezoid groove, seed 002,
// docs/g74_1.md, rules G74_1.*): what each word means, read from the words alone. The two G74.1
// blocks have 17 addresses, and A, B, D and P mean different things in each, so a word's role
// depends on its block (I1: a G74.1 block with X or Z gives the groove, one without them cuts it).
//
// The vocabulary (anything else is refused with the block's line and the word):
//   G00 G01 positioning blocks with X Z (absolute, X a diameter), U W (incremental), F S T M;
//   G18 G21 G40 G97 G98 G99 (kept as they are);
//   G74.1 X Z P(Δi) Q(Δk) H(h) D(d) A(∠a) B(∠b) L(∠p);   (the groove)
//   G74.1 R(e) V(Δv) U(Δu) W(Δw) I(r) J A(r1) B(r2) D(r3) E(r4) P(abde);   (how to cut it)
// Refused: G20 (the relations' constants are in mm), G02/G03, G41/G42 (a mirror changes the
// compensation side), G04, every other G code and address, a second word of one address in a block,
// X with U or Z with W, a G74.1 block with a motion code, a program without a G74.1 block.
#include <optional>
#include <string>
#include <vector>

#include "reference/model/program.h"

namespace cyclecert {

// What a word of a G74.1 program means.
enum class GrooveRole {
  Code,          // a G code (G00 G01 G74.1 and the kept ones)
  AbsFirst,      // Z: positioning, or the groove's start (absolute)
  AbsSecond,     // X: positioning, or the groove's start (absolute, diameter)
  IncFirst,      // W of a positioning block
  IncSecond,     // U of a positioning block (diameter)
  Step,          // P(Δi, diameter) and Q(Δk) of the groove block: unsigned, increments or mm (182#7)
  Depth,         // H(h): radius, signed: its sign is the Z direction of the feed
  FloorWidth,    // D(d) of the groove block: diameter, signed: its sign is the X direction of the steps
  Angle,         // A(∠a), B(∠b), L(∠p) of the groove block: degrees
  Length,        // R(e), V(Δv), U(Δu), W(Δw), I(r), A(r1) B(r2) D(r3) E(r4) of the cutting block:
                 // unsigned lengths (U, W, I read as magnitudes, I4)
  CornerKinds,   // P(abde) of the cutting block: four digits
  PathType,      // J of the cutting block
  Feed,          // F
  Passive,       // S, T, M
};

enum class GrooveBlockKind { Plain, Groove, Cutting };

struct GrooveProgram {
  std::vector<GrooveBlockKind> blocks;  // one per program block, same index
  // A radius no point of the program's path exceeds: the positions its blocks reach, and each
  // groove's start with room for the whole groove, the tool's width and its corners (docs/g74_1.md
  // §3–§4: u ≤ |h|·(cot ∠a + cot ∠b) + |d|/2 + 2r + r1 + r2 + |Δu| from the start, either way).
  double largestRadius = 0;
};

// True when a block of the program commands G74.1: such a program is read by readGrooveProgram,
// not by readLatheProgram.
bool isGrooveProgram(const Program& program);

// The program's blocks, or nothing with the reason (line and word) when it is outside the
// vocabulary above.
std::optional<GrooveProgram> readGrooveProgram(const Program& program, std::string& whyNot);

// The role of a word of a block the reader accepted.
GrooveRole grooveRoleOf(GrooveBlockKind kind, const Word& word);

}  // namespace cyclecert
