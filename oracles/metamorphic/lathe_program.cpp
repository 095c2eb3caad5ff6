#include "oracles/metamorphic/lathe_program.h"

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string_view>

#include "reference/gcode/writer.h"
#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

namespace {

bool isMotionCode(int g10) { return g10 == 0 || g10 == 10 || g10 == 20 || g10 == 30; }
bool isCycleCode(int g10) { return g10 == 700 || g10 == 710 || g10 == 720; }
bool isCycleCode(int g10, LatheFamilies families) {
  return isCycleCode(g10) || (families == LatheFamilies::WithPatternRepeating && g10 == 730);
}
bool isOtherCode(int g10) {
  static const std::set<int> codes = {180, 210, 400, 960, 970, 980, 990};
  return codes.count(g10) != 0;
}

std::string refusalOfCode(int g10) {
  if (g10 == 200) return "inch programs (G20) are not handled: the relations' constants are in mm";
  if (g10 == 170 || g10 == 190) return "the relations start from G18 programs";
  if (g10 == 410 || g10 == 420) {
    return "nose-radius compensation is not handled (a mirror changes its side and the tool's tip)";
  }
  if (g10 == 40) return "G04's X/U is a dwell time, not a length";
  if (g10 == 730) return "this relation does not handle G73 (pattern repeating; see oracles/metamorphic/README.md)";
  if (g10 == 741) {
    return "G74.1 (GSK's groove cycle) is handled by mirror-z, mirror-x, translate-z, translate-x, scale-k and "
           "metric-inch only (groove_program.h)";
  }
  return "this G code is not in the relations' vocabulary";
}

bool letterIn(char letter, std::string_view letters) { return letters.find(letter) != std::string_view::npos; }

// The reader's way out: the first word or block outside the vocabulary.
class Refusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Reader {
 public:
  // relief: G73's (Δk, Δi) before the program sets it (parameters 5136, 5135).
  Reader(const Program& program, LatheFamilies families, Point relief)
      : program_(program), families_(families), relief_(relief) {
    out_.blocks.resize(program.blocks.size());
  }

  LatheProgram read() {
    for (std::size_t i = 0; i < program_.blocks.size(); ++i) classify(i);
    ModalState state;  // power-on: G00, G18, metric; the relations transform programs that position the tool first
    std::size_t i = 0;
    while (i < program_.blocks.size()) {
      out_.blocks[i].before = state;
      switch (out_.blocks[i].kind) {
        case BlockKind::Plain:
          move(i, state);
          ++i;
          break;
        case BlockKind::CycleFirst:
          if (out_.blocks[i].cycle == 73) noteRelief(program_.blocks[i]);
          ++i;
          break;
        case BlockKind::CycleSecond:
          i = walkShape(i, state);
          break;
        case BlockKind::Finish:
          noteFinish(i, state);
          ++i;
          break;
      }
    }
    return std::move(out_);
  }

 private:
  [[noreturn]] void refuse(const Block& b, const std::string& what, const std::string& why) const {
    throw Refusal("line " + std::to_string(b.line) + ": " + what + ": " + why);
  }
  [[noreturn]] void refuse(const Block& b, const Word& w, const std::string& why) const {
    refuse(b, w.text.empty() ? formatWord(w) : w.text, why);
  }

  // The block's kind, and every word checked against the vocabulary.
  void classify(std::size_t i) {
    const Block& b = program_.blocks[i];
    BlockInfo& info = out_.blocks[i];
    if (b.hasG(741)) refuse(b, "G74.1", refusalOfCode(741));  // before its words, which are not ours either
    int motionCodes = 0, cycleCode = 0;
    std::set<char> seen;
    for (const Word& w : b.words) {
      if (!letterIn(w.letter, "GMXZUWIKRPQFST")) refuse(b, w, "this address is not in the relations' vocabulary");
      if (w.letter != 'G' && w.letter != 'M' && !seen.insert(w.letter).second) {
        refuse(b, w, "a second word of the same address in one block");
      }
      if (w.letter != 'G') continue;
      const int g10 = gCode10(w.value);
      if (isMotionCode(g10)) {
        ++motionCodes;
      } else if (isCycleCode(g10, families_)) {
        if (cycleCode) refuse(b, w, "two cycle codes in one block");
        cycleCode = g10;
      } else if (!isOtherCode(g10)) {
        refuse(b, w, refusalOfCode(g10));
      }
    }
    if (motionCodes > 1) refuse(b, "the block", "two motion codes (G00–G03) in one block");
    if (!cycleCode) {
      if (b.has('P') || b.has('Q')) refuse(b, "P/Q", "P and Q belong to cycle blocks only");
      if (b.has('X') && b.has('U')) refuse(b, "X and U", "absolute and incremental words for one axis");
      if (b.has('Z') && b.has('W')) refuse(b, "Z and W", "absolute and incremental words for one axis");
      if (b.has('R') && (b.has('I') || b.has('K'))) refuse(b, "R with I/K", "an arc is given by R or by I/K, not both");
      return;
    }
    if (motionCodes) refuse(b, "the block", "a motion code in a cycle block");
    info.cycle = cycleCode / 10;
    std::string_view allowed;
    if (cycleCode == 700) {
      info.kind = BlockKind::Finish;
      allowed = "GPQFSTM";
    } else if (b.has('P') || b.has('Q')) {
      info.kind = BlockKind::CycleSecond;
      allowed = "GPQUWFSTM";
    } else {
      info.kind = BlockKind::CycleFirst;
      allowed = cycleCode == 710 ? "GURFSTM" : cycleCode == 720 ? "GWRFSTM" : "GUWRFSTM";
    }
    for (const Word& w : b.words) {
      if (!letterIn(w.letter, allowed)) {
        refuse(b, w, "not handled in a G" + std::to_string(info.cycle) + " block (FANUC's two-block form only)");
      }
    }
  }

