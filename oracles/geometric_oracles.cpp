// The oracles that judge against the material: no-gouge, rapids-in-air, complete, depth-per-pass.
// Every verdict tolerates epsilon plus the chord tolerance the arcs were flattened with, so that
// flattening never produces a finding.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "oracles/material/boost_geometry.h"

#include "oracles/groove/groove_replay.h"
#include "oracles/material_replay.h"
#include "oracles/oracles.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

namespace {

double tolerance(const JudgeInput& in) { return in.settings.tolerance(); }

// The rules the material oracles serve for SINUMERIK calls: the roughing (to contour + allowance,
// the contour-parallel cut, G0 back), the finishing along the contour, CYCLE95's undercuts.
const std::vector<std::string> kSiemensMaterialSteps = {"ROUGH", "FINISH"};

// The oracle's rules, FANUC's and each SINUMERIK cycle's `steps`.
std::vector<std::string> withSiemensRules(std::vector<std::string> fanuc, const std::vector<std::string>& steps) {
  for (const char* cycle : {"LCYC95.", "CYCLE95."}) {
    for (const std::string& step : steps) fanuc.push_back(cycle + step);
  }
  return fanuc;
}

// A finding of a material oracle: for a SINUMERIK call it cites the call's own cycle's `steps`
// (LCYC95.ROUGH…), not FANUC's rules.
Finding materialFinding(const Oracle& o, const MaterialReplay& r, std::optional<std::size_t> move, std::string message,
                        const std::vector<std::string>& steps) {
  Finding f = finding(o, move, std::move(message));
  if (r.siemens) {
    f.rules.clear();
    for (const std::string& step : steps) f.rules.push_back(r.siemens->rule(step));
  }
  return f;
}

// The target's span along the cut axis, less the tolerance at each end (the cycle does not cut
// beyond its shape's ends); nothing when no more is left.
std::optional<std::pair<double, double>> targetSpan(const MaterialReplay& r, double tolerance) {
  const auto [lo, hi] = cutSpanOf(r.target, DepthFrame(r.away));
  if (!(hi - lo > 2 * tolerance)) return std::nullopt;
  return std::pair{lo + tolerance, hi - tolerance};
}

// The material left beyond the target surface, over the target's span: what remains minus the
// part grown by the allowances, within the span.
BgRegion leftover(const MaterialReplay& r, double tolerance) {
  const auto span = targetSpan(r, tolerance);
  if (!span) return {};
  // The span as a band across the depth axis, as wide as the shadows reach.
  const DepthFrame frame(r.away);
  const BgRegion band = regionFrom({frame.point(span->first, -r.reach), frame.point(span->second, -r.reach),
                                    frame.point(span->second, r.reach), frame.point(span->first, r.reach)});
  BgRegion beyondPart = without(r.remaining(), r.part);
  if (!r.leftAlone.empty()) beyondPart = without(beyondPart, r.leftAlone);
  return checkedIntersection(beyondPart, band);
}

// G73 with a G70 after it (G73.G70): the finishing pass runs along the finish shape and removes
// everything beyond it on the tool's side — along the side the part stands on (partSideOf), not
// only along the relief the model's shadows follow: a shape segment parallel to the relief leaves, in
// the model, the strip between it and the blank (as thin as the allowance's share across the relief)
// that its own pass's shadow runs along. Only what `complete` measures is mended.
BgRegion withoutWhatG70Removes(const JudgeInput& in, const MaterialReplay& r, BgRegion left) {
  const CycleSpec* c = r.cycle;
  if (left.empty() || !c || !c->patternRepeating() || !in.program.hasFinishingCycle) return left;
  const Point side = partSideOf(*c);
  for (std::size_t i = 0; i < r.judgedMoves && !left.empty(); ++i) {
    const Segment move = in.path.segment(i);
    if (in.path.moves[i].kind != MoveKind::Feed || !onFinishShape(in, *c, move)) continue;
    left = without(left, shadowOf(move, side, r.reach, in.settings.chordTolerance));
  }
  return left;
}

// Whether the material left may stand thicker than `allowed` above the target. Where the target is
// a graph over the cut axis, the material's top over the span (the feeds' envelope, capped by the
// stock) measured against the exact target (thickness.h, standsThickerThan) answers without a
// boolean: the material left stands nowhere higher. The profile beneath a point is taken within
// ± the tolerance along the cut axis, as the region's measure leaves out skins narrower than that
// (withoutSkins): the chords of a pass along an arc stray that far sideways, which next to a steep
// tangent reads as thickness along the depth axis. So the top decides a pass, and the region left
// confirms a finding. Where that top stands thicker (a stock whose top slopes, G73's near-net blank
// in the relief's frame), the top without skins decides (mayStandThickerWithoutSkins): the judgement
// below measures the material left without them before it reports.
bool leftoverMayExceed(const MaterialReplay& r, double allowed, double tolerance) {
  if (!r.targetIsGraph) return true;
  const auto span = targetSpan(r, tolerance);
  if (!span) return false;
  return standsThickerThan(r.model->topWithin(span->first, span->second), r.target, r.away, tolerance / 2, allowed) &&
         mayStandThickerWithoutSkins(*r.model, span->first, span->second, r.target, tolerance, allowed);
}

// SINUMERIK (LCYC95.FINISH: "G0 in both axes back to the cycle start"; CYCLE95.FINISH the same):
// the finishing pass's return from the contour's end to the computed start is a straight line that
// crosses the part wherever the contour ends below a profile standing between (a pocket open to the
// contour's end), or the allowance a finishing-only call leaves standing in front of a face it
// went up (removed along the depth axis only). The documented move, not an engine's choice
// (interpretation): no-gouge and rapids-in-air leave it to the documented sequence, as rapids-in-air
// leaves G73's programmed head.
bool isDocumentedFinishingReturn(const MaterialReplay& r, const JudgeInput& in, std::size_t i) {
  if (!r.siemensFinishing || r.siemensFinishing->finishPath.empty()) return false;
  if (in.path.moves[i].kind != MoveKind::Rapid) return false;
  const SiemensCycleSpec& s = *r.siemensFinishing;
  const Segment move = in.path.segment(i);
  return distance(move.from, s.frame.toPlane(s.finishPath.back().to)) <= tolerance(in) &&
         distance(move.to, s.frame.toPlane(s.start)) <= tolerance(in);
}

// G74.1 (oracles/groove/groove_replay.h): the rules each material oracle cites for a groove, and a
// finding on a move with the groove's crossed material as its witness (a blade's swept region met,
// or a point's pieces).
const std::vector<std::string> kGrooveCutRules = {"G74_1.STEP3", "G74_1.STEP9", "G74_1.STEP10"};
const std::vector<std::string> kGrooveRapidRules = {"G74_1.STEP4", "G74_1.STEP6", "G74_1.STEP7", "G74_1.STEP8",
                                                    "G74_1.STEP9", "G74_1.STEP10"};

std::vector<std::string> withGrooveRules(std::vector<std::string> rules, const std::vector<std::string>& groove) {
  rules.insert(rules.end(), groove.begin(), groove.end());
  return rules;
}

Finding grooveFinding(const Oracle& o, const JudgeInput& in, const GrooveReplay& r, std::size_t i,
                      const ToolCrossing& c, const std::string& what, const std::vector<std::string>& rules) {
  std::ostringstream m;
  m << what;
  if (r.noseRadius > 0) m << ": the nose of radius " << r.noseRadius << " sweeps " << c.amount << " mm² of it (" << c.thickness << " mm thick)";
  else if (r.tool.isPoint()) m << " over " << c.amount << " mm";
  else m << ": the " << r.tool.width << " mm blade sweeps " << c.amount << " mm² of it (" << c.thickness << " mm thick)";
  Finding f = finding(o, i, m.str());
  f.rules = rules;
  f.witness.segment = in.path.segment(i);
  if (r.tool.isPoint() && r.noseRadius <= 0) {
    for (const Segment& piece : c.pieces) {
      f.witness.regions.push_back({r.groove->toPlane(piece.from), r.groove->toPlane(piece.to)});
    }
  } else {
    f.witness.regions = r.planeOutlines(c.crossed);
  }
  return f;
}

// no-gouge: no move enters the finish shape grown by the allowances by more than the tolerance.
// G74.1: no move of the tool (the blade's swept rectangle, or the point) enters the part beyond the
// groove's target profile (the finish profile with J1/J2, the rough one with J0).
class NoGougeOracle : public Oracle {
 public:
  std::string id() const override { return "no-gouge"; }
  std::vector<std::string> rules() const override {
    return withGrooveRules(
        withSiemensRules({"G71.OP", "G71.ALLOW.UNITS", "G72.ALLOW", "G71.QUAD", "G73.PASS.SHIFT"}, kSiemensMaterialSteps),
        kGrooveCutRules);
  }
  bool judges(CycleFamily) const override { return true; }  // also SINUMERIK and G74.1
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (const GrooveReplay* g = ctx.groove) {
      for (std::size_t i = g->range.begin; i < g->range.end; ++i) {
        const ToolCrossing& c = g->partCrossings[i];
        if (!c.any()) continue;
        std::ostringstream m;
        m << "move " << i << " enters the part beyond the groove's " << (g->groove->finishes() ? "finish" : "rough") << " profile";
        out.push_back(grooveFinding(*this, in, *g, i, c, m.str(), kGrooveCutRules));
      }
      return;
    }
    const MaterialReplay* r = ctx.replay;
    if (!r) return;
    for (std::size_t i = 0; i < r->judgedMoves; ++i) {
      if (isDocumentedFinishingReturn(*r, in, i)) continue;
      const Crossing c = r->partCrossing(in.path.segment(i), tolerance(in), in.settings.chordTolerance);
      if (c.length <= 0) continue;
      std::ostringstream m;
      m << "move " << i << " enters the part grown by the allowances over " << c.length << " mm";
      Finding f = materialFinding(*this, *r, i, m.str(), kSiemensMaterialSteps);
      for (const Segment& piece : c.pieces) f.witness.regions.push_back({piece.from, piece.to});
      f.witness.segment = in.path.segment(i);
      out.push_back(f);
    }
  }
};

