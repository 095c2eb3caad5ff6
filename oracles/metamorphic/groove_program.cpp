#include "oracles/metamorphic/groove_program.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <string_view>

#include "reference/gcode/writer.h"

namespace cyclecert {

namespace {

constexpr int kG74_1 = 741;

bool letterIn(char letter, std::string_view letters) { return letters.find(letter) != std::string_view::npos; }

// The reader's way out: the first word or block outside the vocabulary.
class Refusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

[[noreturn]] void refuse(const Block& b, const std::string& what, const std::string& why) {
  throw Refusal("line " + std::to_string(b.line) + ": " + what + ": " + why);
}
[[noreturn]] void refuse(const Block& b, const Word& w, const std::string& why) {
  refuse(b, w.text.empty() ? formatWord(w) : w.text, why);
}

bool isKeptCode(int g10) {
  static const std::set<int> codes = {180, 210, 400, 970, 980, 990};
  return codes.count(g10) != 0;
}

std::string refusalOfCode(int g10) {
  if (g10 == 200) return "inch programs (G20) are not handled: the relations' constants are in mm";
  if (g10 == 20 || g10 == 30) return "arcs outside the cycle are not in the G74.1 programs' vocabulary";
  if (g10 == 410 || g10 == 420) return "nose-radius compensation is not handled (a mirror changes its side)";
  if (g10 == 960) return "G96 makes the spindle speed depend on the radius: not in the G74.1 programs' vocabulary";
  if (g10 == 40) return "G04's X/U is a dwell time, not a length";
  return "this G code is not in the G74.1 programs' vocabulary";
}

double cotangent(double degrees) { return 1 / std::tan(degrees * std::numbers::pi / 180); }

double valueOr(const Block& b, char letter, double fallback) {
  const Word* w = b.find(letter);
  return w ? w->value : fallback;
}

// docs/g74_1.md §3–§5: how far from its start (along x, radius) a groove and the tool cutting it
// may reach, whichever the sign of d; generous, since a mirror line only needs to lie beyond it.
double grooveReach(const Block& groove, const Block* cutting) {
  const double h = std::abs(valueOr(groove, 'H', 0)), d = std::abs(valueOr(groove, 'D', 0));
  const double a = std::clamp(valueOr(groove, 'A', 90), 1e-3, 90.0), b = std::clamp(valueOr(groove, 'B', 90), 1e-3, 90.0);
  double reach = h * (cotangent(a) + cotangent(b)) + d / 2 + 1;
  if (cutting) {
    reach += 2 * std::abs(valueOr(*cutting, 'I', 0)) + std::abs(valueOr(*cutting, 'A', 0)) +
             std::abs(valueOr(*cutting, 'B', 0)) + std::abs(valueOr(*cutting, 'U', 0));
  }
  return reach;
}

GrooveBlockKind classify(const Block& b) {
  std::set<char> seen;
  bool groove = false;
  int motionCodes = 0;
  for (const Word& w : b.words) {
    if (!letterIn(w.letter, "GMXZUWPQHDABLRVIJEFST")) refuse(b, w, "this address is not in the G74.1 programs' vocabulary");
    if (w.letter != 'G' && w.letter != 'M' && !seen.insert(w.letter).second) {
      refuse(b, w, "a second word of the same address in one block");
    }
    if (w.letter != 'G') continue;
    const int g10 = gCode10(w.value);
    if (g10 == kG74_1) {
      groove = true;
    } else if (g10 == 0 || g10 == 10) {
      ++motionCodes;
    } else if (!isKeptCode(g10)) {
      refuse(b, w, refusalOfCode(g10));
    }
  }
  if (!groove) {
    for (const Word& w : b.words) {
      if (!letterIn(w.letter, "GMXZUWFST")) refuse(b, w, "outside a G74.1 block only X Z U W F S T M are handled");
    }
    if (b.has('X') && b.has('U')) refuse(b, "X and U", "absolute and incremental words for one axis");
    if (b.has('Z') && b.has('W')) refuse(b, "Z and W", "absolute and incremental words for one axis");
    return GrooveBlockKind::Plain;
  }
  if (motionCodes) refuse(b, "the block", "a motion code in a G74.1 block");
  // I1: a G74.1 block with X or Z gives the groove; one without them cuts it.
  const bool givesTheGroove = b.has('X') || b.has('Z');
  const std::string_view allowed = givesTheGroove ? "GXZPQHDABLFSTM" : "GRVUWIJABDEPFSTM";
  for (const Word& w : b.words) {
    if (!letterIn(w.letter, allowed)) {
      refuse(b, w,
             givesTheGroove ? "not an address of the groove block (X Z P Q H D A B L)"
                            : "not an address of the cutting block (R V U W I J A B D E P)");
    }
  }
  return givesTheGroove ? GrooveBlockKind::Groove : GrooveBlockKind::Cutting;
}

GrooveProgram read(const Program& program) {
  GrooveProgram out;
  double x = 0;  // radius; power-on at 0
  const Block* lastGroove = nullptr;
  for (const Block& b : program.blocks) {
    const GrooveBlockKind kind = classify(b);
    out.blocks.push_back(kind);
    if (kind == GrooveBlockKind::Plain) {
      if (const Word* w = b.find('X')) x = w->value / 2;
      if (const Word* w = b.find('U')) x += w->value / 2;
      out.largestRadius = std::max(out.largestRadius, std::abs(x));
      continue;
    }
    if (kind == GrooveBlockKind::Groove) lastGroove = &b;
    if (!lastGroove) continue;  // a cutting block without a groove alarms; it moves nothing
    const double start = std::abs(valueOr(*lastGroove, 'X', 0)) / 2;
    const Block* cutting = kind == GrooveBlockKind::Cutting ? &b : nullptr;
    out.largestRadius = std::max(out.largestRadius, start + grooveReach(*lastGroove, cutting));
  }
  if (std::none_of(out.blocks.begin(), out.blocks.end(), [](GrooveBlockKind k) { return k != GrooveBlockKind::Plain; })) {
    throw Refusal("no G74.1 block");
  }
  return out;
}

}  // namespace

bool isGrooveProgram(const Program& program) {
  return std::any_of(program.blocks.begin(), program.blocks.end(), [](const Block& b) { return b.hasG(kG74_1); });
}

std::optional<GrooveProgram> readGrooveProgram(const Program& program, std::string& whyNot) {
  try {
    return read(program);
  } catch (const Refusal& r) {
    whyNot = r.what();
    return std::nullopt;
  }
}

GrooveRole grooveRoleOf(GrooveBlockKind kind, const Word& w) {
  switch (w.letter) {
    case 'G': return GrooveRole::Code;
    case 'F': return GrooveRole::Feed;
    case 'S':
    case 'T':
    case 'M': return GrooveRole::Passive;
    case 'X': return GrooveRole::AbsSecond;
    case 'Z': return GrooveRole::AbsFirst;
    default: break;
  }
  switch (kind) {
    case GrooveBlockKind::Plain: return w.letter == 'U' ? GrooveRole::IncSecond : GrooveRole::IncFirst;
    case GrooveBlockKind::Groove:
      switch (w.letter) {
        case 'P':
        case 'Q': return GrooveRole::Step;
        case 'H': return GrooveRole::Depth;
        case 'D': return GrooveRole::FloorWidth;
        default: return GrooveRole::Angle;  // A B L
      }
    case GrooveBlockKind::Cutting:
      switch (w.letter) {
        case 'P': return GrooveRole::CornerKinds;
        case 'J': return GrooveRole::PathType;
        default: return GrooveRole::Length;  // R V U W I A B D E
      }
  }
  return GrooveRole::Passive;
}

}  // namespace cyclecert
