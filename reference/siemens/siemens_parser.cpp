#include "reference/siemens/siemens_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <utility>
#include <vector>

#include "reference/model/ascii.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_lexer.h"

namespace cyclecert {

namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
constexpr double kLargestSequenceNumber = 9999;  // 802S/D: N0…N9999 (interpretation, SIEMENS.LEX)
// SIEMENS.LEX (interpretation, issue 19): the values cyclecert reads — positions, centres, radii,
// corner sizes, feeds and cycle arguments — lie within ±999,999.999 (mm or mm/rev; the same bound
// as the FANUC profiles' IS-B words), an R parameter's value within ±99,999,999 (the 802's eight
// digits); a larger number is refused where it is written rather than planned.
constexpr double kLargestValue = 999'999.999;
constexpr double kLargestRValue = 99'999'999;
// Every name a block may hold, upper case, the addresses with numbers first: a name is read as the
// entry it equals ignoring case (readName; no upper-case copy of each name is made). `bounded`: the
// values written after it lie within ±kLargestValue.
struct KnownName {
  std::string_view name;
  bool bounded = false;
};
constexpr KnownName kNames[] = {
    {"G"}, {"X", true}, {"Z", true}, {"I", true}, {"K", true}, {"F", true}, {"S"}, {"T"}, {"D"}, {"M"}, {"N"}, {"L"},
    {"R"}, {"CR", true}, {"CHF", true}, {"CHR", true}, {"RND", true},
    {"_CNAME"}, {"LCYC"}, {"CYCLE"}, {"RET"}, {"DIAMON"}, {"DIAMOF"}};
constexpr const char* kEverythingAccepted =
    "an address (G X Z I K F S T D M N L), R<n>=, CR=, CHF=, CHR=, RND=, _CNAME=, a cycle (LCYC95, CYCLE95(…)), "
    "RET, DIAMON, DIAMOF or a ';' comment";

struct Line {
  std::string_view text;  // without its line end
  int number = 0;
};

std::vector<Line> splitLines(std::string_view text) {
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  std::vector<Line> lines;
  std::size_t start = 0;
  int number = 1;
  while (start <= text.size()) {
    std::size_t end = start;
    while (end < text.size() && text[end] != '\n' && text[end] != '\r') ++end;
    lines.push_back({text.substr(start, end - start), number++});
    if (end >= text.size()) break;
    start = end + ((text[end] == '\r' && end + 1 < text.size() && text[end + 1] == '\n') ? 2 : 1);
  }
  return lines;
}

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

// `L42.spf` (or .SPF, any case) alone on its line, a comment allowed after it: the subprogram's name.
std::optional<std::string> subprogramHeading(std::string_view line) {
  std::string_view s = trimmed(line.substr(0, line.find(';')));
  const std::size_t dot = s.find('.');
  if (dot == std::string_view::npos || dot == 0 || !equalIgnoringCase(s.substr(dot), ".spf")) return std::nullopt;
  const std::string_view name = s.substr(0, dot);
  for (char c : name) {
    const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return std::nullopt;
  }
  std::string upper(name);
  for (char& c : upper) c = asciiUpper(c);
  return upper;
}

std::string describe(const SiemensToken& t) {
  switch (t.kind) {
    case SiemensTokenKind::EndOfLine: return "end of line";
    case SiemensTokenKind::Comment: return "a ';' comment";
    default: return std::string(t.text);
  }
}

// A line without words (blank, or a comment only) is no block.
bool holdsNothing(const SiemensBlock& b) {
  return b.words.empty() && b.rAssignments.empty() && b.strings.empty() && b.keywords.empty() && !b.cycle &&
         !b.subprogramCall && !b.sequence;
}

// Reads the tokens of one line into a block (`block`, empty: read in place where it is kept, since
// moving a block costs as much as a word).
class BlockParser {
 public:
  // `lexer`: at the start of the block's line.
  BlockParser(SiemensLexer& lexer, SiemensBlock& block) : lexer_(lexer), current_(lexer_.next()), block_(block) {
    block_.line = lexer_.lineNumber();
  }

