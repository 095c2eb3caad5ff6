// The oracles' own reading of a program: which roughing cycles it asks for and with what shape,
// allowances and parameters, and whether the documented checks forbid a cycle. Deliberately
// written apart from the reference planners (reference/cycles): an oracle that reused the planner's
// checks would agree with it by construction.
#include "oracles/cycle_spec.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "reference/gcode/address_ranges.h"
#include "reference/interpreter/block_groups.h"
#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

Point toFrame(const CycleSpec& c, Point p) { return c.cutsAlongZ() ? p : transposed(p); }

// Applies the modal G codes of a block that change how later words are read, with the runner's
// table (PROG.GROUP.LAST: the last code of a group is the one in force).
void applyModal(const Block& b, ModalState& s) {
  applyModalGCodes(b, s);
  if (const Word* f = b.find('F')) s.feed = f->value * s.unitScale();
}

// PROG.GROUP.UNKNOWN, PROG.GROUP.COMP: applies the block's modal codes and returns the alarm its G
// codes raise, as the runner does (reference/interpreter/block_groups.h), or nothing.
// PROG.SIGN: a feed, a spindle speed and a tool number take no minus sign (PS0006).
std::optional<Alarm> minusSignWithoutMeaning(const Block& b) {
  for (const Word& w : b.words) {
    if ((w.letter == 'F' || w.letter == 'S' || w.letter == 'T') && std::signbit(w.value)) {
      return Alarm{"PS0006", w.text + ": a minus sign after " + std::string(1, w.letter), b.line, ""};
    }
  }
  return std::nullopt;
}

std::optional<Alarm> readBlockGroups(const Block& b, ModalState& s) {
  if (auto sign = minusSignWithoutMeaning(b)) return sign;
  if (const Word* g = firstUnknownGCode(b, s.gCodeSystem)) return improperGCode(b, *g, s).alarm();
  const ModalState before = s;
  applyModal(b, s);
  try {
    checkCompensationChange(b, before, s);
  } catch (const CycleAlarm& a) {
    return a.alarm();
  }
  return std::nullopt;
}

Alarm forbidden(std::string code, int line, std::string why) { return Alarm{std::move(code), std::move(why), line, ""}; }

bool isMotionCode(int g10) { return g10 == 0 || g10 == 10 || g10 == 20 || g10 == 30; }

// G72.NSNF.GCODES, G71.TNRC.PLACE, PROG.GSYS.B: what a shape program may contain, each code by
// its function in the program's system (the table's usableInShapeProgram, as the runner asks it).
std::optional<Alarm> checkShapeCommands(const Block& b, GCodeSystem system, bool compensationAllowed) {
  for (const Word* g : b.all('G')) {
    const GCode* code = findGCode(system, gCode10(g->value));
    const bool tnrc = code && code->group == GGroup::NoseRadiusComp;
    if (!code || !usableInShapeProgram(*code) || (tnrc && !compensationAllowed)) {
      return forbidden("PS0325", b.line, g->text + " in the shape program");
    }
  }
  for (const Word* m : b.all('M')) {
    if (m->value == 98 || m->value == 99) return forbidden("PS0325", b.line, "subprogram call in the shape program");
  }
  return std::nullopt;
}

// The documented shape checks, written from the rules (G71.HEAD.G0G1, G71.HEAD.NOX, G71.T1.MONO,
// G71.T2.MONO, G72.T1.MONO, G71.LIMIT.HEIGHT, G71.T1.ALARM with 5145/5146), in the cycle frame.
std::optional<Alarm> checkShape(const CycleSpec& c, const Block& head, bool headHasDepthWord,
                                const MachineParams& p, bool limitHeight) {
  if (!head.hasG(0) && !head.hasG(10)) return forbidden("PS0065", head.line, "block ns has no G00/G01");
  const Point a = toFrame(c, c.start);
  const Point b = toFrame(c, c.shape.front().to);
  if (!headHasDepthWord || std::abs(b.x - a.x) <= kGeomEps) {
    return forbidden("PS0325", head.line, "block ns does not move the depth axis");
  }
  const int d = signOf(b.x - a.x);
  const Point end = toFrame(c, c.shape.back().to);
  int cut = signOf(end.z - (c.typeII ? a.z : b.z));
  if (cut == 0) cut = -1;
  // Tolerances and codes by plane axis: z (1st) 5145 / PS0064, x (2nd) 5146 / PS0329.
  const double zTol = p.get("5145"), xTol = p.get("5146");
  const bool g72 = !c.cutsAlongZ();
  const double cutTol = g72 ? xTol : zTol, depthTol = g72 ? zTol : xTol;
  const std::string cutCode = g72 ? "PS0329" : "PS0064", depthCode = g72 ? "PS0064" : "PS0329";
  double furthest = cut * (c.typeII ? a.z : b.z), highest = -d * b.x;
  for (std::size_t i = c.typeII ? 0 : 1; i < c.shape.size(); ++i) {
    const Segment s = c.cutsAlongZ() ? c.shape[i] : transposed(c.shape[i]);
    std::vector<Point> points = apexesAlong(s);
    points.push_back(s.to);
    for (Point q : points) {
      if (cut * q.z < furthest - cutTol - kGeomEps) return forbidden(cutCode, s.sourceLine, "the shape turns back along the cut axis");
      furthest = std::max(furthest, cut * q.z);
      if (!c.typeII) {
        if (-d * q.x < highest - depthTol - kGeomEps) return forbidden(depthCode, s.sourceLine, "the shape goes deeper again");
        highest = std::max(highest, -d * q.x);
      }
    }
  }
  // G71.LIMIT.HEIGHT: U(+) nothing above the start point, U(−) nothing below it.
  if (limitHeight && c.cutsAlongZ() && c.allowance.x != 0) {
    for (const Segment& s : c.shape) {
      const Extent e = extent(s);
      const bool above = c.allowance.x > 0 ? e.xMax > c.start.x + kGeomEps : e.xMin < c.start.x - kGeomEps;
      if (above) return forbidden("PS0322", s.sourceLine == 0 ? head.line : s.sourceLine, "the shape passes the start point's height");
    }
  }
  return std::nullopt;
}

