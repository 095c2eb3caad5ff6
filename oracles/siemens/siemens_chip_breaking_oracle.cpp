// siemens-chip-breaking: CYCLE95's DAM (CYCLE95.DAM): a roughing cut along the level is interrupted
// for chip breaking after DAM, so no move of a main pass's cut along its level is longer than DAM.
// (DT, the dwell then, is no move.) DAM = 0 never interrupts.
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

class SiemensChipBreakingOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-chip-breaking"; }
  std::vector<std::string> rules() const override { return {"CYCLE95.DAM"}; }
  bool judges(CycleFamily f) const override { return f == CycleFamily::Cycle95; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const std::optional<SiemensCycleMoves> m = siemensCycleMoves(ctx.in);
    if (!m || m->c.interruptLength <= 0) return;
    const double dam = m->c.interruptLength;
    for (const FeedRun& cut : m->roughing) {
      for (std::size_t i = cut.begin; i < cut.end; ++i) {
        const double length = std::abs(m->to(i).z - m->from(i).z);
        if (!m->isMainLevelCut(i) || length <= dam + m->tol) continue;
        out.push_back(m->report(*this, i, "a cut along the level " + shortDecimalText(length) +
                                              " long without interruption; DAM=" + shortDecimalText(dam) +
                                              " interrupts it for chip breaking after that length"));
      }
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensChipBreakingOracle() { return std::make_unique<SiemensChipBreakingOracle>(); }

}  // namespace cyclecert
