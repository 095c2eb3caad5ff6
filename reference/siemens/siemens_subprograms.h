#pragma once
// Where a contour subprogram named by _CNAME (LCYC95) or NPP (CYCLE95) is found (rule
// SIEMENS.SUB): (1) printed after the main program's M02/M30 (a line `L42.spf`, then its blocks),
// (2) given with the program — a spec case's "subprograms" object (name → text), (3) a sibling
// file NAME.spf or NAME.SPF next to the main program. Names compare without regard to case.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "reference/siemens/siemens_program.h"

namespace cyclecert {

// Subprogram texts given with a program: name → text, and how errors name where they came from
// ("case.json#/subprograms/L42").
struct GivenSubprogram {
  std::string name;
  std::string text;
  std::string file;
};

// Reads a subprogram's text into blocks as parseSiemensSubprogram does (a caller that reads the
// same subprogram more than once may keep what it parsed). Empty: parseSiemensSubprogram.
using SiemensSubprogramParser = std::function<std::shared_ptr<const SiemensBlocks>(std::string_view text, const std::string& file)>;

class SiemensSubprograms {
 public:
  // `siblingDirectory`: the main program's directory, searched for NAME.spf / NAME.SPF; empty:
  // no files are searched (a spec case, a program read from text). A subprogram is parsed when it
  // is first found, by `parse`.
  SiemensSubprograms(const SiemensProgram& program, std::vector<GivenSubprogram> given, std::string siblingDirectory,
                     SiemensSubprogramParser parse = {});

  // The subprogram's blocks. Throws ParseError at `where` (the _CNAME or NPP that names it) when
  // it is in none of the three places, naming them; at the call when the contour calls a
  // subprogram (itself included) or a cycle.
  const SiemensBlocks& find(const std::string& name, const std::string& file, int line, int column);

  // The parse of a subprogram found (find) in the case's "subprograms" or a sibling file, as the
  // parser returned it (shared with the caller's other reads of the same text); nothing for one
  // printed after the main program (part of the program's parse) or not found yet.
  std::shared_ptr<const SiemensBlocks> kept(const std::string& name) const;

 private:
  const SiemensBlocks& located(const std::string& name, const std::string& file, int line, int column);
  const SiemensProgram& program_;
  std::vector<GivenSubprogram> given_;
  std::string siblingDirectory_;
  SiemensSubprogramParser parse_;
  std::map<std::string, std::shared_ptr<const SiemensBlocks>> read_;  // by upper-case name

  std::shared_ptr<const SiemensBlocks> parsed(std::string_view text, const std::string& file) const;
};

// The text of NAME.spf or NAME.SPF in `directory` and its path, or nothing.
std::optional<std::pair<std::string, std::string>> readSiblingSubprogram(const std::string& directory,
                                                                         const std::string& name);

}  // namespace cyclecert