// rapids-in-air: no rapid crosses material that is still there at that moment. G73: the approach to
// each pass and the return to A (G73.APPROACH, G73.RETURN) cross none of the blank still standing;
// block ns, when it is G00, is followed as programmed (G73.HEAD) — where it meets the blank is the
// program's choice, not the engine's, so it is not judged here (feeds judges that it is a rapid).
class RapidsInAirOracle : public Oracle {
 public:
  std::string id() const override { return "rapids-in-air"; }
  std::vector<std::string> rules() const override {
    return withGrooveRules(
        withSiemensRules(
            {"G72.STEP1", "G72.STEP5", "G72.STEP8", "G71.T2.POCKET.EXIT", "G71.T2.RETURN", "G73.APPROACH", "G73.RETURN"},
            kSiemensMaterialSteps),
        kGrooveRapidRules);
  }
  bool judges(CycleFamily) const override { return true; }  // also SINUMERIK and G74.1
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (const GrooveReplay* g = ctx.groove) {
      // G74.1: the rapids inside the groove (retracts, the steps across it, the returns) cross only
      // what earlier moves cleared — swept by the blade, or by the point.
      for (std::size_t i = g->range.begin; i < g->range.end; ++i) {
        const ToolCrossing& c = g->rapidCrossings[i];
        if (!c.any()) continue;
        std::ostringstream m;
        m << "rapid move " << i << " crosses material still standing";
        out.push_back(grooveFinding(*this, in, *g, i, c, m.str(), kGrooveRapidRules));
      }
      return;
    }
    const MaterialReplay* r = ctx.replay;
    if (!r) return;
    const bool programmedRapidHead = r->cycle && r->cycle->patternRepeating() && r->cycle->headIsRapid;
    for (std::size_t i = 0; i < r->rapidCrossings.size(); ++i) {
      const Crossing& c = r->rapidCrossings[i];
      if (c.length <= 0) continue;
      if (programmedRapidHead && isShiftedG73Head(in, *r->cycle, i, tolerance(in))) continue;
      if (isDocumentedFinishingReturn(*r, in, i)) continue;
      std::ostringstream m;
      m << "rapid move " << i << " crosses " << c.length << " mm of material still standing";
      Finding f = materialFinding(*this, *r, i, m.str(), kSiemensMaterialSteps);
      for (const Segment& piece : c.pieces) f.witness.regions.push_back({piece.from, piece.to});
      f.witness.segment = in.path.segment(i);
      out.push_back(f);
    }
  }
};

