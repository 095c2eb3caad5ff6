#pragma once
// Judging a planned toolpath against a spec case's expectation.
#include <optional>
#include <string>

#include "harness/spec/spec_case.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// Nothing when the toolpath meets the expectation; otherwise what differs, for a person. Expected
// warnings are the reference's annotations, judged only with `judgeWarnings` (engines need not
// warn); an alarm's "when" is judged when the engine states it.
std::optional<std::string> unmetExpectation(const SpecCase& c, const Toolpath& actual, bool judgeWarnings = true);

}  // namespace cyclecert
