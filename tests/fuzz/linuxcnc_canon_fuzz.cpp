// libFuzzer target: the reader of LinuxCNC's canonical output (`rs274 -g`,
// harness/engines/linuxcnc/linuxcnc_canon.cpp): the text as rs274's stdout (parseCanonical, which
// reports garbage in CanonicalParse::error and never throws) and as its stderr (linuxCncAlarm).
#include <cstddef>
#include <cstdint>
#include <map>

#include "harness/engines/linuxcnc/linuxcnc_engine.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  const std::string text = fuzz::textOf(data, size);
  parseCanonical(text);
  linuxCncAlarm(text, {{"N10", 1}, {"N20", 2}});
  return 0;
}
