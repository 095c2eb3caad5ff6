#include "reference/cycles/type2_roughing.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "reference/cycles/move_emitter.h"
#include "reference/cycles/pocket_profile.h"
#include "reference/cycles/roughing_rules.h"

namespace cyclecert {

namespace {

std::vector<Segment> roughProfileOf(const Type2Cycle& c) {
  std::vector<Segment> rough;
  for (const Segment& s : c.shape) rough.push_back(s.shifted(c.allowance));
  return rough;
}

// A node of the cut tree (G71.T2.ORDER): the root (the start level), an interval cut at a pass
// level, or a bottom cut along a valley bottom (G71.T2.VALLEY).
struct CutNode {
  enum Kind { Root, Interval, Bottom } kind = Root;
  double depth = 0;
  double parentDepth = 0;
  ProfilePos start, end;
  bool openEnd = false;
  int level = 0;   // k of the pass level δₖ (bottoms: the first level at or below them)
  int parent = -1;
  std::vector<int> children;
};

class Type2Planner {
 public:
  explicit Type2Planner(const Type2Cycle& c)
      : c_(c),
        rules_(roughingRulesOf(c.family)),
        moves_(c.start, c.feed),
        d_(c.depthDirection()),
        cut_(c.cutDirection()),
        aPrime_(c.start + c.allowance),
        profile_(roughProfileOf(c), 1, aPrime_, d_, cut_) {}

  std::vector<Move> plan() {
    buildCutTree();
    for (int node : cutOrder()) cutNode(node);
    const bool pockets = profile_.hasPocketWall();
    if (c_.semiFinish && c_.noRepeatedPath && !pockets) {
      // G71.NSP, no pocket: A–B is not repeated — straight on to B' above what stands, no return to A.
      travelToHeadEnd();
    } else {
      returnToStart();
    }
    if (c_.semiFinish) {
      semiFinishPass(c_.noRepeatedPath && pockets);
      returnToStart();
    }
    return moves_.take();
  }

 private:
  // ---- the cut tree ---------------------------------------------------------------------------

  // Pass levels δₖ = k·Δd; intervals at δₖ hang under the interval at δₖ₋₁ that contains them, and
  // a valley bottom with δₖ₋₁ < depth ≤ δₖ under the interval at δₖ₋₁ around it.
  void buildCutTree() {
    nodes_.push_back(CutNode{});  // the root: level 0 over the whole profile
    nodes_[0].start = {0, aPrime_};
    nodes_[0].end = {profile_.pieces().size() - 1, profile_.pieces().back().to};
    std::vector<int> previousLevel = {0};
    const double deepest = profile_.deepest();
    for (int k = 1; (k - 1) * c_.depthOfCut < deepest - kGeomEps; ++k) {
      const double level = k * c_.depthOfCut;
      const double above = level - c_.depthOfCut;
      std::vector<int> thisLevel;
      for (const ProfileInterval& in : profile_.intervalsAt(level)) {
        thisLevel.push_back(addNode({CutNode::Interval, level, above, in.start, in.end, in.openEnd, k, -1, {}},
                                    previousLevel));
      }
      for (const ValleyBottom& b : profile_.valleyBottoms()) {
        if (b.depth > above + kGeomEps && b.depth <= level + kGeomEps) {
          addNode({CutNode::Bottom, b.depth, above, b.start, b.end, false, k, -1, {}}, previousLevel);
        }
      }
      previousLevel = thisLevel;
    }
  }

  // Adds a node under the candidate parent whose range contains it.
  int addNode(CutNode node, const std::vector<int>& candidates) {
    for (int p : candidates) {
      const CutNode& parent = nodes_[p];
      if (parent.kind == CutNode::Root ||
          (progress(parent.start) <= progress(node.start) + kGeomEps && progress(node.end) <= progress(parent.end) + kGeomEps)) {
        node.parent = p;
        break;
      }
    }
    if (node.parent < 0) node.parent = 0;  // cannot happen for a z-monotonic profile; keep the tree whole
    node.parentDepth = nodes_[node.parent].depth;
    nodes_.push_back(node);
    const int id = static_cast<int>(nodes_.size()) - 1;
    nodes_[node.parent].children.push_back(id);
    return id;
  }