// G73.HEAD, G73.SHAPE: block ns commands G00 or G01 (PS0065); it need not be parallel to an axis,
// and the shape need not be monotone (no PS0064/PS0329, no G71.LIMIT.HEIGHT).
std::optional<Alarm> checkG73Head(const Block& head) {
  if (!head.hasG(0) && !head.hasG(10)) return forbidden("PS0065", head.line, "block ns has no G00/G01");
  return std::nullopt;
}

class SpecReader {
 public:
  SpecReader(const Program& program, const Profile& profile, const MachineParams& params, const ToolOffset& tool)
      : program_(program), profile_(profile), params_(params), tool_(tool),
        state_(initialModalState(profile, params)) {}  // PROG.UNITS, PROG.GSYS.SELECT

  ProgramSpec read() {
    std::size_t i = 0;
    while (i < program_.blocks.size()) {
      const Block& b = program_.blocks[i];
      if ((out_.blockAlarm = readBlockGroups(b, state_))) break;
      // PROG.GSYS.*: the cycles by their function (system C writes G72/G73/G74).
      const GCodeSystem system = state_.gCodeSystem;
      const bool g70 = hasGFunction(b, 700, system), g71 = hasGFunction(b, 710, system),
                 g72 = hasGFunction(b, 720, system), g73 = hasGFunction(b, 730, system);
      if (hasGFunction(b, 741, system)) {
        readGrooveCycleBlock(i, b);
        ++i;
        continue;
      }
      if (g73) refuseOtherG73Dialects(b);
      const bool roughing = g71 || g72 || g73;
      if ((g70 || roughing) && !out_.firstCycleBlockLine) out_.firstCycleBlockLine = b.line;
      if (g70) {
        readFinishingFeeds(b);
        checkFinishingCompensation(b);
      }
      if (g70 || (roughing && (b.has('P') || b.has('Q')))) startMovesAfterCycles();
      if (g73 && !b.has('P') && !b.has('Q')) {
        readG73FirstBlock(b);
      } else if (g73) {
        i = readCycle(i, CycleFamily::G73);
        continue;
      } else if ((g71 || g72) && !b.has('P') && !b.has('Q') && !(g71 && huazhong())) {
        readFirstBlock(b, g71);
      } else if (g71 || g72) {
        i = readCycle(i, g71 ? CycleFamily::G71 : CycleFamily::G72);
        continue;
      } else if (!g70 && hasAxisWord(b)) {
        readMotionOutsideCycles(i, b);
      } else if (huazhongShape_ && callsSubprogram(b)) {
        refuseToFollowSubprogram(b);
      }
      ++i;
    }
    return std::move(out_);
  }

 private:
  // PROG.WHOLE: a block that moves the tool from a known position outside the cycles is a move of
  // the toolpath, before or after them.
  void readMotionOutsideCycles(std::size_t i, const Block& b) {
    const AxisWordsMean meaning = axisWordsMeaning(b, state_.gCodeSystem);
    if (huazhongShape_) requireFollowableAfterHuazhong(b, meaning);
    const bool moves = axisWordsMoveTheTool(meaning), beforeCycles = out_.cycles.empty() && out_.grooves.empty();
    if (moves && !beforeCycles) out_.motionAfterCycles = true;
    // Before the cycles, the path starts at the first known position; from then on every move is drawn.
    const PlaneAxes axes = state_.axes();
    if (moves && beforeCycles && known_.known(axes.first) && known_.known(axes.second)) out_.motionBeforeCycles = true;
    followKnownAxes(known_, b, meaning, state_);
    const Point before = state_.planePoint();
    state_.position = positionAfterBlock(b, state_);
    if (!moves) return;
    if (beforeCycles && out_.motionBeforeCycles) {
      if (auto m = programMove(b, before)) out_.movesBeforeCycles.push_back(*m);
    } else if (afterCycles_) {
      if (auto m = programMove(b, before)) out_.movesAfterCycles.push_back(*m);
    }
    if (huazhongShape_) recordRunAfterHuazhong(i, b, before);
  }

