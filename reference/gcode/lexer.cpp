#include "reference/gcode/lexer.h"

#include <cctype>

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iterator>
#include <optional>
#include <system_error>
#include <utility>

#include "reference/model/ascii.h"
#include "reference/model/program.h"

namespace cyclecert {

namespace {

// Plain ASCII tests: <cctype> depends on the locale and is undefined for negative chars, and
// every byte of a UTF-8 sequence is negative as a char.
bool isAsciiLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isSign(char c) { return c == '+' || c == '-'; }
bool isBlank(char c) { return c == ' ' || c == '\t'; }
bool isLineEnd(char c) { return c == '\n' || c == '\r'; }

bool startsWithIgnoringCase(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() && equalIgnoringCase(text.substr(0, prefix.size()), prefix);
}

// Length of the well-formed UTF-8 sequence starting at offset, or 0 when there is none, so that
// error messages quote a whole character and never a broken one.
std::size_t utf8LengthAt(std::string_view text, std::size_t offset) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
  const unsigned char lead = byte(offset);
  std::size_t length = 0;
  unsigned char secondLow = 0x80;
  unsigned char secondHigh = 0xBF;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) secondLow = 0xA0;   // no overlong forms
    if (lead == 0xED) secondHigh = 0x9F;  // no surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) secondLow = 0x90;
    if (lead == 0xF4) secondHigh = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (offset + length > text.size()) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    const unsigned char low = (i == 1) ? secondLow : 0x80;
    const unsigned char high = (i == 1) ? secondHigh : 0xBF;
    if (byte(offset + i) < low || byte(offset + i) > high) return 0;
  }
  return length;
}

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

}  // namespace

char Token::letter() const { return text.empty() ? '\0' : asciiUpper(text.front()); }

std::string_view Token::commentBody() const {
  return text.size() < 2 ? std::string_view{} : text.substr(1, text.size() - 2);
}

std::string describeSourceAt(std::string_view source, std::size_t offset) {
  if (offset >= source.size()) return "end of input";
  const char c = source[offset];
  if (isLineEnd(c)) return "end of line";
  if (c == ' ') return "a space";
  if (c == '\t') return "a tab";
  if (c > ' ' && c < '\x7F') return std::string(1, c);
  if (const std::size_t length = utf8LengthAt(source, offset); length > 0) {
    return std::string(source.substr(offset, length));
  }
  std::array<char, 16> hex{};
  std::snprintf(hex.data(), hex.size(), "byte 0x%02X", static_cast<unsigned char>(c));
  return hex.data();
}

std::string_view nonFiniteSpellingAt(std::string_view source, std::size_t offset) {
  if (offset >= source.size()) return {};
  std::size_t start = offset;
  if (isSign(source[start])) ++start;
  const std::string_view rest = source.substr(start);
  for (std::string_view spelling : {"infinity", "inf", "nan"}) {
    if (startsWithIgnoringCase(rest, spelling)) {
      return source.substr(offset, start - offset + spelling.size());
    }
  }
  return {};
}

Lexer::Lexer(std::string_view source, std::string file) : source_(source), file_(std::move(file)) {
  // Editors on Windows may start a UTF-8 file with a byte-order mark; it is not part of line 1.
  if (source_.starts_with(kByteOrderMark)) pos_ = lineStart_ = kByteOrderMark.size();
}

Token Lexer::next() {
  skipBlanks();
  if (pos_ >= source_.size()) return take(TokenKind::EndOfInput, 0);
  const char c = source_[pos_];
  if (isLineEnd(c)) return lineEnd();
  if (c == ';') return take(TokenKind::EndOfBlock, 1);
  if (c == '(') return comment();
  if (c == '%') return programMarker();
  if (c == '/') return take(TokenKind::BlockDelete, 1);
  if (isAsciiLetter(c)) return take(TokenKind::Letter, 1);
  if (isDigit(c) || isSign(c) || c == '.') return number();
  fail(pos_, "an address letter, a number, a comment or the end of the block");
}

Token Lexer::lineEnd() {
  const bool crlf = source_[pos_] == '\r' && pos_ + 1 < source_.size() && source_[pos_ + 1] == '\n';
  Token token = take(TokenKind::EndOfBlock, crlf ? 2 : 1);
  ++line_;
  lineStart_ = pos_;
  return token;
}

// Comments do not nest and end at the first ')'; a line end before it means the ')' is missing.
Token Lexer::comment() {
  std::size_t close = pos_ + 1;
  while (close < source_.size() && source_[close] != ')' && !isLineEnd(source_[close])) ++close;
  if (close >= source_.size() || source_[close] != ')') {
    fail(close, "')' to close the comment opened at column " + std::to_string(columnOf(pos_)));
  }
  return take(TokenKind::Comment, close - pos_ + 1);
}

Token Lexer::programMarker() {
  for (std::size_t i = lineStart_; i < pos_; ++i) {
    if (!isBlank(source_[i])) fail(pos_, "'%' only on a line of its own");
  }
  // Huazhong names a program on its '%' line: "%3304" (HNC.G71.FMT's programs; a profile that
  // does not, refuses it with the way FANUC writes it).
  std::size_t length = 1;
  while (pos_ + length < source_.size() && std::isdigit(static_cast<unsigned char>(source_[pos_ + length]))) ++length;
  Token token = take(TokenKind::ProgramMarker, length);
  skipBlanks();
  if (pos_ < source_.size() && !isLineEnd(source_[pos_])) fail(pos_, "the end of the line after '%'");
  return token;
}

