// libFuzzer target: the whole plan of a program by the reference engine (planWithReference), in
// the profile and parameters the first byte picks (tests/fuzz/fuzz_input.h; SINUMERIK included).
// Expected refusals, as documented in harness/engines/reference_plan.h: ParseError (malformed program),
// NotSupported (including the planner's caps, PROG.CAP) and UnknownParam / std::invalid_argument;
// a controller alarm is a result. Anything else escaping, a crash, a hang beyond libFuzzer's
// -timeout or an allocation beyond its -rss_limit_mb / -malloc_limit_mb is a finding.
#include <cstddef>
#include <cstdint>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  const fuzz::Chosen chosen = fuzz::choose(fuzz::allSettings(), data, size);
  try {
    planWithReference({chosen.text, "fuzz.nc", chosen.setting.profile, chosen.setting.params, {}});
  } catch (const ParseError&) {
  } catch (const NotSupported&) {
  } catch (const std::invalid_argument&) {  // UnknownParam, a parameter out of its range
  }
  return 0;
}
