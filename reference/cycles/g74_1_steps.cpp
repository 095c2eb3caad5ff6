// G74.1 — the ten numbered steps of seed 002 (G74_1.STEP1…STEP10), one function each, in the
// groove's frame (u along d, w the depth along h: reference/cycles/g74_1_groove.h). The points
// (A11, Am1, Amn, Bmn, Amf, Cmf) and every interpretation are those of docs/g74_1.md §6.
#include <algorithm>
#include <cmath>
#include <string>

#include "reference/cycles/g74_1.h"
#include "reference/cycles/g74_1_nose.h"
#include "reference/cycles/move_emitter.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/alarms.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

// One axial cycle: the u of Amn and the depth of Bmn.
struct AxialCycle {
  double u = 0;
  double end = 0;
};

// One layer of axial cycles (I16, I17): its top (where each Amn is) and bottom (no Bmn deeper), and
// its cycles Am1 … Amf.
struct GrooveLayer {
  double top = 0, bottom = 0;
  std::vector<AxialCycle> cycles;
};

std::string mm(double v) { return shortDecimalText(v); }

// A peck that ends this close to Bmn has reached it (STEP3, STEP5: "reaching or passing Bmn"). Bmn is
// the rough profile's depth under the blade, computed through the flanks and the corner rounds: on a
// round near its tangent point the computation carries a rounding error of up to ~1e-8 mm that grows
// with the part's size. Without this the pecks, landing on Bmn by Δk + e exactly, add a feed of that
// error — and a part scaled up plans one peck more than the part (found by scale-k). One nanometre
// is far below any least input increment (0.001 mm IS-B, 0.0001 mm IS-C). An interpretation.
constexpr double kPeckReachesBmnWithin = 1e-6;  // mm

// Where a feed meant to end at `next` ends: at Bmn when it reaches or passes it.
double feedEnd(double next, double bmn) { return next < bmn - kPeckReachesBmnWithin ? next : bmn; }

// A nose's profile is the path of its lowest point (its centre + R along h, g74_1_nose.h): the
// control point is the centre + R·tip, so the plane point is moved back by R along h and by R·tip.
Point noseShift(const G74_1Cycle& c) {
  if (!c.nose) return {};
  return c.nose->tipShift + Point{-c.frame.depthSign * c.nose->radius, 0};
}

// The profile the planner's point follows: the groove's (a grooving tool's blade, or a sharp point),
// or the one the nose centre sees under G41/G42 (I26).
GrooveProfile profileToPlan(const G74_1Cycle& c, double flankAllowance, double floorAllowance) {
  if (c.nose) return noseCentreProfile(c.groove, flankAllowance, floorAllowance, c.nose->radius);
  return buildGrooveProfile(c.groove, flankAllowance, floorAllowance);
}

class G74_1Planner {
 public:
  explicit G74_1Planner(const G74_1Cycle& c)
      : c_(c),
        rough_(profileToPlan(c, c.flankAllowance, c.floorAllowance)),
        finish_(profileToPlan(c, 0, 0)),
        shift_(noseShift(c)),
        roughStart_(grooveLocal(rough_.start.x + c.toolWidth, 0)),
        finishStart_(grooveLocal(finish_.start.x + c.toolWidth, 0)),
        moves_(c.before, c.feed) {
    requireTheToolFitsTheFloor();
    if (c_.pathType != GroovePathType::FinishOnly) layers_ = layers();
  }

  std::vector<Move> plan() {
    step1PositionToRoughStart();
    if (c_.pathType != GroovePathType::FinishOnly) {
      for (std::size_t m = 0; m < layers_.size(); ++m) cutLayer(m);
      step9CutAlongTheRoughProfile();
    }
    if (c_.pathType != GroovePathType::RoughOnly) step10CutAlongTheFinishProfile();
    returnToThePointBeforeTheGroove();
    return moves_.take();
  }

 private:
  // Steps 2 to 8 for layer m.
  void cutLayer(std::size_t m) {
    const GrooveLayer& layer = layers_[m];
    step2PositionToLayerStart(m);
    for (std::size_t n = 0; n < layer.cycles.size(); ++n) {
      if (n > 0) step7StepAcross(m, layer.cycles[n].u);
      axialCycle(m, layer.cycles[n]);
    }
    step8ToTheNextLayerOrBack(m);
  }

