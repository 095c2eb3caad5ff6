#include "oracles/groove/groove_replay.h"

#include <algorithm>
#include <cmath>

#include "oracles/groove/groove_bounds.h"
#include "oracles/groove/groove_moves.h"
#include "oracles/groove/groove_nose.h"
#include "oracles/material/boost_geometry.h"

namespace cyclecert {

namespace bg = boost::geometry;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kStockMargin = 1;  // mm beyond the groove's span and floor
constexpr double kBoundSlack = 1e-9;  // mm: a tool exactly on the part's top, computed two ways

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
BandFrame bandFrameOf(const GrooveSpec& g) {
  const double margin = g.toolWidth + kStockMargin;
  return {std::min(0.0, g.finish.chain.front().from.x) - margin, g.finish.chain.back().to.x + margin,
          std::tan(g.slope * kPi / 180)};
}

BgRegion stockBandOf(const GrooveSpec& g, const BandFrame& b) {
  const double bottom = std::max(g.depth, b.mouthAt(b.uHi)) + kStockMargin;
  return regionFrom({grooveUW(b.uLo, b.mouthAt(b.uLo)), grooveUW(b.uHi, b.mouthAt(b.uHi)), grooveUW(b.uHi, bottom),
                     grooveUW(b.uLo, bottom)});
}

// The local segment of move i, as the tool is judged by (a nose: its centre, I26).
Segment localSegment(const JudgeInput& in, const GrooveSpec& g, std::size_t i) {
  Segment s = in.path.segment(i);
  Segment local = s;
  local.from = g.judgedPoint(s.from);
  local.to = g.judgedPoint(s.to);
  if (s.isArc()) {
    local.center = g.judgedPoint(s.center);
    if (g.depthSign * g.widthSign < 0) local.kind = reversedKind(s.kind);
  }
  return local;
}

// A nose's centre path: R back along h from its lowest point, the point it is judged by (I26).
Segment centrePath(const GrooveReplay& r, const Segment& move) { return move.shifted(grooveUW(0, -r.noseRadius)); }

// A point's shadow runs along −u (behind the steps) for the pecks, and for a profile pass towards
// the groove's inside: +u on the start side of the floor's middle, −u on the far side (the pass
// removes the allowance layer between it and the pecks). +1 or −1 along u.
int shadowSide(const GrooveReplay& r, const Segment& move, bool profilePass) {
  const GrooveOutline& target = r.groove->target();
  const bool startSide = profilePass && 0.5 * (move.from.x + move.to.x) < 0.5 * (target.floorFrom + target.floorTo);
  return startSide ? 1 : -1;
}

// The region the tool sweeps along one move — the blade's rectangle, the nose's disc (a point sweeps
// none) — computed when first asked: a blade's feed is crossed with the part and removed by the
// same sweep.
class MoveSweep {
 public:
  MoveSweep(const GrooveReplay& r, const Segment& move, double chordTolerance)
      : r_(r), move_(move), chordTolerance_(chordTolerance) {}
  const BgRegion& region() {
    if (!swept_) swept_ = sweepOf(r_, move_, chordTolerance_);
    return *swept_;
  }
  // The region if it was computed (nothing otherwise), handed over.
  std::optional<BgRegion> take() { return std::move(swept_); }

