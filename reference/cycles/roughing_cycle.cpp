#include "reference/cycles/roughing_cycle.h"

#include "reference/gcode/address_ranges.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

namespace cyclecert {

void applyFirstBlock(const CycleCall& call, const RoughingFormat& format) {
  const Block& b = call.block();
  const bool inch = call.modal.inch;
  if (const Word* dd = b.find(format.depthOfCutAddress)) {
    checkCycleAddress(*dd, CycleAddress::DepthOfCut, inch);
    call.params.set("5132", dd->value * call.modal.unitScale());  // Δd: radius, unsigned
  }
  if (const Word* e = b.find('R')) {
    checkCycleAddress(*e, CycleAddress::Retract, inch);
    call.params.set("5133", e->value * call.modal.unitScale());  // e: radius, unsigned
  }
}

SecondBlock readSecondBlock(const CycleCall& call, const RoughingFormat& format) {
  const Block& b = call.block();
  const PlaneAxes axes = call.modal.axes();
  SecondBlock s;
  s.p = b.find('P');
  s.q = b.find('Q');
  if (!s.p || !s.q) {
    throw CycleAlarm(alarm::kPQMissing, b.line,
                     format.code + " block has " + (s.p ? "P but no Q" : "Q but no P") + " (both are required)");
  }
  checkCycleAddress(*s.p, CycleAddress::SequenceNumber, call.modal.inch);
  checkCycleAddress(*s.q, CycleAddress::SequenceNumber, call.modal.inch);
  // G71.ALLOW.UNITS: Δu along the 2nd axis and Δw along the 1st, each in that axis's programming.
  if (const Word* du = b.find(axes.secondInc)) {
    checkCycleAddress(*du, CycleAddress::Allowance, call.modal.inch);
    s.allowanceSecond = physicalLength(du->value, axes.secondDiameter, call.modal);
  }
  if (const Word* dw = b.find(axes.firstInc)) {
    checkCycleAddress(*dw, CycleAddress::Allowance, call.modal.inch);
    s.allowanceFirst = physicalLength(dw->value, axes.firstDiameter, call.modal);
  }
  // G71.FST: the F of the cycle blocks, or the modal F before them (the runner keeps it).
  s.feed = call.modal.feed;
  if (s.feed <= 0) {
    throw CycleAlarm(alarm::kFeedZero, b.line, "no cutting feed F in the cycle blocks or before them");
  }
  return s;
}

void applyType1Parameters(const CycleCall& call, Type1Cycle& cycle) {
  cycle.depthOfCut = call.params.get("5132");
  cycle.retract = call.params.get("5133");
  if (cycle.depthOfCut <= 0) {
    throw CycleAlarm(alarm::kCuttingAmount, call.block().line,
                     "depth of cut Δd is 0: program it in the first " + cycle.code + " block or set parameter 5132");
  }
  cycle.semiFinish = !call.params.bit("RF1");
  cycle.directReturn = call.params.bit("DTP");
}

std::vector<Move> movesInPlane(std::vector<Move> moves, bool transposeFrame) {
  if (!transposeFrame) return moves;
  for (Move& m : moves) {
    m.to = transposed(m.to);
    if (m.center) m.center = transposed(*m.center);
    m.shape = reversedKind(m.shape);
  }
  return moves;
}

}  // namespace cyclecert
