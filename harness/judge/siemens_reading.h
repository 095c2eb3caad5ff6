#pragma once
// What a SINUMERIK program asks, for the oracles (profiles sinumerik-802s / -802d): the Siemens front
// end (reference/siemens: the program, R parameters, the contour subprograms) runs with recording
// planners, which plan nothing — each cycle call and its parameters become a SiemensCycleSpec
// (oracles/siemens/siemens_cycle_spec.h), and the program's own moves before and after the cycles
// become ProgramSpec's movesBeforeCycles / movesAfterCycles (PROG.WHOLE). The alarm the controller
// must raise is read from the program alone: 61002 where R105 / VARI is read
// (requireMachiningTypeNumber), 61610 and 10931 by the cycles' documented checks (requireInfeedDepth,
// checkContour) and the oracles' own profile (an allowance or nose radius the contour cannot take).
#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"

namespace cyclecert {

// Requires profile.dialect == Dialect::Siemens. Throws ParseError and NotSupported as the front end
// does (the program cannot be read).
ProgramSpec readSiemensProgramSpec(const PlanRequest& request, const Profile& profile);

}  // namespace cyclecert
