#pragma once
// A small G71 cycle for tests about the blocks around it, and the reference's plan of a program
// given as text (fanuc-0i-f), or why it is not planned. With the tool positioned at (X40, Z2)
// first the cycle starts at A = (x 20, z 2); with U+ allowance a start below x 20 is PS0322.
#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace cyclecert {

inline const char* const kSmallG71Cycle =
    "G71 U2 R0.5;\n"
    "G71 P10 Q20 U0.4 W0.1 F0.2;\n"
    "N10 G00 X20;\n"
    "G01 Z-10;\n"
    "N20 X40 Z-20;\n";

inline Toolpath planFanucProgram(const std::string& program, const std::string& file = "program.nc") {
  return planWithReference({program, file, "fanuc-0i-f", {}, {}});
}

// Why the reference does not plan the program (its NotSupported message), or "(no NotSupported)".
inline std::string notSupportedMessage(const std::string& program, const std::string& file = "program.nc") {
  try {
    planFanucProgram(program, file);
  } catch (const NotSupported& e) {
    return e.what();
  }
  return "(no NotSupported)";
}

}  // namespace cyclecert