 private:
  static BgRegion sweepOf(const GrooveReplay& r, const Segment& move, double chordTolerance) {
    if (r.nose) return sweptConvexShape(centrePath(r, move), r.nose->disc, chordTolerance);
    return sweptRegion(move, r.blade.across, r.tool.width, r.blade.back, r.blade.length, chordTolerance);
  }
  const GrooveReplay& r_;
  const Segment& move_;
  double chordTolerance_;
  std::optional<BgRegion> swept_;
};

// What a feed removes: the blade's sweep, a nose's sweep and shadow, or a point's shadow.
BgRegion removedBy(const GrooveReplay& r, const Segment& move, MoveSweep& sweep, int side, double shadow,
                   double chordTolerance) {
  if (!r.tool.isPoint()) return sweep.region();
  if (r.nose) {  // the disc about the centre, R back along h from the point judged (I26)
    return sweptConvexShape(centrePath(r, move), side > 0 ? r.nose->shadowedForward : r.nose->shadowedBack,
                            chordTolerance);
  }
  return sweptRegion(move, grooveUW(side, 0), shadow, grooveUW(0, -1), 0, chordTolerance);
}

// A feed whose removal unites with the staircase exactly (groove_bounds.h) is added to it: a straight
// move along u or w — the blade's rectangle reaching back out of the band, or a point's shadow
// rectangle over material gone above it (a move along u: a shadow of no area, nothing). False for
// any other move (its removal stays a region).
bool clearsAStep(ClearedStaircase& cleared, const GrooveReplay& r, const Segment& move, int side, double shadow,
                 const ToolExtent& e) {
  if (move.isArc()) return false;
  const bool alongU = std::abs(move.from.z - move.to.z) <= kGeomEps;
  const bool alongW = std::abs(move.from.x - move.to.x) <= kGeomEps;
  if (!alongU && !alongW) return false;
  if (!r.tool.isPoint()) {
    if (!cleared.goneAbove(e.uFrom, e.uTo, e.wShallowest - r.blade.length)) return false;
    cleared.clearDownTo(e.uFrom, e.uTo, e.wDeepest);
    return true;
  }
  if (r.noseRadius > 0) return false;  // a disc's sweep: an exact region (groove_nose.h)
  if (alongU) return true;
  const double u = move.from.x;
  const double uFrom = side > 0 ? u : u - shadow, uTo = side > 0 ? u + shadow : u;
  if (!cleared.goneAbove(uFrom, uTo, e.wShallowest)) return false;
  cleared.clearDownTo(uFrom, uTo, e.wDeepest);
  return true;
}

// The material at a moment: what was there at the start without the other removals so far
// (applied as they come) and without the staircase (set difference: the order does not matter).
BgRegion materialNow(const BgRegion& withoutTheOthers, const ClearedStaircase& cleared, double top) {
  if (cleared.empty()) return withoutTheOthers;
  BgRegion steps;
  for (const std::vector<Point>& ring : cleared.outlines(top)) {
    const BgRegion one = regionFromSimpleOutline(ring);  // a histogram over u: simple by construction
    steps.insert(steps.end(), one.begin(), one.end());
  }
  return without(withoutTheOthers, steps);
}

}  // namespace

BgRegion GrooveReplay::leftover() const {
  if (remaining.empty()) return {};  // the bounds proved the target emptied (remaining not made)
  return consistentIntersection(remaining, reachable);
}

namespace {

// A move's extent: a nose's is its centre's grown by R on every side (a box around the disc's sweep).
ToolExtent extentOf(const GrooveReplay& r, const Segment& move, double chord) {
  if (r.noseRadius <= 0) return toolExtent(move, r.tool.width, chord);
  ToolExtent e = toolExtent(centrePath(r, move), 0, chord);
  e.uFrom -= r.noseRadius;
  e.uTo += r.noseRadius;
  e.wShallowest -= r.noseRadius;
  e.wDeepest += r.noseRadius;
  return e;
}

ToolCrossing crossingOfTheTool(const GrooveReplay& r, const BgRegion& region, const Segment& move, MoveSweep& sweep,
                               double eps, double chord) {
  if (r.tool.isPoint() && r.noseRadius <= 0) return toolCrossing(region, move, r.tool, r.blade, eps, chord);
  if (region.empty()) return {};
  return sweptCrossing(region, sweep.region(), eps);
}

using Box = bg::model::box<BgPoint>;

// The deepest outline (greatest w over each u) of a convex shape's sweep along a chord: the upper
// hull in w of its corners at both ends (`corners`, any order), u strictly increasing.
std::vector<Point> deepestOutlineOf(std::vector<Point> corners) {
  std::sort(corners.begin(), corners.end(), [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.z > b.z); });
  std::vector<Point> hull;
  for (Point c : corners) {
    if (!hull.empty() && hull.back().x == c.x) continue;  // the deeper one at this u came first
    // Drop a corner that lies above (shallower than) the chord past it.
    while (hull.size() >= 2) {
      const Point a = hull[hull.size() - 2], b = hull.back();
      if ((b.x - a.x) * (c.z - a.z) - (c.x - a.x) * (b.z - a.z) < 0) break;  // b deeper than chord a–c
      hull.pop_back();
    }
    hull.push_back(c);
  }
  return hull;
}

