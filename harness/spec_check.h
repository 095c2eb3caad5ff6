#pragma once
// Judging a planned toolpath against a spec case's expectation.
#include <optional>
#include <string>

#include "harness/spec_case.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// Nothing when the toolpath meets the expectation; otherwise what differs, for a person.
std::optional<std::string> unmetExpectation(const SpecCase& c, const Toolpath& actual);

}  // namespace cyclecert
