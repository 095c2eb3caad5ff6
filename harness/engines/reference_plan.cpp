#include "harness/engines/reference_plan.h"

#include <algorithm>
#include <deque>
#include <map>
#include <memory>
#include <regex>
#include <string_view>
#include <tuple>
#include <unordered_map>

#include "reference/gcode/parser.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/alarms.h"
#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_parser.h"
#include "reference/siemens/siemens_runner.h"
#include "reference/siemens/siemens_signature.h"

namespace cyclecert {

UnknownProfile::UnknownProfile(const std::string& name)
    : std::invalid_argument("unknown profile '" + name + "' (see `cyclecert profiles`)") {}

std::string profileFromHeader(const std::string& text) {
  static const std::regex header(R"(\(\s*profile\s*:\s*([A-Za-z0-9._-]+)\s*\))", std::regex::icase);
  std::smatch m;
  return std::regex_search(text, m, header) ? m[1].str() : std::string();
}

namespace {

// The texts parsed lately on this thread (the last 128 of each kind), by file and text: an engine
// and the judge read the same program, and fuzz plans a whole batch of cases (kFuzzBatch, 64)
// before it judges them. `parse(text, file)` parses one.
template <class Parsed, class Parse>
std::shared_ptr<const Parsed> parsedOnce(std::string_view text, const std::string& file, const Parse& parse) {
  constexpr std::size_t kKept = 128;
  thread_local std::unordered_map<std::string, std::shared_ptr<const Parsed>> parsed;
  thread_local std::deque<std::string> oldestFirst;
  std::string key = file + '\0' + std::string(text);
  if (const auto found = parsed.find(key); found != parsed.end()) return found->second;
  auto program = std::make_shared<const Parsed>(parse(text, file));
  if (oldestFirst.size() == kKept) {
    parsed.erase(oldestFirst.front());
    oldestFirst.pop_front();
  }
  parsed.emplace(key, program);
  oldestFirst.push_back(std::move(key));
  return program;
}

// The contours read lately on this thread (the last 128) from a kept parse of a subprogram
// (parsedOnce), by that parse, the name and the modal state read with: the reference engine and
// the oracles' reading of its program read the same contour from the same parse. Each entry keeps
// its parse alive, so that no other parse takes its address while the entry stands.
SiemensContour contourReadOnce(const std::string& name, const std::shared_ptr<const SiemensBlocks>& blocks,
                               SiemensModal modal) {
  constexpr std::size_t kKept = 128;
  using Key = std::tuple<const SiemensBlocks*, std::string, int, bool>;
  struct Read {
    std::shared_ptr<const SiemensBlocks> blocks;
    SiemensContour contour;
  };
  thread_local std::map<Key, Read> read;
  thread_local std::deque<Key> oldestFirst;
  Key key{blocks.get(), name, modal.motion, modal.diameterX};
  if (const auto found = read.find(key); found != read.end()) return found->second.contour;
  SiemensContour contour = readSiemensContour(name, *blocks, modal);
  if (oldestFirst.size() == kKept) {
    read.erase(oldestFirst.front());
    oldestFirst.pop_front();
  }
  read.emplace(key, Read{blocks, contour});
  oldestFirst.push_back(std::move(key));
  return contour;
}

}  // namespace

const Profile& requestedProfile(const PlanRequest& request) {
  std::string profileName = request.profile;
  if (profileName.empty()) profileName = profileFromHeader(request.programText);
  profileName = profileNameOrDefault(profileName);
  const Profile* profile = findProfile(profileName);
  if (!profile) throw UnknownProfile(profileName);
  return *profile;
}

namespace {

// The text's first `lines` lines (all of it when it has fewer).
std::string_view linesUpTo(std::string_view text, int lines) {
  std::size_t end = 0;
  for (int k = 0; k < lines; ++k) {
    const std::size_t next = text.find('\n', k == 0 ? 0 : end + 1);
    if (next == std::string_view::npos) return text;
    end = next;
  }
  return text.substr(0, end);
}

// SIEMENS.DIALECT: a SINUMERIK program read with a FANUC-dialect profile fails where the FANUC
// reader stops; the error then says which profiles read it.
std::shared_ptr<const Program> parsedInTheFanucDialect(const PlanRequest& request, const Profile& profile) {
  try {
    return parsedOnce<Program>(request.programText, request.file, parseProgram);
  } catch (const ParseError& e) {
    // A huge program refused by the block cap (PROG.CAP.BLOCKS) is not scanned whole (std::regex
    // took 13 s over 55 MB): as many lines as the cap allows blocks, or up to the error's line.
    const int scanned = std::max(e.loc().line, static_cast<int>(kMostBlocksPerProgram));
    const auto siemens = siemensSignature(linesUpTo(request.programText, scanned));
    if (!siemens) throw;
    throw ParseError(e.loc(), e.expected() + " (the " + profile.name + " profile reads the FANUC dialect; this is a SINUMERIK " +
                                  "program, " + *siemens + ": read it with --profile sinumerik-802s for LCYC95 or " +
                                  "sinumerik-802d for CYCLE95)",
                     e.found());
  }
}

// The SINUMERIK profiles' programs go to the Siemens runner (reference/siemens/siemens_runner.h).
Toolpath planSiemensRequest(const PlanRequest& request, const Profile& profile) {
  return planSiemensProgram(siemensRunInputFor(request), profile);
}

// A program of a FANUC-dialect profile: its parameters and its parsed blocks.
ReadRequest readFanucRequest(const PlanRequest& request, const Profile& profile) {
  ReadRequest read;
  read.profile = &profile;
  read.params = profile.defaults;
  for (const auto& [name, value] : request.params) read.params.set(name, value);
  read.program = parsedInTheFanucDialect(request, profile);
  return read;
}

// The Siemens runner's parsers, keeping what they parse as parsedInTheFanucDialect does.
SiemensParsers siemensParsersKeepingWhatTheyParse() {
  SiemensParsers parsers;
  parsers.program = [](std::string_view text, const std::string& file) {
    return parsedOnce<SiemensProgram>(text, file, parseSiemensProgram);
  };
  parsers.subprogram = [](std::string_view text, const std::string& file) {
    return parsedOnce<SiemensBlocks>(text, file, parseSiemensSubprogram);
  };
  parsers.contour = contourReadOnce;
  return parsers;
}

}  // namespace

SiemensRunInput siemensRunInputFor(const PlanRequest& request) {
  return {request.programText, request.file, request.subprograms, request.subprogramDirectory, request.options.tool,
          siemensParsersKeepingWhatTheyParse()};
}

ReadRequest readRequest(const PlanRequest& request) { return readRequest(request, requestedProfile(request)); }

ReadRequest readRequest(const PlanRequest& request, const Profile& profile) {
  if (profile.dialect == Dialect::Siemens) {
    throw NotSupported(0, "the " + profile.name + " profile's programs are SINUMERIK programs, not read as FANUC blocks "
                          "(the oracles read them with readSiemensProgramSpec, harness/judge/siemens_reading.h)");
  }
  return readFanucRequest(request, profile);
}

Toolpath planWithReference(const PlanRequest& request) {
  const Profile& profile = requestedProfile(request);
  if (profile.dialect == Dialect::Siemens) return planSiemensRequest(request, profile);
  const ReadRequest read = readFanucRequest(request, profile);
  return planProgram(*read.program, *read.profile, read.params, request.options);
}

PlanRequest planRequestFor(const SpecCase& c) {
  RunOptions options;
  options.mdi = c.mdi;
  if (c.tool) options.tool = *c.tool;
  PlanRequest request{c.program, c.file + "#/program", c.profile, c.params, options};
  for (const auto& [name, text] : c.subprograms) request.subprograms.push_back({name, text, c.file + "#/subprograms/" + name});
  return request;
}

Toolpath planSpecCase(const SpecCase& c) { return planWithReference(planRequestFor(c)); }

PlotInput plotInputFor(const Toolpath& path, const std::string& title) {
  PlotInput in;
  in.title = title;
  in.path = path;
  for (const CycleRecord& c : path.cycles) {
    in.finish.segments.insert(in.finish.segments.end(), c.shape.begin(), c.shape.end());
    const std::vector<Segment> rough = c.roughProfile();
    in.rough.segments.insert(in.rough.segments.end(), rough.begin(), rough.end());
  }
  return in;
}

}  // namespace cyclecert
