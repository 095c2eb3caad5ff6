#include "reference/cycles/move_emitter.h"

#include <utility>

namespace cyclecert {

void MoveEmitter::emit(MoveKind kind, Point to, MovePhase phase, int pass, std::vector<std::string> rules) {
  if (distance(current(), to) <= kGeomEps) return;  // zero-length moves are never emitted
  Move m;
  m.kind = kind;
  m.to = to;
  if (kind == MoveKind::Feed) m.feed = feed_;
  m.phase = phase;
  m.pass = pass;
  m.rules = std::move(rules);
  moves_.push_back(std::move(m));
}

void MoveEmitter::emitAlong(MoveKind kind, const Segment& along, MovePhase phase, int pass,
                            std::vector<std::string> rules) {
  const std::size_t before = moves_.size();
  emit(kind, along.to, phase, pass, std::move(rules));
  if (along.isArc() && moves_.size() > before) {
    moves_.back().shape = along.kind;
    moves_.back().center = along.center;
  }
}

}  // namespace cyclecert