Token Lexer::number() {
  const std::size_t start = pos_;
  if (isSign(source_[pos_])) ++pos_;
  std::size_t digits = skipDigits();
  if (pos_ < source_.size() && source_[pos_] == '.') {
    ++pos_;
    digits += skipDigits();
  }
  if (digits == 0) {
    const std::string_view spelling = nonFiniteSpellingAt(source_, start);
    if (!spelling.empty()) {
      throw ParseError({file_, line_, columnOf(start)}, "a finite number", std::string(spelling));
    }
    fail(pos_, "a digit");
  }
  if (pos_ < source_.size() && source_[pos_] == '.') fail(pos_, "a single decimal point in a number");
  const std::size_t end = pos_;
  pos_ = start;
  return take(TokenKind::Number, end - start);
}

void Lexer::skipBlanks() {
  while (pos_ < source_.size() && isBlank(source_[pos_])) ++pos_;
}

std::size_t Lexer::skipDigits() {
  const std::size_t start = pos_;
  while (pos_ < source_.size() && isDigit(source_[pos_])) ++pos_;
  return pos_ - start;
}

Token Lexer::take(TokenKind kind, std::size_t length) {
  Token token{kind, source_.substr(pos_, length), pos_, line_, columnOf(pos_)};
  pos_ += length;
  return token;
}

int Lexer::columnOf(std::size_t offset) const { return static_cast<int>(offset - lineStart_) + 1; }

void Lexer::fail(std::size_t offset, const std::string& expected) const {
  throw ParseError({file_, line_, columnOf(offset)}, expected, describeSourceAt(source_, offset));
}

std::vector<Token> tokenize(std::string_view source, const std::string& file) {
  Lexer lexer(source, file);
  std::vector<Token> tokens;
  do {
    tokens.push_back(lexer.next());
  } while (tokens.back().kind != TokenKind::EndOfInput);
  return tokens;
}

int significantDigits(std::string_view number) {
  int count = 0;
  for (char c : number) {
    if (c < '0' || c > '9') continue;
    if (count > 0 || c != '0') ++count;
  }
  return count;
}

// Plain: an optional sign, digits with at most one decimal point among them. The value, when the
// number has at most kMostSignificantDigits significant digits and at most 22 decimals, is m / 10^k
// with m < 10^15 < 2^53 and 10^k ≤ 10^22, both exact doubles, so the one correctly rounded division
// gives the double nearest to the number, which is from_chars' result too (Clinger's fast path) at
// a fraction of its cost: the numbers are most of a SINUMERIK case's parsing. Inline here, in
// readNumber's fast path (every FANUC number's), as a call it cost the FANUC parser more.
namespace {

inline LeadingNumber readLeadingPlainNumber(std::string_view s) {
  static constexpr double kPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                            1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  std::size_t end = 0;
  const bool negative = !s.empty() && s[0] == '-';
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) ++end;
  std::uint64_t m = 0;
  int significant = 0, decimals = 0;
  bool point = false, digits = false;
  for (; end < s.size(); ++end) {
    const char c = s[end];
    if (c == '.' && !point) {
      point = true;
      continue;
    }
    if (c < '0' || c > '9') break;
    digits = true;
    if (m != 0 || c != '0') ++significant;
    // Beyond the fast reading's digits only the length is sought (m stays below 10^15).
    if (significant <= kMostSignificantDigits) m = m * 10 + static_cast<std::uint64_t>(c - '0');
    if (point) ++decimals;
  }
  const bool secondPoint = end < s.size() && s[end] == '.';
  if (!digits || secondPoint) return {};
  LeadingNumber n{end, std::nullopt};
  if (significant <= kMostSignificantDigits && decimals < static_cast<int>(std::size(kPowersOfTen))) {
    const double value = static_cast<double>(m) / kPowersOfTen[decimals];
    n.value = negative ? -value : value;
  }
  return n;
}

}  // namespace

LeadingNumber leadingPlainNumber(std::string_view s) { return readLeadingPlainNumber(s); }

NumberReading readNumber(std::string_view text) {
  // A plain decimal's value read fast (readLeadingPlainNumber), when the whole text is one.
  if (const LeadingNumber plain = readLeadingPlainNumber(text); plain.value && plain.length == text.size()) {
    return {*plain.value, nullptr};
  }
  NumberReading r;
  if (significantDigits(text) > kMostSignificantDigits) {
    r.expected = "a number of at most 15 significant digits";
    return r;
  }
  // from_chars takes a leading '-' but not a leading '+'.
  const std::string_view digits = !text.empty() && text.front() == '+' ? text.substr(1) : text;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), r.value);
  if (error != std::errc{} || end != digits.data() + digits.size() || !std::isfinite(r.value)) {
    r.expected = "a number within the range of a double";
  }
  return r;
}

}  // namespace cyclecert
