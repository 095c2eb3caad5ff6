#pragma once
// The values a stock-removal cycle call hands its planner (rules LCYC95.PARAMS, CYCLE95.PARAMS,
// SIEMENS.CYCLE95.DEFAULTS): LCYC95 reads R105…R112 when it is called; CYCLE95 takes its
// arguments, an empty or missing one taking the cycle's default.
#include <map>
#include <optional>
#include <string>

#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_program.h"

namespace cyclecert {

// The R parameters set so far (R0…R999); one never set reads 0 (interpretation: SIEMENS.RPARAM).
using RParameters = std::map<int, double>;

// How a machining type number (R105, VARI) becomes a MachiningType: machiningTypeOf, or a test's own.
using MachiningTypeLookup = std::optional<MachiningType> (*)(double);

// Throws CycleAlarm 61002 (when: "cycle block") unless `value` is a whole number 1…12; `what`
// names it ("R105", "VARI").
void requireMachiningTypeNumber(double value, const std::string& what, int line);

// LCYC95's values from the R parameters (the call at `line`). The type: `typeOf(R105)`; when that
// gives nothing for a valid number, throws NotSupported "LCYC95 is not planned yet".
Lcyc95Parameters lcyc95ParametersFrom(const RParameters& r, int line, MachiningTypeLookup typeOf = machiningTypeOf);

// NPP, CYCLE95's first argument: the contour subprogram's name. Throws ParseError when it is not
// a non-empty string.
const CycleArgument& cycle95ContourArgument(const CycleCallText& call, const std::string& file);

// CYCLE95's values from its arguments (NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM,
// _VRT). Throws ParseError at an argument of the wrong kind (a number for NPP, a string for the
// others), for more than 12, or for an empty NPP.
Cycle95Parameters cycle95ParametersFrom(const CycleCallText& call, const std::string& file,
                                        MachiningTypeLookup typeOf = machiningTypeOf);

}  // namespace cyclecert
