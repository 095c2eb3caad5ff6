#include "reference/siemens/siemens_subprograms.h"

#include "reference/model/ascii.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_parser.h"

namespace cyclecert {

SiemensSubprograms::SiemensSubprograms(const SiemensProgram& program, std::vector<GivenSubprogram> given,
                                       std::string siblingDirectory, SiemensSubprogramParser parse)
    : program_(program), given_(std::move(given)), siblingDirectory_(std::move(siblingDirectory)), parse_(std::move(parse)) {}

std::shared_ptr<const SiemensBlocks> SiemensSubprograms::parsed(std::string_view text, const std::string& file) const {
  if (parse_) return parse_(text, file);
  return std::make_shared<const SiemensBlocks>(parseSiemensSubprogram(text, file));
}

namespace {

// SIEMENS.SUB (interpretation): a contour subprogram holds the contour. A subprogram call in it (L42;
// the contour's own name would recur without end) or a cycle call is refused at its line and
// column rather than passed over: the reference follows no call from a contour.
const SiemensBlocks& contourOnly(const SiemensBlocks& sub, const std::string& name) {
  for (const SiemensBlock& b : sub.blocks) {
    if (!b.subprogramCall && !b.cycle) continue;
    const std::string expected = "a block of the contour " + name +
                                 " (G0–G3 with X, Z, CR=, I/K, CHF=, CHR=, RND=, F; RET or M17 at its end): "
                                 "the reference follows no call from a contour";
    if (b.subprogramCall) {
      const bool itself = equalIgnoringCase(b.subprogramCall->text, name);
      throw ParseError({sub.file, b.line, b.subprogramCall->column}, expected,
                       "the subprogram call " + b.subprogramCall->text + (itself ? " (the contour calling itself)" : ""));
    }
    if (b.cycle) throw ParseError({sub.file, b.line, b.cycle->column}, expected, "the cycle call " + b.cycle->name);
  }
  return sub;
}

}  // namespace

const SiemensBlocks& SiemensSubprograms::find(const std::string& name, const std::string& file, int line, int column) {
  return contourOnly(located(name, file, line, column), name);
}

std::shared_ptr<const SiemensBlocks> SiemensSubprograms::kept(const std::string& name) const {
  for (const PrintedSubprogram& p : program_.printed) {
    if (equalIgnoringCase(p.name, name)) return nullptr;
  }
  std::string key = name;
  for (char& c : key) c = asciiUpper(c);
  const auto found = read_.find(key);
  return found != read_.end() ? found->second : nullptr;
}

const SiemensBlocks& SiemensSubprograms::located(const std::string& name, const std::string& file, int line, int column) {
  for (const PrintedSubprogram& p : program_.printed) {
    if (equalIgnoringCase(p.name, name)) return p.body;
  }
  std::string key = name;
  for (char& c : key) c = asciiUpper(c);
  if (const auto found = read_.find(key); found != read_.end()) return *found->second;
  for (const GivenSubprogram& g : given_) {
    if (!equalIgnoringCase(g.name, name)) continue;
    return *read_.emplace(key, parsed(g.text, g.file)).first->second;
  }
  if (!siblingDirectory_.empty()) {
    if (const auto sibling = readSiblingSubprogram(siblingDirectory_, name)) {
      return *read_.emplace(key, parsed(sibling->second, sibling->first)).first->second;
    }
  }
  const std::string sibling = siblingDirectory_.empty() ? std::string("a file ") + name + ".spf next to the main program (when it is read from a file)"
                                                        : "a file " + name + ".spf or " + name + ".SPF in " + siblingDirectory_;
  throw ParseError({file, line, column},
                   "the subprogram " + name + ": printed after the main program's M02/M30 under a line '" + name +
                       ".spf', in the case's \"subprograms\" object, or " + sibling,
                   "no subprogram " + name);
}

}  // namespace cyclecert
