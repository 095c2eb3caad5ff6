// siemens-chip-breaking: CYCLE95's DT and DAM (CYCLE95.DAM): each roughing step is interrupted for
// chip breaking after DAM, so no cut along a level — a main pass's, or one across an undercut's
// pocket (CYCLE95.UNDERCUT: the pocket's passes are roughing steps too) — is longer than DAM; and
// the tool dwells DT seconds at each interruption: a piece of a cut along a level that ends off the
// profile, the cut going on along the level, ends with a dwell of DT; no other piece of a cut along
// a level dwells. DAM = 0 never interrupts, and then nothing dwells.
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

class SiemensChipBreakingOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-chip-breaking"; }
  std::vector<std::string> rules() const override { return {"CYCLE95.DAM", "CYCLE95.UNDERCUT"}; }
  bool judges(CycleFamily f) const override { return f == CycleFamily::Cycle95; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    if (!m.c.isCycle95()) return;
    for (const FeedRun& cut : m.roughing) {
      for (std::size_t i = cut.begin; i < cut.end; ++i) {
        if (!m.isMainLevelCut(i) && !m.undercutLevelCut(i)) continue;
        judgeLength(m, i, out);
        judgeDwell(m, i, i + 1 < cut.end && continuesAlongTheLevel(m, i), out);
      }
    }
  }

  void judgeLength(const SiemensCycleMoves& m, std::size_t i, std::vector<Finding>& out) const {
    const double dam = m.c.interruptLength;
    const double length = std::abs(m.to(i).z - m.from(i).z);
    if (dam <= 0 || length <= dam + m.tol) return;
    out.push_back(m.report(*this, i, "a cut along the level " + shortDecimalText(length) +
                                         " long without interruption; DAM=" + shortDecimalText(dam) +
                                         " interrupts it for chip breaking after that length"));
  }

  // The next move goes on along the same level towards −z: the next piece of the same cut, or the
  // cleanup along a flat of the profile at that level.
  static bool continuesAlongTheLevel(const SiemensCycleMoves& m, std::size_t i) {
    const Move& next = m.in.path.moves[i + 1];
    if (next.kind != MoveKind::Feed || next.shape != SegmentKind::Line) return false;
    const Point a = m.from(i + 1), b = m.to(i + 1);
    return std::abs(b.x - a.x) <= m.tol && b.z < a.z;
  }

  // An interruption is a piece that ends in the stock, off the profile, with the cut going on
  // along the level: the tool dwells DT there. A piece that ends on the profile (within the
  // tolerance) reaches the roughing intersection: no dwell — unless the cut goes on from there (a
  // sliver piece within the tolerance of the intersection, or the cleanup along a flat of the
  // profile at the level), where either is accepted.
  void judgeDwell(const SiemensCycleMoves& m, std::size_t i, bool continues, std::vector<Finding>& out) const {
    const bool atTheProfile = nearPath(m.to(i), m.c.profile, m.tol);
    if (continues && atTheProfile) return;
    const bool interrupted = continues && m.c.interruptLength > 0;
    const double expected = interrupted ? m.c.dwell : 0;
    const double dwell = m.in.path.moves[i].dwell.value_or(0);
    if (std::abs(dwell - expected) <= 1e-9 * std::max(1.0, expected)) return;
    const std::string where = interrupted ? "at the interruption after this piece of the cut"
                                          : "after this cut along the level, which is no interruption for chip breaking";
    out.push_back(m.report(*this, i, "a dwell of " + shortDecimalText(dwell) + " s " + where + "; DT=" +
                                         shortDecimalText(m.c.dwell) + ", DAM=" + shortDecimalText(m.c.interruptLength) +
                                         " make it " + shortDecimalText(expected) + " s"));
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensChipBreakingOracle() { return std::make_unique<SiemensChipBreakingOracle>(); }

}  // namespace cyclecert
