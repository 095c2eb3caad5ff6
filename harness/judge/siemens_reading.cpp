#include "harness/judge/siemens_reading.h"

#include <string_view>

#include "reference/model/alarms.h"
#include "reference/siemens/siemens_roughing_contour.h"
#include "reference/siemens/siemens_roughing_frame.h"
#include "reference/siemens/siemens_runner.h"

namespace cyclecert {

namespace {

SiemensCycleSpec callSpec(CycleFamily family, const SiemensCycleCall& call, const MachiningType& type) {
  SiemensCycleSpec c;
  c.family = family;
  c.line = call.line;
  c.position = call.position;
  c.type = type;
  c.tool = call.tool;
  if (call.contour) {
    c.contourName = call.contour->name;
    c.contourFile = call.contour->file;
    c.contour = call.contour->segments;
  }
  return c;
}

SiemensCycleSpec lcyc95Spec(const SiemensCycleCall& call, const Lcyc95Parameters& p) {
  SiemensCycleSpec c = callSpec(CycleFamily::Lcyc95, call, p.type);
  c.allowance = p.allowance;
  c.maxInfeed = p.maxInfeed;
  c.infeedAngle = p.infeedAngle;
  c.retract = p.retract;
  c.roughingFeed = p.roughingFeed;
  c.undercutFeed = p.roughingFeed;  // LCYC95 roughs no undercut: every roughing feed at R111
  c.finishingFeed = p.finishingFeed;
  return c;
}

SiemensCycleSpec cycle95Spec(const SiemensCycleCall& call, const Cycle95Parameters& p) {
  SiemensCycleSpec c = callSpec(CycleFamily::Cycle95, call, p.type);
  c.allowance = p.allowance;
  c.allowanceZ = p.allowanceZ;
  c.allowanceX = p.allowanceX;
  c.maxInfeed = p.infeed;
  c.retract = p.retract;
  c.roughingFeed = p.roughingFeed;
  c.undercutFeed = p.undercutFeed;
  c.finishingFeed = p.finishingFeed;
  c.interruptLength = std::abs(p.interruptLength);
  c.dwell = std::abs(p.dwell);
  return c;
}

// LCYC95.ALARMS, in the order the cycle checks before any move: the infeed depth (61610), the
// feeds it cuts at (10860, SIEMENS.FEED) and the infeed angle it plans (LCYC95.PARAMS), the contour
// (10931: empty, an arc over a quarter circle, against the finishing direction), then the allowance
// and the nose radius (10931, from the oracles' own profile); FF2 where CYCLE95 roughs one of the
// undercuts of that profile (10860).
void checkAndDescribe(SiemensCycleSpec& c, const SiemensCycleCall& call, const StockRemovalParameterNames& names) {
  requireInfeedDepth(c.maxInfeed, c.type, names.depth, c.line);
  requireFeedsInUse(c.type, {c.roughingFeed, names.roughingFeed}, {c.finishingFeed, names.finishingFeed}, c.line);
  requirePlannableInfeedAngle(c.infeedAngle, c.line);
  if (!call.contour) throw NotSupported(call.line, "the stock-removal cycle was called without a contour");
  checkContour(*call.contour, frameOf(c.type), c.line);
  describeSiemensCycle(c);
  if (c.family == CycleFamily::Cycle95 && c.roughs() && !c.undercuts.empty()) requireUndercutFeed(c.undercutFeed, c.line);
}

// The call read: no moves, and the tool left at the computed start, where the cycle ends
// (LCYC95.FINISH, LCYC95.ROUGH: the last move returns there).
SiemensCycleOutcome recorded(ProgramSpec& spec, SiemensCycleSpec c, const SiemensCycleCall& call,
                             const StockRemovalParameterNames& names) {
  spec.siemensCycles.push_back(std::move(c));
  SiemensCycleSpec& kept = spec.siemensCycles.back();
  checkAndDescribe(kept, call, names);
  SiemensCycleOutcome out;
  out.end = kept.frame.toPlane(kept.start);
  return out;
}

ProgramMove programMoveOf(const Move& m) {
  ProgramMove p;
  p.end = m.to;
  p.rapid = m.kind == MoveKind::Rapid;
  p.arc = m.shape != SegmentKind::Line;
  p.feed = m.feed.value_or(0);
  return p;
}

// PROG.WHOLE: the program's own moves, before the first cycle call and after the last one.
void readProgramMoves(const Toolpath& run, ProgramSpec& spec) {
  const std::size_t firstCycleMove = run.cycles.empty() ? run.moves.size() : run.cycles.front().firstMove;
  for (std::size_t i = 0; i < firstCycleMove; ++i) spec.movesBeforeCycles.push_back(programMoveOf(run.moves[i]));
  spec.motionBeforeCycles = !spec.movesBeforeCycles.empty();
  if (run.cycles.empty()) return;
  for (std::size_t i = run.cycles.back().firstMove; i < run.moves.size(); ++i) {
    spec.movesAfterCycles.push_back(programMoveOf(run.moves[i]));
  }
  spec.motionAfterCycles = !spec.movesAfterCycles.empty();
  spec.cyclesEnd = spec.siemensCycles.empty() ? run.cycles.back().start
                                              : spec.siemensCycles.back().frame.toPlane(spec.siemensCycles.back().start);
}

}  // namespace

ProgramSpec readSiemensProgramSpec(const PlanRequest& request, const Profile& profile) {
  ProgramSpec spec;
  const bool is802S = profile.siemensControl == SiemensControl::Sinumerik802S;
  spec.siemensFamily = is802S ? CycleFamily::Lcyc95 : CycleFamily::Cycle95;
  SiemensPlanners planners;
  planners.lcyc95 = [&spec](const SiemensCycleCall& call, const Lcyc95Parameters& p) {
    return recorded(spec, lcyc95Spec(call, p), call, kLcyc95ParameterNames);
  };
  planners.cycle95 = [&spec](const SiemensCycleCall& call, const Cycle95Parameters& p) {
    return recorded(spec, cycle95Spec(call, p), call, kCycle95ParameterNames);
  };
  const Toolpath run = planSiemensProgram(siemensRunInputFor(request), profile, planners);
  spec.siemensAlarm = run.alarm;
  readProgramMoves(run, spec);
  if (!spec.siemensCycles.empty()) spec.firstCycleBlockLine = spec.siemensCycles.front().line;
  return spec;
}

}  // namespace cyclecert
