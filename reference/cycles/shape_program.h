#pragma once
// The shape program ns…nf of a G71/G72/G73 cycle: found by sequence number, checked against the
// commands a shape program may contain, and turned into plane segments.
#include <vector>

#include "reference/cycles/cycle_call.h"

namespace cyclecert {

struct ShapeProgram {
  std::size_t nsIndex = 0, nfIndex = 0;
  int nsLine = 0;
  bool headIsRapid = true;       // block ns has G00 (else G01)
  bool headHasFirstAxis = false; // block ns has a word of the plane's 1st axis (e.g. Z/W)
  bool headHasSecondAxis = false;// block ns has a word of the plane's 2nd axis (e.g. X/U)
  Point start;                   // A
  Point headEnd;                 // B
  std::vector<Segment> body;     // B → C
  bool compensated = false;      // B and the body are the compensated path (G41/G42 at the cycle)
  int compensationInShape = 40;  // HAAS.TNRC.SHAPE: G41/G42 commanded in block ns (haas profile)

  // The whole finish shape A → B → C (the head block as a line).
  std::vector<Segment> finishShape() const;
};

// Reads blocks P…Q of the call's program. Throws CycleAlarm:
//  PS0063 when P or Q names no block (or Q stands before P),
//  PS0065 when block ns has no G00/G01 word (G71.HEAD.G0G1),
//  PS0325 for commands not usable in a shape program (G72.NSNF.GCODES, G71.TNRC.PLACE).
ShapeProgram readShapeProgram(const CycleCall& call, const Word& p, const Word& q);

// The block found by a P or Q word (PS0063 naming the cycle block when there is none).
std::size_t findSequenceBlock(const CycleCall& call, const Word& w, char which);

// G72.NSNF.GCODES, G71.TNRC.PLACE, PROG.GSYS.B: PS0325 for a command a shape program may not
// contain, each G code judged by its function in the program's G code system (usableInShapeProgram:
// system B's G91 is allowed as system A's U/W are, its G98 return level is not). G40/G41/G42 are
// allowed when `tnrcAllowed` (the profile tolerates them, NT1 for roughing, NT2 for G70).
void checkUsableInShape(const Block& b, GCodeSystem system, bool tnrcAllowed);

// The modal codes a shape block changes for the blocks after it within ns…nf: its motion code and,
// in systems B/C and Huazhong, G90/G91 (PROG.GSYS.B, PROG.GSYS.INCREMENTAL).
void applyShapeModes(const Block& b, ModalState& s);

// The group-01 motion code (0…3) a block commands, or `modal` when it commands none.
int motionCode(const Block& b, int modal);

// G71.TNRC.CANCEL, G71.TNRC.ZERO, G71.CHECK: with G41/G42 in force at the cycle, the cycle works
// on the compensated shape: A stays where it is (compensation is cancelled on the way to the start
// point), block ns is the start-up (its end B moves to the compensated position for the next
// block), and the body is the path of the imaginary tool-nose point. PS0041 when the nose radius
// does not fit the shape. HAAS.TNRC.SHAPE: on a profile that compensates the shape, G41/G42 in
// block ns do the same (block ns is then the start-up block, as the manual's examples write it).
void compensateShape(const CycleCall& call, ShapeProgram& shape);

// G72.NSNF.FOLLOW: execution resumes after nf when ns directly follows the cycle block,
// otherwise after the cycle block.
std::size_t resumeIndexAfterCycle(const CycleCall& call, const ShapeProgram& shape);

}  // namespace cyclecert
