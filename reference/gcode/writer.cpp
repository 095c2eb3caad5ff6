#include "reference/gcode/writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string_view>
#include <system_error>

#include "reference/gcode/lexer.h"
#include "reference/model/ascii.h"

namespace cyclecert {

namespace {

// The shortest plain decimal text that reads back as exactly this double.
std::string shortestFixed(double value) {
  char buffer[512];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::fixed);
  if (error != std::errc{}) return "0";  // only for values no program holds (beyond ~1e300)
  return std::string(buffer, end);
}

// The value rounded to 15 significant digits; its shortest text then has at most 15 digits.
double roundedToMostDigits(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*e", kMostSignificantDigits - 1, value);
  return std::strtod(buffer, nullptr);
}

// The word as the source spelled it ("T0202", "X54.0", "G1"), when its text still says its value
// exactly (a relation that changed the value and not the text gets the value written instead).
std::optional<std::string> sourceSpelling(const Word& word) {
  if (word.text.size() < 2 || asciiUpper(word.text[0]) != word.letter) return std::nullopt;
  std::string number;
  for (char c : word.text.substr(1)) {
    if (c != ' ' && c != '\t') number += c;
  }
  const std::string_view digits = number.front() == '+' ? std::string_view(number).substr(1) : std::string_view(number);
  double value = 0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (error != std::errc{} || end != digits.data() + digits.size() || value != word.value) return std::nullopt;
  if ((number.find('.') != std::string::npos) != word.hasDecimalPoint) return std::nullopt;
  return std::string(1, word.letter) + number;
}

}  // namespace

std::string formatNumber(double value, bool decimalPoint) {
  if (value == 0) value = 0;  // no "-0"
  std::string text = shortestFixed(value);
  if (significantDigits(text) > kMostSignificantDigits) text = shortestFixed(roundedToMostDigits(value));
  if (decimalPoint && text.find('.') == std::string::npos) text += '.';
  return text;
}

std::string formatWord(const Word& word) {
  if (const auto spelling = sourceSpelling(word)) return *spelling;
  const bool code = word.letter == 'G' || word.letter == 'M';
  if (code && word.value >= 0 && word.value < 10 && word.value == std::floor(word.value) && !word.hasDecimalPoint) {
    return std::string(1, word.letter) + "0" + formatNumber(word.value, false);
  }
  return std::string(1, word.letter) + formatNumber(word.value, word.hasDecimalPoint);
}

Word makeWord(char letter, double value, bool decimalPoint) {
  Word w;
  w.letter = letter;
  w.value = value;
  w.hasDecimalPoint = decimalPoint;
  w.text = formatWord(w);
  return w;
}

std::string writeBlock(const Block& block) {
  std::string line;
  const auto append = [&line](const std::string& item) {
    if (!line.empty() && line != "/") line += ' ';
    line += item;
  };
  if (block.blockDelete) line = "/";
  if (block.sequence) append("N" + std::to_string(*block.sequence));
  for (const Word& w : block.words) append(formatWord(w));
  return line;
}

std::string writeProgram(const Program& program) {
  std::string text;
  if (program.number) {
    char number[32];
    std::snprintf(number, sizeof number, "O%04ld;\n", *program.number);
    text += number;
  }
  for (const Block& b : program.blocks) text += writeBlock(b) + ";\n";
  return text;
}

}  // namespace cyclecert
