#pragma once
// Writing a G code in a G code system: the reverse of reference/interpreter/g_codes.h's findGCode,
// from the same table, so that a program written in system B or C (the gsys-b/gsys-c relations,
// the fuzzer's gsys formats) names each function as the reader will look it up — no second list.
#include <optional>
#include <string>

#include "reference/interpreter/g_code_system.h"

namespace cyclecert {

// The number ×10 that `system` writes `function` with (a system A number ×10 as g_codes.h names
// functions: 710 stock removal in turning, kAbsoluteProgramming, …), or nothing when the system's
// list has no code for it.
std::optional<int> gCodeNumberIn(GCodeSystem system, int function);

// The code as a program of that system writes it: "G73" for 710 in system C, "G90" for
// kAbsoluteProgramming in B. Throws std::invalid_argument when the system has no code for it.
std::string gCodeWrittenIn(GCodeSystem system, int function);

}  // namespace cyclecert
