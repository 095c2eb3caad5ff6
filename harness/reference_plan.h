#pragma once
// Planning a program or a spec case with the reference engine, from text.
#include <string>
#include <utility>
#include <vector>

#include "harness/spec_case.h"
#include "reference/engine/program_runner.h"
#include "reference/model/toolpath.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

struct PlanRequest {
  std::string programText;
  std::string file;      // for error messages
  std::string profile;   // empty: from a "(profile: NAME)" header comment, else fanuc-0i-f
  std::vector<std::pair<std::string, double>> params;  // by number or mnemonic, applied in order
  RunOptions options;    // MDI mode, tool offset
};

// Throws ParseError (malformed program), UnknownProfile, UnknownParam / std::invalid_argument
// (bad parameter) and NotSupported; a controller alarm is part of the returned toolpath.
Toolpath planWithReference(const PlanRequest& request);
Toolpath planSpecCase(const SpecCase& c);

// The profile a program names in a "(profile: NAME)" comment, or "".
std::string profileFromHeader(const std::string& programText);

class UnknownProfile : public std::invalid_argument {
 public:
  explicit UnknownProfile(const std::string& name);
};

// Plot input for a planned toolpath: the cycles' finish shapes and rough profiles.
PlotInput plotInputFor(const Toolpath& path, const std::string& title);

}  // namespace cyclecert
