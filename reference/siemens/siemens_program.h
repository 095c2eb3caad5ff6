#pragma once
// A SINUMERIK program as read (seed 004, rules SIEMENS.*): one block per line, each with its words
// (single-letter addresses such as G3 X20.8, and the named ones CR=, CHF=, CHR=, RND=), its R
// parameter and string variable assignments, a cycle call (LCYC95, CYCLE95(…)) and a subprogram
// call (L42). Nothing is evaluated here: the runner (siemens_runner.h) gives the words meaning.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cyclecert {

// An address with a number: "G3", "X20.8", "T1", "CR=8", "CHF=1.5". `address` is upper case, a
// view of the parser's constant name (siemens_parser.cpp), valid for the program's whole run.
struct SiemensWord {
  std::string_view address;
  double value = 0;
  std::string text;  // as written
  int line = 0;
  int column = 0;
};

// `R105=1`.
struct RAssignment {
  int number = 0;
  double value = 0;
  int line = 0;
  int column = 0;
};

// `_CNAME="L42"`.
struct StringAssignment {
  std::string name;  // upper case
  std::string value;
  int line = 0;
  int column = 0;
};

// One argument of a cycle call: a number, a string, or nothing (`, ,`: the cycle's default).
struct CycleArgument {
  std::optional<double> number;
  std::optional<std::string> text;
  int line = 0;
  int column = 0;
  bool empty() const { return !number && !text; }
};

// `LCYC95` or `CYCLE95("L18", 1.5, , 0.3, …)`.
struct CycleCallText {
  std::string name;  // "LCYC95", "CYCLE95", upper case
  bool withArguments = false;
  std::vector<CycleArgument> arguments;
  int line = 0;
  int column = 0;
};

// A word without a value: RET, DIAMON, DIAMOF.
struct SiemensKeyword {
  std::string name;  // upper case
  int line = 0;
  int column = 0;
};

struct SiemensBlock {
  int line = 0;
  std::optional<long> sequence;  // N
  std::vector<SiemensWord> words;
  std::vector<RAssignment> rAssignments;
  std::vector<StringAssignment> strings;
  std::vector<SiemensKeyword> keywords;
  std::optional<CycleCallText> cycle;
  std::optional<SiemensWord> subprogramCall;  // L42: address "L", the name is "L42"
  std::string text;                           // the line as written, without its comment

  const SiemensWord* find(std::string_view address) const;
  bool hasKeyword(std::string_view name) const;
  // M02, M30 (main program), M17 (subprogram) or RET: the program or subprogram ends here.
  bool endsProgram() const;
};

// A program's blocks, read from one text.
struct SiemensBlocks {
  std::string file;
  std::vector<SiemensBlock> blocks;
};

// A subprogram printed after the main program's end, as seed 004 prints its contours: a line
// `L42.spf`, then its blocks up to M02/M17/RET.
struct PrintedSubprogram {
  std::string name;  // "L42"
  int headingLine = 0;
  SiemensBlocks body;
};

struct SiemensProgram {
  SiemensBlocks main;
  std::vector<PrintedSubprogram> printed;
};

}  // namespace cyclecert
