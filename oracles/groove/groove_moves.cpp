#include "oracles/groove/groove_moves.h"

#include <cmath>

#include "oracles/oracles.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

// The first move of the profile passes: the start of the first run of consecutive feeds that holds
// a feed across the groove (along u: the floor, a slanted flank, a corner); range.end when there is
// none. (A feed back along w alone is no profile pass: groove-retract judges it.)
std::size_t profileStartOf(const GrooveMoves& m) {
  std::size_t runStart = m.range.begin;
  bool inRun = false;
  for (std::size_t i = m.range.begin; i < m.range.end; ++i) {
    if (!m.isFeed(i)) {
      inRun = false;
      continue;
    }
    if (!inRun) runStart = i;
    inRun = true;
    if (std::abs(m.du(i)) > m.tol || m.in.path.moves[i].shape != SegmentKind::Line) return runStart;
  }
  return m.range.end;
}

// STEP3…STEP6: before the profile passes, the pecks grouped by axial cycle — a cycle ends where the
// tool moves along u, or rapids back to the cycle's start or above it (STEP6: the next cycle may
// start a step shorter than the tolerance further, at Amf) unless a feed towards the floor follows
// in place: a retract e longer than the depth reached (STEP4, e > Δk) also rises above the start.
std::vector<AxialCycle> axialCyclesOf(const GrooveMoves& m) {
  std::vector<AxialCycle> cycles;
  bool open = false;
  const auto peckFollows = [&](std::size_t i) {
    return i + 1 < m.profileStart && m.isFeedTowardsTheFloor(i + 1) && std::abs(m.du(i + 1)) <= m.tol;
  };
  for (std::size_t i = m.range.begin; i < m.profileStart; ++i) {
    const bool backAtTheStart = open && m.isRapid(i) && m.to(i).z <= cycles.back().top + m.tol && !peckFollows(i);
    if (std::abs(m.du(i)) > m.tol || backAtTheStart) {
      open = false;
      continue;
    }
    if (!m.isFeedTowardsTheFloor(i)) continue;
    if (!open) cycles.push_back(AxialCycle{{}, m.from(i).z, m.from(i).x});
    open = true;
    cycles.back().pecks.push_back(i);
  }
  return cycles;
}

}  // namespace

bool GrooveMoves::isAxial(std::size_t i) const {
  return in.path.moves[i].shape == SegmentKind::Line && std::abs(du(i)) <= tol && std::abs(dw(i)) > kGeomEps;
}

Finding GrooveMoves::report(const Oracle& o, std::size_t i, std::string message) const {
  Finding f = finding(o, i, std::move(message));
  if (i < in.path.moves.size()) f.witness.segment = in.path.segment(i);
  return f;
}

std::string GrooveMoves::planeText(Point local) const {
  const Point p = g.controlPoint(local);
  return "X" + shortDecimalText(2 * p.x) + " Z" + shortDecimalText(p.z);
}

std::optional<GrooveMoves> grooveMoves(const JudgeInput& in) {
  const GrooveSpec* g = in.program.singleGroove();
  if (!g || in.path.alarm || in.path.moves.empty()) return std::nullopt;
  GrooveMoves m{*g, in, in.settings.tolerance(), {firstMoveOfTheCycles(in), firstMoveAfterTheCycles(in)}, 0, {}};
  if (m.range.begin >= m.range.end) return std::nullopt;
  m.profileStart = profileStartOf(m);
  m.cycles = axialCyclesOf(m);
  return m;
}

}  // namespace cyclecert
