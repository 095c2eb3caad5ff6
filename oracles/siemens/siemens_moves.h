#pragma once
// The moves of each stock-removal call of a SINUMERIK program, as the Siemens oracles see them — in
// the call's frame (siemens_cycle_spec.h), found by geometry and kind alone, never by the engine's
// phase labels: the cycles' moves lie between the program's own moves (PROG.WHOLE), and the calls
// follow one another in program order, each ending where its documented sequence ends, back at its
// own computed start (siemensCallsMoves). When a call finishes (types 5…12) its finishing pass is
// the last run of feeds (LCYC95.FINISH: G0 to the contour start, the contour, G0 back); every feed
// before it roughs, and a roughing cut is a run of feeds ended by the retract.
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
  // What a move of the roughing runs is as a cut along a level, found once with the call's moves
  // (siemensCallsMoves) for every oracle that asks: by move, from range.begin (nothing for a move
  // outside the roughing runs).
  struct LevelCut {
    bool main = false;                         // isMainLevelCut
    const SiemensUndercut* undercut = nullptr;  // undercutLevelCut
  };
  std::vector<LevelCut> levelCuts;

  // A line in feed along a level towards −z (frame), not on the roughing profile and not in an
  // undercut: a cut of a main roughing pass (LCYC95.ROUGH "G1 parallel to the axis").
  bool isMainLevelCut(std::size_t i) const { return levelCuts[i - range.begin].main; }
  // A line in feed along a level towards −z (frame) in one of CYCLE95's undercuts, not on the
  // roughing profile: the cut across the pocket of an undercut pass (CYCLE95.UNDERCUT); that
  // undercut, or nullptr.
  const SiemensUndercut* undercutLevelCut(std::size_t i) const { return levelCuts[i - range.begin].undercut; }
  // Move i's finding with its segment as the witness: the message names the call (its cycle and
  // line), and the finding cites those of the oracle's rules that are the call's own cycle's.
  Finding report(const Oracle& o, std::size_t i, std::string message) const;
};

// The moves of each of the program's calls, in program order; none when an alarm stops the program
// (the alarm oracle judges it) or the engine's path alarmed. A call's moves are its documented
// sequence: as many runs of feeds as it makes passes — one per roughing pass (its main levels, and
// CYCLE95's undercut levels) and the finishing pass —, then up to the first move that brings the
// tool back to its computed start (the return after roughing, the G0 back after finishing). The
// last call ends where the program's own moves after the cycles begin.
std::vector<SiemensCycleMoves> siemensCallsMoves(const JudgeInput& in);

}  // namespace cyclecert