  // G74_1.FMT (I1): a G74.1 block with X or Z gives the groove (its own alarms are raised there); one
  // without them runs the cycle with the nearest first block before it. Only the gsk profile has
  // G74.1, in G18 (the reference refuses it elsewhere as not supported): there the oracles read none.
  void readGrooveCycleBlock(std::size_t i, const Block& b) {
    out_.hasGrooveCycle = true;
    if (profile_.name != "gsk" || state_.axes().gCode != 18) return;
    if (givesTheGroove(b)) {
      grooveBlock_ = i;
      if (auto bad = grooveBlockAlarm(b, state_, params_)) {
        GrooveSpec forbidden;
        forbidden.line = forbidden.grooveLine = b.line;
        forbidden.forbiddenBy = bad;
        out_.grooves.push_back(std::move(forbidden));
      }
      return;
    }
    startMovesAfterCycles();
    out_.grooves.push_back(
        readGrooveSpec(grooveBlock_ ? &program_.blocks[*grooveBlock_] : nullptr, b, state_, params_, tool_));
  }

  // A cycle block (G70, or G71/G72 with P/Q) ends the moves after the cycles read so far: they were
  // between cycles. The cycle leaves the tool where it started.
  void startMovesAfterCycles() {
    afterCycles_ = true;
    out_.movesAfterCycles.clear();
    out_.cyclesEnd = state_.planePoint();
  }

  // The block just read as a move of the toolpath from `before`, or nothing when it does not move
  // in the plane.
  std::optional<ProgramMove> programMove(const Block& b, Point before) const {
    ProgramMove m;
    m.line = b.line;
    m.end = state_.planePoint();
    if (distance(m.end, before) <= kGeomEps) return std::nullopt;
    m.rapid = state_.motion == 0;
    m.arc = state_.motion == 2 || state_.motion == 3;
    m.feed = state_.feed;
    return m;
  }

  // G73.DIALECTS: the Huazhong and Haas G73 are other formats, not in cyclecert's sources: the
  // oracles do not read them (nor does the reference plan them).
  void refuseOtherG73Dialects(const Block& b) const {
    if (profile_.roughingFormat == RoughingBlockFormat::FanucTwoBlocks) return;
    throw NotSupported(b.line, "the oracles do not read G73 of the " + profile_.name +
                                   " profile (G73.DIALECTS: its format is not in cyclecert's sources)");
  }

  // G73.FMT, G73.PARAMS, G73.D.RANGE: the first G73 block's U (Δi, the plane's 2nd-axis
  // incremental address, a radius value), W (Δk, the 1st's) and R (d) are modal: they overwrite
  // parameters 5135/5136/5137. U/W outside the address table, or an R that is no whole number
  // ≥ 1, is the alarm the next G73 cycle stops with.
  void readG73FirstBlock(const Block& b) {
    const PlaneAxes axes = state_.axes();
    try {
      for (char letter : {axes.secondInc, axes.firstInc}) {
        if (const Word* w = b.find(letter)) checkCycleAddress(*w, CycleAddress::Allowance, state_.inch);
      }
    } catch (const CycleAlarm& a) {
      firstBlockAlarm_ = a.alarm();
      return;
    }
    const Word* r = b.find('R');
    if (r && r->value < 1) {
      firstBlockAlarm_ = forbidden("PS0062", b.line, "the number of divisions d of G73 must be at least 1");
      return;
    }
    if (r && (r->value != std::floor(r->value) || r->value > 99'999'999)) {
      firstBlockAlarm_ = forbidden("PS0003", b.line, "d of G73 is not a whole number within 1…99999999");
      return;
    }
    if (const Word* di = b.find(axes.secondInc)) params_.set("5135", di->value * state_.unitScale());
    if (const Word* dk = b.find(axes.firstInc)) params_.set("5136", dk->value * state_.unitScale());
    if (r) params_.set("5137", r->value);
  }

  // G73.FS10.FMT: with FCV = 1 the block with P and Q may give I (Δi), K (Δk) and D (d, no decimal
  // point, ≥ 1), which write 5135/5136/5137; with FCV = 0 any of them is PS0009.
  std::optional<Alarm> readG73Series10Words(const Block& b) {
    if (!params_.bit("FCV")) {
      for (char letter : {'I', 'K', 'D'}) {
        if (b.find(letter)) return forbidden("PS0009", b.line, std::string(1, letter) + " in a G73 P/Q block needs FCV = 1");
      }
      return std::nullopt;
    }
    try {
      for (char letter : {'I', 'K'}) {
        if (const Word* w = b.find(letter)) checkCycleAddress(*w, CycleAddress::Allowance, state_.inch);
      }
    } catch (const CycleAlarm& a) {
      return a.alarm();
    }
    const Word* d = b.find('D');
    if (d && d->hasDecimalPoint) return forbidden("PS0007", b.line, "D of the Series 10/11 G73 has a decimal point");
    if (d && d->value < 1) return forbidden("PS0062", b.line, "D, the number of divisions, is below 1");
    if (d && d->value > 99'999'999) return forbidden("PS0003", b.line, "D has more than 8 digits");
    if (const Word* i = b.find('I')) params_.set("5135", i->value * state_.unitScale());
    if (const Word* k = b.find('K')) params_.set("5136", k->value * state_.unitScale());
    if (d) params_.set("5137", d->value);
    return std::nullopt;
  }

