// libFuzzer target: the SINUMERIK reader (reference/siemens) — a main program with subprograms
// printed after it, the same text as a subprogram of its own, and the oracles' reading of it as a
// program of the profile the first byte picks (802S or 802D) with the text also given as the
// contour subprogram L42. Expected refusals: ParseError and NotSupported.
#include <cstddef>
#include <cstdint>

#include "harness/engines/reference_plan.h"
#include "harness/judge/siemens_reading.h"
#include "reference/model/alarms.h"
#include "reference/siemens/siemens_parser.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  const bool d802 = size > 0 && (data[0] & 1);
  const std::string text = size > 0 ? fuzz::textOf(data + 1, size - 1) : "";
  try {
    parseSiemensProgram(text, "fuzz.mpf");
  } catch (const ParseError&) {
  }
  try {
    parseSiemensSubprogram(text, "L42.spf");
  } catch (const ParseError&) {
  }
  PlanRequest request{text, "fuzz.mpf", d802 ? "sinumerik-802d" : "sinumerik-802s", {}, {}};
  request.subprograms.push_back({"L42", text, "L42.spf"});
  try {
    readSiemensProgramSpec(request, requestedProfile(request));
  } catch (const ParseError&) {
  } catch (const NotSupported&) {
  }
  return 0;
}
