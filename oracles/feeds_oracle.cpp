// feeds: cutting moves run at the cycle's F (G71.FST, G72.FST: F inside ns…nf is ignored by the
// roughing cycle), or at an F of the finishing shape when the program has a G70 (G70.EX).
#include <algorithm>
#include <cmath>
#include <sstream>

#include "oracles/oracles.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

namespace {

class FeedsOracle : public Oracle {
 public:
  std::string id() const override { return "feeds"; }
  std::vector<std::string> rules() const override {
    return {"G71.FST", "G72.FST", "G70.EX", "G72.STEP2", "G71.HEAD.G0G1", "G73.PASS", "G73.HEAD"};
  }

  // Rapids as rapids: the infeeds along the head block (at A' on the cut axis, towards the part)
  // are rapids after a G00 head block and cutting feed after a G01 one (G72.STEP2, G71.HEAD.G0G1).
  void judgeInfeeds(const JudgeInput& in, std::vector<Finding>& out) const {
    const CycleSpec* c = in.program.singleRoughingCycle();
    if (!c || (c->typeII && c->noRepeatedPath)) return;  // G71.NSP makes the second A'→B' a rapid
    if (c->patternRepeating()) {
      judgeG73Heads(in, *c, out);
      return;
    }
    const double tol = in.settings.tolerance();
    // On the head line itself: engines that round print 4 decimals at worst. (The whole tolerance
    // would take in the first µm of a steep wall after B, where a pocket entry may rapid.)
    const double onLine = std::min(tol, 1e-4);
    const Point aPrime = inFrame(*c, c->start + c->allowance), a = inFrame(*c, c->start);
    const Point head = inFrame(*c, c->shape.front().to) - inFrame(*c, c->shape.front().from);
    if (std::abs(head.z) > tol) return;  // a type II head block that is not along the depth axis
    const int d = c->depthDirection();
    for (std::size_t i = 0; i < in.path.moves.size(); ++i) {
      const Point from = inFrame(*c, in.path.from(i)), to = inFrame(*c, in.path.moves[i].to);
      // Block ns spans A'→B': a move down the head line that ends at or above A', or no deeper
      // than A (the return to the start point, which lies below A' when Δu points away), is not
      // along block ns.
      // Along the head line also in direction (within 0.6°): a short move down a steep wall just
      // after B stays within the tolerance of the line without running along it.
      const bool alongDepth = std::abs(to.z - from.z) <= 0.01 * std::abs(to.x - from.x);
      const bool infeed = std::abs(from.z - aPrime.z) <= onLine && std::abs(to.z - aPrime.z) <= onLine && alongDepth &&
                          d * (to.x - from.x) > tol && d * (to.x - aPrime.x) > tol && d * (to.x - a.x) > tol;
      if (!infeed || (in.path.moves[i].kind == MoveKind::Rapid) == c->headIsRapid) continue;
      out.push_back(finding(*this, i, std::string("an infeed along the head block is a ") +
                                          (c->headIsRapid ? "cutting feed, but block ns is G00: it must be a rapid"
                                                          : "rapid, but block ns is G01: it must be at the cutting feed")));
    }
  }

  // G73.HEAD: block ns, shifted for each pass, moves as programmed — a rapid after G00, cutting feed
  // after G01 (the passes' other moves run at F: G73.PASS, judged with every feed below).
  void judgeG73Heads(const JudgeInput& in, const CycleSpec& c, std::vector<Finding>& out) const {
    const double tol = in.settings.tolerance();
    for (std::size_t i = 0; i < in.path.moves.size(); ++i) {
      if (!isShiftedG73Head(in, c, i, tol) || (in.path.moves[i].kind == MoveKind::Rapid) == c.headIsRapid) continue;
      out.push_back(finding(*this, i, std::string("block ns of G73, shifted for a pass, is a ") +
                                          (c.headIsRapid ? "cutting feed, but block ns is G00: it must be a rapid"
                                                         : "rapid, but block ns is G01: it must be at the cutting feed")));
    }
  }