  // Steps 3 to 6: an axial cycle of layer m, from Amn = (u, top) to Bmn = (u, end) and back. A
  // cycle whose Bmn is Amn (the blade on a slanted flank's top) makes no move.
  void axialCycle(std::size_t m, const AxialCycle& cycle) {
    if (cycle.end <= layers_[m].top + kGeomEps) return;
    double reached = step3FirstFeed(m, cycle);
    while (reached < cycle.end - kGeomEps) {
      step4Retract(m, cycle.u, reached);
      reached = step5FeedAgain(m, cycle, reached);
    }
    step6BackToCycleStart(m, cycle.u);
  }

  // G74_1.STEP1: from where the tool stands straight to the rough start A11 (I18): the blade's
  // start-side edge on the rough near flank at the start level (I12).
  void step1PositionToRoughStart() {
    moves_.emit(MoveKind::Rapid, plane(roughStart_), MovePhase::Approach, 0, {"G74_1.STEP1"});
  }

  // G74_1.STEP2: to the layer start Am1 — along x at the start level for the first layer, along z
  // down from Cmf for the others.
  void step2PositionToLayerStart(std::size_t m) {
    const GrooveLayer& layer = layers_[m];
    move(MoveKind::Rapid, layer.cycles.front().u, layer.top, m, "G74_1.STEP2");
  }

  // G74_1.STEP3: feed Δk along z towards the floor; reaching or passing Bmn, feed to Bmn (I19).
  // Returns the depth reached.
  double step3FirstFeed(std::size_t m, const AxialCycle& cycle) {
    const double to = feedEnd(layers_[m].top + c_.peck, cycle.end);
    move(MoveKind::Feed, cycle.u, to, m, "G74_1.STEP3");
    return to;
  }

  // G74_1.STEP4: rapid retract e, opposite to the feed.
  void step4Retract(std::size_t m, double u, double reached) {
    move(MoveKind::Rapid, u, reached - c_.retract, m, "G74_1.STEP4");
  }

  // G74_1.STEP5: feed (Δk + e) from the retracted point if it ends strictly between Amn and Bmn;
  // else feed to Bmn. Returns the depth reached.
  double step5FeedAgain(std::size_t m, const AxialCycle& cycle, double reached) {
    const double to = feedEnd(reached - c_.retract + (c_.peck + c_.retract), cycle.end);
    move(MoveKind::Feed, cycle.u, to, m, "G74_1.STEP5");
    return to;
  }

  // G74_1.STEP6: rapid along z back to Amn.
  void step6BackToCycleStart(std::size_t m, double u) { move(MoveKind::Rapid, u, layers_[m].top, m, "G74_1.STEP6"); }

  // G74_1.STEP7: rapid along x by Δi/2 to the next cycle start, clamped at Amf (the starts are laid
  // out so: layers()).
  void step7StepAcross(std::size_t m, double u) { move(MoveKind::Rapid, u, layers_[m].top, m, "G74_1.STEP7"); }

  // G74_1.STEP8: not the last layer: rapid along x to Cmf (the next layer's first cycle start, at
  // this layer's top); step 2 then goes down. The last layer: rapid along z to the start level,
  // then along x back to A11.
  void step8ToTheNextLayerOrBack(std::size_t m) {
    if (m + 1 < layers_.size()) {
      move(MoveKind::Rapid, layers_[m + 1].cycles.front().u, layers_[m].top, m, "G74_1.STEP8");
      return;
    }
    move(MoveKind::Rapid, local(moves_.current()).x, 0, m, "G74_1.STEP8");
    move(MoveKind::Rapid, roughStart_.x, 0, m, "G74_1.STEP8");
  }

  // G74_1.STEP9: feed along the rough profile (the blade's path, §7), then back to A11 along z to
  // the start level and along x.
  void step9CutAlongTheRoughProfile() {
    followProfile(rough_, MovePhase::SemiFinish, "G74_1.STEP9");
    backAlongTheStartLevel(roughStart_, MovePhase::SemiFinish, "G74_1.STEP9");
  }

  // G74_1.STEP10: from A11 (or the rough pass's end there) to the finish start (X, Z) shifted by the
  // tool width, feed along the finish profile, back to the finish start.
  void step10CutAlongTheFinishProfile() {
    moves_.emit(MoveKind::Rapid, plane(finishStart_), MovePhase::Finish, 0, {"G74_1.STEP10"});
    followProfile(finish_, MovePhase::Finish, "G74_1.STEP10");
    backAlongTheStartLevel(finishStart_, MovePhase::Finish, "G74_1.STEP10");
  }