  // G73.FMT, G73.ALARMS, G73.D.RANGE, G73.FS10.FMT: the block with P and Q, in the order the
  // documented checks come: P/Q present (PS0061), the address table, the Series 10/11 words, the
  // feed (PS0011), d ≥ 1 (PS0062, from 5137), the blocks P and Q name (PS0063).
  std::optional<Alarm> g73BlockAlarm(const Block& b, CycleSpec& c, std::size_t ns, std::size_t nf) {
    const PlaneAxes axes = state_.axes();
    if (firstBlockAlarm_) return firstBlockAlarm_;
    if (!b.has('P') || !b.has('Q')) return forbidden("PS0061", b.line, "P or Q missing");
    if (auto bad = rangeAlarm(b, axes.firstInc, axes.secondInc)) return bad;
    if (auto bad = readG73Series10Words(b)) return bad;
    if (c.feed <= 0) return forbidden("PS0011", b.line, "no cutting feed");
    c.relief = {params_.get("5136"), params_.get("5135")};
    const double divisions = params_.get("5137");
    c.divisions = !(divisions >= 1) ? 0 : static_cast<int>(std::min(divisions, 1e9));  // 5137 may be set to anything
    if (c.divisions < 1) return forbidden("PS0062", b.line, "the number of divisions d of G73 is 0 (5137)");
    if (ns == kNotFound || nf == kNotFound || nf < ns) return forbidden("PS0063", b.line, "block P or Q not found");
    return std::nullopt;
  }

  // G70.EX: the F words of the finishing shape apply in G70.
  void readFinishingFeeds(const Block& b) {
    out_.hasFinishingCycle = true;
    const Word* p = b.find('P');
    const Word* q = b.find('Q');
    const auto ns = p ? program_.findSequence(static_cast<long>(p->value)) : std::nullopt;
    const auto nf = q ? program_.findSequence(static_cast<long>(q->value)) : std::nullopt;
    if (!ns || !nf) return;
    for (std::size_t i = *ns; i <= *nf && i < program_.blocks.size(); ++i) {
      if (const Word* f = program_.blocks[i].find('F')) out_.finishingFeeds.push_back(f->value * state_.unitScale());
    }
  }

  // The index of the block a P or Q word names, or kNotFound (absent word or sequence number).
  // Plain indices: GCC 12 misreads optionals in the callers' comparisons.
  static constexpr std::size_t kNotFound = static_cast<std::size_t>(-1);
  std::size_t blockOfSequence(const Word* w) const {
    return w ? program_.findSequence(static_cast<long>(w->value)).value_or(kNotFound) : kNotFound;
  }

  // G72.RANGE: the P/Q block's words against the address table.
  std::optional<Alarm> rangeAlarm(const Block& b, char allowanceFirst, char allowanceSecond) const {
    try {
      for (char letter : {'P', 'Q'}) {
        if (const Word* w = b.find(letter)) checkCycleAddress(*w, CycleAddress::SequenceNumber, state_.inch);
      }
      for (char letter : {allowanceFirst, allowanceSecond}) {
        if (const Word* w = b.find(letter)) checkCycleAddress(*w, CycleAddress::Allowance, state_.inch);
      }
    } catch (const CycleAlarm& a) {
      return a.alarm();
    }
    return std::nullopt;
  }

  // G71.TNRC.NT2: compensation commanded inside a G70 shape is allowed with NT2 = 1 only if the G70
  // is commanded in G40 mode (PS0325), block Q has no G41/G42 (PS0325) and has G40 (PS0538); with
  // NT2 = 0 it is PS0325 (G71.TNRC.PLACE).
  void checkFinishingCompensation(const Block& b) {
    const Word* p = b.find('P');
    const Word* q = b.find('Q');
    const std::size_t ns = blockOfSequence(p), nf = blockOfSequence(q);
    if (ns == kNotFound || nf == kNotFound || nf < ns) return;
    const auto isTnrc = [](const Block& x) { return x.hasG(400) || x.hasG(410) || x.hasG(420); };
    bool inside = false;
    for (std::size_t i = ns; i <= nf; ++i) inside = inside || isTnrc(program_.blocks[i]);
    if (!inside || profile_.toleratesTnrcInShape) return;
    const Block& end = program_.blocks[nf];
    std::optional<Alarm> bad;
    if (!params_.bit("NT2")) {
      for (std::size_t i = ns; i <= nf && !bad; ++i) {
        if (isTnrc(program_.blocks[i])) bad = forbidden("PS0325", program_.blocks[i].line, "compensation inside the G70 shape");
      }
    } else if (state_.tnrc != 40) {
      bad = forbidden("PS0325", b.line, "G70 with compensation in its shape commanded in G41/G42 mode");
    } else if (end.hasG(410) || end.hasG(420)) {
      bad = forbidden("PS0325", end.line, "G41/G42 in the end block of the G70 shape");
    } else if (!end.hasG(400)) {
      bad = forbidden("PS0538", end.line, "no G40 in the end block of the G70 shape");
    }
    if (bad) finishingAlarms_.push_back(*bad);
  }

