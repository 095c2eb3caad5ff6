#include "oracles/run_after_cycle.h"

namespace cyclecert {

namespace {

bool endsAt(const JudgeInput& in, std::size_t move, Point p) {
  return distance(in.path.moves[move].to, p) <= in.settings.tolerance();
}

// The last move at or before `from` (counting down) that ends at p; a line block allows no other
// move in between, an arc block its pieces.
std::optional<std::size_t> lastMoveEndingAt(const JudgeInput& in, std::size_t from, Point p, bool piecesBetween) {
  for (std::size_t j = from + 1; j-- > 0;) {
    if (endsAt(in, j, p)) return j;
    if (!piecesBetween) break;
  }
  return std::nullopt;
}

// The last move of each block, matched from the end: the last block ends the path; each block ends
// just before the next one's moves begin (right before a line, before an arc's pieces). Nothing
// when a block is not found (its index in *unmatched).
std::optional<std::vector<std::size_t>> lastMovesFromTheEnd(const JudgeInput& in, const std::vector<ProgramMove>& blocks,
                                                            std::size_t* unmatched) {
  std::vector<std::size_t> lastMove(blocks.size());
  std::optional<std::size_t> at;
  for (std::size_t k = blocks.size(); k-- > 0;) {
    if (k + 1 == blocks.size()) {
      at = in.path.moves.empty() ? std::nullopt : lastMoveEndingAt(in, in.path.moves.size() - 1, blocks[k].end, false);
    } else {
      at = lastMove[k + 1] == 0 ? std::nullopt : lastMoveEndingAt(in, lastMove[k + 1] - 1, blocks[k].end, blocks[k + 1].arc);
    }
    if (!at) {
      if (unmatched) *unmatched = k;
      return std::nullopt;
    }
    lastMove[k] = *at;
  }
  return lastMove;
}

// The first move of blocks matched by lastMovesFromTheEnd, which follow a move ending at `from`.
std::size_t firstMoveOf(const JudgeInput& in, const std::vector<ProgramMove>& blocks,
                        const std::vector<std::size_t>& lastMove, Point from) {
  std::size_t first = lastMove.front();
  if (blocks.front().arc && first > 0) {
    if (auto a = lastMoveEndingAt(in, first - 1, from, true)) first = *a + 1;
  }
  return first;
}

}  // namespace

RunLocation locateRunAfterHuazhong(const JudgeInput& in) {
  const std::vector<ProgramMove>& blocks = in.program.runAfterHuazhong;
  const CycleSpec* cycle = in.program.singleRoughingCycle();
  RunLocation where;
  if (blocks.empty() || !cycle || in.path.alarm) return where;
  std::size_t unmatched = 0;
  const auto lastMove = lastMovesFromTheEnd(in, blocks, &unmatched);
  if (!lastMove) {
    where.unmatched = unmatched;
    return where;
  }
  RunAfterCycle run;
  run.lastMove = *lastMove;
  // HNC.G71.RETURN: the cycle ends at A, where the block after G71 starts.
  run.roughingEnd = firstMoveOf(in, blocks, run.lastMove, cycle->start);
  run.judgedEnd = in.path.moves.size();
  for (std::size_t k = blocks.size(); k-- > 0;) {
    if (blocks[k].finishing) {
      run.judgedEnd = run.lastMove[k] + 1;
      break;
    }
  }
  where.run = run;
  return where;
}

std::size_t firstMoveAfterTheCycles(const JudgeInput& in) {
  const std::vector<ProgramMove>& blocks = in.program.movesAfterCycles;
  if (blocks.empty() || !in.program.runAfterHuazhong.empty() || in.path.alarm) return in.path.moves.size();
  const auto lastMove = lastMovesFromTheEnd(in, blocks, nullptr);
  return lastMove ? firstMoveOf(in, blocks, *lastMove, in.program.cyclesEnd) : in.path.moves.size();
}

std::size_t movesJudgedAgainstThePart(const JudgeInput& in) {
  if (in.program.runAfterHuazhong.empty()) return firstMoveAfterTheCycles(in);
  const RunLocation where = locateRunAfterHuazhong(in);
  return where.run ? where.run->judgedEnd : in.path.moves.size();
}

std::size_t firstMoveOfTheCycles(const JudgeInput& in) {
  const std::vector<ProgramMove>& blocks = in.program.movesBeforeCycles;
  std::size_t next = 0;  // the path's move the next block begins with
  for (const ProgramMove& b : blocks) {
    std::size_t j = next;
    while (j < in.path.moves.size() && !endsAt(in, j, b.end) && b.arc) ++j;  // an arc's pieces
    if (j >= in.path.moves.size() || !endsAt(in, j, b.end)) return 0;  // not drawn: the path starts at the cycle
    next = j + 1;
  }
  return next;
}

MoveRange movesOfTheRoughing(const JudgeInput& in) {
  MoveRange range{firstMoveOfTheCycles(in), firstMoveAfterTheCycles(in)};
  if (in.program.runAfterHuazhong.empty()) return range;
  const RunLocation where = locateRunAfterHuazhong(in);
  if (where.run) range.end = where.run->roughingEnd;
  return range;
}

}  // namespace cyclecert
