#include "reference/cycles/huazhong_format.h"

#include <string>

#include "reference/gcode/address_ranges.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

void requireZxPlane(const CycleCall& call) {
  if (call.modal.plane == 18) return;
  throw NotSupported(call.block().line, "the Huazhong G71 of seed 003 is given in the ZX plane (G18) only; G" +
                                            std::to_string(call.modal.plane) + " is in force");
}

// HNC.G71.FMT: Δd (U) and r (R), radius values without sign, kept in 5132/5133.
void readDepthAndRetract(const CycleCall& call) {
  const Block& b = call.block();
  if (const Word* dd = b.find('U')) {
    checkCycleAddress(*dd, CycleAddress::DepthOfCut, call.modal.inch);
    call.params.set("5132", dd->value * call.modal.unitScale());
  }
  if (const Word* r = b.find('R')) {
    checkCycleAddress(*r, CycleAddress::Retract, call.modal.inch);
    call.params.set("5133", r->value * call.modal.unitScale());
  }
}

// HNC.G71.FMT, figure 1-23: X = Δx on the diameter (+ outer, − inner), Z = Δz.
void readAllowances(const CycleCall& call, SecondBlock& s) {
  const Block& b = call.block();
  if (const Word* dx = b.find('X')) {
    checkCycleAddress(*dx, CycleAddress::Allowance, call.modal.inch);
    s.allowanceSecond = physicalLength(dx->value, true, call.modal);
  }
  if (const Word* dz = b.find('Z')) {
    checkCycleAddress(*dz, CycleAddress::Allowance, call.modal.inch);
    s.allowanceFirst = physicalLength(dz->value, false, call.modal);
  }
}

}  // namespace

bool readsHuazhongG71(const CycleCall& call) {
  return call.profile.roughingFormat == RoughingBlockFormat::HuazhongOneBlock;
}

void refuseHuazhongG71WithoutPQ(const CycleCall& call) {
  throw cycleBlockAlarm(alarm::kPQMissing, call.block().line,
                        "the Huazhong G71 is one block G71 U R P Q X Z F: P (ns) and Q (nf) are required (HNC.G71.PQ)");
}

SecondBlock readHuazhongG71Block(const CycleCall& call) {
  requireZxPlane(call);
  const Block& b = call.block();
  SecondBlock s;
  s.p = b.find('P');
  s.q = b.find('Q');
  if (!s.p || !s.q) {
    throw cycleBlockAlarm(alarm::kPQMissing, b.line,
                          std::string("G71 block has ") + (s.p ? "P but no Q" : "Q but no P") +
                              " (both are required, HNC.G71.PQ)");
  }
  refuseAddressesOutsideHuazhongG71(b);
  checkCycleAddress(*s.p, CycleAddress::SequenceNumber, call.modal.inch);
  checkCycleAddress(*s.q, CycleAddress::SequenceNumber, call.modal.inch);
  readDepthAndRetract(call);
  readAllowances(call, s);
  // HNC.G71.FST: roughing uses the F of the G71 block (or the modal F before it).
  s.feed = call.modal.feed;
  if (s.feed <= 0) throw cycleBlockAlarm(alarm::kFeedZero, b.line, "no cutting feed F in the G71 block or before it");
  return s;
}

void refuseSubprogramsInHuazhongShape(const CycleCall& call, const SecondBlock& sb) {
  const std::size_t ns = findSequenceBlock(call, *sb.p, 'P');
  const std::size_t nf = findSequenceBlock(call, *sb.q, 'Q');
  for (std::size_t i = ns; i <= nf && i < call.program.blocks.size(); ++i) {
    const Block& b = call.program.blocks[i];
    for (const Word* m : b.all('M')) {
      if (m->value == 98) {
        throw NotSupported(b.line, m->text + ": seed 003 allows subprogram calls between ns and nf (HNC.G71.SUB); "
                                             "the reference does not follow them: write the contour inline");
      }
    }
  }
}

void checkHuazhongHead(const CycleCall& call, const ShapeProgram& shape) {
  if (!shape.headHasFirstAxis) return;
  throw NotSupported(shape.nsLine, "block ns of the Huazhong G71 moves Z as well: seed 003's format without pockets "
                                   "is planned as type I, whose first block moves X only (line " +
                                       std::to_string(call.block().line) + ")");
}

std::size_t huazhongResumeIndex(const CycleCall& call) { return call.blockIndex + 1; }

void refuseG72UnderHuazhong(const CycleCall& call) {
  if (!readsHuazhongG71(call)) return;
  throw NotSupported(call.block().line, "G72 of a Huazhong controller is not described in seed 003 (profile " +
                                            call.profile.name + "): only G71 is modelled");
}

}  // namespace cyclecert
