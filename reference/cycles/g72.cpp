// G72 — facing roughing cycle (seed 001): type I follows the eight documented steps
// G72.STEP1…8; type II roughs pockets in the face (reference/cycles/README.md). G72 cuts along the
// plane's 2nd axis (X in G18) and steps along the 1st (Z): it plans with the axes exchanged, so
// that G71 and G72 share one implementation of each type.
#include <cmath>

#include "reference/cycles/cycles.h"
#include "reference/cycles/huazhong_format.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// G72.FMT: Δd and Δw share the 1st axis's incremental address (W in G18).
RoughingFormat g72Format(const CycleCall& call) { return {"G72", call.modal.axes().firstInc}; }

// In the frame, the cut axis is the plane's 2nd axis (PS0329, 5146) and the depth axis its 1st.
RoughingFrame g72Frame(const CycleCall& call) {
  const PlaneAxes axes = call.modal.axes();
  return {CycleFamily::G72, true, {alarm::kNotMonotonicSecond, call.params.get("5146"), std::string(1, axes.second)},
          {alarm::kNotMonotonicFirst, call.params.get("5145"), std::string(1, axes.first)}};
}

// G72.TYPE.SELECT: type I's block ns commands the 1st axis (Z) only; with the 2nd axis as well
// (U0 when it does not move) it is type II. Block ns without Z motion is PS0325 (G71.HEAD.NOX,
// applied to G72 with the axes exchanged).
bool selectsTypeII(const CycleCall& call, const ShapeProgram& shape) {
  const std::string firstAxis(1, call.modal.axes().first);
  if (!shape.headHasFirstAxis) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape has no " + firstAxis + " motion");
  }
  if (std::abs(shape.headEnd.z - shape.start.z) <= kGeomEps) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape does not move " + firstAxis + " (zero motion)");
  }
  return shape.headHasSecondAxis;
}

}  // namespace

void applyG72FirstBlock(const CycleCall& call) {
  refuseG72UnderHuazhong(call);
  applyFirstBlock(call, g72Format(call));
}

CycleOutcome planG72(const CycleCall& call) {
  refuseG72UnderHuazhong(call);
  const SecondBlock sb = readSecondBlock(call, g72Format(call));
  return withShapeAlarmTiming(call, [&] {
    ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
    // HAAS.G71.R1: R1 selects type II whatever block ns commands.
    const bool typeII = selectsTypeII(call, shape) || sb.typeIIRequested;
    compensateShape(call, shape);
    const RoughingFrame frame = g72Frame(call);
    return typeII ? planTypeII(call, shape, sb, frame) : planTypeI(call, shape, sb, frame);
  });
}

}  // namespace cyclecert
