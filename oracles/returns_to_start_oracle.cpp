// returns-to-start: a roughing (and finishing) cycle ends where it started, at A (G72.STEP8,
// G71.T1.STEP8, G71.T2.RETURN, G70.EX).
#include <sstream>

#include "oracles/oracles.h"

namespace cyclecert {

namespace {

class ReturnsToStartOracle : public Oracle {
 public:
  std::string id() const override { return "returns-to-start"; }
  std::vector<std::string> rules() const override { return {"G72.STEP8", "G71.T1.STEP8", "G71.T2.RETURN", "G70.EX"}; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    // Only when nothing but the cycles moves after them: then the path must end at the last A.
    if (in.path.alarm || in.program.cycles.empty() || in.program.motionAfterCycles || in.path.moves.empty()) return;
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
