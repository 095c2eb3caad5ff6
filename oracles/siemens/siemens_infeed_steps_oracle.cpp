// siemens-infeed-steps: the cycle computes its infeed (LCYC95.PARAMS R108, LCYC95.DEPTH, CYCLE95.DEPTH):
// the profile's height divided into the fewest equal steps not above R108 / MID, so every main
// roughing cut runs on one of the levels top − k·step (k = 1…count, the last the profile's lowest
// point). An engine stepping by R108 itself, with a smaller last step, cuts between them.
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

class SiemensInfeedStepsOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-infeed-steps"; }
  std::vector<std::string> rules() const override { return {"LCYC95.PARAMS", "LCYC95.DEPTH", "CYCLE95.DEPTH"}; }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const std::optional<SiemensCycleMoves> m = siemensCycleMoves(ctx.in);
    if (!m) return;
    const SiemensLevels& l = m->c.levels;
    for (const FeedRun& cut : m->roughing) {
      for (std::size_t i = cut.begin; i < cut.end; ++i) {
        if (!m->isMainLevelCut(i) || l.isLevel(m->from(i).x, m->tol)) continue;
        const double depth = std::abs(m->from(i).x - l.top);
        out.push_back(m->report(
            *this, i,
            "a roughing cut " + shortDecimalText(depth) + " below the profile's top; the depth " +
                shortDecimalText(l.top - l.bottom) + " divides into " + shortDecimalText(l.count) + " equal steps of " +
                shortDecimalText(l.step) + " (the fewest not above " + (m->c.isCycle95() ? "MID" : "R108") + "=" +
                shortDecimalText(m->c.maxInfeed) + "), so the cuts stand a whole number of steps below the top"));
      }
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensInfeedStepsOracle() { return std::make_unique<SiemensInfeedStepsOracle>(); }

}  // namespace cyclecert