  double progress(const ProfilePos& p) const { return profile_.progress(p.p); }

  // G71.T2.ORDER: depth first (0i-F: a pocket to its bottom, then the next) or level by level (0i-C).
  std::vector<int> cutOrder() {
    for (CutNode& n : nodes_) {
      std::stable_sort(n.children.begin(), n.children.end(),
                       [&](int a, int b) { return progress(nodes_[a].start) < progress(nodes_[b].start) - kGeomEps; });
    }
    std::vector<int> order;
    if (!c_.levelByLevel) {
      appendDepthFirst(0, order);
      return order;
    }
    for (std::size_t i = 1; i < nodes_.size(); ++i) order.push_back(static_cast<int>(i));
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
      if (nodes_[a].level != nodes_[b].level) return nodes_[a].level < nodes_[b].level;
      return progress(nodes_[a].start) < progress(nodes_[b].start) - kGeomEps;
    });
    return order;
  }

  void appendDepthFirst(int node, std::vector<int>& order) const {
    for (int child : nodes_[node].children) {
      order.push_back(child);
      appendDepthFirst(child, order);
    }
  }

  // The level of the nearest node containing both cuts: above it everything between them is cut.
  double commonDepth(int a, int b) const {
    std::vector<int> ancestorsOfA;
    for (int n = a; n >= 0; n = nodes_[n].parent) ancestorsOfA.push_back(n);
    for (int n = nodes_[b].parent; n >= 0; n = nodes_[n].parent) {
      if (std::find(ancestorsOfA.begin(), ancestorsOfA.end(), n) != ancestorsOfA.end()) return nodes_[n].depth;
    }
    return 0;
  }

  // ---- the motion of one cut --------------------------------------------------------------------

  void cutNode(int id) {
    const CutNode& n = nodes_[id];
    ++pass_;
    const std::vector<Segment> nearWall = profile_.wallAbove(n.start, n.parentDepth);
    const Point q = nearWall.empty() ? n.start.p : nearWall.front().from;
    const bool infeedAlongHead = headAlongDepth() && onHeadLine(q) &&
                                 std::all_of(nearWall.begin(), nearWall.end(), [&](const Segment& s) { return onHeadLine(s.to); });
    travelTo(q, commonDepth(previous_, id), infeedAlongHead, n.start.p, returnPointBefore(id, q));
    if (!infeedAlongHead) {
      // G71.HEAD.G0G1: where the near wall begins with block ns itself (a shape that falls from B
      // below the first level), that part is positioned in block ns's mode — rapid after G00 —
      // and only the shape beyond B is followed in cutting feed.
      std::size_t head = 0;
      while (headAlongDepth() && head < nearWall.size() && !nearWall[head].isArc() && onHeadLine(nearWall[head].from) &&
             onHeadLine(nearWall[head].to)) {
        ++head;
      }
      if (head > 0) emit(headMode(), nearWall[head - 1].to, MovePhase::Pass, {"G71.HEAD.G0G1"});
      followPath({nearWall.begin() + static_cast<long>(head), nearWall.end()}, {"G71.T2.FOLLOW"});
    }
    emit(MoveKind::Feed, n.end.p, MovePhase::Pass, {rules_.typeIICut, "G71.T2.ORDER"});
    leave(n);
    previous_ = id;
  }

  // G71.NSP, consecutive pockets: with NSP = 0 the tool goes back to point I — where it stood
  // above the first of the pockets that share a parent — after each pocket, before the next one;
  // NSP = 1 goes on from pocket to pocket. Returns I's cut-axis coordinate when the detour applies.
  std::optional<double> returnPointBefore(int id, Point q) {
    const CutNode& n = nodes_[id];
    const bool pocket = n.kind == CutNode::Interval && !profile_.isHeadPiece(n.start.piece);
    if (!pocket || c_.levelByLevel) return std::nullopt;
    const auto first = pointI_.find(n.parent);
    if (first == pointI_.end()) {
      pointI_[n.parent] = q.z;
      return std::nullopt;
    }
    if (c_.noRepeatedPath) return std::nullopt;
    return first->second;
  }