  void parse() {
    while (current_.kind != SiemensTokenKind::EndOfLine && current_.kind != SiemensTokenKind::Comment) item();
    const std::size_t commentAt = current_.kind == SiemensTokenKind::Comment ? static_cast<std::size_t>(current_.column - 1)
                                                                             : lexer_.line().size();
    block_.text = std::string(trimmed(lexer_.line().substr(0, commentAt)));
  }

 private:
  SiemensToken advance() { return std::exchange(current_, lexer_.next()); }

  [[noreturn]] void fail(const SiemensToken& at, const std::string& expected) const {
    throw ParseError({lexer_.file(), lexer_.lineNumber(), at.column}, expected, describe(at));
  }

  // `expected()` says what was expected: the message is only built for an error (a parse builds
  // none, and its words are most of a fuzz case's parsing).
  template <class Expected>
  SiemensToken expect(SiemensTokenKind kind, const Expected& expected) {
    if (current_.kind != kind) fail(current_, expected());
    return advance();
  }

  // The entry of kNames the name `name` is, or nullptr. Its first letter is compared before the
  // whole name (a name is a token: never empty): most names are one letter, and most entries fail
  // there.
  static const KnownName* readName(const SiemensToken& name) {
    const char first = asciiUpper(name.text.front());
    for (const KnownName& known : kNames) {
      if (known.name.front() == first && equalIgnoringCase(name.text, known.name)) return &known;
    }
    return nullptr;
  }

  void item() {
    if (current_.kind != SiemensTokenKind::Name) fail(current_, kEverythingAccepted);
    const SiemensToken name = advance();
    const KnownName* known = readName(name);
    if (!known) fail(name, kEverythingAccepted);
    const std::string_view is = known->name;
    if (is == "R") return rAssignment(name);
    if (is == "CR" || is == "CHF" || is == "CHR" || is == "RND") return namedValue(name, is);
    if (is == "_CNAME") return stringAssignment(name, std::string(is));
    if (is == "LCYC" || is == "CYCLE") return cycleCall(name, std::string(is));
    if (is == "RET" || is == "DIAMON" || is == "DIAMOF") {
      block_.keywords.push_back({std::string(is), lexer_.lineNumber(), name.column});
      return;
    }
    return addressWord(name, *known);  // G X Z I K F S T D M N L
  }

  // The word as written: its name, `between` (a named value's '=') and its number, without the
  // blanks written between them. The tokens are views into the line, in its order: where they
  // follow each other without a blank (as words are written) the word is one piece of the line.
  SiemensWord wordFrom(const SiemensToken& name, std::string_view address, const SiemensToken& number,
                       std::string_view between) const {
    const std::size_t length = name.text.size() + between.size() + number.text.size();
    if (number.text.data() + number.text.size() == name.text.data() + length) {  // one piece
      return {address, number.number, std::string(name.text.data(), length), lexer_.lineNumber(), name.column};
    }
    std::string text;
    text.reserve(length);
    text.append(name.text).append(between).append(number.text);
    return {address, number.number, std::move(text), lexer_.lineNumber(), name.column};
  }

  void addressWord(const SiemensToken& name, const KnownName& known) {
    const std::string_view address = known.name;
    if (current_.kind == SiemensTokenKind::Equals) {
      fail(current_, "a number right after address " + std::string(address) + " (" + std::string(address) +
                         "=… is not in the 802's language)");
    }
    const SiemensToken number =
        expect(SiemensTokenKind::Number, [address] { return "a number after address " + std::string(address); });
    if (known.bounded) {
      requireWithin(number, kLargestValue, [address] { return "a value of " + std::string(address); });
    }
    SiemensWord word = wordFrom(name, address, number, "");
    if (address == "N") return sequence(number, word);
    if (address == "L") return subprogramCall(number, std::move(word));
    keepWord(name, std::move(word));
  }

  // A number outside ±largest, refused at its token naming the bound and what it is for (`what()`,
  // built only then).
  template <class What>
  void requireWithin(const SiemensToken& number, double largest, const What& what) const {
    if (std::abs(number.number) <= largest) return;
    char bound[32];
    std::snprintf(bound, sizeof bound, "%.3f", largest);
    std::string text = bound;
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
    fail(number, what() + " within -" + text + "…" + text);
  }

