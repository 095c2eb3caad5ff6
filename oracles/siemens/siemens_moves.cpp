#include "oracles/siemens/siemens_moves.h"

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

}  // namespace

bool SiemensCycleMoves::isMainLevelCut(std::size_t i) const {
  const Move& m = in.path.moves[i];
  if (m.kind != MoveKind::Feed || m.shape != SegmentKind::Line) return false;
  const Point a = from(i), b = to(i);
  if (std::abs(b.x - a.x) > tol || b.z - a.z >= -tol) return false;
  return !nearPath(0.5 * (a + b), c.profile, tol) && !inUndercut(c, a, b, tol);
}

Finding SiemensCycleMoves::report(const Oracle& o, std::size_t i, std::string message) const {
  Finding f = finding(o, i, std::move(message));
  if (i < in.path.moves.size()) f.witness.segment = in.path.segment(i);
  return f;
}

std::optional<SiemensCycleMoves> siemensCycleMoves(const JudgeInput& in) {
  const SiemensCycleSpec* c = in.program.singleSiemensCycle();
  if (!c || in.path.alarm) return std::nullopt;
  SiemensCycleMoves m{*c, in, in.settings.tolerance(), movesOfTheRoughing(in), {}, {}};
  std::vector<FeedRun> runs = feedRuns(m, m.range.begin, m.range.end);
  m.finishing = {m.range.end, m.range.end};
  if (c->finishes() && !runs.empty()) {
    m.finishing = runs.back();
    runs.pop_back();
  }
  if (c->roughs()) m.roughing = std::move(runs);
  return m;
}

}  // namespace cyclecert
