#include "oracles/oracles.h"

#include <cmath>

#include "reference/model/offset.h"

namespace cyclecert {

std::vector<std::unique_ptr<Oracle>> makeOracles() {
  std::vector<std::unique_ptr<Oracle>> all;
  all.push_back(makeAlarmOracle());
  all.push_back(makeNoGougeOracle());
  all.push_back(makeRapidsInAirOracle());
  all.push_back(makeCompleteOracle());
  all.push_back(makeDepthPerPassOracle());
  all.push_back(makePassLevelsOracle());
  all.push_back(makeRetractOracle());
  all.push_back(makePocketEntryOracle());
  all.push_back(makeReturnsToStartOracle());
  all.push_back(makeFeedsOracle());
  all.push_back(makeSiemensAlarmOracle());
  all.push_back(makeSiemensRetractOracle());
  all.push_back(makeSiemensInfeedStepsOracle());
  all.push_back(makeSiemensInfeedOracle());
  all.push_back(makeSiemensFeedsOracle());
  all.push_back(makeSiemensChipBreakingOracle());
  all.push_back(makeSiemensReturnsOracle());
  all.push_back(makeGroovePeckOracle());
  all.push_back(makeGrooveRetractOracle());
  all.push_back(makeGrooveRadialStepOracle());
  all.push_back(makeGrooveLayerOracle());
  all.push_back(makeGrooveReturnsOracle());
  return all;
}

Finding finding(const Oracle& o, std::optional<std::size_t> move, std::string message) {
  Finding f;
  f.oracle = o.id();
  f.rules = o.rules();
  f.move = move;
  f.message = std::move(message);
  return f;
}

Point inFrame(const CycleSpec& c, Point p) { return c.cutsAlongZ() ? p : transposed(p); }

bool isCutAlongCutAxis(const JudgeInput& in, const CycleSpec& c, std::size_t i, double tol) {
  if (i >= in.path.moves.size()) return false;
  const Move& m = in.path.moves[i];
  const Point from = inFrame(c, in.path.from(i)), to = inFrame(c, m.to);
  return m.kind == MoveKind::Feed && m.shape == SegmentKind::Line && std::abs(to.x - from.x) <= tol &&
         c.cutDirection() * (to.z - from.z) > tol;
}

bool isShiftedG73Head(const JudgeInput& in, const CycleSpec& c, std::size_t i, double tol) {
  if (!c.patternRepeating() || c.shape.empty() || i >= in.path.moves.size()) return false;
  const Segment& head = c.shape.front();
  const Point from = in.path.from(i), to = in.path.moves[i].to;
  const Point b = head.to + c.allowance;
  Segment ends;  // where the shifted B may stand: B + (Δw, Δu/2) + t·(Δk, Δi), t ∈ [0, 1]
  ends.from = b;
  ends.to = b + c.relief;
  // G70.EX, G73.G70: G70 after G73 follows block ns to B itself.
  const bool g70Head = in.program.hasFinishingCycle && distance(to, head.to) <= tol;
  return distance(to - from, head.to - head.from) <= tol && (distanceToSegment(to, ends) <= tol || g70Head);
}

bool runsOnProfile(const JudgeInput& in, const CycleSpec& c, const std::vector<Segment>& rough, std::size_t i,
                   double tol) {
  const Point mid = 0.5 * (in.path.from(i) + in.path.moves[i].to);
  return nearPath(mid, rough, tol) || (in.program.hasFinishingCycle && nearPath(mid, c.shape, tol));
}

}  // namespace cyclecert