  // Δd and e are modal and live in parameters 5132/5133 (G71.DD.MODAL, G71.E.MODAL, G72.DD).
  void readFirstBlock(const Block& b, bool g71) {
    const PlaneAxes axes = state_.axes();
    try {
      if (const Word* dd = b.find(g71 ? axes.secondInc : axes.firstInc)) checkCycleAddress(*dd, CycleAddress::DepthOfCut, state_.inch);
      if (const Word* e = b.find('R')) checkCycleAddress(*e, CycleAddress::Retract, state_.inch);
    } catch (const CycleAlarm& a) {
      firstBlockAlarm_ = a.alarm();
      return;
    }
    if (const Word* dd = b.find(g71 ? axes.secondInc : axes.firstInc); dd && dd->value > 0) {
      params_.set("5132", dd->value * state_.unitScale());
    }
    if (const Word* e = b.find('R'); e && e->value >= 0) params_.set("5133", e->value * state_.unitScale());
  }

  // G71.FS10.*: the block with P and Q in the Series 10/11 format (FCV = 1) gives Δd with D, in
  // least input increments, and it stays in parameter 5132; with FCV = 0 a D there is PS0009.
  std::optional<Alarm> readSeries10Depth(const Block& b, CycleSpec& c) {
    const Word* d = b.find('D');
    if (haas()) return readHaasWords(b, c);
    if (!params_.bit("FCV")) {
      if (d) return forbidden("PS0009", b.line, "D in the P/Q block needs the Series 10/11 format (FCV = 1)");
      return std::nullopt;
    }
    for (char letter : {'I', 'K'}) {
      if (const Word* w = b.find(letter); w && w->value != 0) {
        throw std::runtime_error("line " + std::to_string(b.line) + ": " + w->text +
                                 ": the oracles do not read I/K of the Series 10/11 format");
      }
    }
    if (!d) return std::nullopt;
    if (d->hasDecimalPoint) return forbidden("PS0007", b.line, "D of the Series 10/11 format has a decimal point");
    if (d->value <= 0) return forbidden("PS0062", b.line, "D is not positive");
    if (d->value > 999'999'999) return forbidden("PS0003", b.line, "D has more than 9 digits");
    c.depthOfCut = d->value * (state_.inch ? 0.0001 * 25.4 : 0.001);
    params_.set("5132", c.depthOfCut);
    return std::nullopt;
  }

  // HAAS.G71.FMT: the Haas one-block G71/G72 P Q U W D I K F S T [R1].
  bool haas() const { return profile_.roughingFormat == RoughingBlockFormat::HaasOneBlock; }

  // HAAS.G71.D: D = Δd in the program's units (radius, positive), kept in 5132 like a first block's;
  // HAAS.G71.IK: I (radius) and K, the rough-pass allowance, add to U/2 and W; HAAS.G71.R1: R1
  // selects type II, another R there is PS0009.
  std::optional<Alarm> readHaasWords(const Block& b, CycleSpec& c) {
    try {
      for (char letter : {'I', 'K'}) {
        if (const Word* w = b.find(letter)) checkCycleAddress(*w, CycleAddress::Allowance, state_.inch);
      }
      if (const Word* d = b.find('D'); d && d->value > 0) checkCycleAddress(*d, CycleAddress::DepthOfCut, state_.inch);
    } catch (const CycleAlarm& a) {
      return a.alarm();
    }
    if (const Word* i = b.find('I')) c.allowance.x += i->value * state_.unitScale();
    if (const Word* k = b.find('K')) c.allowance.z += k->value * state_.unitScale();
    if (const Word* r = b.find('R')) {
      if (r->value != 1 || r->hasDecimalPoint) return forbidden("PS0009", b.line, "R other than R1 in a Haas P/Q block");
      haasTypeII_ = true;
    }
    const Word* d = b.find('D');
    if (!d) return std::nullopt;
    if (d->value <= 0) return forbidden("PS0062", b.line, "D is not positive");
    c.depthOfCut = d->value * state_.unitScale();
    params_.set("5132", c.depthOfCut);
    return std::nullopt;
  }

  // HNC.G71.FMT: the Huazhong G71 is one block G71 U(Δd) R(r) P Q X(Δx) Z(Δz) F S T.
  bool huazhong() const { return profile_.roughingFormat == RoughingBlockFormat::HuazhongOneBlock; }

