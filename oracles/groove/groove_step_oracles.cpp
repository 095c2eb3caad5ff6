// The groove oracles that judge G74.1's steps from the moves alone (groove_moves.h), each citing its
// G74_1 rules (docs/g74_1.md §6):
// - groove-peck: no peck goes more than Δk deeper than its axial cycle has reached (STEP3, STEP5);
// - groove-retract: between two pecks the tool retracts e along Z opposite to the feed, as a rapid
//   (STEP4, STEP5), and after the cycle's last peck it rapids along Z back to the cycle's start
//   (STEP6);
// - groove-radial-step: the rapids that step across the groove between axial cycles move no more
//   than Δi/2 (STEP7);
// - groove-layer: with V no axial cycle cuts more than Δv below its start, and every cycle starts a
//   whole number of Δv below the start level (STEP2, STEP8, I16);
// - groove-returns: the cycle's first move is the rapid to the rough start A11 (STEP1, I18), its last
//   the rapid back to the point before the cycle (STEP10, I20).
#include <cmath>
#include <sstream>

#include "oracles/groove/groove_moves.h"
#include "oracles/groove/groove_replay.h"
#include "oracles/oracles.h"

namespace cyclecert {

namespace {

bool isGroove(CycleFamily f) { return f == CycleFamily::G74_1; }

// The cycle's moves, found once by the replay (JudgeContext::groove), or nullptr.
const GrooveMoves* movesOf(const JudgeContext& ctx) {
  return ctx.groove && ctx.groove->moves ? &*ctx.groove->moves : nullptr;
}

class GroovePeckOracle : public Oracle {
 public:
  std::string id() const override { return "groove-peck"; }
  std::vector<std::string> rules() const override { return {"G74_1.STEP3", "G74_1.STEP5"}; }
  bool judges(CycleFamily f) const override { return isGroove(f); }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const GrooveMoves* m = movesOf(ctx);
    if (!m) return;
    for (const AxialCycle& c : m->cycles) {
      double reached = c.top;
      for (std::size_t i : c.pecks) {
        const double deeper = m->to(i).z - std::max(reached, m->from(i).z);
        if (deeper > m->g.peck + m->tol) {
          std::ostringstream s;
          s << "the peck at move " << i << " goes " << deeper << " mm deeper than its axial cycle had reached; Δk = "
            << m->g.peck;
          out.push_back(m->report(*this, i, s.str()));
        }
        reached = std::max(reached, m->to(i).z);
      }
    }
  }
};

class GrooveRetractOracle : public Oracle {
 public:
  std::string id() const override { return "groove-retract"; }
  std::vector<std::string> rules() const override { return {"G74_1.STEP4", "G74_1.STEP5", "G74_1.STEP6"}; }
  bool judges(CycleFamily f) const override { return isGroove(f); }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const GrooveMoves* m = movesOf(ctx);
    if (!m) return;
    for (const AxialCycle& c : m->cycles) {
      for (std::size_t k = 0; k + 1 < c.pecks.size(); ++k) judgeRetract(*m, c.pecks[k], c.pecks[k + 1], out);
      judgeBackToTheStart(*m, c, out);
    }
  }

 private:
  // STEP4: the moves between two pecks are one rapid of e along −w (none when e is 0).
  void judgeRetract(const GrooveMoves& m, std::size_t peck, std::size_t next, std::vector<Finding>& out) const {
    const double e = m.g.retract;
    const std::size_t j = peck + 1;
    const bool none = j == next;
    if (none && e <= m.tol) return;
    const bool ok = !none && next == j + 1 && m.isRapid(j) && m.isAxial(j) && std::abs(m.dw(j) + e) <= m.tol;
    if (ok) return;
    std::ostringstream s;
    s << "after the peck at move " << peck << " the tool must retract e = " << e
      << " along Z, opposite to the feed, as a rapid, before the next peck";
    if (!none && m.dw(j) > m.tol) s << "; move " << j << " goes towards the bottom";
    else if (!none && !m.isRapid(j)) s << "; move " << j << " is a cutting feed";
    else if (!none) s << "; move " << j << " moves " << -m.dw(j) << " back along Z";
    out.push_back(m.report(*this, none ? peck : j, s.str()));
  }

  // STEP6: after the cycle's last peck, a rapid along Z back to the cycle's start Amn.
  void judgeBackToTheStart(const GrooveMoves& m, const AxialCycle& c, std::vector<Finding>& out) const {
    const std::size_t j = c.pecks.back() + 1;
    if (j < m.range.end && m.isRapid(j) && m.isAxial(j) && std::abs(m.to(j).z - c.top) <= m.tol) return;
    std::ostringstream s;
    s << "after the last peck of the axial cycle at " << m.planeText(grooveUW(c.u, c.top))
      << " the tool must rapid along Z back to that cycle's start";
    out.push_back(m.report(*this, j < m.range.end ? j : c.pecks.back(), s.str()));
  }
};

