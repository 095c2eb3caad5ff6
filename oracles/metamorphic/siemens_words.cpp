#include "oracles/metamorphic/siemens_words.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <stdexcept>
#include <string_view>

#include "reference/gcode/writer.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_lexer.h"

namespace cyclecert {

namespace {

class Refusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// CYCLE95's arguments by position (1-based): 2 MID, 3 FALZ, 4 FALX, 5 FAL, 11 DAM, 12 _VRT are lengths.
const std::map<std::size_t, std::string>& cycle95LengthArguments() {
  static const std::map<std::size_t, std::string> names = {{2, "MID"},  {3, "FALZ"}, {4, "FALX"},
                                                           {5, "FAL"},  {11, "DAM"}, {12, "_VRT"}};
  return names;
}

SiemensRole addressRole(const std::string& name) {
  if (name == "Z") return SiemensRole::AbsZ;
  if (name == "X") return SiemensRole::AbsX;
  if (name == "K") return SiemensRole::CentreZ;
  if (name == "I") return SiemensRole::CentreX;
  return SiemensRole::Other;
}

SiemensRole parameterRole(double number) {
  return number == 106 || number == 108 || number == 110 ? SiemensRole::LengthParameter : SiemensRole::OtherParameter;
}

// One line's tokens read into numbers with roles.
class LineReader {
 public:
  LineReader(std::string_view line, std::size_t lineOffset, std::size_t text, std::string textName, int lineNumber,
             SiemensWords& out)
      : lexer_(line, textName, lineNumber), lineOffset_(lineOffset), text_(text), textName_(std::move(textName)),
        lineNumber_(lineNumber), out_(out) {
    advance();
  }

  void read() {
    while (current_.kind != SiemensTokenKind::EndOfLine && current_.kind != SiemensTokenKind::Comment) {
      if (current_.kind != SiemensTokenKind::Name) refuse(current_, "a number or sign without an address");
      const SiemensToken name = current_;
      const std::string upper = name.upperName();
      advance();
      if (current_.kind == SiemensTokenKind::Equals) {
        advance();
        namedValue(name, upper);
      } else if (current_.kind == SiemensTokenKind::Number) {
        addressValue(name, upper);
      } else {
        keyword(name, upper);
      }
    }
  }

 private:
  void advance() { current_ = lexer_.next(); }

  [[noreturn]] void refuse(const SiemensToken& at, const std::string& why) const {
    throw Refusal(textName_ + " line " + std::to_string(lineNumber_) + ", column " + std::to_string(at.column) + ": " +
                  std::string(at.text) + ": " + why);
  }

  void note(const SiemensToken& word, const SiemensToken& number, SiemensRole role, const std::string& address,
            const std::string& what) {
    SiemensNumber n;
    n.text = text_;
    n.offset = lineOffset_ + static_cast<std::size_t>(number.column - 1);
    n.length = number.text.size();
    n.wordOffset = lineOffset_ + static_cast<std::size_t>(word.column - 1);
    n.value = number.number;
    n.decimalPoint = number.text.find('.') != std::string_view::npos;
    n.role = role;
    n.address = address;
    n.line = lineNumber_;
    n.where = textName_ + " line " + std::to_string(lineNumber_) + ", column " + std::to_string(number.column) + ": " + what;
    out_.numbers.push_back(n);
  }

  SiemensToken number() {
    if (current_.kind != SiemensTokenKind::Number) refuse(current_, "a number was expected here");
    const SiemensToken n = current_;
    advance();
    return n;
  }

  // X20.8, G3, R105=1, CYCLE95(…), LCYC95.
  void addressValue(const SiemensToken& name, const std::string& upper) {
    const SiemensToken value = number();
    if (upper == "R" && current_.kind == SiemensTokenKind::Equals) {
      advance();
      const SiemensToken assigned = number();
      note(name, assigned, parameterRole(value.number), "R" + std::string(value.text),
           "R" + std::string(value.text) + "=" + std::string(assigned.text));
      return;
    }
    if (upper == "G") refuseGCode(value);
    if (upper == "CYCLE" && value.number == 95) {
      cycle95Arguments(name);
      return;
    }
    if (upper.size() > 1 && !(upper == "LCYC" && value.number == 95)) {
      refuse(name, std::string(value.text) + " is not in the relations' vocabulary (of the cycles, LCYC95 and CYCLE95 are)");
    }
    if (upper.size() == 1 && std::string_view("GXZIKFSTDMNL").find(upper[0]) == std::string_view::npos) {
      refuse(name, "this address is not in the relations' vocabulary");
    }
    note(name, value, addressRole(upper), upper, upper + std::string(value.text));
  }

  void refuseGCode(const SiemensToken& value) {
    const int g = gCode10(value.number);
    if (g == 910) refuse(value, "G91 (incremental positions) is not handled: a translation would move every increment");
    if (g == 220) refuse(value, "G22 (radius programming) is not handled: the relations read X as a diameter");
    if (g == 170 || g == 190) refuse(value, "the relations start from G18 programs");
    if (g == 410 || g == 420) refuse(value, "nose-radius compensation is not handled (a mirror changes its side)");
  }

