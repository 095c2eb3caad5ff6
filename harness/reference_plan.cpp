#include "harness/reference_plan.h"

#include <deque>
#include <regex>
#include <unordered_map>

#include "reference/gcode/parser.h"
#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

UnknownProfile::UnknownProfile(const std::string& name)
    : std::invalid_argument("unknown profile '" + name + "' (see `cyclecert profiles`)") {}

std::string profileFromHeader(const std::string& text) {
  static const std::regex header(R"(\(\s*profile\s*:\s*([A-Za-z0-9._-]+)\s*\))", std::regex::icase);
  std::smatch m;
  return std::regex_search(text, m, header) ? m[1].str() : std::string();
}

namespace {

// The programs parsed lately on this thread, by file and text: an engine and the judge read the
// same program, and fuzz plans a whole batch of cases (kFuzzBatch, 64) before it judges them.
std::shared_ptr<const Program> parsedOnce(const std::string& text, const std::string& file) {
  constexpr std::size_t kKept = 128;
  thread_local std::unordered_map<std::string, std::shared_ptr<const Program>> parsed;
  thread_local std::deque<std::string> oldestFirst;
  std::string key = file + '\0' + text;
  if (const auto found = parsed.find(key); found != parsed.end()) return found->second;
  auto program = std::make_shared<const Program>(parseProgram(text, file));
  if (oldestFirst.size() == kKept) {
    parsed.erase(oldestFirst.front());
    oldestFirst.pop_front();
  }
  parsed.emplace(key, program);
  oldestFirst.push_back(std::move(key));
  return program;
}

}  // namespace

ReadRequest readRequest(const PlanRequest& request) {
  std::string profileName = request.profile;
  if (profileName.empty()) profileName = profileFromHeader(request.programText);
  profileName = profileNameOrDefault(profileName);
  ReadRequest read;
  read.profile = findProfile(profileName);
  if (!read.profile) throw UnknownProfile(profileName);
  read.params = read.profile->defaults;
  for (const auto& [name, value] : request.params) read.params.set(name, value);
  read.program = parsedOnce(request.programText, request.file);
  return read;
}

Toolpath planWithReference(const PlanRequest& request) {
  const ReadRequest read = readRequest(request);
  return planProgram(*read.program, *read.profile, read.params, request.options);
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
