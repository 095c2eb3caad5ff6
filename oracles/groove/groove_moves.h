#pragma once
// The moves of a program's one G74.1 cycle as the groove oracles see them — in the groove's own
// frame (u along d, w the depth: groove_spec.h), found by geometry and kind alone, never by the
// engine's phase labels: the cycle's moves lie between the program's own moves (PROG.WHOLE); the
// profile passes (STEP9, STEP10) begin with the first run of feeds that holds a feed across the
// groove (along u, or an arc); before it, each run of axial feeds towards the floor at one u is an
// axial cycle (STEP3…STEP6) and its feeds are pecks.
#include <optional>
#include <string>
#include <vector>

#include "oracles/groove/groove_spec.h"
#include "oracles/judgement.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

// One axial cycle: its pecks (move indices, in order), its start depth (Amn's w) and its u.
struct AxialCycle {
  std::vector<std::size_t> pecks;
  double top = 0;
  double u = 0;
};

struct GrooveMoves {
  const GrooveSpec& g;
  const JudgeInput& in;
  double tol = 0;
  MoveRange range;              // the cycle's moves, ① to the return
  std::size_t profileStart = 0;  // the first move of the profile passes (range.end without any)
  std::vector<AxialCycle> cycles;

  // Where the tool is judged (local): the programmed point, or a nose's centre (I26).
  Point from(std::size_t i) const { return g.judgedPoint(in.path.from(i)); }
  Point to(std::size_t i) const { return g.judgedPoint(in.path.moves[i].to); }
  double du(std::size_t i) const { return to(i).x - from(i).x; }
  double dw(std::size_t i) const { return to(i).z - from(i).z; }
  bool isFeed(std::size_t i) const { return in.path.moves[i].kind == MoveKind::Feed; }
  bool isRapid(std::size_t i) const { return in.path.moves[i].kind == MoveKind::Rapid; }
  // A line along w (within the tolerance in u) that moves in w (by however little: a last peck may
  // end a rounding step below the one before).
  bool isAxial(std::size_t i) const;
  // An axial feed towards the floor.
  bool isFeedTowardsTheFloor(std::size_t i) const { return isFeed(i) && isAxial(i) && dw(i) > kGeomEps; }
  // Move i's finding with its segment as the witness.
  Finding report(const Oracle& o, std::size_t i, std::string message) const;
  // A local point (as from/to) as program text of its control point: "X… Z…" (X a diameter).
  std::string planeText(Point local) const;
};

// The moves of the program's one G74.1 cycle, or nothing: no groove the rules allow, an engine's
// path that alarmed, an empty path.
std::optional<GrooveMoves> grooveMoves(const JudgeInput& in);

}  // namespace cyclecert
