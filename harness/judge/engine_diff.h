#pragma once
// Two engines on the same case (`cyclecert diff`, `fuzz --vs`): do they agree, and if not, where do
// they first part? Alarms are compared as the spec checks compare them (FANUC codes exactly, an
// engine's own codes on the line: reference/model/alarms.h).
#include <optional>
#include <string>

#include "harness/engines/engine.h"

namespace cyclecert {

struct EngineDivergence {
  std::string text;                 // for a person, naming both engines
  std::optional<std::size_t> move;  // the first move that differs, when both planned
};

// Nothing when the results agree within `tolerance` or cannot be compared (either is not
// applicable or an engine failure: those are results of their own, not disagreements).
std::optional<EngineDivergence> compareEngineResults(const EngineResult& a, const std::string& aName,
                                                     const EngineResult& b, const std::string& bName,
                                                     double tolerance);

}  // namespace cyclecert
