#include "reference/cycles/series10_format.h"

#include <cmath>
#include <string>

#include "reference/cycles/roughing_cycle.h"
#include "reference/gcode/address_ranges.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

const OneBlockDialect kSeries10{"Series 10/11", OneBlockDialect::DepthUnits::LeastInputIncrements, false, false, false};
const OneBlockDialect kHaas{"Haas", OneBlockDialect::DepthUnits::ProgramUnits, true, true, true};

std::string wordAt(const Word& w) { return w.text + " at column " + std::to_string(w.column); }

// G71.FS10.FCV0: with FCV = 0 (Series 0 format) D has no meaning in the block with P and Q.
void refuseSeries10Depth(const Word& d, const std::string& code) {
  throw cycleBlockAlarm(alarm::kImproperAddress, d.line,
                        wordAt(d) + ": D in a " + code + " P/Q block is the Series 10/11 program format; " +
                            "set parameter 0001#1 (FCV) = 1 to read it (--param FCV=1), or give Δd in a first " +
                            code + " block (a Haas program: --profile haas)");
}

void requirePositiveDepth(const Word& d) {
  if (d.value <= 0) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, d.line, wordAt(d) + ": the depth of cut must be positive");
  }
}

// G71.FS10.D: D without a decimal point, in least input increments (IS-B: 0.001 mm, 0.0001 inch).
double depthFromLeastIncrements(const Word& d, const ModalState& modal) {
  if (d.hasDecimalPoint) {
    throw cycleBlockAlarm(alarm::kIllegalDecimalPoint, d.line,
                          wordAt(d) + ": D of the Series 10/11 format is written without a decimal point, in least "
                                      "input increments (D1000 = 1.000 mm); a Haas program writes D1.0 (--profile haas)");
  }
  requirePositiveDepth(d);
  if (d.value > 999'999'999) throw cycleBlockAlarm(alarm::kOutOfRange, d.line, wordAt(d) + " has more than 9 digits");
  const double leastIncrement = modal.inch ? 0.0001 : 0.001;
  return d.value * leastIncrement * modal.unitScale();
}

// HAAS.G71.D: "D - depth of cut for each pass of stock removal, positive radius", in the program's
// units like its other dimension words (D.1 in a G20 program is 0.1 inch); the range of a first
// block's Δd (G72.RANGE).
double depthInProgramUnits(const Word& d, const ModalState& modal) {
  requirePositiveDepth(d);
  checkCycleAddress(d, CycleAddress::DepthOfCut, modal.inch);
  return d.value * modal.unitScale();
}

double depthOfCutWord(const OneBlockDialect& dialect, const Word& d, const ModalState& modal) {
  return dialect.depthUnits == OneBlockDialect::DepthUnits::LeastInputIncrements ? depthFromLeastIncrements(d, modal)
                                                                                : depthInProgramUnits(d, modal);
}

// G71.FS10.IK: I and K are read; cyclecert does not model them (the manual's text for them is not
// among our sources), so a non-zero I or K is not supported rather than silently ignored.
void checkSeries10IK(const Block& b, const std::string& code) {
  for (char letter : {'I', 'K'}) {
    const Word* w = b.find(letter);
    if (w && w->value != 0) {
      throw NotSupported(w->line, wordAt(*w) + ": " + std::string(1, letter) + " of the Series 10/11 " + code +
                                      " format is not modelled by cyclecert (only I0/K0 or none)");
    }
  }
}

// HAAS.G71.IK: I = "X-axis size and direction of the rough pass allowance, radius", K = the Z-axis
// one: the rough passes leave them on top of the finish allowance U/W.
Point roughAllowance(const Block& b, const ModalState& modal) {
  Point allowance;
  if (const Word* i = b.find('I')) {
    checkCycleAddress(*i, CycleAddress::Allowance, modal.inch);
    allowance.x = i->value * modal.unitScale();  // a radius value: not halved
  }
  if (const Word* k = b.find('K')) {
    checkCycleAddress(*k, CycleAddress::Allowance, modal.inch);
    allowance.z = k->value * modal.unitScale();
  }
  return allowance;
}

