#pragma once
// The programs the metamorphic relations transform: metric G18 lathe programs (FANUC form) with
// G71/G72 roughing cycles and G70 finishing cycles. This reads such a program from its words alone
// (the interpreter's block motion, never the planners): what each word means (its role), which
// blocks are cycle blocks and shape blocks, and where each block starts, so that a relation can
// rewrite words without changing what they mean — or say exactly why it cannot.
//
// The vocabulary (anything else is refused with the block's line and the word):
//   G00 G01 G02 G03 (motion), G70 G71 G72 (cycles), G18 G21 G40 G96 G97 G98 G99 (kept as they are);
//   X Z (absolute, X a diameter), U W (incremental, U a diameter), I K (arc centre from the arc's
//   start, radius values), R (arc radius; only in G02/G03 blocks, never with I/K);
//   G71 first block U(Δd) R(e), G72 first block W(Δd) R(e); second block P Q U(Δu) W(Δw);
//   G70 P Q; F (feed), S T M (kept as they are, never read).
// With `LatheFamilies::WithPatternRepeating` also G73 (G73.FMT): first block U(Δi) W(Δk) R(d) (Δi a
// radius, both signed, d a count), second block P Q U(Δu) W(Δw) F as G71's; the shape may be any.
// Refused: G20 (the relations' constants are in mm), G17/G19 (the relations start from G18),
// G41/G42 (a mirror changes the compensation side and the tip), G04 (its X/U is a time), any other
// G code, the letters Y V J and every other address, a second word of the same address in a block,
// X with U or Z with W in one block, R or I/K in a line block, R with I/K, a cycle block with axis
// words (the HNC one-block form) or a motion code, a roughing cycle whose shape does not follow its
// P/Q block directly, P/Q naming a block that does not exist, an arc the interpreter rejects.
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "reference/interpreter/modal_state.h"
#include "reference/model/params.h"
#include "reference/model/geometry.h"
#include "reference/model/program.h"

namespace cyclecert {

// Parameter settings by number or mnemonic, applied in order (as a spec case's "params").
using ParamSettings = std::vector<std::pair<std::string, double>>;

// The settings over the parameter catalogue's defaults (a FANUC profile's): what a FANUC profile
// reads them as. A setting the catalogue refuses is skipped (the engine that runs the program names it).
MachineParams machineParamsOf(const ParamSettings& params);

enum class BlockKind {
  Plain,        // positioning, cutting, or no motion; the shape blocks ns…nf are plain blocks
  CycleFirst,   // G71/G72 without P and Q: Δd and e
  CycleSecond,  // G71/G72 with P and Q
  Finish,       // G70 P Q
};

// What a word means, whatever its letter.
enum class WordRole {
  MotionCode,       // G00 G01 G02 G03
  CycleCode,        // G70 G71 G72
  OtherCode,        // G18 G21 G40 G96 G97 G98 G99
  AbsFirst,         // Z: the 1st axis, absolute
  AbsSecond,        // X: the 2nd axis, absolute, diameter
  IncFirst,         // W
  IncSecond,        // U, diameter
  CentreFirst,      // K: arc centre along Z from the arc's start (radius value)
  CentreSecond,     // I: along X (radius value)
  ArcRadius,        // R of a G02/G03 block
  DepthOfCut,       // Δd: U of G71's first block, W of G72's (radius, unsigned)
  Retract,          // e: R of the first block
  ReliefFirst,      // G73's Δk: W of its first block (signed, along the 1st axis)
  ReliefSecond,     // G73's Δi: U of its first block (signed, a radius)
  Divisions,        // G73's d: R of its first block (a count, not a length)
  AllowanceFirst,   // Δw: W of the P/Q block
  AllowanceSecond,  // Δu: U of the P/Q block (diameter)
  Sequence,         // P, Q of a cycle block
  Feed,             // F
  Passive,          // S, T, M
};

struct BlockInfo {
  BlockKind kind = BlockKind::Plain;
  int cycle = 0;                        // 70, 71, 72, 73: a cycle block's code; a shape block's cycle
  std::optional<std::size_t> shapeOf;   // shape blocks (ns…nf): index of their cycle's P/Q block
  bool head = false;                    // block ns
  ModalState before;                    // when the block is read: its start point, modal codes
  int motion = 0;                       // the motion mode it moves in (its own G00–G03, else modal)
  std::optional<Segment> segment;       // its motion in the plane (z, x radius), when it moves
  // Finish blocks: G70's P and Q name a roughing cycle's ns and nf and G70 starts at that cycle's
  // start point, so the shape means the same to both (relations that rewrite positions need it).
  bool finishAtCycleStart = false;
};

struct RoughingCycleInfo {
  std::size_t block = 0;   // the P/Q block
  int code = 0;            // 71, 72 or 73
  std::size_t ns = 0, nf = 0;
  Point start;             // A
};

struct LatheProgram {
  std::vector<BlockInfo> blocks;  // one per program block, same index
  std::vector<RoughingCycleInfo> cycles;
  // Every point the program's motions reach (block end points, arcs' apexes), and the cycles'
  // start points; radius for x. A G73's shape counts at both ends of its passes' shifts: at the
  // allowance and at the relief plus the allowance (G73.PASS.SHIFT), with Δi/Δk as the program
  // (or, read with settings, parameters 5135/5136) sets them.
  Extent reach{0, 0, 0, 0};
};

// The cycle families a relation handles. The relations written for G71/G72 read with the default
// and refuse G73 as a code outside their vocabulary; those that also hold for G73 ask for it.
enum class LatheFamilies { Roughing, WithPatternRepeating };

// Reads the program as a G code system A program, or returns nothing and says why (line and word)
// it is outside the vocabulary.
std::optional<LatheProgram> readLatheProgram(const Program& program, std::string& whyNot,
                                             LatheFamilies families = LatheFamilies::Roughing);

// The same, for a program that runs with these settings: refused (with the reason) when they select
// G code system B or C (3401#6 GSB, #7 GSC, PROG.GSYS.SELECT as the FANUC profiles read them) —
// there U/W are no increments, G90/G91 are modes and system C's G71 is metric input, so the
// vocabulary's words would be misread. Every relation reads its source through this.
std::optional<LatheProgram> readLatheProgram(const Program& program, const ParamSettings& params, std::string& whyNot,
                                             LatheFamilies families = LatheFamilies::Roughing);

// A shape that G70 runs from somewhere else than its roughing cycle's start point means another
// geometry with incremental words than with absolute ones: relations that rewrite positions refuse
// it (false, with the G70's line in whyNot).
bool finishesAtCycleStarts(const Program& p, const LatheProgram& lathe, std::string& whyNot);

// The role of a word of a block the reader accepted.
WordRole roleOf(const BlockInfo& info, const Word& word);

}  // namespace cyclecert
