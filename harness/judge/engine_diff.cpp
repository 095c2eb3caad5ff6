#include "harness/judge/engine_diff.h"

#include "harness/judge/toolpath_compare.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

std::string outcome(const EngineResult& r) {
  if (r.kind == EngineResult::Alarmed) {
    return "alarm " + r.path.alarm->code + " at line " + std::to_string(r.path.alarm->line) + " (" +
           r.path.alarm->message + ")";
  }
  return "a toolpath of " + std::to_string(r.path.moves.size()) + " moves";
}

std::optional<std::string> alarmsDisagree(const Alarm& a, const std::string& aName, const Alarm& b,
                                          const std::string& bName) {
  // A FANUC code on one side is the expectation the other is judged against.
  const bool aFanuc = isFanucAlarmCode(a.code);
  const Alarm& expected = aFanuc ? a : b;
  const Alarm& got = aFanuc ? b : a;
  const bool lineKnown = isFanucAlarmCode(expected.code) || expected.line > 0;
  if (auto why = alarmMismatch(expected.code, lineKnown ? std::optional<int>(expected.line) : std::nullopt, got)) {
    return aName + " raised " + a.code + " at line " + std::to_string(a.line) + ", " + bName + " raised " + b.code +
           " at line " + std::to_string(b.line) + " (" + b.message + ")";
  }
  return std::nullopt;
}

}  // namespace

std::optional<EngineDivergence> compareEngineResults(const EngineResult& a, const std::string& aName,
                                                     const EngineResult& b, const std::string& bName,
                                                     double tolerance) {
  if (!hasOutcome(a) || !hasOutcome(b)) return std::nullopt;
  if (a.kind != b.kind) return EngineDivergence{aName + " gave " + outcome(a) + ", " + bName + " gave " + outcome(b), {}};
  if (a.kind == EngineResult::Alarmed) {
    if (auto why = alarmsDisagree(*a.path.alarm, aName, *b.path.alarm, bName)) return EngineDivergence{*why, {}};
    return std::nullopt;
  }
  if (auto d = firstMoveDivergence(a.path.moves, b.path.moves, tolerance, aName, bName)) {
    return EngineDivergence{d->text, d->move};
  }
  return std::nullopt;
}

}  // namespace cyclecert