// HAAS.G71.R1: "R1 (with no decimal)" on the cycle block selects type II roughing; any other R
// there has no documented meaning.
bool requestsTypeII(const Block& b) {
  const Word* r = b.find('R');
  if (!r) return false;
  if (r->value == 1 && !r->hasDecimalPoint) return true;
  throw cycleBlockAlarm(alarm::kImproperAddress, r->line,
                        wordAt(*r) + ": R in a Haas G71/G72 P/Q block can only be R1 (no decimal point), which "
                                     "selects type II roughing; the retract is Setting 73 (parameter 5133)");
}

// HAAS.G71.PLANE: the Haas pages give G71/G72 in the Z-X plane only.
void requireZxPlane(const OneBlockDialect& dialect, const CycleCall& call, const std::string& code) {
  if (!dialect.zxPlaneOnly || call.modal.plane == 18) return;
  throw NotSupported(call.block().line, "the " + dialect.name + " " + code + " needs the Z-X plane (G18); G" +
                                            std::to_string(call.modal.plane) + " is in force");
}

// G73.FS10.FMT: with FCV = 0 (Series 0 format) I, K and D have no meaning in the G73 block with P and Q.
void refuseSeries10G73Words(const Block& b) {
  for (char letter : {'I', 'K', 'D'}) {
    const Word* w = b.find(letter);
    if (!w) continue;
    throw cycleBlockAlarm(alarm::kImproperAddress, w->line,
                          wordAt(*w) + ": " + std::string(1, letter) + " in a G73 P/Q block is the Series 10/11 " +
                              "program format (I, K = relief, D = divisions); set parameter 0001#1 (FCV) = 1 to read " +
                              "it (--param FCV=1), or give them as U, W, R in a first G73 block");
  }
}

// G73.FS10.FMT: D = the number of divisions, a whole number written without a decimal point.
double divisionsFromD(const Word& d) {
  if (d.hasDecimalPoint) {
    throw cycleBlockAlarm(alarm::kIllegalDecimalPoint, d.line,
                          wordAt(d) + ": D of the Series 10/11 G73 is the number of divisions, written without a "
                                      "decimal point (D4)");
  }
  if (d.value < 1) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, d.line, wordAt(d) + ": the number of divisions d of G73 must be at least 1");
  }
  if (d.value > 99'999'999) throw cycleBlockAlarm(alarm::kOutOfRange, d.line, wordAt(d) + " has more than 8 digits");
  return d.value;
}

}  // namespace

void readG73OneBlockWords(const CycleCall& call) {
  const Block& b = call.block();
  if (!call.params.bit("FCV")) {
    refuseSeries10G73Words(b);
    return;
  }
  const bool inch = call.modal.inch;
  if (const Word* i = b.find('I')) {
    checkCycleAddress(*i, CycleAddress::Allowance, inch);
    call.params.set("5135", i->value * call.modal.unitScale());  // Δi: a radius value, not halved
  }
  if (const Word* k = b.find('K')) {
    checkCycleAddress(*k, CycleAddress::Allowance, inch);
    call.params.set("5136", k->value * call.modal.unitScale());
  }
  if (const Word* d = b.find('D')) call.params.set("5137", divisionsFromD(*d));
}

const OneBlockDialect* oneBlockDialect(const CycleCall& call) {
  if (call.profile.roughingFormat == RoughingBlockFormat::HaasOneBlock) return &kHaas;
  return call.params.bit("FCV") ? &kSeries10 : nullptr;
}

void readOneBlockWords(const CycleCall& call, const std::string& code, SecondBlock& sb) {
  const Block& b = call.block();
  const Word* d = b.find('D');
  const OneBlockDialect* dialect = oneBlockDialect(call);
  if (!dialect) {
    if (d) refuseSeries10Depth(*d, code);
    return;
  }
  requireZxPlane(*dialect, call, code);
  if (dialect->readsRoughAllowance) {
    sb.roughAllowance = roughAllowance(b, call.modal);
  } else {
    checkSeries10IK(b, code);
  }
  if (dialect->r1SelectsTypeII) sb.typeIIRequested = requestsTypeII(b);
  if (d) call.params.set("5132", depthOfCutWord(*dialect, *d, call.modal));
}

}  // namespace cyclecert
