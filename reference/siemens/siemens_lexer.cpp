#include "reference/siemens/siemens_lexer.h"

#include <utility>

#include "reference/gcode/lexer.h"
#include "reference/model/ascii.h"
#include "reference/model/program.h"

namespace cyclecert {

namespace {

bool isNameStart(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isBlank(char c) { return c == ' ' || c == '\t'; }

}  // namespace

std::string SiemensToken::upperName() const {
  std::string upper(text);
  for (char& c : upper) c = asciiUpper(c);
  return upper;
}

std::string_view SiemensToken::stringBody() const {
  return text.size() < 2 ? std::string_view{} : text.substr(1, text.size() - 2);
}

SiemensLexer::SiemensLexer(std::string_view line, std::string file, int lineNumber)
    : line_(line), file_(std::move(file)), lineNumber_(lineNumber) {}

void SiemensLexer::startLine(std::string_view line, int lineNumber) {
  line_ = line;
  lineNumber_ = lineNumber;
  pos_ = 0;
}

SiemensToken SiemensLexer::next() {
  while (pos_ < line_.size() && isBlank(line_[pos_])) ++pos_;
  if (pos_ >= line_.size()) return take(SiemensTokenKind::EndOfLine, 0);
  const char c = line_[pos_];
  if (c == ';') return take(SiemensTokenKind::Comment, line_.size() - pos_);
  if (isNameStart(c)) return name();
  if (isDigit(c) || c == '+' || c == '-' || c == '.') return number();
  if (c == '"') return string();
  if (c == '=') return take(SiemensTokenKind::Equals, 1);
  if (c == '(') return take(SiemensTokenKind::OpenParen, 1);
  if (c == ')') return take(SiemensTokenKind::CloseParen, 1);
  if (c == ',') return take(SiemensTokenKind::Comma, 1);
  fail(pos_, "an address, a number, '=', a string in double quotes, a cycle's '(…)' or a ';' comment");
}

SiemensToken SiemensLexer::name() {
  std::size_t end = pos_;
  while (end < line_.size() && isNameStart(line_[end])) ++end;
  return take(SiemensTokenKind::Name, end - pos_);
}

// The number's characters by the FANUC reader's rules, its value as the FANUC reader reads it: a
// plain number's both in one pass (leadingPlainNumber); what that leaves — its refusals, a number
// beyond the fast reading — to the FANUC lexer (fanucNumberLength) and readNumber, so that their
// messages stay the only ones.
SiemensToken SiemensLexer::number() {
  const LeadingNumber plain = leadingPlainNumber(line_.substr(pos_));
  SiemensToken token = take(SiemensTokenKind::Number, plain.length != 0 ? plain.length : fanucNumberLength());
  if (plain.value) {
    token.number = *plain.value;
    return token;
  }
  const NumberReading r = readNumber(token.text);
  if (r.expected) throw ParseError({file_, lineNumber_, token.column}, r.expected, std::string(token.text));
  token.number = r.value;
  return token;
}

// The number here as the FANUC lexer reads it (a lexer over the rest of the line: its errors are
// moved to this file, line and column, so it needs no copy of the file's name).
std::size_t SiemensLexer::fanucNumberLength() const {
  try {
    return Lexer(line_.substr(pos_), std::string()).next().text.size();
  } catch (const ParseError& e) {
    throw ParseError({file_, lineNumber_, static_cast<int>(pos_) + e.loc().column}, e.expected(), e.found());
  }
}

SiemensToken SiemensLexer::string() {
  const std::size_t close = line_.find('"', pos_ + 1);
  if (close == std::string_view::npos) {
    fail(line_.size(), "'\"' to close the string opened at column " + std::to_string(pos_ + 1));
  }
  return take(SiemensTokenKind::String, close - pos_ + 1);
}

SiemensToken SiemensLexer::take(SiemensTokenKind kind, std::size_t length) {
  SiemensToken token{kind, line_.substr(pos_, length), static_cast<int>(pos_) + 1, 0};
  pos_ += length;
  return token;
}

void SiemensLexer::fail(std::size_t offset, const std::string& expected) const {
  const std::string found = offset >= line_.size() ? "end of line" : describeSourceAt(line_, offset);
  throw ParseError({file_, lineNumber_, static_cast<int>(offset) + 1}, expected, found);
}

}  // namespace cyclecert