  // A plain block: its motion mode, its segment, and the position after it.
  void move(std::size_t i, ModalState& state) {
    const Block& b = program_.blocks[i];
    BlockInfo& info = out_.blocks[i];
    info.before = state;
    info.motion = state.motion;
    for (const Word* g : b.all('G')) {
      const int g10 = gCode10(g->value);
      if (isMotionCode(g10)) info.motion = g10 / 10;
    }
    state.motion = info.motion;
    const bool arc = info.motion == 2 || info.motion == 3;
    if (!arc && (b.has('R') || b.has('I') || b.has('K'))) {
      refuse(b, "R/I/K", "in a line block (corner rounding and chamfers are not handled)");
    }
    if (!hasAxisWord(b)) return;
    try {
      info.segment = motionSegment(b, info.motion, state);
    } catch (const CycleAlarm& a) {
      refuse(b, "the arc", a.alarm().message);
    }
    state.position = targetPosition(b, state);
    include(state.planePoint());
    if (info.segment) include(*info.segment);
  }

  // The cycle's shape ns…nf, walked from A with a state of its own; the cycle ends at A.
  std::size_t walkShape(std::size_t i, const ModalState& state) {
    const Block& b = program_.blocks[i];
    const std::size_t ns = findSequence(b, 'P'), nf = findSequence(b, 'Q');
    if (ns != i + 1) refuse(b, "P", "the shape program must follow its cycle block directly");
    if (nf < ns) refuse(b, "Q", "block Q stands before block P");
    ModalState shapeState = state;
    Extent shape{state.planePoint().z, state.planePoint().z, state.planePoint().x, state.planePoint().x};
    for (std::size_t k = ns; k <= nf; ++k) {
      BlockInfo& info = out_.blocks[k];
      if (info.kind != BlockKind::Plain) refuse(program_.blocks[k], "the block", "a cycle block inside a shape program");
      info.shapeOf = i;
      info.head = k == ns;
      info.cycle = out_.blocks[i].cycle;
      move(k, shapeState);
      if (info.segment) shape = united(shape, extent(*info.segment));
    }
    out_.cycles.push_back({i, out_.blocks[i].cycle, ns, nf, state.planePoint()});
    include(state.planePoint());
    if (out_.blocks[i].cycle == 73) includePasses(shape, allowanceOf(b));
    return nf + 1;
  }

  // G73.FMT, G73.PARAMS: a first block's U (Δi) and W (Δk) stay in force for later cycles.
  void noteRelief(const Block& b) {
    if (const Word* u = b.find('U')) relief_.x = u->value;
    if (const Word* w = b.find('W')) relief_.z = w->value;
  }

  // (Δw, Δu/2) of a P/Q block.
  static Point allowanceOf(const Block& b) {
    const Word* u = b.find('U');
    const Word* w = b.find('W');
    return {w ? w->value : 0.0, u ? u->value / 2 : 0.0};
  }

  // G73.PASS.SHIFT: the passes follow the shape shifted by allowance + s·relief, 0 ≤ s ≤ 1; an
  // extent is linear in the shift, so both ends bound every pass.
  void includePasses(const Extent& shape, Point allowance) {
    for (const Point shift : {allowance, allowance + relief_}) {
      include(Extent{shape.zMin + shift.z, shape.zMax + shift.z, shape.xMin + shift.x, shape.xMax + shift.x});
    }
  }

  static Extent united(const Extent& a, const Extent& e) {
    return {std::min(a.zMin, e.zMin), std::max(a.zMax, e.zMax), std::min(a.xMin, e.xMin), std::max(a.xMax, e.xMax)};
  }

