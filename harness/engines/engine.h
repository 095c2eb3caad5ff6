#pragma once
// An engine under test: takes a spec case (program, profile, parameters, stock, tool) and returns
// what it planned — a canonical toolpath, an alarm, "not applicable" (with the reason), or an
// engine failure (crash, timeout, garbage output). See README "Plugging in an engine".
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "harness/spec/spec_case.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct EngineResult {
  enum Kind { Planned, Alarmed, NotApplicable, Failed } kind = Failed;
  Toolpath path;       // Planned (and Alarmed: path.alarm holds the alarm)
  std::string detail;  // NotApplicable: the reason; Failed: what went wrong
  double seconds = 0;  // wall time the engine took

  static EngineResult planned(Toolpath t);
  static EngineResult notApplicable(std::string why);
  static EngineResult failed(std::string what);
};

std::string kindName(EngineResult::Kind k);  // "planned", "alarm", "not-applicable", "engine-failure"

// Whether the engine answered the case — a toolpath or an alarm — so that its result can be judged
// and compared; not applicable and engine failures are results of their own.
inline bool hasOutcome(const EngineResult& r) { return r.kind == EngineResult::Planned || r.kind == EngineResult::Alarmed; }

class Engine {
 public:
  virtual ~Engine() = default;
  virtual std::string name() const = 0;         // as given to --engine: "reference", "process:…", "mutant:…"
  virtual std::string description() const = 0;  // one line for `cyclecert engines`
  virtual std::string version() const = 0;      // for reports
  virtual EngineResult run(const SpecCase& c) = 0;
  // Several cases at once, results in the same order: engines whose start-up dominates (LinuxCNC's
  // rs274) run them in one go; the others one by one.
  virtual std::vector<EngineResult> runBatch(const std::vector<SpecCase>& cases);
};

struct EngineOptions {
  double timeoutSeconds = 10;                 // per case, for engines in another process
  std::size_t maxReplyBytes = 64u << 20;      // a longer reply is an engine failure
};

// "reference", "process:COMMAND", "linuxcnc", "mutant:NAME". Throws std::invalid_argument with the
// list of engines for an unknown name.
std::unique_ptr<Engine> makeEngine(const std::string& name, const EngineOptions& options = {});

// Every built-in engine name with its description (`cyclecert engines`).
std::vector<std::pair<std::string, std::string>> listEngines();

// That list as `cyclecert engines` prints it: one line per engine, its name in a column two spaces
// wider than the longest name, then its description.
std::string enginesListing();

}  // namespace cyclecert