  // G74_1.STEP10 (I20): the groove done, rapid straight back to where the tool stood before the
  // cycle — after every path type.
  void returnToThePointBeforeTheGroove() {
    moves_.emit(MoveKind::Rapid, c_.before, MovePhase::Return, 0, {"G74_1.STEP10"});
  }

  // The profile pass of steps 9 and 10: a feed to the path's first point, then the path.
  void followProfile(const GrooveProfile& profile, MovePhase phase, const char* rule) {
    const std::vector<Segment> path = bladePath(profile, c_.toolWidth);
    if (path.empty()) return;
    moves_.emit(MoveKind::Feed, plane(path.front().from), phase, 0, {rule});
    for (const Segment& s : path) moves_.emitAlong(MoveKind::Feed, c_.frame.toPlane(s).shifted(shift_), phase, 0, {rule});
  }

  // From the profile's end on the mouth: along z to the start level, along x to `to`.
  void backAlongTheStartLevel(Point to, MovePhase phase, const char* rule) {
    moves_.emit(MoveKind::Rapid, plane(grooveLocal(local(moves_.current()).x, 0)), phase, 0, {rule});
    moves_.emit(MoveKind::Rapid, plane(to), phase, 0, {rule});
  }

  // I16, I17: the layers Δv deep from the start level to the rough floor (one without V); in each,
  // the cycle starts from Am1 (the blade's start side on the rough profile's near boundary at the
  // layer's top) by Δi/2 to Amf (the programmed point on its far boundary), and each Bmn as deep as
  // the rough profile lets the blade go there, at most the layer's bottom.
  std::vector<GrooveLayer> layers() const {
    const double depth = rough_.floorDepth;
    const double count = c_.layerDepth ? std::ceil(depth / *c_.layerDepth - kGeomEps) : 1.0;
    requireFewerMovesThanTheCap(count, 1, 1);
    std::vector<GrooveLayer> out;
    double moves = 0;
    for (int m = 0; m < static_cast<int>(count); ++m) {
      if (!out.empty() && !anyReachedTheBottom(out.back())) break;  // I22: nothing cleared down to this layer
      GrooveLayer layer;
      layer.top = c_.layerDepth ? m * *c_.layerDepth : 0.0;
      layer.bottom = c_.layerDepth ? std::min((m + 1) * *c_.layerDepth, depth) : depth;
      const GrooveSlice slice = sliceAt(rough_, layer.top);
      const double first = out.empty() ? slice.nearU + c_.toolWidth : nextLayerStart(out.back(), slice),
                   last = std::max(out.empty() ? slice.farU : nextLayerEnd(out.back(), slice), first);
      const double steps = std::ceil((last - first) / c_.radialStep - kGeomEps);
      const double pecks = std::ceil((layer.bottom - layer.top) / c_.peck - kGeomEps);
      moves += (steps + 1) * (2 * pecks + 1);
      requireFewerMovesThanTheCap(count, steps + 1, moves);
      for (int k = 0; k < static_cast<int>(steps); ++k) layer.cycles.push_back(axialCycleAt(layer, first + k * c_.radialStep));
      layer.cycles.push_back(axialCycleAt(layer, last));
      out.push_back(std::move(layer));
    }
    return out;
  }

  // I22: a layer below the first runs its axial cycles only over the cycles of the layer above that
  // reached that layer's bottom: it starts (Cmf, STEP8; Am1, STEP2) at the first of them and ends
  // (Amf, STEP7) at the last — so the plunge to it and the rapids across it run where the layer above
  // cut out, not through the staircase that layer left along a slanted flank; at the slice's
  // boundaries where they lie further in. When no cycle reached the bottom there is no such layer
  // (layers(): the layers end there, the rest is left to STEP9).
  double nextLayerStart(const GrooveLayer& above, const GrooveSlice& slice) const {
    const double atTheSlice = slice.nearU + c_.toolWidth;
    for (const AxialCycle& cycle : above.cycles) {
      if (reachedTheBottom(above, cycle)) return std::max(cycle.u, atTheSlice);
    }
    return atTheSlice;
  }