  // One word of an address per block (G and M may repeat: codes of different groups); a second
  // would leave which one counts to the reader (interpretation, SIEMENS.LEX).
  void keepWord(const SiemensToken& name, SiemensWord word) {
    if (word.address != "G" && word.address != "M") {
      if (const SiemensWord* first = block_.find(word.address)) {
        throw ParseError({lexer_.file(), lexer_.lineNumber(), name.column},
                         "one " + std::string(word.address) + " word per block (" + first->text + " at column " +
                             std::to_string(first->column) + ")",
                         word.text);
      }
    }
    // Room for a block's usual words at once (G X Z and one more) rather than growing 1, 2, 4.
    if (block_.words.empty()) block_.words.reserve(4);
    block_.words.push_back(std::move(word));
  }

  void sequence(const SiemensToken& number, const SiemensWord& word) {
    if (block_.sequence) fail(number, "one N number per block");
    if (number.text.find_first_not_of("0123456789") != std::string_view::npos || word.value > kLargestSequenceNumber) {
      fail(number, "a block number N0…N9999 without sign or decimal point");
    }
    block_.sequence = static_cast<long>(word.value);
  }

  // L42: the subprogram named "L42" (seed 004's contours are named so).
  void subprogramCall(const SiemensToken& number, SiemensWord word) {
    if (number.text.find_first_not_of("0123456789") != std::string_view::npos) {
      fail(number, "a subprogram number after L (L42), without sign or decimal point");
    }
    if (block_.subprogramCall) fail(number, "one subprogram call per block");
    word.text = "L" + std::string(number.text);
    block_.subprogramCall = std::move(word);
  }

  void rAssignment(const SiemensToken& name) {
    const SiemensToken number =
        expect(SiemensTokenKind::Number, [] { return std::string("an R parameter number after R (R105=…)"); });
    if (number.text.find_first_not_of("0123456789") != std::string_view::npos || number.number > 999) {
      fail(number, "an R parameter number 0…999 without sign or decimal point");
    }
    const std::string_view r = number.text;
    expect(SiemensTokenKind::Equals, [r] { return "'=' after R" + std::string(r) + " (R" + std::string(r) + "=value)"; });
    const SiemensToken value = expect(SiemensTokenKind::Number, [r] {
      return "a number after R" + std::string(r) + "= (expressions and other parameters are not read)";
    });
    requireWithin(value, kLargestRValue, [r] { return "a value of R" + std::string(r); });
    block_.rAssignments.push_back({static_cast<int>(number.number), value.number, lexer_.lineNumber(), name.column});
  }

  void namedValue(const SiemensToken& name, std::string_view address) {
    const SiemensToken equals = expect(SiemensTokenKind::Equals, [address] {
      return "'=' after " + std::string(address) + " (" + std::string(address) + "=value)";
    });
    const SiemensToken number =
        expect(SiemensTokenKind::Number, [address] { return "a number after " + std::string(address) + "="; });
    requireWithin(number, kLargestValue, [address] { return "a value of " + std::string(address) + "="; });
    keepWord(name, wordFrom(name, address, number, equals.text));
  }

  void stringAssignment(const SiemensToken& name, const std::string& variable) {
    expect(SiemensTokenKind::Equals, [&] { return "'=' after " + variable + " (" + variable + "=\"L42\")"; });
    const SiemensToken value =
        expect(SiemensTokenKind::String, [&] { return "a subprogram name in double quotes after " + variable + "="; });
    block_.strings.push_back({variable, std::string(value.stringBody()), lexer_.lineNumber(), name.column});
  }

  void cycleCall(const SiemensToken& name, const std::string& prefix) {
    const SiemensToken number =
        expect(SiemensTokenKind::Number, [&] { return "the cycle's number after " + prefix + " (" + prefix + "95)"; });
    if (block_.cycle) fail(name, "one cycle call per block");
    CycleCallText call;
    call.name = prefix + std::string(number.text);
    call.line = lexer_.lineNumber();
    call.column = name.column;
    if (current_.kind == SiemensTokenKind::OpenParen) {
      advance();
      call.withArguments = true;
      arguments(call);
    }
    block_.cycle = std::move(call);
  }

