#include "reference/cycles/type1_roughing.h"

#include <algorithm>
#include <cmath>

#include "reference/cycles/move_emitter.h"
#include "reference/cycles/roughing_rules.h"

namespace cyclecert {

namespace {

// The rough profile (A', B', C' and the shifted shape) and the pass geometry derived from it.
class Type1Planner {
 public:
  explicit Type1Planner(const Type1Cycle& c)
      : c_(c),
        rules_(roughingRulesOf(c.family)),
        moves_(c.start, c.feed),
        aPrime_(c.start + c.allowance),
        bPrime_(c.headEnd + c.allowance),
        d_(c.depthDirection()),
        cut_(c.cutDirection()) {
    for (const Segment& s : c.body) roughBody_.push_back(s.shifted(c.allowance));
    indexRoughProfileReach();
  }

  std::vector<Move> plan() {
    step1RapidToShiftedStart();
    double level = aPrime_.x + d_ * c_.depthOfCut;
    int pass = 1;
    if (!reachesBPrime(level)) {
      step2FirstInfeed(level, pass);
      for (;;) {
        step3CutToRoughProfile(level, pass);
        step4Retract45(pass);
        step5RapidBackToAPrime(pass);
        const double next = level + d_ * c_.depthOfCut;
        if (reachesBPrime(next)) break;
        ++pass;
        step6Infeed(next, pass);
        level = next;
      }
    }
    if (c_.semiFinish) {
      infeedToBPrime();
      step7SemiFinishAlongRoughProfile();
    }
    step8ReturnToStart();
    return moves_.take();
  }

 private:
  const std::string& step(int k) const { return rules_.step[static_cast<std::size_t>(k)]; }

  Point current() const { return moves_.current(); }

  // How deep a level lies below A' along the depth direction.
  double depthOf(double x) const { return d_ * (x - aPrime_.x); }

  // G72.STEP6: an infeed that "reaches B' or leaves the segment A'B'" ends the passes.
  bool reachesBPrime(double level) const { return depthOf(level) >= depthOf(bPrime_.x) - kGeomEps; }

  // G72.STEP2 / G72.STEP6: infeeds are rapid when block ns is G00, at the cycle feed when G01.
  MoveKind infeedKind() const { return c_.headIsRapid ? MoveKind::Rapid : MoveKind::Feed; }

  // G72.STEP1 / G71.T1.STEP1: rapid from A to A' (shifted by the allowances).
  void step1RapidToShiftedStart() { moves_.emit(MoveKind::Rapid, aPrime_, MovePhase::Approach, 0, {step(1), rules_.allowance}); }

  // G72.STEP2: the first infeed of Δd from A', towards B'.
  void step2FirstInfeed(double level, int pass) {
    moves_.emit(infeedKind(), {aPrime_.z, level}, MovePhase::Pass, pass, {step(2), rules_.infeed, rules_.depthOfCut});
  }

  // G72.STEP3: cut along the cut axis to the rough profile.
  void step3CutToRoughProfile(double level, int pass) {
    const double endZ = passEnd(level);
    // A pass whose end lies at or behind its start cuts nothing and is not emitted.
    if (cut_ * (endZ - aPrime_.z) <= kGeomEps) return;
    moves_.emit(MoveKind::Feed, {endZ, level}, MovePhase::Pass, pass, {step(3), rules_.cut});
  }

  // G72.STEP4 / G71.T1.RETRACT45: retract e on both axes at 45°, in cutting feed, opposite to the
  // cut and to the infeed.
  void step4Retract45(int pass) {
    const Point p = current();
    moves_.emit(MoveKind::Feed, {p.z - cut_ * c_.retract, p.x - d_ * c_.retract}, MovePhase::Pass, pass,
                {step(4), rules_.retract});
  }

