// siemens-retract: after each roughing cut the tool retracts with G0 by R110 / _VRT in EACH axis,
// away from the contour (LCYC95.ROUGH: "在每个坐标轴方向按参数 R110 … 退刀"; CYCLE95.ROUGH, and each
// undercut pass, CYCLE95.UNDERCUT): in the frame the move after the cut's last feed is (+v, +v).
// A 45° retract of length v (v/√2 per axis) or a retract along one axis is a finding — except
// where the part stands in the way of the diagonal (the profile within tolerance of it or above,
// a pocket's falling side closer than v): there the retract lifts by v along the depth axis only
// (CYCLE95.UNDERCUT note, interpretation).
#include <algorithm>
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

// Whether the profile comes within `tol` of the diagonal from `p` by `v` in each axis, or stands
// above it, for z in (p.z, p.z + v]: each element sampled every 0.01 mm at most (an arc's sagitta
// between samples stays far below the tolerance; at most 100,001 samples an element).
bool partInTheWayOfTheDiagonal(const std::vector<Segment>& profile, Point p, double v, double tol) {
  for (const Segment& s : profile) {
    const int samples = 1 + static_cast<int>(std::min(1e5, std::ceil(s.length() / 0.01)));
    for (int j = 0; j <= samples; ++j) {
      const Point q = pointAt(s, static_cast<double>(j) / samples);
      const double along = q.z - p.z;
      if (along > tol && along <= v + tol && q.x >= p.x + along - tol) return true;
    }
  }
  return false;
}

class SiemensRetractOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-retract"; }
  std::vector<std::string> rules() const override { return {"LCYC95.ROUGH", "CYCLE95.ROUGH", "CYCLE95.UNDERCUT"}; }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    const double v = std::abs(m.c.retract);
    if (v <= m.tol) return;  // no retract to make (a zero-length move is no move)
    const std::string name = m.c.isCycle95() ? "_VRT" : "R110";
    for (const FeedRun& cut : m.roughing) {
      const std::size_t i = cut.end;
      if (i >= m.range.end) {
        out.push_back(m.report(*this, cut.end - 1, "the roughing cut ending here is not followed by the retract by " +
                                                        name + "=" + shortDecimalText(v) + " in each axis"));
        continue;
      }
      const Point d = m.to(i) - m.from(i);
      if (m.isRapid(i) && std::abs(d.z - v) <= m.tol && std::abs(d.x - v) <= m.tol) continue;
      if (m.isRapid(i) && std::abs(d.z) <= m.tol && std::abs(d.x - v) <= m.tol &&
          partInTheWayOfTheDiagonal(m.c.profile, m.from(i), v, m.tol)) {
        continue;
      }
      const Point plane = m.in.path.moves[i].to - m.in.path.from(i);
      out.push_back(m.report(*this, i, std::string("after the roughing cut (moves ") + std::to_string(cut.begin) + "…" +
                                            std::to_string(cut.end - 1) + ") the tool moves " +
                                            (m.isRapid(i) ? "G0" : "in feed") + " by Z" + shortDecimalText(plane.z) +
                                            " X(radius)" + shortDecimalText(plane.x) + "; the cycle retracts with G0 by " +
                                            name + "=" + shortDecimalText(v) + " in each axis, away from the contour (along the depth axis only where the part stands in the way)"));
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensRetractOracle() { return std::make_unique<SiemensRetractOracle>(); }

}  // namespace cyclecert
