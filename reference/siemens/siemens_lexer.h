#pragma once
// The tokenizer for one line of a SINUMERIK program (seed 004; rules SIEMENS.LEX). A line is a
// block; `;` starts a comment that runs to the end of the line (in FANUC's dialect `;` ends a
// block). Names are runs of letters and '_' ("G", "CR", "LCYC", "_CNAME"); a number is read as the
// FANUC reader reads one (reference/gcode/lexer.h: optional sign, digits, one decimal point, no
// exponent), so `G3X20.8Z-25.8` is G 3 X 20.8 Z -25.8. Strings are in double quotes.
#include <string>
#include <string_view>

namespace cyclecert {

enum class SiemensTokenKind { Name, Number, Equals, String, OpenParen, CloseParen, Comma, Comment, EndOfLine };

struct SiemensToken {
  SiemensTokenKind kind = SiemensTokenKind::EndOfLine;
  std::string_view text;  // a view into the line: a name, a number, a string with its quotes, …
  int column = 0;         // 1-based, in bytes
  double number = 0;      // Number: its value
  std::string upperName() const;            // Name: upper case
  std::string_view stringBody() const;      // String: between the quotes
};

class SiemensLexer {
 public:
  // `line` (without its line end) must outlive the lexer and its tokens.
  SiemensLexer(std::string_view line, std::string file, int lineNumber);
  // Goes on to another line of the same file (`line` must outlive the lexer and its tokens).
  void startLine(std::string_view line, int lineNumber);
  SiemensToken next();  // EndOfLine forever once the line is exhausted
  const std::string& file() const { return file_; }
  int lineNumber() const { return lineNumber_; }
  std::string_view line() const { return line_; }

 private:
  SiemensToken name();
  SiemensToken number();
  std::size_t fanucNumberLength() const;
  SiemensToken string();
  SiemensToken take(SiemensTokenKind kind, std::size_t length);
  [[noreturn]] void fail(std::size_t offset, const std::string& expected) const;

  std::string_view line_;
  std::string file_;
  int lineNumber_;
  std::size_t pos_ = 0;
};

}  // namespace cyclecert