  void noteFinish(std::size_t i, const ModalState& state) {
    const Block& b = program_.blocks[i];
    const std::size_t ns = findSequence(b, 'P'), nf = findSequence(b, 'Q');
    for (const RoughingCycleInfo& c : out_.cycles) {
      if (c.ns == ns && c.nf == nf && nearlyEqual(c.start, state.planePoint())) out_.blocks[i].finishAtCycleStart = true;
    }
  }

  std::size_t findSequence(const Block& b, char letter) const {
    const Word* w = b.find(letter);
    if (!w) refuse(b, std::string(1, letter), "missing (a cycle block needs both P and Q)");
    const auto index = program_.findSequence(static_cast<long>(w->value));
    if (!index) refuse(b, *w, "names a block that is not in the program");
    return *index;
  }

  void include(Point p) { include(Extent{p.z, p.z, p.x, p.x}); }
  void include(const Segment& s) { include(extent(s)); }
  void include(const Extent& e) {
    Extent& r = out_.reach;
    if (!anyReach_) r = e;
    r = united(r, e);
    anyReach_ = true;
  }

  const Program& program_;
  const LatheFamilies families_;
  Point relief_;  // G73's (Δk, Δi) in force
  LatheProgram out_;
  bool anyReach_ = false;
};

}  // namespace

MachineParams machineParamsOf(const ParamSettings& params) {
  MachineParams m;
  for (const auto& [name, value] : params) {
    try {
      m.set(name, value);
    } catch (const std::invalid_argument&) {
      // skipped: the engine running the program names the bad setting
    }
  }
  return m;
}

namespace {

std::optional<LatheProgram> readWithRelief(const Program& program, std::string& whyNot, LatheFamilies families,
                                           Point relief) {
  try {
    return Reader(program, families, relief).read();
  } catch (const Refusal& r) {
    whyNot = r.what();
    return std::nullopt;
  }
}

}  // namespace

std::optional<LatheProgram> readLatheProgram(const Program& program, std::string& whyNot, LatheFamilies families) {
  return readWithRelief(program, whyNot, families, Point{0, 0});
}

std::optional<LatheProgram> readLatheProgram(const Program& program, const ParamSettings& params, std::string& whyNot,
                                             LatheFamilies families) {
  const MachineParams machine = machineParamsOf(params);
  const GCodeSystem system = gCodeSystemOf(defaultProfile(), machine);
  if (system != GCodeSystem::A) {
    whyNot = "the settings select " + gCodeSystemName(system) +
             " (3401#6 GSB / #7 GSC): the relations read G code system A programs (X/Z absolute, U/W "
             "incremental, G70–G72 the cycles), which the words of this one do not mean";
    return std::nullopt;
  }
  return readWithRelief(program, whyNot, families, Point{machine.get("5136"), machine.get("5135")});
}

bool finishesAtCycleStarts(const Program& p, const LatheProgram& lathe, std::string& whyNot) {
  for (std::size_t i = 0; i < lathe.blocks.size(); ++i) {
    if (lathe.blocks[i].kind == BlockKind::Finish && !lathe.blocks[i].finishAtCycleStart) {
      whyNot = "line " + std::to_string(p.blocks[i].line) +
               ": G70 does not run a roughing cycle's shape from that cycle's start point";
      return false;
    }
  }
  return true;
}

WordRole roleOf(const BlockInfo& info, const Word& w) {
  switch (w.letter) {
    case 'G': {
      const int g10 = gCode10(w.value);
      if (isMotionCode(g10)) return WordRole::MotionCode;
      if (isCycleCode(g10, LatheFamilies::WithPatternRepeating)) return WordRole::CycleCode;
      return WordRole::OtherCode;
    }
    case 'F': return WordRole::Feed;
    case 'P':
    case 'Q': return WordRole::Sequence;
    case 'S':
    case 'T':
    case 'M': return WordRole::Passive;
    default: break;
  }
  switch (info.kind) {
    case BlockKind::CycleFirst:
      if (info.cycle == 73) {
        return w.letter == 'R' ? WordRole::Divisions : w.letter == 'U' ? WordRole::ReliefSecond : WordRole::ReliefFirst;
      }
      return w.letter == 'R' ? WordRole::Retract : WordRole::DepthOfCut;
    case BlockKind::CycleSecond: return w.letter == 'U' ? WordRole::AllowanceSecond : WordRole::AllowanceFirst;
    case BlockKind::Finish: return WordRole::Passive;  // the reader lets only G P Q F S T M through
    case BlockKind::Plain: break;
  }
  switch (w.letter) {
    case 'Z': return WordRole::AbsFirst;
    case 'X': return WordRole::AbsSecond;
    case 'W': return WordRole::IncFirst;
    case 'U': return WordRole::IncSecond;
    case 'K': return WordRole::CentreFirst;
    case 'I': return WordRole::CentreSecond;
    case 'R': return WordRole::ArcRadius;
    default: return WordRole::Passive;
  }
}

}  // namespace cyclecert
