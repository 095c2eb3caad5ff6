// retract: after each roughing pass the tool leaves the part as the rules say — type I at once at
// 45° by e in cutting feed (G71.T1.RETRACT45, G72.STEP4); type II after following the shape, out
// along the depth axis by at least e, and out of a valley bottom by e, backing along the cut by
// no more than e (G71.T2.FOLLOW). A roughing pass is a cut along the cut axis that does not lie on
// the rough profile (the semi-finish pass and the bottom cuts do).
#include <cmath>
#include <sstream>

#include "oracles/oracles.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

namespace {

class RetractOracle : public Oracle {
 public:
  std::string id() const override { return "retract"; }
  std::vector<std::string> rules() const override { return {"G71.T1.RETRACT45", "G72.STEP4", "G72.RETRACT", "G71.T2.FOLLOW"}; }
  bool judges(CycleFamily f) const override { return f == CycleFamily::G71 || f == CycleFamily::G72; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    const CycleSpec* c = in.program.singleRoughingCycle();
    // G73 has no retract: each pass ends with the rapid back to A (G73.RETURN), which rapids-in-air
    // and returns-to-start judge.
    if (!c || in.path.alarm || c->patternRepeating()) return;
    Check check{*c, in, c->roughProfile(), in.settings.tolerance()};
    const MoveRange judged = movesOfTheRoughing(in);
    for (std::size_t i = judged.begin; i < judged.end; ++i) {
      if (!isCutAlongCutAxis(in, *c, i, check.tol)) continue;
      if (!runsOnProfile(in, *c, check.rough, i, check.tol)) {
        c->typeII ? check.typeIIPassLeaves(i, *this, out) : check.typeIPassLeaves(i, *this, out);
      } else if (c->typeII) {
        check.bottomLeaves(i, *this, out);
      }
    }
  }

 private:
  struct Check {
    const CycleSpec& c;
    const JudgeInput& in;
    std::vector<Segment> rough;
    double tol;

    Point from(std::size_t i) const { return inFrame(c, in.path.from(i)); }
    Point to(std::size_t i) const { return inFrame(c, in.path.moves[i].to); }
    bool isFeedLine(std::size_t i) const {
      return i < in.path.moves.size() && in.path.moves[i].kind == MoveKind::Feed && in.path.moves[i].shape == SegmentKind::Line;
    }
    double back(std::size_t i) const { return -c.cutDirection() * (to(i).z - from(i).z); }
    double out(std::size_t i) const { return -c.depthDirection() * (to(i).x - from(i).x); }

    void report(std::size_t i, const Oracle& o, std::vector<Finding>& findings, const std::string& message) const {
      Finding f = finding(o, i, message);
      if (i < in.path.moves.size()) f.witness.segment = in.path.segment(i);
      findings.push_back(f);
    }

    // e = 0 (R0, or 5133 = 0): the retract has no length, so no move shows it (an engine leaves out
    // a move of length 0, as the reference does): there is nothing to judge after the pass.
    bool retractIsNil() const { return c.retract <= tol; }

    // Type I: the move after the pass is the 45° retract: e back along the cut, e out.
    void typeIPassLeaves(std::size_t pass, const Oracle& o, std::vector<Finding>& findings) const {
      if (retractIsNil()) return;
      const std::size_t r = pass + 1;
      if (!isFeedLine(r) || std::abs(back(r) - c.retract) > tol || std::abs(out(r) - c.retract) > tol) {
        std::ostringstream s;
        s << "after the pass ending at move " << pass << " the tool does not retract at 45° by e = " << c.retract
          << " in cutting feed";
        if (isFeedLine(r)) s << " (it moves " << back(r) << " back and " << out(r) << " out)";
        report(r, o, findings, s.str());
      }
    }

    // Where the tool travels on: a rapid, or a feed that moves deeper — the approach into a pocket
    // fed from the clearance height (5134, G71.T2.POCKET.EXIT) when the clearance reaches that high.
    bool travels(std::size_t i) const { return in.path.moves[i].kind == MoveKind::Rapid || out(i) < -tol; }

    // Type II: after following the shape, the last feed before the tool travels moves out along the
    // depth axis by at least e (the follow and the retract may be one move or two).
    void typeIIPassLeaves(std::size_t pass, const Oracle& o, std::vector<Finding>& findings) const {
      if (retractIsNil()) return;
      std::size_t next = pass + 1;
      while (next < in.path.moves.size() && !travels(next)) ++next;
      if (next >= in.path.moves.size()) return;  // no travel after it: nothing to judge
      const std::size_t r = next - 1;
      const bool ok = r > pass && isFeedLine(r) && std::abs(back(r)) <= tol && out(r) >= c.retract - tol;
      if (!ok) {
        std::ostringstream s;
        s << "after the pass ending at move " << pass << " and following the shape, the tool does not retract out along "
          << "the depth axis by at least e = " << c.retract << " in cutting feed";
        report(r, o, findings, s.str());
      }
    }

    // Type II valley bottom: out by e, back along the cut by no more than e.
    void bottomLeaves(std::size_t bottom, const Oracle& o, std::vector<Finding>& findings) const {
      const std::size_t r = bottom + 1;
      if (!isFeedLine(r) || back(r) <= tol) return;  // the shape goes on (a semi-finish pass)
      if (std::abs(out(r) - c.retract) > tol || back(r) > c.retract + tol) {
        std::ostringstream s;
        s << "the retract from the valley bottom at move " << bottom << " moves " << back(r) << " back and " << out(r)
          << " out; it must move e = " << c.retract << " out and at most e back (45°)";
        report(r, o, findings, s.str());
      }
    }
  };
};

}  // namespace

std::unique_ptr<Oracle> makeRetractOracle() { return std::make_unique<RetractOracle>(); }

}  // namespace cyclecert