std::string targetName(const JudgeInput& in, const MaterialReplay& r) {
  if (r.siemens) return r.siemensFinishing ? "finishing path" : "roughing profile (contour + allowance)";
  return in.program.hasFinishingCycle ? "finish shape" : "rough profile";
}

// complete: what remains beyond the target after the last move is no thicker than the rules allow:
// Δd without the semi-finish pass, the tolerance with it (or after G70). G73: the tolerance — its
// last pass runs at the allowance (G73.PASS.SHIFT, G73.D1), or G70 at the shape.
class CompleteOracle : public Oracle {
 public:
  std::string id() const override { return "complete"; }
  std::vector<std::string> rules() const override {
    std::vector<std::string> rules = withSiemensRules(
        {"G71.T1.SEMIFIN", "G72.STEP7", "G71.T2.RETURN", "G71.T2.VALLEY", "G73.PASS.SHIFT", "G73.D1"}, kSiemensMaterialSteps);
    rules.push_back("CYCLE95.UNDERCUT");
    return withGrooveRules(rules, kGrooveCutRules);
  }
  bool judges(CycleFamily) const override { return true; }  // also SINUMERIK and G74.1
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (ctx.groove) {
      judgeGroove(*ctx.groove, tolerance(in), out);
      return;
    }
    const MaterialReplay* r = ctx.replay;
    if (!r) return;
    // A SINUMERIK call's roughing ends with the contour-parallel cut at the allowance (LCYC95.ROUGH,
    // CYCLE95.ROUGH) and its undercuts roughed (CYCLE95.UNDERCUT), its finishing on the contour.
    const bool finished =
        !r->cycle || r->cycle->semiFinish || r->cycle->patternRepeating() || in.program.hasFinishingCycle;
    const double allowed = (finished ? 0 : r->cycle->depthOfCut) + tolerance(in);
    if (!leftoverMayExceed(*r, allowed, tolerance(in))) return;
    const BgRegion left = withoutWhatG70Removes(in, *r, leftover(*r, tolerance(in)));
    // Measured against a finely flattened profile (kMeasuringChord, material_replay.h).
    auto thickest = thickestAbove(left, r->target, r->away, kMeasuringChord);
    if (!thickest || thickest->thickness <= allowed) return;
    // A skin narrower than the tolerance along the cut axis is not material left.
    const auto solid = thickestAbove(withoutSkins(left, r->away, tolerance(in)), r->target, r->away, kMeasuringChord);
    if (!solid || solid->thickness <= allowed) return;
    thickest = solid;
    std::ostringstream m;
    m << "after the last move " << thickest->thickness << " mm of material stand above the " << targetName(in, *r)
      << " at (z " << thickest->where.z << ", x " << thickest->where.x << "); at most " << allowed << " may remain";
    Finding f = materialFinding(*this, *r, std::nullopt, m.str(), kSiemensMaterialSteps);
    if (r->siemens && r->siemens->isCycle95()) f.rules.push_back("CYCLE95.UNDERCUT");
    f.witness.regions = outlinesOf(left);
    f.witness.point = thickest->where;
    out.push_back(f);
  }

 private:
  // G74.1 (STEP9, STEP10): after the cycle the groove is empty to its target profile — the rough
  // profile with J0, the finish profile with its chamfers and rounds with J1/J2: no ring of what
  // is left inside it is thicker (2·area/perimeter) than the tolerance.
  void judgeGroove(const GrooveReplay& g, double tol, std::vector<Finding>& out) const {
    const BgRegion left = g.leftover();
    BgRegion solid;
    for (const BgPolygon& p : left) {
      if (thickestRing(BgRegion{p}) > tol) solid.push_back(p);
    }
    if (solid.empty()) return;
    std::ostringstream m;
    m << "after the last move material " << thickestRing(solid) << " mm thick is left inside the groove's "
      << (g.groove->finishes() ? "finish" : "rough") << " profile";
    Finding f = finding(*this, std::nullopt, m.str());
    f.rules = kGrooveCutRules;
    f.witness.regions = g.planeOutlines(solid);
    out.push_back(f);
  }
};

