#pragma once
// Controller alarms the reference raises, with FANUC 0i-F's codes. The seeds name PS0064, PS0065,
// PS0325 and PS0329; the other codes come from FANUC 0i-F's alarm list (see specs/rules.json notes).
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "reference/model/toolpath.h"

namespace cyclecert {

namespace alarm {
inline constexpr std::string_view kOutOfRange = "PS0003";        // too many digits: outside the address's range
inline constexpr std::string_view kNegativeSign = "PS0006";      // a minus sign after an address that takes none (F, S, T)
inline constexpr std::string_view kIllegalDecimalPoint = "PS0007";  // decimal point in an address that takes none
inline constexpr std::string_view kImproperAddress = "PS0009";   // an address the block gives no meaning
inline constexpr std::string_view kImproperGCode = "PS0010";     // G code the controller does not have
inline constexpr std::string_view kInterference = "PS0041";      // nose radius does not fit the shape (TNRC)
inline constexpr std::string_view kFeedZero = "PS0011";          // cutting feed with F = 0
inline constexpr std::string_view kArcInCompStartOrCancel = "PS0034";  // G41/G42 start-up or G40 cancel in G02/G03
inline constexpr std::string_view kPlaneChangeInComp = "PS0037";  // G17/G18/G19 while G41/G42 is in force
inline constexpr std::string_view kRadiusTolerance = "PS0020";   // I/K arc end not on the circle
inline constexpr std::string_view kIllegalRadius = "PS0023";     // R arc impossible / arc without R, I, K
inline constexpr std::string_view kPQMissing = "PS0061";         // P or Q missing in the cycle block
inline constexpr std::string_view kCuttingAmount = "PS0062";     // Δd not positive
inline constexpr std::string_view kSequenceNotFound = "PS0063";  // block named by P (or Q) not found
inline constexpr std::string_view kNotMonotonicFirst = "PS0064";   // 1st plane axis (Z)
inline constexpr std::string_view kHeadNotG00G01 = "PS0065";
inline constexpr std::string_view kOverStartPoint = "PS0322";
inline constexpr std::string_view kUnavailableInShape = "PS0325";
inline constexpr std::string_view kNotMonotonicSecond = "PS0329";  // 2nd plane axis (X)
inline constexpr std::string_view kTnrcNotCancelled = "PS0538";    // G70 shape end block without G40 (NT2)
inline constexpr std::string_view kNotInMdi = "PS0067";            // multiple repetitive cycle in MDI mode
}  // namespace alarm

// The controller's title for an alarm code ("FINISHING SHAPE IS NOT MONOTONOUS (FIRST AXIS)").
std::string alarmTitle(std::string_view code);

// Judging an engine's alarm against the one the rules call for. FANUC's codes (PS followed by four
// digits) are compared exactly. An engine with codes of its own (LinuxCNC's "LINUXCNC", a vendor's
// numbering) cannot be mapped onto FANUC's reliably — one message may stand for several FANUC
// alarms — so it is judged on what it can be judged on: that it raised an alarm, and where (the
// program line) when it names one. Returns what does not match, or nothing.
bool isFanucAlarmCode(std::string_view code);
std::optional<std::string> alarmMismatch(std::string_view expectedCode, std::optional<int> expectedLine,
                                         const Alarm& got);

// Thrown by the reference where the controller would stop with an alarm.
class CycleAlarm : public std::exception {
 public:
  CycleAlarm(std::string_view code, int line, std::string detail);
  const Alarm& alarm() const { return alarm_; }
  void setWhen(std::string when) { alarm_.when = std::move(when); }
  const char* what() const noexcept override { return alarm_.message.c_str(); }

 private:
  Alarm alarm_;
};

// An alarm the controller raises on reading a cycle's own block (when: "cycle block").
inline CycleAlarm cycleBlockAlarm(std::string_view code, int line, std::string detail) {
  CycleAlarm a(code, line, std::move(detail));
  a.setWhen("cycle block");
  return a;
}

// Thrown where a program needs a capability the reference does not have yet (e.g. type II). Line 0:
// the program as a whole (its message names no line).
class NotSupported : public std::runtime_error {
 public:
  NotSupported(int line, const std::string& what);
  int line() const { return line_; }

 private:
  int line_;
};

}  // namespace cyclecert
