#include "reference/cycles/type1_roughing.h"

#include <algorithm>
#include <cmath>

namespace cyclecert {

namespace {

// The rough profile (A', B', C' and the shifted shape) and the pass geometry derived from it.
class Type1Planner {
 public:
  explicit Type1Planner(const Type1Cycle& c)
      : c_(c),
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
    return std::move(moves_);
  }

 private:
  std::string step(int k) const {
    return c_.code == "G72" ? "G72.STEP" + std::to_string(k) : "G71.T1.STEP" + std::to_string(k);
  }

  Point current() const { return moves_.empty() ? c_.start : moves_.back().to; }

  void emit(MoveKind kind, Point to, MovePhase phase, int pass, std::vector<std::string> rules) {
    if (distance(current(), to) <= kGeomEps) return;  // zero-length moves are never emitted
    Move m;
    m.kind = kind;
    m.to = to;
    if (kind == MoveKind::Feed) m.feed = c_.feed;
    m.phase = phase;
    m.pass = pass;
    m.rules = std::move(rules);
    moves_.push_back(std::move(m));
  }

  // How deep a level lies below A' along the depth direction.
  double depthOf(double x) const { return d_ * (x - aPrime_.x); }

  // G72.STEP6: an infeed that "reaches B' or leaves the segment A'B'" ends the passes.
  bool reachesBPrime(double level) const { return depthOf(level) >= depthOf(bPrime_.x) - kGeomEps; }

  // G72.STEP2 / G72.STEP6: infeeds are rapid when block ns is G00, at the cycle feed when G01.
  MoveKind infeedKind() const { return c_.headIsRapid ? MoveKind::Rapid : MoveKind::Feed; }

  // G72.STEP1 / G71.T1.STEP1: rapid from A to A' (shifted by the allowances).
  void step1RapidToShiftedStart() { emit(MoveKind::Rapid, aPrime_, MovePhase::Approach, 0, {step(1), allowanceRule()}); }

  std::string allowanceRule() const { return c_.code == "G72" ? "G72.ALLOW" : "G71.ALLOW.UNITS"; }
  std::string infeedRule() const { return c_.code == "G72" ? "G72.STEP2" : "G71.HEAD.G0G1"; }

  // G72.STEP2: the first infeed of Δd from A', towards B'.
  void step2FirstInfeed(double level, int pass) {
    emit(infeedKind(), {aPrime_.z, level}, MovePhase::Pass, pass, {step(2), infeedRule(), c_.code == "G72" ? "G72.DD" : "G71.DD.MODAL"});
  }

  // G72.STEP3: cut along the cut axis to the rough profile.
  void step3CutToRoughProfile(double level, int pass) {
    const double endZ = passEnd(level);
    // A pass whose end lies at or behind its start cuts nothing and is not emitted.
    if (cut_ * (endZ - aPrime_.z) <= kGeomEps) return;
    emit(MoveKind::Feed, {endZ, level}, MovePhase::Pass, pass, {step(3), c_.code == "G72" ? "G72.STEP3" : "G71.OP"});
  }

  // G72.STEP4 / G71.T1.RETRACT45: retract e on both axes at 45°, in cutting feed, opposite to the
  // cut and to the infeed.
  void step4Retract45(int pass) {
    const Point p = current();
    emit(MoveKind::Feed, {p.z - cut_ * c_.retract, p.x - d_ * c_.retract}, MovePhase::Pass, pass,
         {step(4), c_.code == "G72" ? "G72.RETRACT" : "G71.T1.RETRACT45"});
  }

  // G72.STEP5: rapid back along the cut axis to A' (seed 001 says "Z of A'" for G72: a slip for X).
  void step5RapidBackToAPrime(int pass) { emit(MoveKind::Rapid, {aPrime_.z, current().x}, MovePhase::Pass, pass, {step(5)}); }

  // G72.STEP6: the next infeed, Δd + e from the retracted position.
  void step6Infeed(double level, int pass) { emit(infeedKind(), {aPrime_.z, level}, MovePhase::Pass, pass, {step(6), infeedRule()}); }

  // G72.STEP6 (else branch): the infeed that would reach B' goes to B' instead.
  void infeedToBPrime() { emit(infeedKind(), bPrime_, MovePhase::SemiFinish, 0, {step(6), infeedRule()}); }

  // G72.STEP7 / G71.T1.SEMIFIN: cutting feed along the rough profile from B' to C'.
  void step7SemiFinishAlongRoughProfile() {
    for (const Segment& s : roughBody_) {
      const std::size_t before = moves_.size();
      emit(MoveKind::Feed, s.to, MovePhase::SemiFinish, 0, {step(7), "G71.T1.SEMIFIN"});
      if (s.isArc() && moves_.size() > before) {
        moves_.back().shape = s.kind;
        moves_.back().center = s.center;
      }
    }
  }

  // G72.STEP8 / G71.DTP: back to A. DTP=1 goes straight; DTP=0 leaves the part along the depth
  // axis first, then travels along the cut axis (interpretation: the figure is missing).
  void step8ReturnToStart() {
    if (c_.directReturn) {
      emit(MoveKind::Rapid, c_.start, MovePhase::Return, 0, {step(8), "G71.DTP"});
      return;
    }
    emit(MoveKind::Rapid, {current().z, c_.start.x}, MovePhase::Return, 0, {step(8)});
    emit(MoveKind::Rapid, c_.start, MovePhase::Return, 0, {step(8)});
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
  Point aPrime_, bPrime_;
  int d_, cut_;
  std::vector<Segment> roughBody_;
  std::vector<double> reachUpTo_;
  std::vector<Move> moves_;
};

}  // namespace

int Type1Cycle::depthDirection() const { return signOf(headEnd.x - start.x); }

int Type1Cycle::cutDirection() const {
  const int c = signOf(end().z - headEnd.z);
  return c != 0 ? c : -1;  // a shape without motion along the cut axis: towards −z by convention
}

std::vector<Move> planType1(const Type1Cycle& cycle) { return Type1Planner(cycle).plan(); }

}  // namespace cyclecert