  // HNC.G71.FST: each block after the Huazhong G71 moves as written — G00 rapids, else cutting
  // feed at the F in force (in the finishing run: set between G71 and ns, else the G71 block's).
  void judgeRunAfterHuazhong(const JudgeInput& in, const RunAfterCycle& run, std::vector<Finding>& out) const {
    const std::vector<ProgramMove>& blocks = in.program.runAfterHuazhong;
    std::size_t first = run.roughingEnd;
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      const ProgramMove& b = blocks[k];
      for (std::size_t i = first; i <= run.lastMove[k]; ++i) {
        const Move& m = in.path.moves[i];
        const bool rapid = m.kind == MoveKind::Rapid;
        std::ostringstream s;
        if (rapid != b.rapid) {
          s << "move " << i << " (the block at line " << b.line << (b.finishing ? ", finishing run" : "") << ") is ";
          if (rapid) s << "a rapid, but the block is a cutting move at F" << b.feed;
          else s << "a cutting feed, but the block is G00";
        } else if (!rapid && (!m.feed || std::abs(*m.feed - b.feed) > 1e-9 * std::max(1.0, b.feed))) {
          s << "move " << i << " (the block at line " << b.line << (b.finishing ? ", finishing run" : "") << ") runs at F"
            << m.feed.value_or(0) << ", but the F in force there is " << b.feed;
        } else {
          continue;
        }
        Finding f = finding(*this, i, s.str());
        f.rules = {"HNC.G71.FST"};
        out.push_back(f);
      }
      first = run.lastMove[k] + 1;
    }
  }

  // G74.1 too (judgeGroove).
  bool judges(CycleFamily f) const override { return !isSiemensFamily(f); }

  // G74_1.ADDR (I21): the groove's feeds run at the F in force before the cycle — F 0 when the
  // program gives none (the seed's example), drawn so with a warning.
  void judgeGroove(const JudgeInput& in, const GrooveSpec& g, std::vector<Finding>& out) const {
    const MoveRange range{firstMoveOfTheCycles(in), firstMoveAfterTheCycles(in)};
    for (std::size_t i = range.begin; i < range.end; ++i) {
      const Move& m = in.path.moves[i];
      if (m.kind != MoveKind::Feed) continue;
      if (m.feed && std::abs(*m.feed - g.feed) <= 1e-9 * std::max(1.0, g.feed)) continue;
      std::ostringstream s;
      s << "cutting move " << i << " of G74.1 at F" << m.feed.value_or(0) << ", but the F in force is " << g.feed;
      Finding f = finding(*this, i, s.str());
      f.rules = {"G74_1.ADDR", "G74_1.STEP3", "G74_1.STEP9", "G74_1.STEP10"};
      out.push_back(f);
    }
  }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (in.path.alarm) return;
    if (const GrooveSpec* g = in.program.singleGroove()) judgeGroove(in, *g, out);
    if (in.program.cycles.empty()) return;
    judgeInfeeds(in, out);
    std::vector<double> allowed;
    for (const CycleSpec& c : in.program.cycles) allowed.push_back(c.feed);
    if (in.program.hasFinishingCycle) allowed.insert(allowed.end(), in.program.finishingFeeds.begin(), in.program.finishingFeeds.end());
    // HNC.G71.FST: after a Huazhong G71 the moves of the blocks after it are judged block by block;
    // the cycle's own (and the program's before it) end where they begin.
    const RunLocation huazhong = locateRunAfterHuazhong(in);
    const std::size_t cycleEnd = huazhong.run ? huazhong.run->roughingEnd : in.path.moves.size();
    if (huazhong.run) judgeRunAfterHuazhong(in, *huazhong.run, out);
    for (std::size_t i = 0; i < cycleEnd; ++i) {
      const Move& m = in.path.moves[i];
      if (m.kind != MoveKind::Feed) continue;
      if (!m.feed || *m.feed <= 0) {
        out.push_back(finding(*this, i, "a cutting move without a feed rate"));
        continue;
      }
      bool ok = false;
      for (double f : allowed) ok = ok || std::abs(*m.feed - f) <= 1e-9 * std::max(1.0, f);
      if (!ok && (!in.program.motionAfterCycles || huazhong.run)) {
        std::ostringstream s;
        s << "cutting move at F" << *m.feed << ", but the cycle's F is " << in.program.cycles.front().feed;
        out.push_back(finding(*this, i, s.str()));
      }
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeFeedsOracle() { return std::make_unique<FeedsOracle>(); }

}  // namespace cyclecert
