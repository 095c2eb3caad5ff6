#include "reference/siemens/siemens_cycle_parameters.h"

#include <cmath>

#include "reference/model/alarms.h"
#include "reference/model/program.h"
#include "reference/model/number_text.h"
#include "reference/siemens/siemens_roughing_contour.h"

namespace cyclecert {

namespace {

double rValue(const RParameters& r, int number) {
  const auto found = r.find(number);
  return found == r.end() ? 0.0 : found->second;
}

MachiningType machiningType(double value, const std::string& what, const std::string& cycle, int line,
                            MachiningTypeLookup typeOf) {
  requireMachiningTypeNumber(value, what, line);
  const auto type = typeOf(value);
  if (!type) throw NotSupported(line, cycle + " is not planned yet");
  return *type;
}

// CYCLE95's parameters in order, and how an empty one defaults.
constexpr const char* kCycle95Names[] = {"NPP", "MID", "FALZ", "FALX", "FAL", "FF1", "FF2", "FF3", "VARI", "DT", "DAM", "_VRT"};
constexpr std::size_t kCycle95Count = 12;
// SIEMENS.CYCLE95.DEFAULTS: _VRT empty or 0 retracts 1 mm (interpretation of the 840D cycles
// manual); every other empty number is 0.
constexpr double kDefaultRetract = 1.0;

}  // namespace

void requireMachiningTypeNumber(double value, const std::string& what, int line) {
  if (value >= 1 && value <= 12 && value == std::floor(value)) return;
  throw cycleBlockAlarm(siemens_alarm::kMachiningType, line,
                        what + " = " + shortDecimalText(value) + ": the machining type is a whole number 1…12");
}

Lcyc95Parameters lcyc95ParametersFrom(const RParameters& r, int line, MachiningTypeLookup typeOf) {
  Lcyc95Parameters p;
  p.type = machiningType(rValue(r, 105), "R105", "LCYC95", line, typeOf);
  p.allowance = rValue(r, 106);
  p.maxInfeed = rValue(r, 108);
  p.infeedAngle = rValue(r, 109);
  p.retract = rValue(r, 110);
  p.roughingFeed = rValue(r, 111);
  p.finishingFeed = rValue(r, 112);
  return p;
}

const CycleArgument& cycle95ContourArgument(const CycleCallText& call, const std::string& file) {
  const CycleArgument* npp = call.arguments.empty() ? nullptr : &call.arguments.front();
  if (!npp || !npp->text || npp->text->empty()) {
    const int column = npp ? npp->column : call.column;
    throw ParseError({file, call.line, column}, "the contour subprogram's name in double quotes as NPP (CYCLE95(\"L18\", …))",
                     npp && npp->number ? "a number" : "nothing");
  }
  return *npp;
}

Cycle95Parameters cycle95ParametersFrom(const CycleCallText& call, const std::string& file, MachiningTypeLookup typeOf) {
  if (call.arguments.size() > kCycle95Count) {
    const CycleArgument& extra = call.arguments[kCycle95Count];
    throw ParseError({file, extra.line, extra.column},
                     "at most 12 arguments to CYCLE95(NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT)",
                     "argument 13");
  }
  const auto number = [&](std::size_t i) {
    if (i >= call.arguments.size() || call.arguments[i].empty()) return 0.0;
    const CycleArgument& a = call.arguments[i];
    if (!a.number) throw ParseError({file, a.line, a.column}, std::string("a number for ") + kCycle95Names[i], "\"" + *a.text + "\"");
    return *a.number;
  };
  Cycle95Parameters p;
  p.contourName = *cycle95ContourArgument(call, file).text;
  p.infeed = number(1);
  p.allowanceZ = number(2);
  p.allowanceX = number(3);
  p.allowance = number(4);
  p.roughingFeed = number(5);
  p.undercutFeed = number(6);
  p.finishingFeed = number(7);
  const double vari = number(8);
  p.dwell = number(9);
  p.interruptLength = number(10);
  p.retract = number(11) == 0 ? kDefaultRetract : number(11);
  p.type = machiningType(vari, "VARI", "CYCLE95", call.line, typeOf);
  return p;
}

}  // namespace cyclecert
