// reference: cyclecert's own engine, in process.
#include <chrono>

#include "cyclecert_version.h"
#include "harness/engines/engines.h"
#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

class ReferenceEngine : public Engine {
 public:
  std::string name() const override { return "reference"; }
  std::string description() const override { return "cyclecert reference engine"; }
  std::string version() const override { return std::string("cyclecert ") + CYCLECERT_VERSION; }
  EngineResult run(const SpecCase& c) override {
    const auto start = std::chrono::steady_clock::now();
    EngineResult r;
    try {
      r = EngineResult::planned(planSpecCase(c));
    } catch (const NotSupported& e) {
      r = EngineResult::notApplicable(e.what());
    } catch (const std::exception& e) {
      r = EngineResult::failed(e.what());
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }
};

}  // namespace

std::unique_ptr<Engine> makeReferenceEngine() { return std::make_unique<ReferenceEngine>(); }

}  // namespace cyclecert
