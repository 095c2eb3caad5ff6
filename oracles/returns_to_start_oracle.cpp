// returns-to-start: a roughing (and finishing) cycle ends where it started, at A (G72.STEP8,
// G71.T1.STEP8, G71.T2.RETURN, G70.EX).
#include <cmath>
#include <sstream>

#include "oracles/oracles.h"

namespace cyclecert {

namespace {

class ReturnsToStartOracle : public Oracle {
 public:
  std::string id() const override { return "returns-to-start"; }
  std::vector<std::string> rules() const override { return {"G72.STEP8", "G71.T1.STEP8", "G71.T2.RETURN", "G70.EX", "G71.DTP"}; }

  // G71.DTP, type I after the semi-finish pass: DTP = 1 returns from C' straight to A; DTP = 0 along
  // the depth axis first, then along the cut axis (our reading of the missing figure).
  void judgeReturnShape(const JudgeInput& in, std::vector<Finding>& out) const {
    const CycleSpec* c = in.program.singleRoughingCycle();
    if (!c || c->typeII || !c->semiFinish || in.program.hasFinishingCycle || in.path.moves.size() < 2) return;
    const double tol = in.settings.tolerance();
    const std::size_t last = in.path.moves.size() - 1;
    const Point cPrime = c->shape.back().to + c->allowance;
    const Point end = inFrame(*c, in.path.moves[last].to), before = inFrame(*c, in.path.from(last));
    // The semi-finish ends level with A along the cut axis (or at A): the return has no cut-axis
    // leg, so it has no shape to judge.
    if (std::abs(inFrame(*c, cPrime).z - inFrame(*c, c->start).z) <= tol) return;
    if (c->directReturn) {
      if (distance(in.path.from(last), cPrime) > tol) {
        out.push_back(finding(*this, last, "with DTP = 1 the tool returns from C' straight to A"));
      }
    } else if (std::abs(end.x - before.x) > tol) {
      out.push_back(finding(*this, last, "with DTP = 0 the return ends along the cut axis, after leaving the part along the depth axis"));
    }
  }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    // Only when nothing but the cycles moves after them: then the path must end at the last A.
    if (in.path.alarm || in.program.cycles.empty() || in.program.motionAfterCycles || in.path.moves.empty()) return;
    judgeReturnShape(in, out);
    const Point start = in.program.cycles.back().start;
    const Point end = in.path.from(in.path.moves.size());
    if (distance(start, end) > in.settings.epsilon) {
      std::ostringstream m;
      m << "the path ends at (z " << end.z << ", x " << end.x << "), not at the cycle start point A (z " << start.z
        << ", x " << start.x << ")";
      Finding f = finding(*this, in.path.moves.size() - 1, m.str());
      f.witness.point = end;
      out.push_back(f);
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeReturnsToStartOracle() { return std::make_unique<ReturnsToStartOracle>(); }

}  // namespace cyclecert
