#pragma once
// A shrunk fuzz failure kept as a spec case in the regressions directory (corpus/regressions by
// default), so that `check` runs it from then on. It expects nothing but what the oracles require
// ({"oracles": "pass"}), and, when the failure was a disagreement with a built-in engine, agreement
// with that engine run at check time — never a toolpath copied from an engine's output.
#include <string>
#include <vector>

#include "harness/fuzz/fuzz_run.h"

namespace cyclecert {

// Writes DIR/<fuzzCaseFolder>/fuzz-<engine>-<seed>.json (e.g. fanuc-0i-f/g71, sinumerik-802d/cycle95; a
// SINUMERIK case with its contour in "subprograms") and returns its path.
std::string writeRegressionCase(const std::string& dir, const FuzzFailure& failure, const std::string& engineName,
                                const std::string& vsName, const std::vector<std::string>& rules,
                                const std::string& reproduce);

}  // namespace cyclecert
