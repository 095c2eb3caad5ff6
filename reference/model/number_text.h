#pragma once
// A number as messages show it: "13", "1.5", "7.362914" (at most 6 decimals, no trailing zeros).
#include <string>

namespace cyclecert {

std::string siemensNumberText(double v);

}  // namespace cyclecert
