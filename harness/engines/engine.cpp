#include "harness/engines/engine.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>

#include "harness/engines/engines.h"
#include "harness/engines/linuxcnc/linuxcnc_engine.h"

namespace cyclecert {

EngineResult EngineResult::planned(Toolpath t) {
  EngineResult r;
  r.kind = t.alarm ? Alarmed : Planned;
  r.path = std::move(t);
  return r;
}

EngineResult EngineResult::notApplicable(std::string why) {
  EngineResult r;
  r.kind = NotApplicable;
  r.detail = std::move(why);
  return r;
}

EngineResult EngineResult::failed(std::string what) {
  EngineResult r;
  r.kind = Failed;
  r.detail = std::move(what);
  return r;
}

std::string kindName(EngineResult::Kind k) {
  switch (k) {
    case EngineResult::Planned: return "planned";
    case EngineResult::Alarmed: return "alarm";
    case EngineResult::NotApplicable: return "not-applicable";
    case EngineResult::Failed: return "engine-failure";
  }
  return "engine-failure";
}

// Where the build put its products (fetch-rs274.sh extracts rs274 there): $CYCLECERT_BUILD_DIR, else
// the folder of the running program (cyclecert and the tests are built into it).
static std::string buildDirectory() {
  if (const char* dir = std::getenv("CYCLECERT_BUILD_DIR"); dir && *dir) return dir;
  std::error_code error;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
  return error ? std::string("build") : self.parent_path().string();
}

std::unique_ptr<Engine> makeEngine(const std::string& name, const EngineOptions& options) {
  if (name == "reference") return makeReferenceEngine();
  if (name == "linuxcnc") return makeLinuxCncEngine(buildDirectory(), options);
  if (name.rfind("process:", 0) == 0 && name.size() > 8) return makeProcessEngine(name.substr(8), options);
  if (name.rfind("mutant:", 0) == 0) {
    if (auto m = makeMutantEngine(name.substr(7))) return m;
  }
  std::string known;
  for (const auto& [engine, description] : listEngines()) known += "\n  " + engine;
  throw std::invalid_argument("unknown engine '" + name + "'; the engines are:" + known + "\n  process:COMMAND");
}

std::vector<std::pair<std::string, std::string>> listEngines() {
  std::vector<std::pair<std::string, std::string>> all = {
      {"reference",
       "cyclecert's reference engine, in-process: G70, G71, G72, G73 for FANUC 0i-F/0i-C (also the Series 10/11 block "
       "and G code systems B/C) and GSK; the Huazhong one-block G71; the Haas one-block G71/G72 and G70"},
      {"linuxcnc", "LinuxCNC's rs274 interpreter (G71/G72 as LinuxCNC reads them; make fetches it from Debian)"},
      {"process:COMMAND", "any program speaking JSON lines on stdin/stdout (README: plugging in an engine)"},
  };
  for (const auto& [name, fault] : mutantFaults()) all.push_back({"mutant:" + name, "the reference with one fault: " + fault});
  return all;
}

std::string enginesListing() {
  const auto engines = listEngines();
  std::size_t longest = 0;
  for (const auto& [name, description] : engines) longest = std::max(longest, name.size());
  std::string text;
  for (const auto& [name, description] : engines) {
    text += name + std::string(longest + 2 - name.size(), ' ') + description + "\n";
  }
  return text;
}

std::vector<EngineResult> Engine::runBatch(const std::vector<SpecCase>& cases) {
  std::vector<EngineResult> results;
  results.reserve(cases.size());
  for (const SpecCase& c : cases) results.push_back(run(c));
  return results;
}

}  // namespace cyclecert
