#include "reference/siemens/siemens_signature.h"

#include <regex>

namespace cyclecert {

// Line by line, each line up to its ';' (a SINUMERIK comment, where a header may name the cycles).
std::optional<std::string> siemensSignature(std::string_view text) {
  static const std::regex signature(R"((L?CYC(LE)?9[0-9]\b|_CNAME\s*=|\bR[0-9]+\s*=|\b[A-Za-z_][A-Za-z0-9_]*\.spf\b))",
                                    std::regex::icase);
  int line = 1;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view whole = text.substr(start, end - start);
    const std::string code(whole.substr(0, whole.find(';')));
    std::smatch m;
    if (std::regex_search(code, m, signature)) return m.str(0) + " at line " + std::to_string(line);
    start = end + 1;
    ++line;
  }
  return std::nullopt;
}

}  // namespace cyclecert
