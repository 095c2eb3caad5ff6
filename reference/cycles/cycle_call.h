#pragma once
// What a cycle planner receives from the program runner, and what it gives back.
#include <cstddef>
#include <vector>

#include "reference/interpreter/modal_state.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/model/program.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct CycleCall {
  const Program& program;
  std::size_t blockIndex;   // the cycle block with P and Q
  const ModalState& modal;  // state when that block is read: position = cycle start A
  MachineParams& params;    // Δd and e are modal and live in parameters 5132/5133
  const Profile& profile;
  const ToolOffset& tool;   // the active tool's nose radius and imaginary tip (for G41/G42)

  const Block& block() const { return program.blocks[blockIndex]; }
};

struct CycleOutcome {
  std::vector<Move> moves;         // physical plane coordinates (z = 1st axis, x = 2nd axis)
  std::vector<Warning> warnings;
  std::vector<Segment> shape;      // finish shape A → B → C, plane coordinates
  Point allowance;                 // shift of the rough profile, plane coordinates
  bool compensated = false;        // `shape` is the compensated path (G41/G42)
  std::vector<Segment> roughShape; // the rough profile when it is no shift of `shape` (CycleRecord)
  std::size_t resumeAt = 0;        // index of the block executed after the cycle
};

}  // namespace cyclecert