  // Travel above what still stands, then down to the entry point (G71.T2.POCKET.EXIT (20), (21)).
  void travelTo(Point q, double commonDepth, bool infeedAlongHead, Point cutStart, std::optional<double> viaI) {
    const double travel = std::min(depthOf(current()), commonDepth - c_.retract);
    // Down block ns itself (the tool stands on the head line) it moves in block ns's mode.
    const bool downTheHead = headAlongDepth() && onHeadLine(current()) && travel > depthOf(current()) + kGeomEps;
    emit(downTheHead ? headMode() : MoveKind::Rapid, {current().z, profile_.xAtDepth(travel)}, MovePhase::Pass,
         {downTheHead ? "G71.HEAD.G0G1" : "G71.T2.POCKET.EXIT"});
    if (viaI) emit(MoveKind::Rapid, {*viaI, current().x}, MovePhase::Pass, {"G71.NSP"});
    emit(MoveKind::Rapid, {q.z, current().x}, MovePhase::Pass, {"G71.T2.POCKET.EXIT"});
    if (infeedAlongHead) {
      // The type I infeed along a head block parallel to the depth axis (G72.STEP2).
      emit(headMode(), cutStart, MovePhase::Pass, {"G72.STEP2", "G71.HEAD.G0G1"});
      return;
    }
    if (headAlongDepth() && onHeadLine(q)) {
      // The entry point is on block ns (B, where the shape falls away from it): the way down to it
      // runs along block ns, in its mode (G71.HEAD.G0G1), as the type I infeeds do.
      emit(headMode(), q, MovePhase::Pass, {"G71.HEAD.G0G1"});
      return;
    }
    const double approach = commonDepth - c_.clearance;
    if (approach > depthOf(current()) + kGeomEps) {
      emit(MoveKind::Rapid, {q.z, profile_.xAtDepth(approach)}, MovePhase::Pass, {"G71.T2.POCKET.EXIT"});
    }
    emit(MoveKind::Feed, q, MovePhase::Pass, {"G71.T2.POCKET.EXIT"});
  }

  // After the cut: 45° from a valley bottom, else up the far wall, then along x to e above the
  // level above (more than e where the follow stopped early, at a peak or a block along the cut).
  void leave(const CutNode& n) {
    if (n.kind == CutNode::Bottom) {
      const Point p = current();
      // 45° by e, but never back past the bottom's near end (a V, or a bottom shorter than e,
      // would otherwise be left through its near wall).
      const double back = std::min(c_.retract, distance(n.start.p, n.end.p));
      emit(MoveKind::Feed, {p.z - cut_ * back, p.x - d_ * c_.retract}, MovePhase::Pass, {"G71.T2.FOLLOW", "G71.T2.VALLEY"});
      return;
    }
    if (!n.openEnd) {
      const auto farWall = profile_.wallAfter(n.end, n.parentDepth, c_.followAlongCut);
      followPath(farWall, {"G71.T2.FOLLOW", "G71.CHAMFER"});
    }
    emit(MoveKind::Feed, {current().z, profile_.xAtDepth(n.parentDepth - c_.retract)}, MovePhase::Pass, {"G71.T2.FOLLOW"});
  }

  // ---- return and semi-finish ------------------------------------------------------------------

  // G71.T2.RETURN: back to A, passing Δd above a shape that stands as high as the start point.
  double returnDepth() const {
    const double startDepth = depthOf(c_.start);
    const double highest = profile_.shallowestAfterHead();
    return highest <= startDepth + kGeomEps ? highest - c_.depthOfCut : startDepth;
  }

