#include "reference/gcode/parser.h"

#include <utility>

#include "reference/gcode/lexer.h"
#include "reference/gcode/program_limits.h"

namespace cyclecert {

namespace {

// FANUC accepts sequence numbers N1 to N99999.
constexpr double kLargestSequenceNumber = 99999;
bool isUnsignedWholeNumber(std::string_view number) {
  return number.find_first_not_of("0123456789") == std::string_view::npos;
}

bool hasDecimalPoint(std::string_view number) { return number.find('.') != std::string_view::npos; }

class ProgramParser {
 public:
  ProgramParser(std::string_view text, const std::string& file)
      : lexer_(text, file), current_(lexer_.next()) {}

  Program parse() {
    program_.file = lexer_.file();
    while (current_.kind != TokenKind::EndOfInput) {
      if (current_.kind == TokenKind::ProgramMarker) {
        readProgramMarker(advance());
        continue;
      }
      parseBlock();
    }
    return std::move(program_);
  }

 private:
  // '%' lines frame the program; Huazhong's "%3304" also names it.
  void readProgramMarker(const Token& marker) {
    if (marker.text.size() == 1) return;
    if (program_.percentName) fail(marker, "one program name per file", std::string(marker.text));
    program_.percentName = PercentName{std::string(marker.text), marker.line};
  }

  // Returns the current token and moves on to the next one.
  Token advance() {
    Token taken = std::exchange(current_, lexer_.next());
    consumedEnd_ = taken.offset + taken.text.size();
    return taken;
  }

  bool atBlockEnd() const {
    return current_.kind == TokenKind::EndOfBlock || current_.kind == TokenKind::EndOfInput ||
           current_.kind == TokenKind::ProgramMarker;
  }

  void parseBlock() {
    Block block;
    block.words.reserve(8);  // a block has a few words: one allocation, not one per doubling
    block.line = current_.line;
    const std::size_t begin = current_.offset;
    consumedEnd_ = begin;
    if (current_.kind == TokenKind::BlockDelete) {
      block.blockDelete = true;
      advance();
    }
    while (!atBlockEnd()) parseBlockItem(block);
    block.text = std::string(lexer_.source().substr(begin, consumedEnd_ - begin));
    if (current_.kind == TokenKind::EndOfBlock) advance();
    if (!block.words.empty() || block.sequence) keep(std::move(block));
  }

  // PROG.CAP.BLOCKS: the block beyond kMostBlocksPerProgram is refused at its line.
  void keep(Block block) {
    requireBlockWithinTheCap(program_.blocks.size() + 1, lexer_.file(), block.line);
    program_.blocks.push_back(std::move(block));
  }

  void parseBlockItem(Block& block) {
    switch (current_.kind) {
      case TokenKind::Comment:
        appendComment(block, advance().commentBody());
        return;
      case TokenKind::Letter:
        parseWord(block);
        return;
      case TokenKind::Number:
        fail(current_, "an address letter before the number", std::string(current_.text));
      case TokenKind::BlockDelete:
        fail(current_, "'/' only at the start of a block", "/");
      case TokenKind::EndOfBlock:
      case TokenKind::ProgramMarker:
      case TokenKind::EndOfInput:
        break;
    }
  }

  static void appendComment(Block& block, std::string_view body) {
    if (!block.comment.empty()) block.comment += ' ';
    block.comment += body;
  }

  void parseWord(Block& block) {
    const Token letter = advance();
    if (current_.kind != TokenKind::Number) failMissingNumber(letter);
    const Token number = advance();
    Word word;
    word.letter = letter.letter();
    word.value = valueOf(number);
    word.hasDecimalPoint = hasDecimalPoint(number.text);
    word.text = std::string(lexer_.source().substr(letter.offset, consumedEnd_ - letter.offset));
    word.line = letter.line;
    word.column = letter.column;
    switch (word.letter) {
      case 'N':
        setSequence(block, letter, number, word);
        break;
      case 'O':
        setProgramNumber(letter, number, word);
        break;
      default:
        block.words.push_back(std::move(word));
    }
  }

  double valueOf(const Token& number) const {
    const NumberReading r = readNumber(number.text);
    if (r.expected) fail(number, r.expected, std::string(number.text));
    return r.value;
  }

  void setSequence(Block& block, const Token& letter, const Token& number, const Word& word) const {
    if (block.sequence) fail(letter, "one sequence number per block", word.text);
    if (!isUnsignedWholeNumber(number.text)) {
      fail(number, "a sequence number without sign or decimal point", std::string(number.text));
    }
    if (word.value > kLargestSequenceNumber) {
      fail(number, "a sequence number of at most 5 digits", std::string(number.text));
    }
    block.sequence = static_cast<long>(word.value);
  }

  void setProgramNumber(const Token& letter, const Token& number, const Word& word) {
    if (program_.number) fail(letter, "one program number per file", word.text);
    if (!isUnsignedWholeNumber(number.text)) {
      fail(number, "a program number without sign or decimal point", std::string(number.text));
    }
    program_.number = static_cast<long>(word.value);
  }

  [[noreturn]] void failMissingNumber(const Token& letter) const {
    const std::string address(1, letter.letter());
    if (current_.kind == TokenKind::Letter) {
      const std::string_view spelling = nonFiniteSpellingAt(lexer_.source(), current_.offset);
      if (!spelling.empty()) {
        fail(current_, "a finite number after address " + address, std::string(spelling));
      }
    }
    fail(current_, "a number after address " + address, describe(current_));
  }

  static std::string describe(const Token& token) {
    switch (token.kind) {
      case TokenKind::Comment:
        return "a comment";
      case TokenKind::EndOfBlock:
        return token.text == ";" ? ";" : "end of line";
      case TokenKind::EndOfInput:
        return "end of input";
      case TokenKind::Letter:
      case TokenKind::Number:
      case TokenKind::ProgramMarker:
      case TokenKind::BlockDelete:
        break;
    }
    return std::string(token.text);
  }

  [[noreturn]] void fail(const Token& at, const std::string& expected,
                         const std::string& found) const {
    throw ParseError({lexer_.file(), at.line, at.column}, expected, found);
  }

  Lexer lexer_;
  Token current_;
  std::size_t consumedEnd_ = 0;  // source offset just past the last token taken
  Program program_;
};

}  // namespace

Program parseProgram(std::string_view text, const std::string& file) {
  return ProgramParser(text, file).parse();
}

}  // namespace cyclecert
