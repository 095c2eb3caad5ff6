#include "reference/model/alarms.h"

#include <map>

namespace cyclecert {

std::string alarmTitle(std::string_view code) {
  static const std::map<std::string_view, std::string_view> titles = {
      {alarm::kOutOfRange, "TOO MANY DIGITS (value outside the address's range)"},
      {alarm::kNegativeSign, "ILLEGAL USE OF NEGATIVE SIGN"},
      {alarm::kIllegalDecimalPoint, "ILLEGAL USE OF DECIMAL POINT"},
      {alarm::kImproperAddress, "IMPROPER NC-ADDRESS"},
      {alarm::kImproperGCode, "IMPROPER G-CODE"},
      {alarm::kFeedZero, "FEED ZERO (COMMAND)"},
      {alarm::kInterference, "INTERFERENCE IN TOOL NOSE RADIUS COMPENSATION"},
      {alarm::kArcInCompStartOrCancel, "NO CIRC ALLOWED IN ST-UP/EXT BLK"},
      {alarm::kPlaneChangeInComp, "CAN NOT CHANGE PLANE IN G41/G42"},
      {alarm::kRadiusTolerance, "OVER TOLERANCE OF RADIUS"},
      {alarm::kIllegalRadius, "ILLEGAL RADIUS COMMAND"},
      {alarm::kPQMissing, "P OR Q COMMAND IS NOT IN THE MULTIPLE REPETITIVE CYCLES BLOCK"},
      {alarm::kCuttingAmount, "THE CUTTING AMOUNT IS ILLEGAL IN THE ROUGH CUTTING CYCLE"},
      {alarm::kSequenceNotFound, "THE BLOCK OF A SEQUENCE NUMBER SPECIFIED BY P OR Q IS NOT FOUND"},
      {alarm::kNotMonotonicFirst, "FINISHING SHAPE IS NOT A MONOTONOUS CHANGE (FIRST AXIS)"},
      {alarm::kHeadNotG00G01, "G00/G01 IS NOT IN THE FIRST BLOCK OF SHAPE PROGRAM"},
      {alarm::kOverStartPoint, "FINISHING SHAPE WHICH OVER OF STARTING POINT"},
      {alarm::kUnavailableInShape, "UNAVAILABLE COMMAND IS IN SHAPE PROGRAM"},
      {alarm::kTnrcNotCancelled, "TOOL NOSE RADIUS COMPENSATION IS NOT CANCELLED"},
      {alarm::kNotInMdi, "MULTIPLE REPETITIVE CYCLE IS NOT ALLOWED IN MDI MODE"},
      {alarm::kNotMonotonicSecond, "FINISHING SHAPE IS NOT A MONOTONOUS CHANGE (SECOND AXIS)"},
  };
  const auto it = titles.find(code);
  return it == titles.end() ? std::string("ALARM") : std::string(it->second);
}

CycleAlarm::CycleAlarm(std::string_view code, int line, std::string detail) {
  alarm_.code = std::string(code);
  alarm_.line = line;
  alarm_.message = alarmTitle(code) + ": " + detail;
}

NotSupported::NotSupported(int line, const std::string& what)
    : std::runtime_error(line > 0 ? "line " + std::to_string(line) + ": " + what : what), line_(line) {}

bool isFanucAlarmCode(std::string_view code) {
  if (code.size() != 6 || code.substr(0, 2) != "PS") return false;
  for (char ch : code.substr(2)) if (ch < '0' || ch > '9') return false;
  return true;
}

std::optional<std::string> alarmMismatch(std::string_view expectedCode, std::optional<int> expectedLine,
                                         const Alarm& got) {
  const std::string expected(expectedCode);
  if (isFanucAlarmCode(got.code) && got.code != expected) {
    return "expected alarm " + expected + ", got " + got.code + " (" + got.message + ")";
  }
  // A foreign code without a line says only that it alarmed; with a line, the line is judged.
  const bool lineGiven = isFanucAlarmCode(got.code) || got.line > 0;
  if (expectedLine && lineGiven && *expectedLine != got.line) {
    return "expected alarm " + expected + " at line " + std::to_string(*expectedLine) + ", got " + got.code +
           " at line " + std::to_string(got.line) + (isFanucAlarmCode(got.code) ? "" : " (" + got.message + ")");
  }
  return std::nullopt;
}

}  // namespace cyclecert
