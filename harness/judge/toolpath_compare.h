#pragma once
// Comparing a toolpath with an expected one (or another engine's), move by move, within a tolerance.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "reference/model/toolpath.h"

namespace cyclecert {

struct MoveDivergence {
  std::size_t move = 0;  // the first move that differs (or the first extra / missing one)
  std::string text;      // for a person: move index, field, both moves
};

// The first divergence of `actual` from `expected`: kind, shape, end point, centre (arcs) and,
// where `expected` gives one, the feed and the dwell (none counts as 0 s). The names label the two sides in the text ("move 3:
// expected …, got …"; "move 3: reference …, linuxcnc …").
std::optional<MoveDivergence> firstMoveDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                                  double tolerance, const std::string& expectedName = "expected",
                                                  const std::string& actualName = "got");

// The same, as text only.
std::optional<std::string> firstDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                           double tolerance);

std::string describeMove(const Move& m);  // "rapid line to (x 20, z 2)", with centre, feed, dwell

}  // namespace cyclecert
