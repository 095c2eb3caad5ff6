// LCYC95 and CYCLE95 (seed 004): not planned yet — the planners' work in progress replaces this.
#include "reference/model/alarms.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert {

std::optional<MachiningType> machiningTypeOf(double) { return std::nullopt; }

SiemensCycleOutcome planLcyc95(const SiemensCycleCall& call, const Lcyc95Parameters&) {
  throw NotSupported(call.line, "LCYC95 is not planned yet");
}

SiemensCycleOutcome planCycle95(const SiemensCycleCall& call, const Cycle95Parameters&) {
  throw NotSupported(call.line, "CYCLE95 is not planned yet");
}

}  // namespace cyclecert