// The blade's: its bottom edge's corners at both ends.
std::vector<Point> bladeBottomAlong(Point from, Point to, double width) {
  return deepestOutlineOf({from + grooveUW(-width, 0), from, to + grooveUW(-width, 0), to});
}

// A nose's: the disc's polygon (noseDisc) about the centre at both ends, those of its points that
// can lie on the sweep's hull (SweptShape::along).
std::vector<Point> noseBottomAlong(Point from, Point to, const SweptShape& disc) {
  std::vector<Point> corners;
  disc.along(from, to, corners);
  return deepestOutlineOf(std::move(corners));
}

// Whether a nose's sweep along the move stays above the part's top within `slack` (as
// bladeStaysAbove: a pass along the profile follows it R off).
bool noseStaysAbove(const PartTop& top, const GrooveReplay& r, const Segment& move, double slack, double chord) {
  if (!r.nose) return false;
  const std::vector<Point> points = flatten(centrePath(r, move), chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!top.liesBelow(noseBottomAlong(points[k], points[k + 1], r.nose->disc), slack)) return false;
  }
  return true;
}

// Whether the blade's sweep along each chord reaches back out of the band (its shank, blade.length
// back from the chord's deepest point, above the band's top everywhere): then it removes
// everything above its deepest outline over its span.
bool reachesOut(const GrooveReplay& r, const BandFrame& band, Point from, Point to) {
  return std::max(from.z, to.z) - r.blade.length <= band.shallowestMouth(band.uLo, band.uHi);
}

// D := max(D, the blade feed's deepest outline) over each chord's span, for the chords that
// reach out of the band.
void raiseByFeed(ClearedOutline& deepest, const GrooveReplay& r, const BandFrame& band, const Segment& move,
                 double chord) {
  const std::vector<Point> points = flatten(move, chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (reachesOut(r, band, points[k], points[k + 1])) {
      deepest.clearDownTo(bladeBottomAlong(points[k], points[k + 1], r.tool.width));
    }
  }
}

// Whether a blade's rapid stays at or above max(D, mouth) within `slack` along every chord: it
// crosses nothing of what stands thicker than that, whatever the removals not yet applied.
bool bladeRapidClear(const ClearedOutline& deepest, const GrooveReplay& r, const Segment& move, double slack,
                     double chord) {
  const std::vector<Point> points = flatten(move, chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!deepest.covers(bladeBottomAlong(points[k], points[k + 1], r.tool.width), slack)) return false;
  }
  return true;
}

// Whether a point's rapid runs within `slack` of the cleared rows (or in the air) along every
// chord: what stands lies no farther than that inside of it, and a point's crossing counts only
// what lies more than ε inside (crossingOf).
bool pointRapidClear(const ShadowedRows& rows, const Segment& move, double slack, double chord) {
  const std::vector<Point> points = flatten(move, chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!rows.clears(points[k], points[k + 1], slack)) return false;
  }
  return true;
}

// A point's feed: each chord's rows behind it (its shadow towards `side`).
void shadowRowsOf(ShadowedRows& rows, const Segment& move, int side, double shadow, double chord) {
  const std::vector<Point> points = flatten(move, chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) rows.clearBehind(points[k], points[k + 1], side, shadow);
}

// A feed whose removal is not yet applied to the material (the blade's sweep, when the part's
// crossing already made it).
struct PendingRemoval {
  Segment move;
  int side = 0;
  std::optional<BgRegion> sweep;
};