  // CR=8, CHF=1.5, _CNAME="L42".
  void namedValue(const SiemensToken& name, const std::string& upper) {
    if (upper == "_CNAME") {
      if (current_.kind != SiemensTokenKind::String) refuse(current_, "_CNAME takes a string");
      advance();
      return;
    }
    const bool corner = upper == "CHF" || upper == "CHR" || upper == "RND";
    if (upper != "CR" && !corner) refuse(name, "this NAME= is not in the relations' vocabulary");
    const SiemensToken value = number();
    note(name, value, corner ? SiemensRole::CornerLength : SiemensRole::ArcRadius, upper,
         upper + "=" + std::string(value.text));
  }

  void keyword(const SiemensToken& name, const std::string& upper) {
    if (upper == "DIAMOF") refuse(name, "radius programming is not handled: the relations read X as a diameter");
    if (upper != "RET" && upper != "DIAMON") refuse(name, "not in the relations' vocabulary");
  }

  // ("L18", 1.5, , 0.3, …): the arguments by position; an empty or missing length argument is noted.
  void cycle95Arguments(const SiemensToken& name) {
    if (current_.kind != SiemensTokenKind::OpenParen) refuse(current_, "CYCLE95 takes its arguments in '(…)'");
    advance();
    std::size_t position = 1;
    std::set<std::size_t> given;
    while (true) {
      if (current_.kind == SiemensTokenKind::Number) {
        const auto length = cycle95LengthArguments().find(position);
        note(current_, current_, length != cycle95LengthArguments().end() ? SiemensRole::CycleLength : SiemensRole::CycleOther,
             "CYCLE95", "CYCLE95 argument " + std::to_string(position) + " " + std::string(current_.text));
        given.insert(position);
        advance();
      } else if (current_.kind == SiemensTokenKind::String) {
        advance();
      }
      if (current_.kind == SiemensTokenKind::CloseParen) break;
      if (current_.kind != SiemensTokenKind::Comma) refuse(current_, "',' or ')' in CYCLE95's arguments");
      advance();
      ++position;
    }
    advance();
    for (const auto& [index, argument] : cycle95LengthArguments()) {
      if (!given.count(index)) {
        out_.defaultedLengths.push_back(textName_ + " line " + std::to_string(lineNumber_) + ", column " +
                                        std::to_string(name.column) + ": CYCLE95's " + argument + " (argument " +
                                        std::to_string(index) + ") is empty: it takes the cycle's default");
      }
    }
  }

  SiemensLexer lexer_;
  SiemensToken current_;
  std::size_t lineOffset_, text_;
  std::string textName_;
  int lineNumber_;
  SiemensWords& out_;
};

// A printed subprogram's heading (SIEMENS.SUB): a line `NAME.spf` of its own.
bool isPrintedHeading(std::string_view line) {
  while (!line.empty() && (line.back() == ' ' || line.back() == '\t')) line.remove_suffix(1);
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t')) line.remove_prefix(1);
  if (line.size() < 5 || line.find_first_of(" \t;") != std::string_view::npos) return false;
  std::string tail(line.substr(line.size() - 4));
  for (char& c : tail) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return tail == ".spf";
}

void readText(const std::string& text, std::size_t index, const std::string& name, SiemensWords& out) {
  std::size_t start = 0;
  int lineNumber = 1;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (isPrintedHeading(line)) {  // SIEMENS.SUB: `L42.spf`, a name, not a block
      start = end + 1;
      ++lineNumber;
      continue;
    }
    try {
      LineReader(line, start, index, name, lineNumber, out).read();
    } catch (const ParseError& e) {
      throw Refusal(name + " line " + std::to_string(lineNumber) + ", column " + std::to_string(e.loc().column) +
                    ": expected " + e.expected() + ", found " + e.found());
    }
    start = end + 1;
    ++lineNumber;
  }
}

}  // namespace

std::optional<SiemensWords> readSiemensWords(const SiemensSource& source, std::string& whyNot) {
  SiemensWords out;
  try {
    readText(source.program, 0, "the program", out);
    for (std::size_t k = 0; k < source.subprograms.size(); ++k) {
      readText(source.subprograms[k].second, k + 1, "subprogram " + source.subprograms[k].first, out);
    }
  } catch (const Refusal& r) {
    whyNot = r.what();
    return std::nullopt;
  }
  return out;
}

SiemensSource applyEdits(const SiemensSource& source, std::vector<SiemensTextEdit> edits) {
  SiemensSource out = source;
  std::sort(edits.begin(), edits.end(), [](const SiemensTextEdit& a, const SiemensTextEdit& b) {
    return a.text != b.text ? a.text < b.text : a.from > b.from;  // last first: earlier offsets stay valid
  });
  for (const SiemensTextEdit& e : edits) {
    std::string& text = e.text == 0 ? out.program : out.subprograms[e.text - 1].second;
    text.replace(e.from, e.to - e.from, e.replacement);
  }
  return out;
}

SiemensSource rewriteNumbers(const SiemensSource& source, const std::vector<std::pair<SiemensNumber, double>>& changes) {
  std::vector<SiemensTextEdit> edits;
  for (const auto& [n, value] : changes) {
    edits.push_back({n.text, n.offset, n.offset + n.length, formatNumber(value, n.decimalPoint)});
  }
  return applyEdits(source, std::move(edits));
}

SiemensTextEdit replaceWord(const SiemensNumber& word, std::string replacement) {
  return {word.text, word.wordOffset, word.offset + word.length, std::move(replacement)};
}

}  // namespace cyclecert
