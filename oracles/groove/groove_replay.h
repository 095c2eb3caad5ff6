#pragma once
// The material replay of a program's one G74.1 cycle, shared by no-gouge, rapids-in-air and
// complete (computed once per judgement, JudgeContext::groove). It works in the groove's frame
// (u along d, w the depth: groove_spec.h) with the tool as a ToolShape (oracles/material/tool_shape.h):
// - a grooving tool (I = r > 0) is a blade of width r whose programmed point is its corner on d's
//   side (I12): it spans u ∈ [u − r, u], its shank runs back to the start side (−w) out of the
//   stock. A move removes exactly what the blade sweeps;
// - a pointed tool (no I, I13) is a point; each peck removes its shadow towards the start side of
//   the steps (−u: the axial cycles step along +u, so what lies behind a peck down to its depth is
//   cut), the point model's shadow in the groove's frame; a profile pass's feed (groove_moves.h)
//   removes its shadow towards the groove's inside (+u on the start side, −u on the far side);
// - a pointed tool's nose under G41/G42 (I26, groove_nose.h) is the disc of radius R around the
//   nose centre (each move's control point − R·tip): a move sweeps it, a feed removes the sweep and
//   its shadow as a point's; what it must empty is the target opened by the disc.
// The stock (interpretation, oracles/README.md): the part in front of the face at S — the band
// below the mouth line (the outer bottom through S at the slope ∠p) down to 1 mm below the groove's
// floor, over the groove's span at the mouth plus the tool width and 1 mm on both sides. The part
// no move may enter is that band without the groove the cycle must cut (its target: the finish
// profile with J1/J2, the rough profile with J0). J2 (finish only) works on a groove roughed before:
// its material at the start is the band without the rough profile's interior (the allowances).
#include <optional>
#include <vector>

#include "oracles/groove/groove_moves.h"
#include "oracles/groove/groove_spec.h"
#include "oracles/judgement.h"
#include "oracles/material/tool_shape.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

struct GrooveReplay {
  const GrooveSpec* groove = nullptr;
  ToolShape tool;
  double noseRadius = 0;     // a pointed tool's nose under G41/G42 (groove_nose.h); 0: none
  // The nose's shapes, made once (noseRadius > 0): the disc a move sweeps, and the disc with the
  // shadow a feed removes towards +u and towards −u.
  struct NoseShapes {
    SweptShape disc, shadowedForward, shadowedBack;
  };
  std::optional<NoseShapes> nose;
  BladeFrame blade;          // the blade's rectangle in the groove's frame
  MoveRange range;           // the cycle's moves
  std::optional<GrooveMoves> moves;  // the cycle's moves as the step oracles see them, found once
  BgRegion stock;            // local frame
  // Made only when needed (empty otherwise): target for either, part for a crossing the bounds
  // (groove_bounds.h) cannot rule out, reachable with remaining.
  BgRegion target;           // the groove's interior the cycle must empty (local)
  BgRegion reachable;        // the part of target the tool can reach: target, or opened by a nose
  BgRegion part;             // the stock without the target: no move may enter it (local)
  // The material after the cycle's last move (local); left empty, not made, when ClearedOutline
  // (groove_bounds.h) proves a blade emptied the target: nothing then is left inside it.
  BgRegion remaining;
  std::vector<ToolCrossing> partCrossings;   // per move of the path (empty outside the range)
  std::vector<ToolCrossing> rapidCrossings;  // per move: material still standing a rapid crosses
  // What remains of the reachable target after the last move (local).
  BgRegion leftover() const;
  // A local region's outlines in the plane (witnesses).
  std::vector<std::vector<Point>> planeOutlines(const BgRegion& local) const;
};

// Nothing when the program is not one G74.1 cycle the rules allow, or the engine alarmed.
std::optional<GrooveReplay> replayGroove(const JudgeInput& in);

}  // namespace cyclecert