  // HNC.G71.FMT: U (Δd) and R (r) of the Huazhong block; kept like FANUC's modal 5132/5133.
  std::optional<Alarm> readHuazhongDepth(const Block& b) {
    try {
      refuseAddressesOutsideHuazhongG71(b);
      if (const Word* dd = b.find('U')) checkCycleAddress(*dd, CycleAddress::DepthOfCut, state_.inch);
      if (const Word* r = b.find('R')) checkCycleAddress(*r, CycleAddress::Retract, state_.inch);
    } catch (const CycleAlarm& a) {
      return a.alarm();
    }
    if (const Word* dd = b.find('U')) params_.set("5132", dd->value * state_.unitScale());
    if (const Word* r = b.find('R')) params_.set("5133", r->value * state_.unitScale());
    return std::nullopt;
  }

  static bool callsSubprogram(const Block& b) {
    for (const Word* m : b.all('M')) {
      if (m->value == 98) return true;
    }
    return false;
  }

  // HNC.G71.SUB: ns…nf may call subprograms; the oracles do not follow them (nor does the reference),
  // so the shape and the finishing run would lack their moves: not judged rather than judged wrongly.
  [[noreturn]] static void refuseToFollowSubprogram(const Block& b) {
    throw NotSupported(b.line, "the oracles do not follow subprogram calls (M98) after a Huazhong G71 (HNC.G71.SUB): "
                               "write the contour inline");
  }

  // HNC.G71.FST: after a Huazhong G71 the program goes on with the block after it, and the oracles
  // find its moves at the end of the path by where each block leaves the tool. A block whose end
  // they do not know (G28/G30's reference position, G53, G50's new coordinates) or whose moves are
  // offset from its words (G41/G42 with a nose radius) is not judged rather than judged wrongly.
  void requireFollowableAfterHuazhong(const Block& b, AxisWordsMean meaning) const {
    const bool unknownEnd = meaning == AxisWordsMean::ReferenceReturn || meaning == AxisWordsMean::MachineCoordinates ||
                            meaning == AxisWordsMean::CoordinateSetting;
    if (unknownEnd) {
      throw NotSupported(b.line, "the oracles do not follow G28/G30/G53/G50 after a Huazhong G71 (its finishing run, "
                                 "HNC.G71.FST, is found by where each block leaves the tool)");
    }
    if (callsSubprogram(b)) refuseToFollowSubprogram(b);
    if (state_.tnrc != 40 && tool_.noseRadius > 0 && axisWordsMoveTheTool(meaning)) {
      throw NotSupported(b.line, "the oracles do not judge the moves after a Huazhong G71 under G41/G42 with a nose "
                                 "radius (HNC.G71.FST): the finishing run is offset from the blocks' words");
    }
  }

  // HNC.G71.FST: a block after the Huazhong G71 that moves the tool in the plane; block ns starts
  // the finishing run.
  void recordRunAfterHuazhong(std::size_t i, const Block& b, Point before) {
    std::optional<ProgramMove> moved = programMove(b, before);
    if (!moved) return;  // no move in the plane
    ProgramMove& m = *moved;
    m.finishing = i >= huazhongShape_->first && i <= huazhongShape_->second;
    if (m.finishing) out_.hasFinishingCycle = true;
    out_.runAfterHuazhong.push_back(m);
  }

  std::size_t readCycle(std::size_t index, CycleFamily family) {
    const Block& b = program_.blocks[index];
    const PlaneAxes axes = state_.axes();
    // HNC.G71.FMT: X = Δx (diameter) and Z = Δz allowances instead of U and W; Δd and r in the block.
    const bool oneBlock = huazhong() && family == CycleFamily::G71;
    const char allowanceFirst = oneBlock ? 'Z' : axes.firstInc, allowanceSecond = oneBlock ? 'X' : axes.secondInc;
    std::optional<Alarm> huazhongAlarm;
    if (oneBlock && (b.has('P') || b.has('Q'))) huazhongAlarm = readHuazhongDepth(b);
    CycleSpec c;
    haasTypeII_ = false;
    c.code = cycleCode(family);
    c.family = family;
    c.line = b.line;
    c.start = state_.planePoint();
    c.feed = state_.feed;
    c.depthOfCut = params_.get("5132");
    c.retract = params_.get("5133");
    c.directReturn = params_.bit("DTP");
    c.clearance = params_.get("5134");
    if (const Word* du = b.find(allowanceSecond)) c.allowance.x = physicalLength(du->value, axes.secondDiameter, state_);
    if (const Word* dw = b.find(allowanceFirst)) c.allowance.z = physicalLength(dw->value, axes.firstDiameter, state_);
    const Word* p = b.find('P');
    const Word* q = b.find('Q');
    const std::size_t ns = blockOfSequence(p), nf = blockOfSequence(q);
    if (family == CycleFamily::G73) {
      c.forbiddenBy = g73BlockAlarm(b, c, ns, nf);
    } else if (firstBlockAlarm_ && !oneBlock) {
      c.forbiddenBy = firstBlockAlarm_;
    } else if (huazhongAlarm) {
      c.forbiddenBy = huazhongAlarm;
    } else if (auto bad = rangeAlarm(b, allowanceFirst, allowanceSecond)) {
      c.forbiddenBy = bad;
    } else if (!p || !q) {
      c.forbiddenBy = forbidden("PS0061", b.line, "P or Q missing");
    } else if (auto bad = readSeries10Depth(b, c)) {
      c.forbiddenBy = bad;
    } else if (ns == kNotFound || nf == kNotFound || nf < ns) {
      c.forbiddenBy = forbidden("PS0063", b.line, "block P or Q not found");
    } else if (c.depthOfCut <= 0) {
      c.forbiddenBy = forbidden("PS0062", b.line, "no depth of cut");
    } else if (c.feed <= 0) {
      c.forbiddenBy = forbidden("PS0011", b.line, "no cutting feed");
    }
    if (c.forbiddenBy) {
      out_.cycles.push_back(std::move(c));
      return index + 1;
    }
    if (oneBlock) {
      for (std::size_t i = ns; i <= nf; ++i) {
        if (callsSubprogram(program_.blocks[i])) refuseToFollowSubprogram(program_.blocks[i]);
      }
    }
    readShape(c, ns, nf);
    if (oneBlock && !c.forbiddenBy) {
      huazhongShape_ = {ns, nf};
      out_.runAfterHuazhong.clear();
    }
    out_.cycles.push_back(std::move(c));
    if (oneBlock) return index + 1;  // HNC.G71.FST: the program goes on; ns…nf run again as the finishing run
    return ns == index + 1 ? nf + 1 : index + 1;  // G72.NSNF.FOLLOW
  }

