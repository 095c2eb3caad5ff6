// pocket-entry: entering a pocket, the tool comes down at rapid no nearer than the clearance
// (parameter 5134) to the material it has still to cut, and feeds the rest (G71.T2.POCKET.EXIT
// (20), (21): "rapid to the height of D, rapid to just before g, then cutting feed").
//
// Judges: type II G71/G72 cycles (block ns moves both axes: the cycles with pockets) with
// 5134 > the tolerance. Type I's infeeds rapid to the pass level by design (G72.STEP2), and with
// 5134 = 0 a rapid may end at the entry point.
//
// Engine-independently: every rapid that moves deeper along the depth axis to below A's level — but
// one down the line of block ns, which moves in block ns's mode (G71.HEAD.G0G1, G72.STEP2) — is continued by the
// clearance along its own direction; the continuation may cross no material still standing at
// that moment (as rapids-in-air measures it: beyond the tolerance, the slot of an earlier feed
// excepted), nor the part grown by the allowances (as no-gouge measures it: the entry point g of a
// pass lies on a pocket's wall, so a rapid all the way to it reaches the part within 5134). Where the tool then goes, at what feed, is the other oracles' business
// (rapids-in-air, feeds).
//
// Known limitation: a continuation that runs down the face of a wall parallel to it only touches
// the layer beside the wall, so a rapid all the way down such a wall to the entry is not reported
// (a probe a hair beside it, tried, also reached the material a valley bottom leaves standing
// within Δd of a short cut, which the reference rightly rapids past).
//
// The replay measures the continuations (material_replay.h: pocketEntryCrossings), while it knows
// the material of that moment; this file says which they are.
#include <cmath>
#include <sstream>

#include "oracles/material_replay.h"
#include "oracles/oracles.h"

namespace cyclecert {

namespace {

// Within `tol` of the infinite line through the segment (nothing for a segment shorter than tol).
bool onLineOf(Point p, const Segment& s, double tol) {
  const Point along = s.to - s.from;
  const double length = std::hypot(along.z, along.x);
  if (length <= tol) return false;
  const Point rel = p - s.from;
  return std::abs(rel.z * along.x - rel.x * along.z) / length <= tol;
}

class PocketEntryOracle : public Oracle {
 public:
  std::string id() const override { return "pocket-entry"; }
  std::vector<std::string> rules() const override { return {"G71.T2.POCKET.EXIT"}; }
  bool judges(CycleFamily f) const override { return f == CycleFamily::G71 || f == CycleFamily::G72; }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const MaterialReplay* r = ctx.replay;
    if (!r || !judgesPocketEntries(*r->cycle, ctx.in.settings)) return;
    for (std::size_t i = 0; i < r->pocketEntryCrossings.size(); ++i) {
      const Crossing& c = r->pocketEntryCrossings[i];
      if (c.length <= 0) continue;
      std::ostringstream m;
      m << "rapid move " << i << " comes down to within the clearance 5134 = " << r->cycle->clearance
        << " mm of material still standing or of the part (" << c.length
        << " mm of it lie within that distance beyond its end): the rapid must stop that far short and the rest be fed";
      Finding f = finding(*this, i, m.str());
      for (const Segment& piece : c.pieces) f.witness.regions.push_back({piece.from, piece.to});
      f.witness.segment = ctx.in.path.segment(i);
      out.push_back(f);
    }
  }
};

}  // namespace

bool judgesPocketEntries(const CycleSpec& c, const JudgeSettings& settings) {
  // G73 has no pockets to enter: its passes follow the whole shape from A (G73.APPROACH).
  return !c.patternRepeating() && c.typeII && c.clearance > settings.tolerance();
}

std::vector<Segment> pocketEntryProbes(const JudgeInput& in, const CycleSpec& c, std::size_t i) {
  const Move& m = in.path.moves[i];
  if (m.kind != MoveKind::Rapid || m.shape != SegmentKind::Line) return {};
  const double tol = in.settings.tolerance();
  const Point from = in.path.from(i), to = m.to;
  // Deeper along the depth axis (towards B from A), and to below A's level: a rapid that comes back
  // down to A's level (the return to the start from a retract above it) enters no pocket.
  const auto deeper = [&](Point p, Point than) { return c.depthDirection() * (inFrame(c, p).x - inFrame(c, than).x) > tol; };
  if (!deeper(to, from) || !deeper(to, c.start)) return {};
  for (const Segment& head : {c.shape.front(), c.shape.front().shifted(c.allowance)}) {
    if (onLineOf(from, head, tol) && onLineOf(to, head, tol)) return {};
  }
  const Point step = to - from;
  const Point reach = (c.clearance / std::hypot(step.z, step.x)) * step;
  return {Segment{SegmentKind::Line, to, to + reach, {}, 0}};
}

std::unique_ptr<Oracle> makePocketEntryOracle() { return std::make_unique<PocketEntryOracle>(); }

}  // namespace cyclecert
