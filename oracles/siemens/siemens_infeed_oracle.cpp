// siemens-infeed: how each roughing pass feeds in from the entry side (the start's z, in the frame)
// down to its level. LCYC95 (LCYC95.ROUGH, LCYC95.PARAMS R109): a G1 inclined R109 degrees from the
// infeed axis towards the cut — depth d runs d·tan R109 along the cut — never past the roughing
// intersection (it may end on the profile sooner: interpretation). CYCLE95 (CYCLE95.ROUGH): straight
// in with G0.
#include <cmath>
#include <numbers>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

class SiemensInfeedOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-infeed"; }
  std::vector<std::string> rules() const override { return {"LCYC95.ROUGH", "LCYC95.PARAMS", "CYCLE95.ROUGH"}; }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    if (m.roughing.empty()) return;
    for (std::size_t i = m.range.begin; i < m.finishing.begin; ++i) {
      if (!isInfeed(m, i)) continue;
      if (m.c.isCycle95()) {
        judgeStraightRapid(m, i, out);
      } else {
        judgeInclinedFeed(m, i, out);
      }
    }
  }

  // A move from the entry side (the start's z) deeper, down to a roughing level or above it — not the
  // rapid into the finishing pass.
  static bool isInfeed(const SiemensCycleMoves& m, std::size_t i) {
    const Point a = m.from(i), b = m.to(i);
    return std::abs(a.z - m.c.start.z) <= m.tol && b.x < a.x - m.tol && b.x <= m.c.levels.top + m.tol &&
           i + 1 != m.finishing.begin;
  }

  void judgeStraightRapid(const SiemensCycleMoves& m, std::size_t i, std::vector<Finding>& out) const {
    const Point d = m.to(i) - m.from(i);
    if (m.isRapid(i) && std::abs(d.z) <= m.tol) return;
    out.push_back(m.report(*this, i, std::string("an infeed ") + (m.isRapid(i) ? "" : "in feed ") + "running " +
                                         shortDecimalText(std::abs(d.z)) +
                                         " along the cut axis; CYCLE95 feeds in to the current depth straight, with G0"));
  }

  void judgeInclinedFeed(const SiemensCycleMoves& m, std::size_t i, std::vector<Finding>& out) const {
    const Point a = m.from(i), b = m.to(i);
    const double angle = m.c.infeedAngle;
    const double expected = (a.x - b.x) * std::tan(angle * std::numbers::pi / 180), run = a.z - b.z;
    const bool atAngle = std::abs(run - expected) <= m.tol;
    const bool cutShort = run < expected && nearPath(b, m.c.profile, m.tol);  // stops at the roughing intersection
    if (m.isFeed(i) && (atAngle || cutShort)) return;
    out.push_back(m.report(*this, i, std::string("an infeed ") + (m.isFeed(i) ? "" : "with G0 ") + "of depth " +
                                         shortDecimalText(a.x - b.x) + " running " + shortDecimalText(run) +
                                         " along the cut axis; LCYC95 feeds in with G1 at R109=" +
                                         shortDecimalText(angle) + " degrees from the infeed axis, i.e. " +
                                         shortDecimalText(expected) + " along the cut (less only where it meets the profile)"));
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensInfeedOracle() { return std::make_unique<SiemensInfeedOracle>(); }

}  // namespace cyclecert
