#include "harness/run/worker_engines.h"

namespace cyclecert {

EnginesMaker namedEngines(const std::string& engine, const std::string& vs, const EngineOptions& options) {
  return [=] { return WorkerEngines{makeEngine(engine, options), vs.empty() ? nullptr : makeEngine(vs, options)}; };
}

}  // namespace cyclecert
