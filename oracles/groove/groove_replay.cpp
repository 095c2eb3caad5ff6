#include "oracles/groove/groove_replay.h"

#include <algorithm>
#include <cmath>

#include "oracles/groove/groove_moves.h"
#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStockMargin = 1;  // mm beyond the groove's span and floor

// The outline's interior and the air above it: its chain from the mouth on the start side to the
// mouth on the far side, closed `above` over the mouth (straight up from both ends). Closed along
// the mouth line itself, the interior would share that edge with the stock, and the difference
// would leave a hole touching the stock's outline (invalid for the booleans after it).
BgRegion interiorOf(const GrooveOutline& o, double above, double chordTolerance) {
  std::vector<Point> points;
  for (const Segment& s : o.chain) appendFlattened(points, s, chordTolerance);
  const Point up = grooveUW(0, -above);
  points.push_back(o.chain.back().to + up);
  points.push_back(o.chain.front().from + up);
  return regionFrom(points);
}

// The stock band (interpretation): below the mouth line, over the finish groove's span at the mouth
// widened by the tool width and kStockMargin on both sides, down to kStockMargin below the floor.
BgRegion stockBandOf(const GrooveSpec& g) {
  const double tp = std::tan(g.slope * kPi / 180);
  const double margin = g.toolWidth + kStockMargin;
  const double uLo = std::min(0.0, g.finish.chain.front().from.x) - margin;
  const double uHi = g.finish.chain.back().to.x + margin;
  const double bottom = std::max(g.depth, uHi * tp) + kStockMargin;
  return regionFrom({grooveUW(uLo, uLo * tp), grooveUW(uHi, uHi * tp), grooveUW(uHi, bottom), grooveUW(uLo, bottom)});
}

// The local segment of move i.
Segment localSegment(const JudgeInput& in, const GrooveSpec& g, std::size_t i) {
  Segment s = in.path.segment(i);
  Segment local = s;
  local.from = g.toLocal(s.from);
  local.to = g.toLocal(s.to);
  if (s.isArc()) {
    local.center = g.toLocal(s.center);
    if (g.depthSign * g.widthSign < 0) local.kind = reversedKind(s.kind);
  }
  return local;
}

// What a feed removes: the blade's sweep, or a point's shadow — along −u (behind the steps) for the
// pecks, and for a profile pass towards the groove's inside: +u on the start side of the floor's
// middle, −u on the far side (the pass removes the allowance layer between it and the pecks).
BgRegion removedBy(const GrooveReplay& r, const Segment& move, bool profilePass, double shadow, double chordTolerance) {
  if (!r.tool.isPoint()) return sweptRegion(move, r.blade.across, r.tool.width, r.blade.back, r.blade.length, chordTolerance);
  const GrooveOutline& target = r.groove->target();
  const bool startSide = profilePass && 0.5 * (move.from.x + move.to.x) < 0.5 * (target.floorFrom + target.floorTo);
  return sweptRegion(move, grooveUW(startSide ? 1 : -1, 0), shadow, grooveUW(0, -1), 0, chordTolerance);
}

}  // namespace

BgRegion GrooveReplay::leftover() const { return checkedIntersection(remaining, target); }

std::vector<std::vector<Point>> GrooveReplay::planeOutlines(const BgRegion& local) const {
  std::vector<std::vector<Point>> out = outlinesOf(local);
  for (auto& ring : out) {
    for (Point& p : ring) p = groove->toPlane(p);
  }
  return out;
}

std::optional<GrooveReplay> replayGroove(const JudgeInput& in) {
  const GrooveSpec* g = in.program.singleGroove();
  if (!g || in.path.alarm || in.path.moves.empty()) return std::nullopt;
  const double chord = in.settings.chordTolerance, eps = in.settings.tolerance();
  GrooveReplay r;
  r.groove = g;
  r.tool.width = g->toolWidth;
  r.range = {firstMoveOfTheCycles(in), firstMoveAfterTheCycles(in)};
  r.stock = stockBandOf(*g);
  bg::model::box<BgPoint> box;
  bg::envelope(r.stock, box);
  const double span = std::max(box.max_corner().x() - box.min_corner().x(), box.max_corner().y() - box.min_corner().y());
  // The shank reaches from the deepest point of the band back out of it; a point's shadow across it.
  r.blade = {grooveUW(-1, 0), grooveUW(0, -1), span + 2 * kStockMargin};
  r.target = interiorOf(g->target(), r.blade.length, chord);
  r.part = without(r.stock, r.target);
  // J2 finishes a groove roughed before (interpretation): its material is the allowance between the
  // rough and the finish profile.
  r.remaining = g->roughs() ? r.stock : without(r.stock, interiorOf(g->rough, r.blade.length, chord));
  const std::optional<GrooveMoves> moves = grooveMoves(in);  // where the profile passes begin
  r.partCrossings.resize(in.path.moves.size());
  r.rapidCrossings.resize(in.path.moves.size());
  for (std::size_t i = r.range.begin; i < r.range.end; ++i) {
    const Segment move = localSegment(in, *g, i);
    if (distance(move.from, move.to) <= kGeomEps && !move.isArc()) continue;
    r.partCrossings[i] = toolCrossing(r.part, move, r.tool, r.blade, eps, chord);
    if (in.path.moves[i].kind == MoveKind::Rapid) {
      r.rapidCrossings[i] = toolCrossing(r.remaining, move, r.tool, r.blade, eps, chord);
    } else {
      const bool profilePass = moves && i >= moves->profileStart;
      r.remaining = without(r.remaining, removedBy(r, move, profilePass, span + 2 * kStockMargin, chord));
    }
  }
  return r;
}

}  // namespace cyclecert