// STEP2 for the first layer: from A11 along the start level to the layer's first cycle start, the
// blade's start-side edge on the rough near flank's top — below an r1 corner, which the profile
// passes cut (I17) — rather than a step between cycles.
bool isFirstLayerStart(const GrooveMoves& m, std::size_t i) {
  const GrooveOutline& rough = m.g.rough;
  if (m.g.corners[0].size <= 0 || rough.chain.empty()) return false;
  const double flankTop = rough.chain.front().to.x;  // the r1 piece ends on the near flank
  if (distance(m.from(i), m.g.roughStart()) > m.tol) return false;
  // A nose's centre (I26) starts where it first meets the near side below r1: within R of that top.
  if (m.g.noseRadius > 0) return m.to(i).x <= flankTop + m.g.noseRadius + m.tol;
  return std::abs(m.to(i).x - (flankTop + m.g.toolWidth)) <= m.tol;
}

class GrooveRadialStepOracle : public Oracle {
 public:
  std::string id() const override { return "groove-radial-step"; }
  std::vector<std::string> rules() const override { return {"G74_1.STEP7"}; }
  bool judges(CycleFamily f) const override { return isGroove(f); }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const GrooveMoves* m = movesOf(ctx);
    if (!m) return;
    // ① (the first move) may run along u; STEP8's moves back to a layer's start run against d.
    for (std::size_t i = m->range.begin + 1; i < m->profileStart; ++i) {
      if (!m->isRapid(i) || std::abs(m->dw(i)) > m->tol || m->du(i) <= m->g.radialStep + m->tol) continue;
      if (i == m->range.begin + 1 && isFirstLayerStart(*m, i)) continue;
      std::ostringstream s;
      s << "rapid move " << i << " steps " << 2 * m->du(i) << " in X (diameter) between axial cycles; Δi = "
        << 2 * m->g.radialStep;
      out.push_back(m->report(*this, i, s.str()));
    }
  }
};

class GrooveLayerOracle : public Oracle {
 public:
  std::string id() const override { return "groove-layer"; }
  std::vector<std::string> rules() const override { return {"G74_1.STEP2", "G74_1.STEP8"}; }
  bool judges(CycleFamily f) const override { return isGroove(f); }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const GrooveMoves* m = movesOf(ctx);
    if (!m || !m->g.layerDepth) return;  // no V: one layer, as deep as the groove
    const double dv = *m->g.layerDepth;
    for (const AxialCycle& c : m->cycles) {
      double deepest = c.top;
      for (std::size_t i : c.pecks) deepest = std::max(deepest, m->to(i).z);
      const double layers = std::round(c.top / dv);
      if (std::abs(c.top - layers * dv) > m->tol) {
        std::ostringstream s;
        s << "the axial cycle at move " << c.pecks.front() << " starts " << c.top
          << " mm below the start level, not a whole number of layers Δv = " << dv;
        out.push_back(m->report(*this, c.pecks.front(), s.str()));
      }
      if (deepest - c.top > dv + m->tol) {
        std::ostringstream s;
        s << "the axial cycle at move " << c.pecks.front() << " cuts a layer " << deepest - c.top
          << " mm deep; Δv = " << dv;
        out.push_back(m->report(*this, c.pecks.back(), s.str()));
      }
    }
  }
};

class GrooveReturnsOracle : public Oracle {
 public:
  std::string id() const override { return "groove-returns"; }
  std::vector<std::string> rules() const override { return {"G74_1.STEP1", "G74_1.STEP10"}; }
  bool judges(CycleFamily f) const override { return isGroove(f); }
  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const GrooveMoves* m = movesOf(ctx);
    if (!m) return;
    judgeApproach(*m, out);
    judgeReturn(*m, out);
  }

 private:
  // STEP1 (I18): one rapid from the point before the cycle to A11 (none when the tool stands there).
  void judgeApproach(const GrooveMoves& m, std::vector<Finding>& out) const {
    const std::size_t i = m.range.begin;
    const Point a11 = m.g.roughStart();
    if (distance(m.from(i), a11) <= m.tol) return;
    if (m.isRapid(i) && distance(m.to(i), a11) <= m.tol) return;
    out.push_back(m.report(*this, i, "the cycle does not begin with a rapid to the rough start A11 " + m.planeText(a11)));
  }

  // STEP10, I20: the cycle's last move is a rapid back to the point before it, for every J.
  void judgeReturn(const GrooveMoves& m, std::vector<Finding>& out) const {
    const std::size_t last = m.range.end - 1;
    const Point before = m.g.judgedPoint(m.g.before);
    const bool back = distance(m.to(last), before) <= m.tol;
    if (back && m.isRapid(last)) return;
    std::ostringstream s;
    if (back) s << "the return to the point before the cycle (move " << last << ") is not a rapid";
    else s << "the cycle ends at " << m.planeText(m.to(last)) << ", not back at the point before it "
           << m.planeText(before);
    Finding f = m.report(*this, last, s.str());
    f.witness.point = m.in.path.moves[last].to;
    out.push_back(f);
  }
};

}  // namespace

std::unique_ptr<Oracle> makeGroovePeckOracle() { return std::make_unique<GroovePeckOracle>(); }
std::unique_ptr<Oracle> makeGrooveRetractOracle() { return std::make_unique<GrooveRetractOracle>(); }
std::unique_ptr<Oracle> makeGrooveRadialStepOracle() { return std::make_unique<GrooveRadialStepOracle>(); }
std::unique_ptr<Oracle> makeGrooveLayerOracle() { return std::make_unique<GrooveLayerOracle>(); }
std::unique_ptr<Oracle> makeGrooveReturnsOracle() { return std::make_unique<GrooveReturnsOracle>(); }

}  // namespace cyclecert