  // (a, "b", , c): an argument is a number, a string or nothing; ',' separates, ')' ends.
  void arguments(CycleCallText& call) {
    for (;;) {
      CycleArgument arg;
      arg.line = lexer_.lineNumber();
      arg.column = current_.column;
      if (current_.kind == SiemensTokenKind::Number) {
        requireWithin(current_, kLargestValue,
                      [&] { return "argument " + std::to_string(call.arguments.size() + 1) + " of " + call.name; });
        arg.number = advance().number;
      } else if (current_.kind == SiemensTokenKind::String) {
        arg.text = std::string(advance().stringBody());
      }
      call.arguments.push_back(std::move(arg));
      if (current_.kind == SiemensTokenKind::CloseParen) {
        advance();
        return;
      }
      expect(SiemensTokenKind::Comma, [&] {
        return "',' or ')' after argument " + std::to_string(call.arguments.size()) + " of " + call.name +
               " (an argument is a number, a \"string\" or empty)";
      });
    }
  }

  SiemensLexer& lexer_;
  SiemensToken current_;
  SiemensBlock& block_;
};

// The blocks of `lines`, in order; `printed` collects the subprograms printed after the main
// program (nullptr: a heading is refused).
SiemensBlocks parseLines(const std::vector<Line>& lines, const std::string& file,
                         std::vector<PrintedSubprogram>* printed) {
  SiemensBlocks main{file, {}};
  // A block per line at most: a program of usual length is read without moving a block as the
  // vector grows; a longer one's vector grows as its blocks come (a file of a million blank lines
  // reserves no more than this).
  constexpr std::size_t kBlocksReservedAtOnce = 1024;
  main.blocks.reserve(std::min(lines.size(), kBlocksReservedAtOnce));
  SiemensBlocks* section = &main;
  SiemensLexer lexer({}, file, 0);  // one for the whole text: the file's name is copied once
  int endLine = 0;  // the line of the current section's M02/M17/M30/RET, 0 before it
  std::size_t blocks = 0;
  for (const Line& line : lines) {
    if (const auto name = subprogramHeading(line.text)) {
      const int column = static_cast<int>(line.text.find_first_not_of(" \t")) + 1;
      if (!printed) {
        throw ParseError({file, line.number, column}, "a block of the subprogram (a heading NAME.spf only in a main program)",
                         std::string(trimmed(line.text)));
      }
      if (!endLine) {
        throw ParseError({file, line.number, column},
                         "the program's end (M02, M30, M17 or RET) before the subprogram heading", std::string(trimmed(line.text)));
      }
      printed->push_back({*name, line.number, {file, {}}});
      section = &printed->back().body;
      endLine = 0;
      continue;
    }
    SiemensBlock& block = section->blocks.emplace_back();
    lexer.startLine(line.text, line.number);
    BlockParser(lexer, block).parse();
    if (holdsNothing(block)) {
      section->blocks.pop_back();
      continue;
    }
    if (endLine) {
      throw ParseError({file, line.number, 1},
                       std::string("nothing after the end at line ") + std::to_string(endLine) +
                           (printed ? " but a subprogram heading NAME.spf (a line of its own, e.g. L42.spf)" : ""),
                       block.text);
    }
    if (block.endsProgram()) endLine = block.line;
    requireBlockWithinTheCap(++blocks, file, line.number);  // PROG.CAP.BLOCKS, printed subprograms included
  }
  return main;
}

}  // namespace

SiemensProgram parseSiemensProgram(std::string_view text, const std::string& file) {
  SiemensProgram program;
  program.main = parseLines(splitLines(text), file, &program.printed);
  return program;
}

SiemensBlocks parseSiemensSubprogram(std::string_view text, const std::string& file) {
  return parseLines(splitLines(text), file, nullptr);
}

}  // namespace cyclecert
