#pragma once
// The moves of a SINUMERIK program's one stock-removal call, as the Siemens oracles see them — in
// the call's frame (siemens_cycle_spec.h), found by geometry and kind alone, never by the engine's
// phase labels: the cycle's moves lie between the program's own moves (PROG.WHOLE); when the call
// finishes (types 5…12) its finishing pass is the last run of feeds (LCYC95.FINISH: G0 to the contour
// start, the contour, G0 back); every feed before it roughs, and a roughing cut is a run of feeds
// ended by the retract.
#include <optional>
#include <string>
#include <vector>

#include "oracles/judgement.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

// A run of consecutive feeds [begin, end).
struct FeedRun {
  std::size_t begin = 0, end = 0;
};

struct SiemensCycleMoves {
  const SiemensCycleSpec& c;
  const JudgeInput& in;
  double tol = 0;
  MoveRange range;                // the call's moves
  FeedRun finishing;              // the finishing pass (empty, at range.end, when the call does not finish)
  std::vector<FeedRun> roughing;  // the roughing cuts, in order, before the finishing pass

  Point from(std::size_t i) const { return c.frame.toFrame(in.path.from(i)); }
  Point to(std::size_t i) const { return c.frame.toFrame(in.path.moves[i].to); }
  bool isFeed(std::size_t i) const { return in.path.moves[i].kind == MoveKind::Feed; }
  bool isRapid(std::size_t i) const { return in.path.moves[i].kind == MoveKind::Rapid; }
  // A line in feed along a level towards −z (frame), not on the roughing profile and not in an
  // undercut: a cut of a main roughing pass (LCYC95.ROUGH "G1 parallel to the axis").
  bool isMainLevelCut(std::size_t i) const;
  // Move i's finding with its segment as the witness.
  Finding report(const Oracle& o, std::size_t i, std::string message) const;
};

// The moves of the program's one call, or nothing: several calls, an alarm (the alarm oracle judges
// it), an engine's path that alarmed.
std::optional<SiemensCycleMoves> siemensCycleMoves(const JudgeInput& in);

}  // namespace cyclecert
