#include "my_controller_engine.h"

#include <chrono>
#include <exception>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace my_controller {
namespace {

class Engine : public cyclecert::Engine {
 public:
  std::string name() const override { return "my-controller"; }
  std::string description() const override { return "My Controller's G71/G72/G70 planner, in process"; }
  std::string version() const override { return "1.0"; }

  cyclecert::EngineResult run(const cyclecert::SpecCase& c) override {
    const auto start = std::chrono::steady_clock::now();
    cyclecert::EngineResult r;
    try {
      r = cyclecert::EngineResult::planned(plan(c));
    } catch (const cyclecert::NotSupported& e) {
      r = cyclecert::EngineResult::notApplicable(e.what());
    } catch (const std::exception& e) {
      r = cyclecert::EngineResult::failed(e.what());
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
  }

 private:
  // Replace this with your planner: read c.program (and c.profile, c.params, c.subprograms), and
  // fill a cyclecert::Toolpath — its start point and its moves (rapid/feed, line/arc, end point,
  // centre, feed), or its alarm. As a stand-in that passes, this example hands the case to
  // cyclecert's reference engine.
  cyclecert::Toolpath plan(const cyclecert::SpecCase& c) { return cyclecert::planSpecCase(c); }
};

}  // namespace

std::unique_ptr<cyclecert::Engine> makeEngine() { return std::make_unique<Engine>(); }

}  // namespace my_controller
