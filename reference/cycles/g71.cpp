// G71 — outer/inner diameter roughing cycle, FANUC 0i-F §4.2.1 (seed 000).
// Cuts along the plane's 1st axis (Z in G18) and steps along the 2nd (X). Type I follows the eight
// steps of seed 001 with the axes exchanged (G71.T1.STEP1…8); type II roughs pockets
// (reference/cycles/README.md).
#include <cmath>

#include "reference/cycles/cycles.h"
#include "reference/cycles/huazhong_format.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// G71.FMT.ZX / G71.FMT.YZ / G71.FMT.XY: Δd is given with the 2nd axis's incremental address
// (U, W, V), the same address as Δu (G71.ADDR.SHARED).
RoughingFormat g71Format(const CycleCall& call) { return {"G71", call.modal.axes().secondInc}; }

RoughingFrame g71Frame(const CycleCall& call) {
  const PlaneAxes axes = call.modal.axes();
  return {CycleFamily::G71, false, {alarm::kNotMonotonicFirst, call.params.get("5145"), std::string(1, axes.first)},
          {alarm::kNotMonotonicSecond, call.params.get("5146"), std::string(1, axes.second)}};
}

// G71.HEAD.NOX: block ns must move the 2nd axis. G71.TYPE.SELECT: with a 1st-axis word as well
// (W0 when it does not move) it selects type II.
bool selectsTypeII(const CycleCall& call, const ShapeProgram& shape) {
  const std::string secondAxis(1, call.modal.axes().second);
  if (!shape.headHasSecondAxis) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape has no " + secondAxis + " motion");
  }
  if (std::abs(shape.headEnd.x - shape.start.x) <= kGeomEps) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape does not move " + secondAxis + " (zero motion)");
  }
  return shape.headHasFirstAxis;
}

// G71.LIMIT.HEIGHT: with U(+) no part of the shape may stand above the cycle start point, with
// U(−) none below it.
void checkLimitHeight(const ShapeProgram& shape, double du) {
  if (du == 0) return;
  const double startX = shape.start.x;
  const auto beyond = [&](double x) { return du > 0 ? x > startX + kGeomEps : x < startX - kGeomEps; };
  const std::string why = std::string("with U") + (du > 0 ? "(+) the shape may not go above" : "(-) the shape may not go below") +
                          " the cycle start point";
  if (beyond(shape.headEnd.x)) throw CycleAlarm(alarm::kOverStartPoint, shape.nsLine, why);
  for (const Segment& s : shape.body) {
    const Extent e = extent(s);
    if (beyond(e.xMax) || beyond(e.xMin)) throw CycleAlarm(alarm::kOverStartPoint, s.sourceLine, why);
  }
}

// HNC.G71.*: the Huazhong one-block G71 (seed 003), planned as type I. Execution resumes after the
// G71 block, so ns…nf run again as the finishing pass.
CycleOutcome planHuazhongG71(const CycleCall& call) {
  const SecondBlock sb = readHuazhongG71Block(call);
  CycleOutcome out = withShapeAlarmTiming(call, [&] {
    refuseSubprogramsInHuazhongShape(call, sb);
    ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
    selectsTypeII(call, shape);  // HNC.G71.HEAD: A→A' must move X (the FANUC checks and alarms)
    checkHuazhongHead(call, shape);
    compensateShape(call, shape);
    // No G71.LIMIT.HEIGHT: seed 003 states none, and its example 2 (X-0.6, start X6) ends at X4,
    // below the start point.
    return planTypeI(call, shape, sb, g71Frame(call));
  });
  out.resumeAt = huazhongResumeIndex(call);
  return out;
}

}  // namespace

void applyG71FirstBlock(const CycleCall& call) {
  if (readsHuazhongG71(call)) refuseHuazhongG71WithoutPQ(call);
  applyFirstBlock(call, g71Format(call));
}

CycleOutcome planG71(const CycleCall& call) {
  if (readsHuazhongG71(call)) return planHuazhongG71(call);
  const SecondBlock sb = readSecondBlock(call, g71Format(call));
  return withShapeAlarmTiming(call, [&] {
    ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
    // HAAS.G71.R1: R1 selects type II whatever block ns commands.
    const bool typeII = selectsTypeII(call, shape) || sb.typeIIRequested;
    compensateShape(call, shape);
    checkLimitHeight(shape, sb.allowanceSecond);
    const RoughingFrame frame = g71Frame(call);
    return typeII ? planTypeII(call, shape, sb, frame) : planTypeI(call, shape, sb, frame);
  });
}

}  // namespace cyclecert
