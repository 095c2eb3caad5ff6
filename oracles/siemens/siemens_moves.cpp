#include "oracles/siemens/siemens_moves.h"

#include <algorithm>
#include <cmath>

#include "oracles/oracles.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

std::vector<FeedRun> feedRuns(const SiemensCycleMoves& m, std::size_t begin, std::size_t end) {
  std::vector<FeedRun> runs;
  std::size_t i = begin;
  while (i < end) {
    if (!m.isFeed(i)) {
      ++i;
      continue;
    }
    FeedRun run{i, i};
    while (run.end < end && m.isFeed(run.end)) ++run.end;
    runs.push_back(run);
    i = run.end;
  }
  return runs;
}

bool isLevelCutTowardsMinusZ(const SiemensCycleMoves& m, std::size_t i) {
  const Move& move = m.in.path.moves[i];
  if (move.kind != MoveKind::Feed || move.shape != SegmentKind::Line) return false;
  const Point a = m.from(i), b = m.to(i);
  return std::abs(b.x - a.x) <= m.tol && b.z - a.z < -m.tol;
}

// The runs of feeds the call's documented sequence makes: one per roughing pass — each main level
// (LCYC95.DEPTH), and for CYCLE95 each level of each undercut (CYCLE95.UNDERCUT) — and the
// finishing pass.
std::size_t feedRunsOfTheCall(const SiemensCycleSpec& c) {
  std::size_t runs = c.finishes() ? 1 : 0;
  if (!c.roughs()) return runs;
  runs += static_cast<std::size_t>(c.levels.count);
  if (!c.isCycle95()) return runs;
  for (const SiemensUndercut& u : c.undercuts) runs += static_cast<std::size_t>(equalLevels(u.top, u.bottom, c.maxInfeed).count);
  return runs;
}

// One past the call's last move: after its runs of feeds, the first move that brings the tool to
// its computed start S (the return after roughing, the G0 back after finishing; the retract itself
// when it ends there). The rest of the cycles' moves, `end`, when the path makes fewer.
std::size_t endOfCall(const JudgeInput& in, const SiemensCycleSpec& c, std::size_t begin, std::size_t end, double tol) {
  std::size_t runs = feedRunsOfTheCall(c);
  std::size_t i = begin;
  while (runs > 0 && i < end) {
    if (in.path.moves[i].kind == MoveKind::Feed && (i + 1 == end || in.path.moves[i + 1].kind != MoveKind::Feed)) --runs;
    ++i;
  }
  const Point startPlane = c.frame.toPlane(c.start);
  for (; i < end; ++i) {
    if (nearlyEqual(in.path.moves[i].to, startPlane, tol)) return i + 1;
  }
  return end;
}

// Move i as a cut along a level towards −z (frame) off the roughing profile: a main pass's cut
// (SiemensCycleMoves::isMainLevelCut) or the cut across an undercut's pocket (undercutLevelCut).
SiemensCycleMoves::LevelCut levelCutOf(const SiemensCycleMoves& m, std::size_t i) {
  if (!isLevelCutTowardsMinusZ(m, i)) return {};
  const Point a = m.from(i), b = m.to(i);
  if (nearPath(0.5 * (a + b), m.c.profile, m.tol)) return {};
  if (!inUndercut(m.c, a, b, m.tol)) {
    // A level's cut comes from the entry side; a move from the contour's first point (the top of
    // the part's face) goes across the allowance to the profile's start behind it (LCYC95.ROUGH note).
    const bool fromContourStart =
        !m.c.contour.empty() && nearlyEqual(a, m.c.frame.toFrame(m.c.contour.front().from), m.tol);
    return {!fromContourStart, nullptr};
  }
  for (const SiemensUndercut& u : m.c.undercuts) {
    if (a.z <= u.rimZ + m.tol && b.z >= u.endZ - m.tol) return {false, &u};
  }
  return {};
}

SiemensCycleMoves movesOfCall(const JudgeInput& in, const SiemensCycleSpec& c, MoveRange range) {
  SiemensCycleMoves m{c, in, in.settings.tolerance(), range, {}, {}, {}};
  std::vector<FeedRun> runs = feedRuns(m, m.range.begin, m.range.end);
  m.finishing = {m.range.end, m.range.end};
  if (c.finishes() && !runs.empty()) {
    m.finishing = runs.back();
    runs.pop_back();
  }
  if (c.roughs()) m.roughing = std::move(runs);
  m.levelCuts.resize(m.range.end - m.range.begin);
  for (const FeedRun& cut : m.roughing) {
    for (std::size_t i = cut.begin; i < cut.end; ++i) m.levelCuts[i - m.range.begin] = levelCutOf(m, i);
  }
  return m;
}

}  // namespace

Finding SiemensCycleMoves::report(const Oracle& o, std::size_t i, std::string message) const {
  Finding f = finding(o, i, std::string(cycleCode(c.family)) + " at line " + std::to_string(c.line) + ": " +
                                std::move(message));
  const std::string own = c.rule("");
  f.rules.erase(std::remove_if(f.rules.begin(), f.rules.end(),
                               [&](const std::string& rule) { return rule.rfind(own, 0) != 0; }),
                f.rules.end());
  if (i < in.path.moves.size()) f.witness.segment = in.path.segment(i);
  return f;
}

std::vector<SiemensCycleMoves> siemensCallsMoves(const JudgeInput& in) {
  std::vector<SiemensCycleMoves> calls;
  const std::vector<SiemensCycleSpec>& specs = in.program.siemensCycles;
  if (specs.empty() || in.program.siemensAlarm || in.path.alarm) return calls;
  const MoveRange all = movesOfTheRoughing(in);
  const double tol = in.settings.tolerance();
  std::size_t begin = std::min(all.begin, all.end);
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const std::size_t end = k + 1 == specs.size() ? all.end : endOfCall(in, specs[k], begin, all.end, tol);
    calls.push_back(movesOfCall(in, specs[k], {begin, end}));
    begin = end;
  }
  return calls;
}

}  // namespace cyclecert