// The material with the pending removals applied, in the order of their moves: the same
// differences, the same regions, as applying each when it comes.
void applyPending(BgRegion& withoutTheOthers, std::vector<PendingRemoval>& pending, const GrooveReplay& r,
                  double shadow, double chord) {
  for (PendingRemoval& p : pending) {
    MoveSweep sweep(r, p.move, chord);
    if (p.sweep) {
      withoutTheOthers = without(withoutTheOthers, *p.sweep);
    } else {
      withoutTheOthers = without(withoutTheOthers, removedBy(r, p.move, sweep, p.side, shadow, chord));
    }
  }
  pending.clear();
}

// Whether the blade's sweep along the move stays above the part's top within `slack`: every
// chord's deepest outline at or above it (a bound finer than the move's box: a pass along a
// slanted flank or a round follows the part's top).
bool bladeStaysAbove(const PartTop& top, const GrooveReplay& r, const Segment& move, double slack, double chord) {
  if (r.tool.isPoint()) return false;
  const std::vector<Point> points = flatten(move, chord);
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    if (!top.liesBelow(bladeBottomAlong(points[k], points[k + 1], r.tool.width), slack)) return false;
  }
  return true;
}

// Whether `region` may meet the box: false when its envelope is disjoint from it (or it is empty).
bool mayMeet(const BgRegion& region, const Box& box) {
  return !region.empty() && !bg::disjoint(bg::return_envelope<Box>(region), box);
}

