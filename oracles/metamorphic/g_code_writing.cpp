#include "oracles/metamorphic/g_code_writing.h"

#include <array>
#include <stdexcept>
#include <utility>
#include <vector>

#include "reference/interpreter/g_codes.h"

namespace cyclecert {

namespace {

constexpr int kMostG10 = 999;  // findGCode's range

// Each system's (function, number ×10) pairs, the lowest number first where two write one
// function, read once from the table through findGCode.
using Numbers = std::vector<std::pair<int, int>>;
const std::array<Numbers, kGCodeSystems>& numbersBySystem() {
  static const std::array<Numbers, kGCodeSystems> numbers = [] {
    std::array<Numbers, kGCodeSystems> out;
    for (int s = 0; s < kGCodeSystems; ++s) {
      for (int g10 = 0; g10 <= kMostG10; ++g10) {
        const GCode* code = findGCode(static_cast<GCodeSystem>(s), g10);
        if (!code) continue;
        Numbers& n = out[static_cast<std::size_t>(s)];
        bool known = false;
        for (const auto& [function, number] : n) known = known || function == code->function;
        if (!known) n.emplace_back(code->function, g10);
      }
    }
    return out;
  }();
  return numbers;
}

}  // namespace

std::optional<int> gCodeNumberIn(GCodeSystem system, int function) {
  for (const auto& [f, number] : numbersBySystem()[static_cast<std::size_t>(system)]) {
    if (f == function) return number;
  }
  return std::nullopt;
}

std::string gCodeWrittenIn(GCodeSystem system, int function) {
  const auto number = gCodeNumberIn(system, function);
  if (!number) {
    throw std::invalid_argument(gCodeSystemName(system) + " has no G code for function " + std::to_string(function));
  }
  return gCodeLabel(*number);
}

}  // namespace cyclecert
