#pragma once
// The SINUMERIK programs the metamorphic relations transform (seed 004; profiles sinumerik-802s,
// sinumerik-802d): a main program and its contour subprograms as text. A SINUMERIK program is not a
// `Program` of the FANUC reader (R parameters, `CYCLE95(…)`, `CR=`, subprograms by name), so its
// numbers are found with the SINUMERIK tokenizer (reference/siemens/siemens_lexer.h) and each gets a
// role; a relation rewrites a number's characters in place, leaving every other character of the
// text as it was (comments, spacing, `T1D1`, the printed `L42.spf` headings).
//
// The vocabulary, by line (anything else is refused with the text, line and column):
//   addresses with a number: G, X Z (absolute), I K (arc centre from the start), F, S, T, D, M, N,
//   L (a subprogram call, or a printed subprogram's heading `L42.spf`);
//   CR= CHF= CHR= RND= (arc radius, chamfer, rounding: lengths);
//   R parameter assignments `R105=1` (R106 R108 R110 lengths; R105 R109 R111 R112 not);
//   `_CNAME="L42"`; `LCYC95`; `CYCLE95("L18", MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT)`;
//   the keywords RET, DIAMON; `;` comments.
// Refused: G91 (incremental positions), G22 and DIAMOF (radius programming: X would not be a
// diameter), G17/G19, G41/G42, any other `NAME=` (AC/IC, variables), a number without an address.
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cyclecert {

// A SINUMERIK case as text: the main program and the contour subprograms given with it (a spec
// case's "subprograms", name → text). Subprograms printed after the main program's M02 (as seed 004
// prints them) are part of `program`.
struct SiemensSource {
  std::string program;
  std::vector<std::pair<std::string, std::string>> subprograms;
};

enum class SiemensRole {
  AbsZ,          // Z
  AbsX,          // X (a diameter: DIAMON / G23)
  CentreZ,       // K
  CentreX,       // I (radius)
  ArcRadius,     // CR=
  CornerLength,  // CHF= CHR= RND=
  LengthParameter,  // R106 (allowance), R108 (infeed depth), R110 (retract) assigned
  OtherParameter,   // R105 (type), R109 (angle), R111 R112 (feeds), any other R assigned
  CycleLength,      // CYCLE95's MID, FALZ, FALX, FAL, DAM, _VRT (arguments 2–5, 11, 12)
  CycleOther,       // CYCLE95's FF1 FF2 FF3 VARI DT
  Other,            // G F S T D M N L and the numbers of LCYC95 / CYCLE95's names
};

// A number of the text: where its characters are, what it means.
struct SiemensNumber {
  std::size_t text = 0;    // 0: the program, k ≥ 1: subprograms[k − 1]
  std::size_t offset = 0;  // in that text
  std::size_t length = 0;
  std::size_t wordOffset = 0;  // where its word starts: the address ("CR" of "CR=10", "X" of "X20")
  double value = 0;
  bool decimalPoint = false;
  SiemensRole role = SiemensRole::Other;
  std::string address;     // "X", "CR", "G", "R106", "CYCLE95"
  int line = 0;            // in its text, 1-based
  std::string where;       // "subprogram L18 line 3, column 5: CR=10", for a person
};

struct SiemensWords {
  std::vector<SiemensNumber> numbers;
  // CYCLE95 calls whose length arguments are empty or missing (they take the cycle's defaults):
  // "line 4: CYCLE95's FALZ (argument 3) is empty".
  std::vector<std::string> defaultedLengths;
};

// The numbers of the source and their roles, or nothing with the first thing outside the
// vocabulary (text, line, column, why).
std::optional<SiemensWords> readSiemensWords(const SiemensSource& source, std::string& whyNot);

// The source with each given number's characters replaced by its new value (formatted as the G-code
// writer formats numbers, keeping a decimal point the number had).
SiemensSource rewriteNumbers(const SiemensSource& source, const std::vector<std::pair<SiemensNumber, double>>& changes);

// A replacement of characters of one text: [from, to) of the program (text 0) or of
// subprograms[text − 1]. Edits must not overlap.
struct SiemensTextEdit {
  std::size_t text = 0, from = 0, to = 0;
  std::string replacement;
};
SiemensSource applyEdits(const SiemensSource& source, std::vector<SiemensTextEdit> edits);

// The edit that replaces a whole word ("CR=10", "I0") by `replacement` ("" removes it).
SiemensTextEdit replaceWord(const SiemensNumber& word, std::string replacement);

}  // namespace cyclecert
