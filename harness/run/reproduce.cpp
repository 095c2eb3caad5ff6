#include "harness/run/reproduce.h"

namespace cyclecert {

std::string shellQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string caseReproduceCommand(const std::string& engine, const std::string& caseFile, const std::string& agreesWith) {
  const std::string vs = agreesWith.empty() ? "reference" : agreesWith;
  if (engine == vs) return "cyclecert plan --case " + shellQuote(caseFile);
  return "cyclecert diff --engine " + shellQuote(engine) + " --vs " + shellQuote(vs) + " " + shellQuote(caseFile);
}

std::string fuzzReproduceCommand(const std::string& engine, const std::string& vs, std::uint64_t caseSeed) {
  return "cyclecert fuzz --engine " + shellQuote(engine) + (vs.empty() ? "" : " --vs " + shellQuote(vs)) + " --seed " +
         std::to_string(caseSeed) + " --cases 1";
}

}  // namespace cyclecert
