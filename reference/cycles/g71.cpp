// G71 — outer/inner diameter roughing cycle, FANUC 0i-F §4.2.1 (seed 000), type I.
// Cuts along the plane's 1st axis (Z in G18) and steps along the 2nd (X). The motion is the eight
// steps of seed 001 with the axes exchanged (G71.T1.STEP1…8, see reference/cycles/README.md).
#include <algorithm>
#include <cmath>

#include "reference/cycles/cycles.h"
#include "reference/cycles/monotonic_check.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// G71.FMT.ZX / G71.FMT.YZ / G71.FMT.XY: Δd is given with the 2nd axis's incremental address
// (U, W, V), the same address as Δu (G71.ADDR.SHARED).
RoughingFormat g71Format(const CycleCall& call) { return {"G71", call.modal.axes().secondInc}; }

// G71.HEAD.NOX and G71.TYPE.SELECT: block ns must move the 2nd axis; with a 1st-axis word as well
// it selects type II (issue 3 of the roadmap).
void selectTypeI(const CycleCall& call, const ShapeProgram& shape) {
  const PlaneAxes axes = call.modal.axes();
  const std::string secondAxis(1, axes.second);
  if (!shape.headHasSecondAxis) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape has no " + secondAxis + " motion");
  }
  if (shape.headHasFirstAxis) {
    throw NotSupported(shape.nsLine, "G71 type II (block ns moves both axes) is not planned by the reference yet");
  }
  if (std::abs(shape.headEnd.x - shape.start.x) <= kGeomEps) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape does not move " + secondAxis + " (zero motion)");
  }
}

// G71.LIMIT.HEIGHT: with U(+) no part of the shape may stand above the cycle start point, with
// U(−) none below it.
void checkLimitHeight(const Type1Cycle& cycle, int nsLine) {
  const double du = cycle.allowance.x;
  if (du == 0) return;
  const double startX = cycle.start.x;
  const auto beyond = [&](double x) { return du > 0 ? x > startX + kGeomEps : x < startX - kGeomEps; };
  const std::string why = std::string("with U") + (du > 0 ? "(+) the shape may not go above" : "(-) the shape may not go below") +
                          " the cycle start point";
  if (beyond(cycle.headEnd.x)) throw CycleAlarm(alarm::kOverStartPoint, nsLine, why);
  for (const Segment& s : cycle.body) {
    const Extent e = extent(s);
    if (beyond(e.xMax) || beyond(e.xMin)) throw CycleAlarm(alarm::kOverStartPoint, s.sourceLine, why);
  }
}

}  // namespace

void applyG71FirstBlock(const CycleCall& call) { applyFirstBlock(call, g71Format(call)); }

CycleOutcome planG71(const CycleCall& call) {
  const PlaneAxes axes = call.modal.axes();
  const SecondBlock sb = readSecondBlock(call, g71Format(call));
  const ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
  selectTypeI(call, shape);

  // The plane's (1st, 2nd) axes are already the cycle frame's (cut, depth) axes.
  Type1Cycle cycle;
  cycle.code = "G71";
  cycle.start = shape.start;
  cycle.headEnd = shape.headEnd;
  cycle.body = shape.body;
  cycle.allowance = {sb.allowanceFirst, sb.allowanceSecond};
  cycle.headIsRapid = shape.headIsRapid;
  cycle.feed = sb.feed;
  applyType1Parameters(call, cycle);

  checkLimitHeight(cycle, shape.nsLine);
  // G71.T1.MONO, G71.CHECK: checked on the finish shape before any move.
  checkType1Monotonic(cycle, {alarm::kNotMonotonicFirst, call.params.get("5145"), std::string_view(&axes.first, 1)},
                      {alarm::kNotMonotonicSecond, call.params.get("5146"), std::string_view(&axes.second, 1)});

  CycleOutcome out;
  out.moves = movesInPlane(planType1(cycle), false);
  out.resumeAt = resumeIndexAfterCycle(call, shape);
  out.shape = shape.finishShape();
  out.allowance = cycle.allowance;
  return out;
}

}  // namespace cyclecert
