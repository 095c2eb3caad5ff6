// libFuzzer target: the toolpath JSON reader as `judge` reads an engine's toolpath
// (harness/cli/judge_command.cpp): parseJsonDocument, then toolpathFromJson, then the toolpath
// written back as JSON. Expected refusal: ToolpathFormatError, which names the field.
#include <cstddef>
#include <cstdint>

#include "reference/model/toolpath_json.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  try {
    const Toolpath path = toolpathFromJson(parseJsonDocument(fuzz::textOf(data, size), "fuzz.json"));
    toJson(path).dump();
  } catch (const ToolpathFormatError&) {
  }
  return 0;
}
