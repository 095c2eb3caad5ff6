// returns-to-start: a roughing (and finishing) cycle ends where it started, at A (G72.STEP8,
// G71.T1.STEP8, G71.T2.RETURN, G70.EX).
#include <cmath>
#include <sstream>

#include "oracles/oracles.h"
#include "oracles/run_after_cycle.h"

namespace cyclecert {

namespace {

class ReturnsToStartOracle : public Oracle {
 public:
  std::string id() const override { return "returns-to-start"; }
  std::vector<std::string> rules() const override { return {"G72.STEP8", "G71.T1.STEP8", "G71.T2.RETURN", "G70.EX", "G71.DTP", "G73.RETURN"}; }

  // G71.DTP, type I after the semi-finish pass: DTP = 1 returns from C' straight to A; DTP = 0 along
  // the depth axis first, then along the cut axis (our reading of the missing figure).
  // `last` is the cycle's last move.
  void judgeReturnShape(const JudgeInput& in, std::size_t last, std::vector<Finding>& out) const {
    const CycleSpec* c = in.program.singleRoughingCycle();
    // G73 returns from the last pass straight to A (G73.RETURN): no DTP shape; its end is judged.
    if (!c || c->typeII || c->patternRepeating() || !c->semiFinish || last < 1) return;
    const double tol = in.settings.tolerance();
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
    if (in.path.alarm || in.program.cycles.empty() || in.path.moves.empty()) return;
    if (!in.program.runAfterHuazhong.empty()) {
      judgeHuazhongReturn(in, out);
      return;
    }
    // Only when nothing but the cycles moves after them: then the path must end at the last A.
    if (in.program.motionAfterCycles) return;
    if (!in.program.hasFinishingCycle) judgeReturnShape(in, in.path.moves.size() - 1, out);
    judgeEnd(in, in.path.moves.size(), "the path", {}, out);
  }

 private:
  // Whether the tool stands at A before move `end` (the path's end when `end` is the move count).
  void judgeEnd(const JudgeInput& in, std::size_t end, const std::string& what, std::vector<std::string> rules,
                std::vector<Finding>& out) const {
    const Point start = in.program.cycles.back().start;
    const Point at = in.path.from(end);
    if (distance(start, at) <= in.settings.epsilon) return;
    std::ostringstream m;
    m << what << " ends at (z " << at.z << ", x " << at.x << "), not at the cycle start point A (z " << start.z << ", x "
      << start.x << ")";
    Finding f = finding(*this, end == 0 ? 0 : end - 1, m.str());
    if (!rules.empty()) f.rules = std::move(rules);
    f.witness.point = at;
    out.push_back(f);
  }

  // HNC.G71.RETURN: the roughing ends at A, where the program goes on with the block after G71
  // (HNC.G71.FST); the path ends with those blocks' moves.
  void judgeHuazhongReturn(const JudgeInput& in, std::vector<Finding>& out) const {
    const RunLocation where = locateRunAfterHuazhong(in);
    if (where.unmatched) {
      const ProgramMove& b = in.program.runAfterHuazhong[*where.unmatched];
      std::ostringstream m;
      m << "after the Huazhong G71 the program goes on with the block after it; the path does not end with those "
           "blocks' moves: the block at line "
        << b.line << " leaves the tool at (z " << b.end.z << ", x " << b.end.x << "), where no move ends in its place";
      Finding f = finding(*this, std::nullopt, m.str());
      f.rules = {"HNC.G71.FST", "HNC.G71.RETURN"};
      f.witness.point = b.end;
      out.push_back(f);
      return;
    }
    if (!where.run) return;
    const std::size_t end = where.run->roughingEnd;
    if (end >= 1) judgeReturnShape(in, end - 1, out);
    judgeEnd(in, end, "the Huazhong G71 (before the block after it)", {"HNC.G71.RETURN"}, out);
  }
};

}  // namespace

std::unique_ptr<Oracle> makeReturnsToStartOracle() { return std::make_unique<ReturnsToStartOracle>(); }

}  // namespace cyclecert
