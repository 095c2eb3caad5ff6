#include "reference/model/program.h"

#include <cmath>
#include <limits>
#include <utility>

namespace cyclecert {

const Word* Block::find(char letter) const {
  for (const Word& word : words) {
    if (word.letter == letter) return &word;
  }
  return nullptr;
}

bool Block::hasG(int codeTimes10) const {
  for (const Word& word : words) {
    if (word.letter == 'G' && gCode10(word.value) == codeTimes10) return true;
  }
  return false;
}

std::optional<std::size_t> Program::findSequence(long n) const {
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (blocks[i].sequence == n) return i;
  }
  return std::nullopt;
}

namespace {

std::string parseErrorMessage(const SourceLoc& loc, const std::string& expected,
                              const std::string& found) {
  return loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(loc.column) +
         ": expected " + expected + ", found " + found;
}

}  // namespace

ParseError::ParseError(SourceLoc loc, std::string expected, std::string found)
    : std::runtime_error(parseErrorMessage(loc, expected, found)),
      loc_(std::move(loc)),
      expected_(std::move(expected)),
      found_(std::move(found)) {}

// Rounding (not truncation) because 74.1 * 10 is 740.999… or 741.000… depending on the digits.
// A value no int can hold (or NaN) gives -1, which matches no real G code.
int gCode10(double value) {
  const double times10 = std::round(value * 10.0);
  if (!(std::abs(times10) <= static_cast<double>(std::numeric_limits<int>::max()))) return -1;
  return static_cast<int>(times10);
}

}  // namespace cyclecert
