#pragma once
// How the cycle planners (type I, type II, G73) append their moves: from where the tool stands (the
// last move's end, or the cycle start), never a move of zero length, feeds at the cycle's F, a move
// along an arc keeping its direction and centre.
#include <cstddef>
#include <string>
#include <vector>

#include "reference/model/toolpath.h"

namespace cyclecert {

class MoveEmitter {
 public:
  MoveEmitter(Point start, double feed) : start_(start), feed_(feed) {}

  // Where the tool stands: the last move's end, or the start before the first move.
  Point current() const { return moves_.empty() ? start_ : moves_.back().to; }

  // A straight move to `to`; not emitted when it is no longer than kGeomEps.
  void emit(MoveKind kind, Point to, MovePhase phase, int pass, std::vector<std::string> rules);
  // A move along `along` to its end (a line, or an arc with its direction and centre); not emitted
  // when its end is within kGeomEps of where the tool stands.
  void emitAlong(MoveKind kind, const Segment& along, MovePhase phase, int pass, std::vector<std::string> rules);

  // The moves, handed over (the emitter is empty afterwards).
  std::vector<Move> take() { return std::move(moves_); }

 private:
  Point start_;
  double feed_;
  std::vector<Move> moves_;
};

}  // namespace cyclecert
