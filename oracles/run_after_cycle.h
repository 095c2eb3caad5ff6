#pragma once
// HNC.G71.FST, HNC.G71.RETURN: after a Huazhong G71 the tool is back at the cycle start and the
// program goes on with the block after G71, so ns…nf run again, as the finishing run, when it
// reaches them. Where those blocks' moves sit at the end of an engine's path, found by where each
// block leaves the tool (ProgramSpec::runAfterHuazhong) — never by the engine's phase labels.
#include <cstddef>
#include <optional>
#include <vector>

#include "oracles/judgement.h"

namespace cyclecert {

struct RunAfterCycle {
  // Per block of ProgramSpec::runAfterHuazhong, the move that ends it; a block's moves follow the
  // previous block's last move (a line is one move, an arc may be split).
  std::vector<std::size_t> lastMove;
  std::size_t roughingEnd = 0;  // the first move after the cycle (the first of the block after G71)
  // One past the finishing run's last move (block nf), or the path's end without a finishing run:
  // the moves after it (a part-off with another tool) belong to no cycle the oracles model.
  std::size_t judgedEnd = 0;
};

struct RunLocation {
  std::optional<RunAfterCycle> run;     // where the blocks' moves are
  std::optional<std::size_t> unmatched;  // else: the block (index into runAfterHuazhong) not found
};

// Nothing to locate (both empty) unless the program's one roughing cycle is a Huazhong G71 the
// program runs on after.
RunLocation locateRunAfterHuazhong(const JudgeInput& in);

// PROG.WHOLE: the first of the moves the program makes after its last cycle (a part-off, the way
// home: ProgramSpec::movesAfterCycles), found at the end of the path by where each block ends; the
// path's size when there are none or the engine's path does not end with them.
std::size_t firstMoveAfterTheCycles(const JudgeInput& in);

// How many moves of the path the geometric, retract and pass-level oracles judge: up to the end of
// a Huazhong finishing run, else up to the moves after the last cycle.
std::size_t movesJudgedAgainstThePart(const JudgeInput& in);

// PROG.WHOLE: the first move of the cycles — after the moves the program makes before its first
// cycle (ProgramSpec::movesBeforeCycles), found at the start of the path by where each block ends;
// 0 when the engine's path does not begin with them (it starts at the cycle).
std::size_t firstMoveOfTheCycles(const JudgeInput& in);

// The moves the oracles of the roughing passes (pass levels, retracts, depth per pass) judge: from
// the first move of the cycles to the end of a Huazhong roughing (its finishing run and the blocks
// before it are no passes), else to the end of the path.
struct MoveRange {
  std::size_t begin = 0, end = 0;
};
MoveRange movesOfTheRoughing(const JudgeInput& in);

}  // namespace cyclecert
