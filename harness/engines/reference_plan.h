#pragma once
// Planning a program or a spec case with the reference engine, from text.
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness/spec/spec_case.h"
#include "reference/engine/program_runner.h"
#include "reference/gcode/parser.h"
#include "reference/model/profile.h"
#include "reference/model/toolpath.h"
#include "reference/siemens/siemens_runner.h"
#include "reference/siemens/siemens_subprograms.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

struct PlanRequest {
  std::string programText;
  std::string file;      // for error messages
  std::string profile;   // empty: from a "(profile: NAME)" header comment, else fanuc-0i-f
  std::vector<std::pair<std::string, double>> params;  // by number or mnemonic, applied in order
  RunOptions options;    // MDI mode, tool offset
  // SINUMERIK profiles (SIEMENS.SUB): contour subprograms given with the program (a spec case's
  // "subprograms"), and the directory searched for NAME.spf / NAME.SPF (empty: none).
  std::vector<GivenSubprogram> subprograms = {};
  std::string subprogramDirectory = {};
};

// A request read: its profile, the machine parameters (the profile's defaults with the request's
// applied), and the program parsed. The engine and the judge read the same program in turn, so
// the programs parsed lately (the last 128, per thread) are kept and shared rather than parsed
// again.
struct ReadRequest {
  const Profile* profile = nullptr;
  MachineParams params;
  std::shared_ptr<const Program> program;
};
// The request's profile: its own, else a "(profile: NAME)" header, else the default. Throws
// UnknownProfile.
const Profile& requestedProfile(const PlanRequest& request);
// A FANUC-dialect request read. Throws ParseError, UnknownProfile and UnknownParam /
// std::invalid_argument; NotSupported for a SINUMERIK profile (harness/judge/siemens_reading.h reads those).
ReadRequest readRequest(const PlanRequest& request);
ReadRequest readRequest(const PlanRequest& request, const Profile& profile);  // its profile found already

// A SINUMERIK request as the Siemens runner's input (reference/siemens/siemens_runner.h). Its
// parsers keep the programs and subprograms parsed lately on this thread, as readRequest keeps the
// FANUC ones: the reference engine and the oracles' reading (harness/judge/siemens_reading.h) read the
// same texts, which are then parsed once.
SiemensRunInput siemensRunInputFor(const PlanRequest& request);

// Throws ParseError (malformed program), UnknownProfile, UnknownParam / std::invalid_argument
// (bad parameter) and NotSupported; a controller alarm is part of the returned toolpath.
Toolpath planWithReference(const PlanRequest& request);
Toolpath planSpecCase(const SpecCase& c);
// A spec case as a plan request: its program, profile, parameters, mode, tool and subprograms.
PlanRequest planRequestFor(const SpecCase& c);

// The profile a program names in a "(profile: NAME)" comment, or "".
std::string profileFromHeader(const std::string& programText);

class UnknownProfile : public std::invalid_argument {
 public:
  explicit UnknownProfile(const std::string& name);
};

// Plot input for a planned toolpath: the cycles' finish shapes and rough profiles.
PlotInput plotInputFor(const Toolpath& path, const std::string& title);

}  // namespace cyclecert
