#pragma once
// Comparing a toolpath with an expected one, move by move, within a tolerance.
#include <optional>
#include <string>
#include <vector>

#include "reference/model/toolpath.h"

namespace cyclecert {

// The first divergence, described for a person (move index, field, expected vs actual), or
// nothing when every move matches: kind, shape, end point, centre (arcs) and, where the
// expectation gives one, the feed.
std::optional<std::string> firstDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                           double tolerance);

}  // namespace cyclecert
