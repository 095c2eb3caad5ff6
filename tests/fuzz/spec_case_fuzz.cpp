// libFuzzer target: the spec-case loader (harness/spec/spec_case.h) on a JSON text, then the case as a
// plan request and a judge request (what `check` makes of it before running an engine). Expected
// refusals: SpecError, which names the file and the field, and the std::runtime_error parseSpecCase
// throws for a text that is not JSON (file:line:column and what was expected; harness/spec/spec_case.cpp).
#include <cstddef>
#include <cstdint>

#include "harness/engines/reference_plan.h"
#include "harness/judge/judging.h"
#include "harness/spec/spec_case.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  try {
    const SpecCase c = parseSpecCase(fuzz::textOf(data, size), "fuzz.json");
    planRequestFor(c);
    judgeRequestFor(c);
  } catch (const std::runtime_error&) {  // SpecError, or not JSON
  }
  return 0;
}
