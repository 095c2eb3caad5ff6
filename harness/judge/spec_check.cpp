#include "harness/judge/spec_check.h"

#include <algorithm>

#include "harness/judge/toolpath_compare.h"
#include "reference/model/alarms.h"

namespace cyclecert {

std::optional<std::string> unmetExpectation(const SpecCase& c, const Toolpath& actual, bool judgeWarnings) {
  if (c.oraclesOnly) return std::nullopt;  // the oracles (and agrees_with) judge it: check_run.cpp
  if (c.expectedAlarm) {
    if (!actual.alarm) return "expected alarm " + c.expectedAlarm->code + ", but the cycle planned without alarm";
    if (auto why = alarmMismatch(c.expectedAlarm->code, c.expectedAlarm->line, *actual.alarm)) return why;
    // "when" is the reference's annotation: judged when the engine gives it.
    if (c.expectedAlarm->when && !actual.alarm->when.empty() && *c.expectedAlarm->when != actual.alarm->when) {
      return "expected alarm " + c.expectedAlarm->code + " raised " + *c.expectedAlarm->when + ", got it raised " +
             (actual.alarm->when.empty() ? std::string("(unspecified)") : actual.alarm->when);
    }
    return std::nullopt;
  }
  if (actual.alarm) {
    return "expected a toolpath, got alarm " + actual.alarm->code + " at line " + std::to_string(actual.alarm->line) +
           ": " + actual.alarm->message;
  }
  for (const std::string& w : judgeWarnings ? c.expectedWarnings : std::vector<std::string>{}) {
    const bool found = std::any_of(actual.warnings.begin(), actual.warnings.end(),
                                   [&](const Warning& x) { return x.message.find(w) != std::string::npos; });
    if (!found) return "expected a warning containing \"" + w + "\"";
  }
  return firstDivergence(*c.expectedMoves, actual.moves, c.tolerance);
}

}  // namespace cyclecert
