#pragma once
// Plain ASCII case folding for program text and parameter names: <cctype> depends on the locale
// and is undefined for negative chars, and every byte of a UTF-8 sequence is negative as a char.
#include <algorithm>
#include <string_view>

namespace cyclecert {

inline char asciiUpper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }

inline bool equalIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return asciiUpper(x) == asciiUpper(y); });
}

}  // namespace cyclecert
