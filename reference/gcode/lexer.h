#pragma once
// The tokenizer for ISO-6983 lathe programs (FANUC / GSK / HNC dialect). It knows characters, not
// grammar: a Letter and the Number after it are separate tokens and the parser pairs them, so that
// "X;" is reported by the parser, which knows which address is missing its number.
//
// Lexical errors (a character outside the dialect, a second decimal point, a sign without digits,
// an unclosed comment, a '%' that shares its line) throw ParseError at the offending byte.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cyclecert {

enum class TokenKind {
  Letter,         // an address letter, either case
  Number,         // optional sign, digits, at most one decimal point: "54", "-0.6", ".5", "10."
  Comment,        // "( … )", never spanning a line end
  EndOfBlock,     // ';' or a line end ("\n", "\r\n" or a lone "\r")
  ProgramMarker,  // '%' on a line of its own: program start or end
  BlockDelete,    // '/'
  EndOfInput,
};

struct Token {
  TokenKind kind = TokenKind::EndOfInput;
  std::string_view text;   // exact source bytes; a view into the text given to the Lexer
  std::size_t offset = 0;  // byte offset of text in the source
  int line = 0;            // 1-based
  int column = 0;          // 1-based, counted in bytes

  char letter() const;                    // Letter: the address in upper case
  std::string_view commentBody() const;   // Comment: the text between the parentheses
};

class Lexer {
 public:
  // The source must outlive the lexer and every token it returns.
  Lexer(std::string_view source, std::string file);

  // The next token; EndOfInput forever once the source is exhausted.
  Token next();

  const std::string& file() const { return file_; }
  std::string_view source() const { return source_; }

 private:
  Token lineEnd();
  Token comment();
  Token programMarker();
  Token number();
  void skipBlanks();
  std::size_t skipDigits();  // returns how many
  Token take(TokenKind kind, std::size_t length);
  int columnOf(std::size_t offset) const;
  [[noreturn]] void fail(std::size_t offset, const std::string& expected) const;

  std::string_view source_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t lineStart_ = 0;  // offset of the first byte of the current line
  int line_ = 1;
};

// A double holds any 15 significant decimal digits exactly; more would silently change the value.
// Every reader of numbers (the FANUC parser, the SINUMERIK lexer) and the writer keep to it.
inline constexpr int kMostSignificantDigits = 15;

// Digits from the first non-zero one on: "-0.0061" has 2, "1.500" has 4.
int significantDigits(std::string_view number);

// A Number token's text read as a double: the value, or what a number must be that this one is not
// ("a number of at most 15 significant digits", "a number within the range of a double"); the
// caller says where.
struct NumberReading {
  double value = 0;
  const char* expected = nullptr;  // set when the text is no number the readers accept
};
NumberReading readNumber(std::string_view text);

// The plain number `s` starts with — a sign, digits with at most one decimal point among them, and
// no second point after — read in one pass: its length (0 when `s` starts with none) and, when it
// is within the fast reading's terms (at most kMostSignificantDigits significant digits, at most
// 22 decimals), its value, the one readNumber gives its text; otherwise readNumber is left to read
// it. The SINUMERIK lexer finds its numbers' ends by it (a SINUMERIK case's numbers are most of
// its parsing, and a scan for the end, then another for the value, cost twice).
struct LeadingNumber {
  std::size_t length = 0;
  std::optional<double> value;
};
LeadingNumber leadingPlainNumber(std::string_view s);

// Every token of the source, ending with EndOfInput.
std::vector<Token> tokenize(std::string_view source, const std::string& file);

// How an error message names the source text at offset: the character itself ("#", "主"),
// "end of line", "end of input", "a space", "a tab" or "byte 0x01".
std::string describeSourceAt(std::string_view source, std::size_t offset);

// The run of letters at offset when it spells a non-finite number ("nan", "inf", "Infinity"), with
// an optional sign in front; otherwise empty. Lets both lexer and parser name "X-inf" and "Xnan".
std::string_view nonFiniteSpellingAt(std::string_view source, std::size_t offset);

}  // namespace cyclecert