// A box around everything the tool sweeps along a move of extent e: a blade's shank reaches
// blade.length back (−w) from its edge.
Box sweptBoxOf(const GrooveReplay& r, const ToolExtent& e) {
  const double shank = r.tool.isPoint() ? 0 : r.blade.length;
  return {toBg(grooveUW(e.uFrom, e.wShallowest - shank)), toBg(grooveUW(e.uTo, e.wDeepest))};
}

}  // namespace

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
  r.noseRadius = g->noseRadius;
  r.range = {firstMoveOfTheCycles(in), firstMoveAfterTheCycles(in)};
  const BandFrame band = bandFrameOf(*g);
  r.stock = stockBandOf(*g, band);
  bg::model::box<BgPoint> box;
  bg::envelope(r.stock, box);
  const double span = std::max(box.max_corner().x() - box.min_corner().x(), box.max_corner().y() - box.min_corner().y());
  // The shank reaches from the deepest point of the band back out of it; a point's shadow across it.
  r.blade = {grooveUW(-1, 0), grooveUW(0, -1), span + 2 * kStockMargin};
  // The target and the part, made when first needed: a part crossing the bounds cannot rule out, or
  // the leftover (most cases need neither).
  bool targetMade = false, partMade = false;
  const auto makeTarget = [&] {
    if (!targetMade) r.target = interiorOf(g->target(), r.blade.length, chord);
    targetMade = true;
  };
  const auto partRegion = [&]() -> const BgRegion& {
    makeTarget();
    if (!partMade) r.part = without(r.stock, r.target);
    partMade = true;
    return r.part;
  };
  // J2 finishes a groove roughed before (interpretation): its material is the allowance between the
  // rough and the finish profile.
  BgRegion withoutTheOthers = g->roughs() ? r.stock : without(r.stock, interiorOf(g->rough, r.blade.length, chord));
  if (std::optional<GrooveMoves> moves = grooveMoves(in)) r.moves.emplace(std::move(*moves));
  const std::optional<GrooveMoves>& moves = r.moves;  // where the profile passes begin
  r.partCrossings.resize(in.path.moves.size());
  r.rapidCrossings.resize(in.path.moves.size());
  // The bounds (groove_bounds.h) answer most moves; the exact regions the rest.
  const std::optional<PartTop> partTop = PartTop::of(g->target(), band, chord);
  ClearedStaircase cleared(band);
  const double aboveTheBand = box.min_corner().x() - 2 * kStockMargin;  // w above the band's top
  const double shadow = span + 2 * kStockMargin;
  if (r.noseRadius > 0) {
    r.nose.emplace(GrooveReplay::NoseShapes{noseShape(r.noseRadius, {0, 0}, 0, chord),
                                            noseShape(r.noseRadius, grooveUW(1, 0), shadow, chord),
                                            noseShape(r.noseRadius, grooveUW(-1, 0), shadow, chord)});
  }
  std::optional<BgRegion> standing;  // materialNow, once a rapid needs it, until the next feed
  // The feeds of a blade or a point (not along an axis) removed from withoutTheOthers only when a
  // rapid or the end needs the exact material: ClearedOutline and ShadowedRows bound what stands
  // meanwhile. (A nose sweeps a disc, groove_nose.h: its feeds are removed as they come.)
  ClearedOutline deepest(band);
  ShadowedRows rows(band);
  std::vector<PendingRemoval> pending;
  const bool blade = !r.tool.isPoint() && r.noseRadius <= 0, point = r.tool.isPoint() && r.noseRadius <= 0;
  // What lies between two outlines no farther apart than `thin` (along w for a blade, along u for a
  // point's rows) is no thicker (2·area/perimeter: its area is at most thin × its extent, its
  // perimeter at least twice the extent): a crossing or a leftover that thin is no finding.
  const double thin = eps / 2;
  for (std::size_t i = r.range.begin; i < r.range.end; ++i) {
    const Segment move = localSegment(in, *g, i);
    if (distance(move.from, move.to) <= kGeomEps && !move.isArc()) continue;
    const ToolExtent e = extentOf(r, move, chord);
    MoveSweep sweep(r, move, chord);
    if (!partTop || (e.wDeepest > partTop->shallowestOver(e.uFrom, e.uTo) + kBoundSlack &&
                     !bladeStaysAbove(*partTop, r, move, thin, chord) && !noseStaysAbove(*partTop, r, move, thin, chord))) {
      r.partCrossings[i] = crossingOfTheTool(r, partRegion(), move, sweep, eps, chord);
    }
    if (in.path.moves[i].kind == MoveKind::Rapid) {
      // What stands lies within what the other removals left: a sweep clear of its envelope crosses none.
      if (!cleared.clearOver(e.uFrom, e.uTo, e.wDeepest) && !(blade && bladeRapidClear(deepest, r, move, thin, chord)) &&
          !(point && pointRapidClear(rows, move, thin, chord))) {
        applyPending(withoutTheOthers, pending, r, shadow, chord);
        if (mayMeet(withoutTheOthers, sweptBoxOf(r, e))) {
          if (!standing) standing = materialNow(withoutTheOthers, cleared, aboveTheBand);
          r.rapidCrossings[i] = crossingOfTheTool(r, *standing, move, sweep, eps, chord);
        }
      }
    } else {
      standing.reset();
      const int side = shadowSide(r, move, moves && i >= moves->profileStart);
      if (blade) raiseByFeed(deepest, r, band, move, chord);
      if (point) shadowRowsOf(rows, move, side, shadow, chord);
      if (clearsAStep(cleared, r, move, side, shadow, e)) continue;
      if (blade || point) {
        pending.push_back({move, side, sweep.take()});
      } else {
        withoutTheOthers = without(withoutTheOthers, removedBy(r, move, sweep, side, shadow, chord));
      }
    }
  }
  // What is left needs the exact material only when the bound cannot prove the target emptied.
  const bool emptied = partTop && ((blade && deepest.covers(partTop->chain(), thin)) ||
                                    (point && rows.coversTarget(partTop->chain(), thin)));
  if (!emptied) {
    applyPending(withoutTheOthers, pending, r, shadow, chord);
    r.remaining = materialNow(withoutTheOthers, cleared, aboveTheBand);
    makeTarget();
    r.reachable = r.noseRadius > 0 ? openedBy(r.target, r.noseRadius) : r.target;
  }
  return r;
}

}  // namespace cyclecert
