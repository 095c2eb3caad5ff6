#pragma once
// A number as messages and translated programs show it: "13", "1.5", "7.362914" — at most 6
// decimals, no trailing zeros, never "-0".
#include <string>

namespace cyclecert {

std::string shortDecimalText(double v);

}  // namespace cyclecert