  void readShape(CycleSpec& c, std::size_t ns, std::size_t nf) {
    ModalState s = state_;
    const Block& head = program_.blocks[ns];
    const PlaneAxes axes = s.axes();
    const bool g71 = c.family != CycleFamily::G72;
    const char depthAbs = g71 ? axes.second : axes.first, depthInc = g71 ? axes.secondInc : axes.firstInc;
    const char cutAbs = g71 ? axes.first : axes.second, cutInc = g71 ? axes.firstInc : axes.secondInc;
    // HAAS.G71.R1; G73 has no types: its passes follow the whole shape (G73.SHAPE).
    c.typeII = !c.patternRepeating() && (head.has(cutAbs) || head.has(cutInc) || haasTypeII_);
    c.headIsRapid = !head.hasG(10);
    // G73.HEAD: block ns without G00/G01 is refused before the shape is read (its G02/G03 would
    // make the next blocks arcs).
    if (c.patternRepeating() && (c.forbiddenBy = checkG73Head(head))) return;
    for (std::size_t i = ns; i <= nf; ++i) {
      const Block& b = program_.blocks[i];
      if (auto bad = checkShapeCommands(b, s.gCodeSystem, profile_.toleratesTnrcInShape ||
                                                              profile_.compensatesTnrcInShape || params_.bit("NT1"))) {
        c.forbiddenBy = bad;
        return;
      }
      for (const Word* g : b.all('G')) {
        if (isMotionCode(gCode10(g->value))) s.motion = gCode10(g->value) / 10;
      }
      applyGroupCodes(b, GGroup::Programming, s);  // PROG.GSYS.B: G90/G91 of systems B/C
      if (!hasAxisWord(b)) continue;
      const int motion = i == ns ? (head.hasG(10) ? 1 : 0) : s.motion;
      try {
        if (auto seg = motionSegment(b, motion, s)) c.shape.push_back(*seg);
        else if (i == ns) c.shape.push_back(Segment{SegmentKind::Line, s.planePoint(), s.planePoint(), {}, b.line});
      } catch (const std::exception&) {
        c.forbiddenBy = forbidden("PS0023", b.line, "impossible arc");
        return;
      }
      s.position = targetPosition(b, s);
    }
    if (c.shape.empty()) c.shape.push_back(Segment{SegmentKind::Line, c.start, c.start, {}, head.line});
    c.semiFinish = !c.patternRepeating() && !params_.bit(c.typeII ? "RF2" : "RF1");
    c.noRepeatedPath = params_.bit("NSP");
    compensate(c, profile_.compensatesTnrcInShape ? tnrcOfBlock(head) : 40);
    if (!c.forbiddenBy && !c.patternRepeating()) c.forbiddenBy = checkShape(c, head, head.has(depthAbs) || head.has(depthInc), params_,
                                           !huazhong());  // seed 003 has no LIMIT.HEIGHT (its example 2 ends below A)
  }

  // G71.TNRC.CANCEL / G71.CHECK: under G41/G42 the cycle works on the imaginary tool-nose path.
  // HAAS.TNRC.SHAPE: on Haas, G41/G42 in block ns compensate the shape as if in force at the cycle.
  void compensate(CycleSpec& c, int inShape) {
    const int tnrc = inShape != 40 ? inShape : state_.tnrc;
    if (tnrc == 40 || tool_.noseRadius <= 0 || c.shape.size() < 2) return;
    const CompensationSide side = tnrc == 41 ? CompensationSide::Left : CompensationSide::Right;
    std::vector<Segment> body(c.shape.begin() + 1, c.shape.end());
    try {
      Segment head = c.shape.front();
      head.to = startUpPoint(head.to, body.front(), tool_, side);
      body = compensatedPath(body, tool_, side);
      if (!body.empty()) body.front().from = head.to;
      c.shape = {head};
      c.shape.insert(c.shape.end(), body.begin(), body.end());
    } catch (const OffsetError& e) {
      c.forbiddenBy = forbidden("PS0041", e.sourceLine, "the nose radius does not fit the shape");
    }
  }

