#include "reference/gcode/program_limits.h"

#include <algorithm>
#include <cmath>

#include "reference/model/program.h"

namespace cyclecert {

std::string groupedCount(unsigned long long n) {
  std::string digits = std::to_string(n);
  for (int i = static_cast<int>(digits.size()) - 3; i > 0; i -= 3) digits.insert(static_cast<std::size_t>(i), ",");
  return digits;
}

std::string countText(double n) {
  constexpr double kLargestShown = 1e15;
  if (!(n <= kLargestShown)) return "more than " + groupedCount(static_cast<unsigned long long>(kLargestShown));
  return groupedCount(static_cast<unsigned long long>(std::llround(std::max(n, 0.0))));
}

void requireBlockWithinTheCap(std::size_t blockNumber, const std::string& file, int line) {
  if (blockNumber <= kMostBlocksPerProgram) return;
  throw ParseError({file, line, 1},
                   "at most " + groupedCount(kMostBlocksPerProgram) +
                       " blocks in a program (cyclecert's bound, PROG.CAP.BLOCKS; README \"Limits\"): split the program",
                   "block " + groupedCount(blockNumber));
}

}  // namespace cyclecert