// depth-per-pass: no feed removes a layer thicker than Δd (measured along the depth axis); G73: than
// the division step |(Δk, Δi)|/(d − 1) (the whole relief for d = 1), measured along the relief
// (CycleSpec::layerLimit; the material's frame, awayFrom).
class DepthPerPassOracle : public Oracle {
 public:
  std::string id() const override { return "depth-per-pass"; }
  std::vector<std::string> rules() const override {
    return {"G71.OP", "G72.DD", "G71.DD.MODAL", "G73.PASS.SHIFT", "G73.D1", "G73.PARAMS"};
  }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    const MaterialReplay* r = ctx.replay;
    if (!r) return;
    const double allowed = r->cycle->layerLimit() + tolerance(in);
    for (std::size_t i = 0; i < r->removedThickness.size(); ++i) {
      const auto& t = r->removedThickness[i];
      if (!t || t->thickness <= allowed) continue;
      std::ostringstream m;
      m << "move " << i << " removes a layer " << t->thickness << " mm thick; "
        << (r->cycle->patternRepeating() ? "the G73 division step is " : "Δd = ") << r->cycle->layerLimit();
      Finding f = finding(*this, i, m.str());
      f.witness.segment = in.path.segment(i);
      f.witness.point = t->where;
      out.push_back(f);
    }
  }
};