  // G72.STEP5: rapid back along the cut axis to A' (seed 001 says "Z of A'" for G72: a slip for X).
  void step5RapidBackToAPrime(int pass) { moves_.emit(MoveKind::Rapid, {aPrime_.z, current().x}, MovePhase::Pass, pass, {step(5)}); }

  // G72.STEP6: the next infeed, Δd + e from the retracted position.
  void step6Infeed(double level, int pass) { moves_.emit(infeedKind(), {aPrime_.z, level}, MovePhase::Pass, pass, {step(6), rules_.infeed}); }

  // G72.STEP6 (else branch): the infeed that would reach B' goes to B' instead.
  void infeedToBPrime() { moves_.emit(infeedKind(), bPrime_, MovePhase::SemiFinish, 0, {step(6), rules_.infeed}); }

  // G72.STEP7 / G71.T1.SEMIFIN: cutting feed along the rough profile from B' to C'.
  void step7SemiFinishAlongRoughProfile() {
    for (const Segment& s : roughBody_) moves_.emitAlong(MoveKind::Feed, s, MovePhase::SemiFinish, 0, {step(7), "G71.T1.SEMIFIN"});
  }

  // G72.STEP8 / G71.DTP: back to A. DTP=1 goes straight; DTP=0 leaves the part along the depth
  // axis first, then travels along the cut axis (interpretation: the figure is missing).
  void step8ReturnToStart() {
    if (c_.directReturn) {
      moves_.emit(MoveKind::Rapid, c_.start, MovePhase::Return, 0, {step(8), "G71.DTP"});
      return;
    }
    moves_.emit(MoveKind::Rapid, {current().z, c_.start.x}, MovePhase::Return, 0, {step(8)});
    moves_.emit(MoveKind::Rapid, c_.start, MovePhase::Return, 0, {step(8)});
  }

  // For each rough-profile segment, the deepest the profile has *retreated* (smallest depth)
  // from B' up to and including that segment; non-increasing, so a binary search finds the first
  // segment that reaches a level (near-linear planning in segments × passes).
  void indexRoughProfileReach() {
    double reach = depthOf(bPrime_.x);
    reachUpTo_.reserve(roughBody_.size());
    for (const Segment& s : roughBody_) {
      const Extent e = extent(s);
      reach = std::min({reach, depthOf(e.xMin), depthOf(e.xMax)});
      reachUpTo_.push_back(reach);
    }
  }

  // G72.STEP3: the first point of the rough profile, walking from B' to C', at the pass level;
  // when the profile never reaches it, the cut ends at C' on the cut axis (interpretation).
  double passEnd(double level) const {
    const double target = depthOf(level);
    const auto it = std::lower_bound(reachUpTo_.begin(), reachUpTo_.end(), target,
                                     [](double reach, double t) { return reach > t + kGeomEps; });
    if (it == reachUpTo_.end()) return roughBody_.empty() ? bPrime_.z : roughBody_.back().to.z;
    const Segment& s = roughBody_[static_cast<std::size_t>(it - reachUpTo_.begin())];
    const std::vector<Point> hits = intersectWithLevelX(s, level);
    if (!hits.empty()) return hits.front().z;
    // Reached only within rounding: the nearer end point stands for the crossing.
    return std::abs(s.from.x - level) < std::abs(s.to.x - level) ? s.from.z : s.to.z;
  }

  const Type1Cycle& c_;
  const RoughingRules& rules_;
  MoveEmitter moves_;
  Point aPrime_, bPrime_;
  int d_, cut_;
  std::vector<Segment> roughBody_;
  std::vector<double> reachUpTo_;
};

}  // namespace

int Type1Cycle::depthDirection() const { return signOf(headEnd.x - start.x); }

int Type1Cycle::cutDirection() const {
  const int c = signOf(end().z - headEnd.z);
  return c != 0 ? c : -1;  // a shape without motion along the cut axis: towards −z by convention
}

std::vector<Move> planType1(const Type1Cycle& cycle) { return Type1Planner(cycle).plan(); }

}  // namespace cyclecert
