// G72 — facing roughing cycle (seed 001), type I: the eight documented steps G72.STEP1…8.
// Cuts along the plane's 2nd axis (X in G18) and steps along the 1st (Z). The planner works with
// the axes exchanged, so that G71 and G72 share one implementation of the steps.
#include <cmath>

#include "reference/cycles/cycles.h"
#include "reference/cycles/monotonic_check.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// G72.FMT: Δd and Δw share the 1st axis's incremental address (W in G18).
RoughingFormat g72Format(const CycleCall& call) { return {"G72", call.modal.axes().firstInc}; }

// G72.TYPE.SELECT: type I's block ns commands the 1st axis (Z) only; with the 2nd axis as well it
// is type II (issue 3 of the roadmap). A block ns without Z motion is PS0325 (G71.HEAD.NOX, applied
// to G72 with the axes exchanged).
void selectTypeI(const CycleCall& call, const ShapeProgram& shape) {
  const std::string firstAxis(1, call.modal.axes().first);
  if (!shape.headHasFirstAxis) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape has no " + firstAxis + " motion");
  }
  if (shape.headHasSecondAxis) {
    throw NotSupported(shape.nsLine, "G72 type II (block ns moves both axes) is not planned by the reference yet");
  }
  if (std::abs(shape.headEnd.z - shape.start.z) <= kGeomEps) {
    throw CycleAlarm(alarm::kUnavailableInShape, shape.nsLine,
                     "the first block of the shape does not move " + firstAxis + " (zero motion)");
  }
}

std::vector<Segment> transposedAll(const std::vector<Segment>& segments) {
  std::vector<Segment> out;
  out.reserve(segments.size());
  for (const Segment& s : segments) out.push_back(transposed(s));
  return out;
}

}  // namespace

void applyG72FirstBlock(const CycleCall& call) { applyFirstBlock(call, g72Format(call)); }

CycleOutcome planG72(const CycleCall& call) {
  const PlaneAxes axes = call.modal.axes();
  const SecondBlock sb = readSecondBlock(call, g72Format(call));
  const ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
  selectTypeI(call, shape);

  // The cycle frame cuts along its z: exchange the plane's axes (G72.POINTS in that frame).
  Type1Cycle cycle;
  cycle.code = "G72";
  cycle.start = transposed(shape.start);
  cycle.headEnd = transposed(shape.headEnd);
  cycle.body = transposedAll(shape.body);
  cycle.allowance = transposed(Point{sb.allowanceFirst, sb.allowanceSecond});  // G72.ALLOW
  cycle.headIsRapid = shape.headIsRapid;
  cycle.feed = sb.feed;
  applyType1Parameters(call, cycle);

  // G72.T1.MONO: in the frame, z is the plane's 2nd axis and x its 1st.
  checkType1Monotonic(cycle, {alarm::kNotMonotonicSecond, call.params.get("5146"), std::string_view(&axes.second, 1)},
                      {alarm::kNotMonotonicFirst, call.params.get("5145"), std::string_view(&axes.first, 1)});

  CycleOutcome out;
  out.moves = movesInPlane(planType1(cycle), true);
  out.resumeAt = resumeIndexAfterCycle(call, shape);
  out.shape = shape.finishShape();
  out.allowance = transposed(cycle.allowance);
  return out;
}

}  // namespace cyclecert
