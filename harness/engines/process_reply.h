#pragma once
// Reading one reply of a process engine (process:COMMAND, README "The process protocol"), without
// the process: harness/engines/process_engine.cpp reads each reply line with these, and
// tests/fuzz/process_reply_fuzz.cpp fuzzes them.
#include <nlohmann/json.hpp>
#include <string>

#include "harness/engines/engine.h"

namespace cyclecert {

// The reply line to request `request` as JSON. Throws ToolpathFormatError (invalid JSON: the line,
// column and what was expected, naming "the reply to request N").
nlohmann::json parseProcessReply(const std::string& line, long request);

// The case's result a reply gives: {"toolpath": …} planned, {"alarm": …} an alarm, {"not_applicable":
// …}, {"error": …} an engine failure. Never throws: a reply that is not a valid toolpath or alarm,
// or has none of the four, is an engine failure saying why (the field as a JSON pointer).
EngineResult processReplyResult(const nlohmann::json& reply);

}  // namespace cyclecert