// pass-levels: type I passes stand a whole number of Δd below A' (G72.STEP2, G72.STEP6): an extra,
// missing-depth or misplaced pass is a pass the documented steps do not make.
class PassLevelsOracle : public Oracle {
 public:
  std::string id() const override { return "pass-levels"; }
  std::vector<std::string> rules() const override { return {"G72.STEP2", "G72.STEP6", "G71.T1.STEP6", "G71.OP"}; }
  bool judges(CycleFamily f) const override { return f == CycleFamily::G71 || f == CycleFamily::G72; }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const CycleSpec* c = ctx.replay ? ctx.replay->cycle : nullptr;
    // G73's passes follow the whole shape, not levels (depth-per-pass judges how far apart they stand).
    if (c && !c->typeII && !c->patternRepeating()) judgePassLevels(ctx.in, *c, out);
  }

 private:
  // Type I passes stand Δd apart from A' (G72.STEP2, G72.STEP6): a pass at a level that is not a
  // whole number of Δd below A' is a pass the steps do not make (an extra or misplaced one).
  void judgePassLevels(const JudgeInput& in, const CycleSpec& c, std::vector<Finding>& out) const {
    const double tol = tolerance(in);
    const Point aPrime = inFrame(c, c.start + c.allowance);
    const std::vector<Segment> rough = c.roughProfile();
    const MoveRange judged = movesOfTheRoughing(in);
    for (std::size_t i = judged.begin; i < judged.end; ++i) {
      // The semi-finish runs on the rough profile, G70 on the finish shape: neither is a roughing pass.
      if (!isCutAlongCutAxis(in, c, i, tol) || runsOnProfile(in, c, rough, i, tol)) continue;
      const double depth = c.depthDirection() * (inFrame(c, in.path.moves[i].to).x - aPrime.x);
      const double k = std::round(depth / c.depthOfCut);
      if (k >= 1 && std::abs(depth - k * c.depthOfCut) <= tol) continue;
      std::ostringstream s;
      s << "pass at move " << i << " stands " << depth << " below A', not a whole number of Δd = " << c.depthOfCut;
      Finding f = finding(*this, i, s.str());
      f.witness.segment = in.path.segment(i);
      out.push_back(f);
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makePassLevelsOracle() { return std::make_unique<PassLevelsOracle>(); }
std::unique_ptr<Oracle> makeNoGougeOracle() { return std::make_unique<NoGougeOracle>(); }
std::unique_ptr<Oracle> makeRapidsInAirOracle() { return std::make_unique<RapidsInAirOracle>(); }
std::unique_ptr<Oracle> makeCompleteOracle() { return std::make_unique<CompleteOracle>(); }
std::unique_ptr<Oracle> makeDepthPerPassOracle() { return std::make_unique<DepthPerPassOracle>(); }

}  // namespace cyclecert