  void returnToStart() {
    emit(MoveKind::Rapid, {current().z, profile_.xAtDepth(returnDepth())}, MovePhase::Return, {"G71.T2.RETURN"});
    emit(MoveKind::Rapid, {c_.start.z, current().x}, MovePhase::Return, {"G71.T2.RETURN"});
    emit(MoveKind::Rapid, c_.start, MovePhase::Return, {"G71.T2.RETURN"});
  }

  // G71.NSP without pockets: from the last cut, above everything, to B' where the semi-finish starts.
  void travelToHeadEnd() {
    const Point bPrime = roughProfileOf(c_).front().to;
    emit(MoveKind::Rapid, {current().z, profile_.xAtDepth(returnDepth())}, MovePhase::Return, {"G71.NSP"});
    emit(MoveKind::Rapid, {bPrime.z, current().x}, MovePhase::Return, {"G71.NSP"});
  }

  // G71.T2.RETURN: the semi-finish pass along the whole rough profile, A' first. With NSP and
  // pockets, the second pass over A–B is rapid (G71.NSP).
  void semiFinishPass(bool headRapid) {
    emit(MoveKind::Rapid, aPrime_, MovePhase::SemiFinish, {"G71.T2.RETURN"});
    const std::vector<Segment> rough = roughProfileOf(c_);
    for (std::size_t i = 0; i < rough.size(); ++i) {
      const bool rapid = i == 0 && ((headAlongDepth() && c_.headIsRapid) || headRapid);
      emitSegment(rough[i], rapid ? MoveKind::Rapid : MoveKind::Feed, MovePhase::SemiFinish, {"G71.T2.RETURN"});
    }
  }

  // ---- moves ------------------------------------------------------------------------------------

  bool onHeadLine(Point p) const { return std::abs(p.z - aPrime_.z) <= kGeomEps; }
  // G71.HEAD.G0G1: moves along block ns run in its mode — rapid after G00, cutting feed after G01.
  MoveKind headMode() const { return c_.headIsRapid ? MoveKind::Rapid : MoveKind::Feed; }
  bool headAlongDepth() const { return std::abs(c_.shape.front().to.z - c_.shape.front().from.z) <= kGeomEps; }
  double depthOf(Point p) const { return profile_.depth(p); }
  Point current() const { return moves_.current(); }

  void followPath(const std::vector<Segment>& path, const std::vector<std::string>& rules) {
    for (const Segment& s : path) emitSegment(s, MoveKind::Feed, MovePhase::Pass, rules);
  }

  // Moves of a cut carry its number (the cut tree's order); the others none.
  int passOf(MovePhase phase) const { return phase == MovePhase::Pass ? pass_ : 0; }

  void emitSegment(const Segment& s, MoveKind kind, MovePhase phase, const std::vector<std::string>& rules) {
    moves_.emitAlong(kind, s, phase, passOf(phase), rules);
  }

  void emit(MoveKind kind, Point to, MovePhase phase, std::vector<std::string> rules) {
    moves_.emit(kind, to, phase, passOf(phase), std::move(rules));
  }

  const Type2Cycle& c_;
  const RoughingRules& rules_;
  MoveEmitter moves_;
  int d_, cut_;
  Point aPrime_;
  PocketProfile profile_;
  std::vector<CutNode> nodes_;
  std::map<int, double> pointI_;  // parent node → cut coordinate of its first pocket's entry (G71.NSP)
  int previous_ = 0;  // the root before the first cut
  int pass_ = 0;
};

}  // namespace

int Type2Cycle::depthDirection() const { return signOf(shape.front().to.x - shape.front().from.x); }

int Type2Cycle::cutDirection() const {
  const int c = signOf(shape.back().to.z - shape.front().from.z);
  return c != 0 ? c : -1;
}

std::vector<Move> planType2(const Type2Cycle& cycle) { return Type2Planner(cycle).plan(); }

bool type2HasPocketWall(const Type2Cycle& cycle) {
  const Point aPrime = cycle.start + cycle.allowance;
  return PocketProfile(roughProfileOf(cycle), 1, aPrime, cycle.depthDirection(), cycle.cutDirection()).hasPocketWall();
}

}  // namespace cyclecert
