#include "reference/gcode/address_ranges.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "reference/model/alarms.h"

namespace cyclecert {

AddressRange rangeOf(CycleAddress role, bool inch) {
  // Seed 001's table, ISB column: metric (mm) and inch.
  switch (role) {
    case CycleAddress::DepthOfCut: return inch ? AddressRange{0.0001, 99999.9999} : AddressRange{0.001, 999999.999};
    case CycleAddress::Retract: return inch ? AddressRange{0, 99999.9999} : AddressRange{0, 999999.999};
    case CycleAddress::Allowance:
      return inch ? AddressRange{-99999.9999, 99999.9999} : AddressRange{-999999.999, 999999.999};
    case CycleAddress::SequenceNumber: return {0, 99999};
  }
  return {0, 0};
}

void checkCycleAddress(const Word& w, CycleAddress role, bool inch) {
  const AddressRange r = rangeOf(role, inch);
  const bool integral = role != CycleAddress::SequenceNumber || w.value == std::floor(w.value);
  if (w.value >= r.min && w.value <= r.max && integral) return;
  std::ostringstream range;
  range << std::setprecision(12);
  range << w.text << " at column " << w.column << " is outside " << r.min << "…" << r.max;
  if (role == CycleAddress::SequenceNumber) range << " (an integer sequence number)";
  if (role == CycleAddress::DepthOfCut && w.value < r.min) {
    CycleAlarm a(alarm::kCuttingAmount, w.line, range.str() + ": the depth of cut must be positive");
    a.setWhen("cycle block");
    throw a;
  }
  CycleAlarm a(alarm::kOutOfRange, w.line, range.str());
  a.setWhen("cycle block");
  throw a;
}

// HNC.G71.FMT: the block's addresses are G, U, R, P, Q, X, Z and F, S, T (and M); any other has no
// meaning in it (PS0009). W, D, I and K are those of the FANUC and Haas one-block formats.
void refuseAddressesOutsideHuazhongG71(const Block& b) {
  static constexpr std::string_view kFormat = "GURPQXZFSTM";
  for (const Word& w : b.words) {
    if (kFormat.find(w.letter) != std::string_view::npos) continue;
    std::string why = w.text + " at column " + std::to_string(w.column) +
                      ": the Huazhong G71 is G71 U(Δd) R(r) P(ns) Q(nf) X(Δx) Z(Δz) F S T, without " + w.letter;
    if (std::string_view("WDIK").find(w.letter) != std::string_view::npos) {
      why += " (G71 P Q U W D is the Haas one-block format, --profile haas, or FANUC's Series 10/11 format, "
             "--profile fanuc-0i-f --param FCV=1)";
    }
    throw cycleBlockAlarm(alarm::kImproperAddress, b.line, why);
  }
}

}  // namespace cyclecert
