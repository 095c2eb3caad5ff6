// siemens-infeed-steps: the cycle computes its infeed (LCYC95.PARAMS R108, LCYC95.DEPTH, CYCLE95.DEPTH):
// the profile's height divided into the fewest equal steps not above R108 / MID, so every main
// roughing cut runs on one of the levels top − k·step (k = 1…count, the last the profile's lowest
// point). An engine stepping by R108 itself, with a smaller last step, cuts between them.
// CYCLE95's undercuts (CYCLE95.UNDERCUT note): each pocket in its own equal steps not above MID,
// from the lowest main level above its rim down to its lowest point — every cut across a pocket runs
// on one of the pocket's levels.
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

class SiemensInfeedStepsOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-infeed-steps"; }
  std::vector<std::string> rules() const override {
    return {"LCYC95.PARAMS", "LCYC95.DEPTH", "CYCLE95.DEPTH", "CYCLE95.UNDERCUT"};
  }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    for (const FeedRun& cut : m.roughing) {
      for (std::size_t i = cut.begin; i < cut.end; ++i) {
        if (m.isMainLevelCut(i)) {
          judgeLevel(m, i, m.c.levels, nullptr, out);
        } else if (const SiemensUndercut* u = m.undercutLevelCut(i)) {
          judgeLevel(m, i, equalLevels(u->top, u->bottom, m.c.maxInfeed), u, out);
        }
      }
    }
  }

  // A cut on the main levels (`undercut` null) or on those of an undercut; the message is written
  // only for a cut off them.
  void judgeLevel(const SiemensCycleMoves& m, std::size_t i, const SiemensLevels& l, const SiemensUndercut* undercut,
                  std::vector<Finding>& out) const {
    if (l.isLevel(m.from(i).x, m.tol)) return;
    const std::string top =
        undercut ? "the top of the undercut at Z" + shortDecimalText(m.c.frame.toPlane({undercut->rimZ, undercut->top}).z)
                 : "the profile's top";
    const double depth = std::abs(m.from(i).x - l.top);
    out.push_back(m.report(
        *this, i,
        "a roughing cut " + shortDecimalText(depth) + " below " + top + "; the depth " + shortDecimalText(l.top - l.bottom) +
            " divides into " + shortDecimalText(l.count) + " equal steps of " + shortDecimalText(l.step) +
            " (the fewest not above " + (m.c.isCycle95() ? "MID" : "R108") + "=" + shortDecimalText(m.c.maxInfeed) +
            "), so the cuts stand a whole number of steps below the top"));
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensInfeedStepsOracle() { return std::make_unique<SiemensInfeedStepsOracle>(); }

}  // namespace cyclecert
