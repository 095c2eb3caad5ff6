#include "reference/cycles/series10_format.h"

#include <cmath>
#include <string>

#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

std::string wordAt(const Word& w) { return w.text + " at column " + std::to_string(w.column); }

// G71.FS10.FCV0: with FCV = 0 (Series 0 format) D has no meaning in the block with P and Q.
void refuseSeries10Depth(const Word& d, const std::string& code) {
  throw cycleBlockAlarm(alarm::kImproperAddress, d.line,
                        wordAt(d) + ": D in a " + code + " P/Q block is the Series 10/11 program format; " +
                            "set parameter 0001#1 (FCV) = 1 to read it (--param FCV=1), or give Δd in a first " +
                            code + " block");
}

// G71.FS10.D: D without a decimal point, in least input increments (IS-B: 0.001 mm, 0.0001 inch).
double depthFromLeastIncrements(const Word& d, const ModalState& modal) {
  if (d.hasDecimalPoint) {
    throw cycleBlockAlarm(alarm::kIllegalDecimalPoint, d.line,
                          wordAt(d) + ": D of the Series 10/11 format is written without a decimal point, in least "
                                      "input increments (D1000 = 1.000 mm)");
  }
  if (d.value <= 0) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, d.line, wordAt(d) + ": the depth of cut must be positive");
  }
  if (d.value > 999'999'999) throw cycleBlockAlarm(alarm::kOutOfRange, d.line, wordAt(d) + " has more than 9 digits");
  const double leastIncrement = modal.inch ? 0.0001 : 0.001;
  return d.value * leastIncrement * modal.unitScale();
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

}  // namespace

void readSeries10Words(const CycleCall& call, const std::string& code) {
  const Block& b = call.block();
  const Word* d = b.find('D');
  if (!call.params.bit("FCV")) {
    if (d) refuseSeries10Depth(*d, code);
    return;
  }
  checkSeries10IK(b, code);
  if (d) call.params.set("5132", depthFromLeastIncrements(*d, call.modal));
}

}  // namespace cyclecert