  double nextLayerEnd(const GrooveLayer& above, const GrooveSlice& slice) const {
    for (auto cycle = above.cycles.rbegin(); cycle != above.cycles.rend(); ++cycle) {
      if (reachedTheBottom(above, *cycle)) return std::min(cycle->u, slice.farU);
    }
    return slice.farU;
  }

  static bool reachedTheBottom(const GrooveLayer& layer, const AxialCycle& cycle) {
    return cycle.end >= layer.bottom - kGeomEps;
  }

  static bool anyReachedTheBottom(const GrooveLayer& layer) {
    return std::any_of(layer.cycles.begin(), layer.cycles.end(),
                       [&layer](const AxialCycle& cycle) { return reachedTheBottom(layer, cycle); });
  }

  AxialCycle axialCycleAt(const GrooveLayer& layer, double u) const {
    return {u, std::min(layer.bottom, deepestUnderTheBlade(rough_, u, c_.toolWidth))};
  }

  // I12: the blade must fit on the floor between its corners of each profile the cycle cuts (its
  // profile pass rides on it): the rough one unless J2, the finish one unless J0. A J0 roughing
  // leaves the finish floor to another cycle (I24).
  void requireTheToolFitsTheFloor() const {
    for (const GrooveProfile* p : {&rough_, &finish_}) {
      const bool cut = p == &rough_ ? c_.pathType != GroovePathType::FinishOnly : c_.pathType != GroovePathType::RoughOnly;
      if (!cut || p->floorTo - p->floorFrom >= c_.toolWidth - kGeomEps) continue;
      throw GrooveDoesNotFit("the tool width I " + mm(c_.toolWidth) + " is wider than the " +
                             (p == &rough_ ? "rough" : "finish") + " groove's floor (" +
                             mm(p->floorTo - p->floorFrom) + " mm between its corners)");
    }
  }

  // PROG.CAP.PASSES: as every planner, a bounded plan.
  void requireFewerMovesThanTheCap(double layers, double cycles, double moves) const {
    if (layers <= kMostRoughingPasses && cycles <= kMostRoughingPasses && moves <= kMostCycleMoves) return;
    throw NotSupported(c_.line, "G74.1 would make " + countText(layers) + " layers of up to " + countText(cycles) +
                                    " axial cycles (" + countText(moves) + " moves); cyclecert plans at most " +
                                    countText(kMostRoughingPasses) + " layers or cycles and " +
                                    countText(kMostCycleMoves) + " moves per cycle");
  }

  void move(MoveKind kind, double u, double w, std::size_t m, const char* rule) {
    moves_.emit(kind, plane(grooveLocal(u, w)), MovePhase::Pass, static_cast<int>(m) + 1, {rule});
  }

  // Local ↔ the plane point the control follows: the programmed point (a blade's corner, a sharp
  // point), or the imaginary tip of a nose planned by its centre (I26).
  Point plane(Point local) const { return c_.frame.toPlane(local) + shift_; }
  Point local(Point plane) const {
    const Point p = plane - shift_;
    return grooveLocal(c_.frame.widthSign * (p.x - c_.frame.start.x), c_.frame.depthSign * (p.z - c_.frame.start.z));
  }

  const G74_1Cycle& c_;
  GrooveProfile rough_, finish_;
  Point shift_;  // plane: the imaginary tip from the nose's lowest point (I26); 0 without a nose
  Point roughStart_, finishStart_;  // A11 and the finish start, local
  std::vector<GrooveLayer> layers_;
  MoveEmitter moves_;
};

}  // namespace

std::vector<Move> planG74_1Moves(const G74_1Cycle& cycle) { return G74_1Planner(cycle).plan(); }

namespace {

std::vector<Segment> inThePlane(const G74_1Cycle& cycle, const GrooveProfile& profile) {
  std::vector<Segment> shape;
  for (const Segment& s : profile.chain) shape.push_back(cycle.frame.toPlane(s));
  return shape;
}

}  // namespace

std::vector<Segment> g74_1FinishShape(const G74_1Cycle& cycle) { return inThePlane(cycle, buildGrooveProfile(cycle.groove, 0, 0)); }

std::vector<Segment> g74_1RoughShape(const G74_1Cycle& cycle) {
  return inThePlane(cycle, buildGrooveProfile(cycle.groove, cycle.flankAllowance, cycle.floorAllowance));
}

}  // namespace cyclecert
