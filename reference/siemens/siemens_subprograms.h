#pragma once
// Where a contour subprogram named by _CNAME (LCYC95) or NPP (CYCLE95) is found (rule
// SIEMENS.SUB): (1) printed after the main program's M02/M30 (a line `L42.spf`, then its blocks),
// (2) given with the program — a spec case's "subprograms" object (name → text), (3) a sibling
// file NAME.spf or NAME.SPF next to the main program. Names compare without regard to case.
#include <map>
#include <memory>
#include <string>
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

class SiemensSubprograms {
 public:
  // `siblingDirectory`: the main program's directory, searched for NAME.spf / NAME.SPF; empty:
  // no files are searched (a spec case, a program read from text).
  SiemensSubprograms(const SiemensProgram& program, std::vector<GivenSubprogram> given, std::string siblingDirectory);

  // The subprogram's blocks. Throws ParseError at `where` (the _CNAME or NPP that names it) when
  // it is in none of the three places, naming them.
  const SiemensBlocks& find(const std::string& name, const std::string& file, int line, int column);

 private:
  const SiemensProgram& program_;
  std::vector<GivenSubprogram> given_;
  std::string siblingDirectory_;
  std::map<std::string, std::unique_ptr<SiemensBlocks>> read_;  // by upper-case name
};

// The text of NAME.spf or NAME.SPF in `directory` and its path, or nothing.
std::optional<std::pair<std::string, std::string>> readSiblingSubprogram(const std::string& directory,
                                                                         const std::string& name);

}  // namespace cyclecert
