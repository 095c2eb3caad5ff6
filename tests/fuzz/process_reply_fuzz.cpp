// libFuzzer target: a process engine's reply line (harness/engines/process_reply.h), read as
// process_engine.cpp reads it: the line as JSON, the echoed request compared, the reply as the
// case's result. Expected refusal: ToolpathFormatError for a line that is not JSON; every other
// problem is an engine failure returned, never thrown.
#include <cstddef>
#include <cstdint>

#include "harness/engines/process_reply.h"
#include "reference/model/toolpath_json.h"
#include "tests/fuzz/fuzz_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  nlohmann::json reply;
  try {
    reply = parseProcessReply(fuzz::textOf(data, size), 1);
  } catch (const ToolpathFormatError&) {
    return 0;
  }
  if (!reply.is_object() || !reply.contains("request") || reply["request"] != 1) return 0;  // not the reply
  processReplyResult(reply);
  return 0;
}