  static int tnrcOfBlock(const Block& b) { return b.hasG(410) ? 41 : (b.hasG(420) ? 42 : 40); }

  const Program& program_;
  const Profile& profile_;
  bool haasTypeII_ = false;  // HAAS.G71.R1 in the cycle block being read
  MachineParams params_;
  const ToolOffset& tool_;
  ModalState state_;
  KnownPosition known_;
  bool afterCycles_ = false;  // a cycle has been read: moving blocks go to movesAfterCycles  // PROG.POSITION: the axes whose work coordinates the program has given
  ProgramSpec out_;
  std::optional<Alarm> firstBlockAlarm_;  // a first cycle block outside the range table
  std::optional<std::size_t> grooveBlock_;  // the last first G74.1 block (I1)
  // ns and nf (block indices) of the last Huazhong G71 the rules allow: the program runs on after it.
  std::optional<std::pair<std::size_t, std::size_t>> huazhongShape_;

 public:
  std::vector<Alarm> finishingAlarms_;    // G70 blocks the rules forbid
};

}  // namespace

int CycleSpec::depthDirection() const {
  const Point a = toFrame(*this, start), b = toFrame(*this, shape.front().to);
  return signOf(b.x - a.x);
}

int CycleSpec::cutDirection() const {
  const Point from = toFrame(*this, typeII ? start : shape.front().to), to = toFrame(*this, shape.back().to);
  const int c = signOf(to.z - from.z);
  return c != 0 ? c : -1;
}

double CycleSpec::divisionStep() const {
  const double total = std::hypot(relief.z, relief.x);
  return divisions > 1 ? total / (divisions - 1) : total;
}

std::vector<Segment> CycleSpec::roughProfile() const {
  std::vector<Segment> rough;
  rough.reserve(shape.size());
  for (const Segment& s : shape) rough.push_back(s.shifted(allowance));
  return rough;
}

ProgramSpec readProgramSpec(const Program& program, const Profile& profile, const MachineParams& params,
                            const ToolOffset& tool, bool mdi) {
  SpecReader reader(program, profile, params, tool);
  ProgramSpec spec = reader.read();
  for (const Alarm& a : reader.finishingAlarms_) spec.finishingAlarms.push_back(a);
  // G72.MDI: the cycles cannot run in MDI mode; the first cycle block alarms.
  if (mdi && spec.firstCycleBlockLine) spec.mdiAlarm = forbidden("PS0067", *spec.firstCycleBlockLine, "MDI mode");
  return spec;
}

const CycleSpec* ProgramSpec::singleRoughingCycle() const {
  return cycles.size() == 1 && !cycles.front().forbiddenBy ? &cycles.front() : nullptr;
}

std::optional<Alarm> ProgramSpec::firstAlarm() const {
  if (mdiAlarm) return mdiAlarm;
  std::optional<Alarm> first;
  const auto consider = [&](const Alarm& a) {
    if (!first || a.line < first->line) first = a;
  };
  for (const CycleSpec& c : cycles) {
    if (c.forbiddenBy) consider(*c.forbiddenBy);
  }
  for (const Alarm& a : finishingAlarms) consider(a);
  if (blockAlarm) consider(*blockAlarm);
  if (siemensAlarm) consider(*siemensAlarm);
  for (const GrooveSpec& g : grooves) {
    if (g.forbiddenBy) consider(*g.forbiddenBy);
  }
  return first;
}

const GrooveSpec* ProgramSpec::singleGroove() const {
  return grooves.size() == 1 && !grooves.front().forbiddenBy && !firstAlarm() ? &grooves.front() : nullptr;
}

const SiemensCycleSpec* ProgramSpec::singleSiemensCycle() const {
  return siemensCycles.size() == 1 && !siemensAlarm ? &siemensCycles.front() : nullptr;
}

std::vector<const SiemensCycleSpec*> ProgramSpec::siemensCallsOnOneContour() const {
  std::vector<const SiemensCycleSpec*> calls;
  if (siemensAlarm || siemensCycles.empty()) return calls;
  const SiemensCycleSpec& first = siemensCycles.front();
  for (const SiemensCycleSpec& c : siemensCycles) {
    if (c.contourName != first.contourName || c.frame.transposed != first.frame.transposed ||
        c.frame.mirrored != first.frame.mirrored) {
      return {};
    }
    calls.push_back(&c);
  }
  return calls;
}

std::optional<CycleFamily> ProgramSpec::judgedFamily() const {
  if (siemensFamily) return siemensFamily;
  if (hasGrooveCycle) return CycleFamily::G74_1;
  if (const CycleSpec* c = singleRoughingCycle()) return c->family;
  return std::nullopt;
}

const CycleSpec* ProgramSpec::firstForbidden() const {
  for (const CycleSpec& c : cycles) {
    if (c.forbiddenBy) return &c;
  }
  return nullptr;
}

}  // namespace cyclecert
