#pragma once
// The engines one worker of --jobs N owns: the engine under test and, with --vs, the engine it is
// compared with. Each worker has its own (an engine holds a child process, an rs274, or state of
// its own), made by the command's EnginesMaker.
#include <functional>
#include <memory>

#include "harness/engines/engine.h"

namespace cyclecert {

struct WorkerEngines {
  std::unique_ptr<Engine> engine;
  std::unique_ptr<Engine> vs;  // null without --vs
};

using EnginesMaker = std::function<WorkerEngines()>;

// Workers' engines made by makeEngine(name, options) (harness/engines/engine.h); vs "" for none.
EnginesMaker namedEngines(const std::string& engine, const std::string& vs, const EngineOptions& options);

}  // namespace cyclecert
