#include "harness/reference_plan.h"

#include <regex>

#include "reference/gcode/parser.h"
#include "reference/model/profile.h"

namespace cyclecert {

UnknownProfile::UnknownProfile(const std::string& name)
    : std::invalid_argument("unknown profile '" + name + "' (see `cyclecert profiles`)") {}

std::string profileFromHeader(const std::string& text) {
  static const std::regex header(R"(\(\s*profile\s*:\s*([A-Za-z0-9._-]+)\s*\))", std::regex::icase);
  std::smatch m;
  return std::regex_search(text, m, header) ? m[1].str() : std::string();
}

Toolpath planWithReference(const PlanRequest& request) {
  std::string profileName = request.profile;
  if (profileName.empty()) profileName = profileFromHeader(request.programText);
  if (profileName.empty()) profileName = "fanuc-0i-f";
  const Profile* profile = findProfile(profileName);
  if (!profile) throw UnknownProfile(profileName);
  MachineParams params = profile->defaults;
  for (const auto& [name, value] : request.params) params.set(name, value);
  const Program program = parseProgram(request.programText, request.file);
  return planProgram(program, *profile, params, request.options);
}

Toolpath planSpecCase(const SpecCase& c) {
  RunOptions options;
  options.mdi = c.mdi;
  if (c.tool) options.tool = *c.tool;
  return planWithReference({c.program, c.file + "#/program", c.profile, c.params, options});
}

PlotInput plotInputFor(const Toolpath& path, const std::string& title) {
  PlotInput in;
  in.title = title;
  in.path = path;
  for (const CycleRecord& c : path.cycles) {
    for (const Segment& s : c.shape) {
      in.finish.segments.push_back(s);
      in.rough.segments.push_back(s.shifted(c.allowance));
    }
  }
  return in;
}

}  // namespace cyclecert
