// G74.1 — axial trapezoid groove cycle (GSK, seed 002 §3.23.7): reading its two blocks
// (G74_1.FMT, G74_1.ADDR, G74_1.RANGE) into a G74_1Cycle and planning it (g74_1_steps.cpp).
// docs/g74_1.md states every interpretation (I1…I28) that the comments below name.
#include "reference/cycles/g74_1.h"
#include "reference/cycles/g74_1_nose.h"

#include <array>
#include <cmath>
#include <string>

#include "reference/cycles/cycles.h"
#include "reference/interpreter/block_words.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

std::string at(const Word& w) { return w.text + " at column " + std::to_string(w.column); }

// G74_1.RANGE (I6b): a value outside its range is PS0003, naming the range.
[[noreturn]] void outOfRange(const Word& w, const std::string& range) {
  throw cycleBlockAlarm(alarm::kOutOfRange, w.line, at(w) + " is outside " + range);
}

// G74_1.FMT: the addresses each block takes (and F S T M, which any block may carry).
void requireAddressesOf(const Block& b, std::string_view letters, const std::string& format) {
  for (const Word& w : b.words) {
    if (std::string_view("GFSTM").find(w.letter) != std::string_view::npos) continue;
    if (letters.find(w.letter) != std::string_view::npos) continue;
    throw cycleBlockAlarm(alarm::kImproperAddress, w.line, at(w) + ": " + format + exponentHint(b, w));
  }
}

constexpr const char* kFirstFormat =
    "the first G74.1 block takes X Z P(Δi) Q(Δk) H(h) D(d) A(∠a) B(∠b) L(∠p) (seed 002's format)";
constexpr const char* kSecondFormat =
    "the second G74.1 block takes R(e) V(Δv) U(Δu) W(Δw) I(r) J A(r1) B(r2) D(r3) E(r4) P(abde) (seed 002's format)";

// I1: a G74.1 block with X or Z gives the groove; one without them cuts it.
bool givesTheGroove(const Block& b) { return b.has('X') || b.has('Z'); }

// The largest magnitude of a length word (IS-C, the increment system of the seed's example: I5).
constexpr double kLargestLength = 9999.9999;
constexpr double kLargestSmall = 99.9999;  // e and r1…r4

const Word& required(const Block& b, char letter, std::string_view code, const std::string& why) {
  if (const Word* w = b.find(letter)) return *w;
  throw cycleBlockAlarm(code, b.line, std::string("the first G74.1 block has no ") + letter + ": " + why);
}

// H, D: signed, not zero (I3).
double signedLength(const Word& w, const char* what) {
  if (std::abs(w.value) > kLargestLength || std::abs(w.value) <= kGeomEps) {
    outOfRange(w, std::string("-9999.9999…9999.9999 without 0 (") + what + ": its sign is the direction)");
  }
  return w.value;
}

// A, B (the flank angles, 0 < ∠ ≤ 90) and L (the slope, 0 ≤ ∠p < 90), default 90 and 0.
double flankAngle(const Block& b, char letter) {
  const Word* w = b.find(letter);
  if (!w) return 90;
  if (w->value <= 0 || w->value > 90) outOfRange(*w, "0 < ∠ ≤ 90 (a flank angle, degrees)");
  return w->value;
}

double slopeAngle(const Block& b) {
  const Word* w = b.find('L');
  if (!w) return 0;
  if (w->value < 0 || w->value >= 90) outOfRange(*w, "0 ≤ ∠p < 90 (the slope angle, degrees)");
  return w->value;
}

// P(Δi), Q(Δk) (I5): parameter 182.7 = 0 reads least input increments (IS-C: 0.0001 mm, 0.00001
// inch; no decimal point), 1 reads mm (inch). Not positive: PS0062, as G71's Δd.
double stepAmount(const Word& w, const CycleCall& call) {
  const bool inMm = call.params.bit("182#7");
  if (w.value <= 0) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, w.line, at(w) + ": the step amounts Δi (P) and Δk (Q) of G74.1 must be positive");
  }
  if (inMm) {
    if (w.value > kLargestLength) outOfRange(w, "0 < value ≤ 9999.9999 (mm or inch: parameter 182.7 = 1)");
    return w.value * call.modal.unitScale();
  }
  if (w.hasDecimalPoint) {
    throw cycleBlockAlarm(alarm::kIllegalDecimalPoint, w.line,
                          at(w) + ": P and Q of G74.1 are least input increments (parameter 182.7 = 0); write a whole "
                                  "number, or set --param 182#7=1 to give them in mm");
  }
  if (w.value > 99'999'999) outOfRange(w, "1…99999999 (least input increments, parameter 182.7 = 0)");
  const double increment = call.modal.inch ? 0.00001 : 0.0001;
  return w.value * increment * call.modal.unitScale();
}

// A word of the second block between 0 and 99.9999 (R, A, B, D, E), 0 when absent.
double smallUnsignedWord(const Block& b, char letter, const char* what) {
  const Word* w = b.find(letter);
  if (!w) return 0;
  if (w->value < 0 || w->value > kLargestSmall) outOfRange(*w, std::string("0…99.9999 (") + what + ")");
  return w->value;
}

// U, W, I: signed ranges, read as magnitudes (I4; I: "输入负值时当成正值处理").
double magnitudeWord(const Word& w, const char* what) {
  if (std::abs(w.value) > kLargestLength) outOfRange(w, std::string("-9999.9999…9999.9999 (") + what + ")");
  return std::abs(w.value);
}

// J: 0, 1 or 2.
GroovePathType pathType(const Block& b) {
  const Word* j = b.find('J');
  if (!j) return GroovePathType::RoughOnly;
  if (j->value != 0 && j->value != 1 && j->value != 2) outOfRange(*j, "J0, J1 or J2 (the path type)");
  return static_cast<GroovePathType>(static_cast<int>(j->value));
}

// P(abde) (I6): up to four digits, each 0 (chamfer) or 1 (round), a b d e from the left; fewer
// digits are zeros on the left.
std::array<GrooveCornerKind, 4> cornerKinds(const Block& b) {
  std::array<GrooveCornerKind, 4> kinds{};
  const Word* p = b.find('P');
  if (!p) return kinds;
  const double v = p->value;
  if (p->hasDecimalPoint || v < 0 || v > 1111 || v != std::floor(v)) {
    outOfRange(*p, "P0000…P1111 (four digits a b d e, each 0 for a chamfer or 1 for a round)");
  }
  int digits = static_cast<int>(v);
  for (int k = 3; k >= 0; --k, digits /= 10) {
    const int digit = digits % 10;
    if (digit > 1) outOfRange(*p, "P0000…P1111 (four digits a b d e, each 0 for a chamfer or 1 for a round)");
    kinds[static_cast<std::size_t>(k)] = digit == 1 ? GrooveCornerKind::Round : GrooveCornerKind::Chamfer;
  }
  return kinds;
}

// G74_1.FMT, G74_1.ADDR, G74_1.RANGE: the first block — the groove.
void readGrooveBlock(const Block& b, const CycleCall& call, G74_1Cycle& c) {
  requireAddressesOf(b, "XZPQHDABL", kFirstFormat);
  const double scale = call.modal.unitScale();
  const Word& x = required(b, 'X', alarm::kOutOfRange, "the groove's start X (absolute, diameter) is needed");
  const Word& z = required(b, 'Z', alarm::kOutOfRange, "the groove's start Z (absolute) is needed");
  const Word& h = required(b, 'H', alarm::kOutOfRange, "the depth h (radius, signed) is needed: no default");
  const Word& d = required(b, 'D', alarm::kOutOfRange, "the floor width d (diameter, signed) is needed: no default");
  const Word& p = required(b, 'P', alarm::kPQMissing, "the radial step Δi is needed: no default");
  const Word& q = required(b, 'Q', alarm::kPQMissing, "the peck depth Δk is needed: no default");
  const double depth = signedLength(h, "the depth h") * scale, width = signedLength(d, "the floor width d") * scale;
  c.frame.start = {z.value * scale, x.value * scale / 2};
  c.frame.depthSign = depth > 0 ? 1 : -1;
  c.frame.widthSign = width > 0 ? 1 : -1;
  c.groove.depth = std::abs(depth);
  c.groove.floorWidth = std::abs(width) / 2;
  c.groove.angleA = flankAngle(b, 'A');
  c.groove.angleB = flankAngle(b, 'B');
  c.groove.slope = slopeAngle(b);
  c.radialStep = stepAmount(p, call) / 2;
  c.peck = stepAmount(q, call);
}

// G74_1.FMT, G74_1.ADDR, G74_1.RANGE: the second block — how to cut it.
void readCuttingBlock(const Block& b, const CycleCall& call, G74_1Cycle& c) {
  requireAddressesOf(b, "RVUWIJABDEP", kSecondFormat);
  const double scale = call.modal.unitScale();
  c.retract = smallUnsignedWord(b, 'R', "the retract e, mm") * scale;
  if (const Word* v = b.find('V')) {
    if (v->value <= 0) {
      throw cycleBlockAlarm(alarm::kCuttingAmount, v->line, at(*v) + ": the layer depth Δv of G74.1 must be positive");
    }
    if (v->value > kLargestLength) outOfRange(*v, "0 < Δv ≤ 9999.9999 (the layer depth)");
    c.layerDepth = v->value * scale;
  }
  if (const Word* u = b.find('U')) c.flankAllowance = magnitudeWord(*u, "the X allowance Δu, diameter") * scale / 2;
  if (const Word* w = b.find('W')) c.floorAllowance = magnitudeWord(*w, "the Z allowance Δw") * scale;
  if (const Word* i = b.find('I')) c.toolWidth = magnitudeWord(*i, "the tool width r") * scale;
  c.pathType = pathType(b);
  const std::array<GrooveCornerKind, 4> kinds = cornerKinds(b);
  const char letters[4] = {'A', 'B', 'D', 'E'};  // r1 r2 r3 r4
  for (std::size_t k = 0; k < 4; ++k) {
    c.groove.corners[k].size = smallUnsignedWord(b, letters[k], "a corner's chamfer width or round radius, mm") * scale;
    c.groove.corners[k].kind = kinds[k];
  }
}

// I1: the nearest G74.1 block with X or Z before the second block; none is PS0061.
const Block& grooveBlockBefore(const CycleCall& call) {
  for (std::size_t k = call.blockIndex; k-- > 0;) {
    const Block& b = call.program.blocks[k];
    if (b.hasG(741) && givesTheGroove(b)) return b;
  }
  throw cycleBlockAlarm(alarm::kPQMissing, call.block().line,
                        "no first G74.1 block (G74.1 X Z P Q H D …) before this one: the groove is not given");
}

// G74_1.ADDR: the seed describes a GSK controller (its manual's section numbering, parameter NO182.7,
// the 980TDi's G74.1); FANUC documents no G74.1.
void refuseOtherProfiles(const CycleCall& call) {
  if (call.profile.name == "gsk") return;
  throw NotSupported(call.block().line, "G74.1 (axial trapezoid groove) is a GSK cycle (seed 002); the " +
                                            call.profile.name + " profile does not have it: use --profile gsk");
}

// I28: the seed gives G74.1 with X and Z words (the axial Z feed, the radial X step) and no plane, and
// no documentation of it in another plane was found.
void refuseOtherPlanes(const CycleCall& call) {
  if (call.modal.axes().gCode == 18) return;
  throw NotSupported(call.block().line, "G74.1 under G" + std::to_string(call.modal.axes().gCode) +
                                            ": seed 002 gives G74.1 with X and Z words (Z feeds, X steps) only, so it is "
                                            "planned in the ZX plane (G18) only (G74_1.ADDR, docs/g74_1.md I28); "
                                            "command G18 before the cycle");
}

std::string compensationCode(int tnrc) { return "G4" + std::to_string(tnrc % 10); }

// I13, I26: a pointed tool (no I) under G41/G42 with a nose radius is planned by its nose centre in
// the groove eroded by R and moved as its imaginary tip; the side must be the groove's inside as
// the profile passes run (G41 when h and d have the same sign, else G42: I26), the other side puts
// the nose outside the groove on every flank — the interference alarm. A grooving tool ignores
// G41/G42 (G74_1.ADDR).
void applyCompensation(const CycleCall& call, G74_1Cycle& c, std::vector<Warning>& warnings) {
  if (call.modal.tnrc == 40) return;
  const std::string code = compensationCode(call.modal.tnrc);
  if (call.block().has('I')) {
    warnings.push_back({call.block().line, code + " is ignored by G74.1 with a grooving tool (I): the blade's corners "
                                                  "follow the groove (G74_1.ADDR)"});
    return;
  }
  if (call.tool.noseRadius <= 0) return;  // the runner warns: nothing to offset
  const CompensationSide inside = grooveInsideSide(c.frame);
  const std::string insideCode = inside == CompensationSide::Left ? "G41" : "G42";
  if (code != insideCode) {
    throw cycleBlockAlarm(alarm::kInterference, call.block().line,
                          "G74.1 with a pointed tool under " + code + " puts the nose outside the groove: with h " +
                              (c.frame.depthSign > 0 ? "> 0" : "< 0") + " and d " + (c.frame.widthSign > 0 ? "> 0" : "< 0") +
                              " the groove's inside is on the " + (inside == CompensationSide::Left ? "left" : "right") +
                              " of its profile passes: command " + insideCode + " (G74_1.ADDR, docs/g74_1.md I26)");
  }
  if (call.tool.tip < 0 || call.tool.tip > 9) {
    throw NotSupported(call.block().line, "the imaginary tip " + std::to_string(call.tool.tip) +
                                              " is not one of 0…9 (--tip, or the case's \"tool\")");
  }
  c.nose = GrooveNose{call.tool.noseRadius, call.tool.noseRadius * imaginaryTipDirection(call.tool.tip)};
}

}  // namespace

void applyG74_1FirstBlock(const CycleCall& call) {
  refuseOtherProfiles(call);
  G74_1Cycle unused;
  readGrooveBlock(call.block(), call, unused);  // its alarms belong to this block
}

bool isG74_1GrooveBlock(const Block& b) { return givesTheGroove(b); }

CycleOutcome planG74_1(const CycleCall& call) {
  refuseOtherProfiles(call);
  refuseOtherPlanes(call);
  const Block& b = call.block();
  G74_1Cycle c;
  c.line = b.line;
  c.before = call.modal.planePoint();
  c.feed = call.modal.feed;
  readGrooveBlock(grooveBlockBefore(call), call, c);
  readCuttingBlock(b, call, c);
  CycleOutcome out;
  applyCompensation(call, c, out.warnings);
  if (c.feed <= 0) {  // I21: the seed's example gives no F
    out.warnings.push_back({b.line, "no cutting feed F before G74.1: its feeds are drawn with F 0 (seed 002's example "
                                    "O0008 gives none)"});
  }
  try {
    out.moves = planG74_1Moves(c);
    out.shape = g74_1FinishShape(c);
    out.roughShape = g74_1RoughShape(c);
  } catch (const NoseDoesNotFit& e) {  // I27
    throw cycleBlockAlarm(alarm::kInterference, b.line, std::string("G74.1: ") + e.what());
  } catch (const GrooveDoesNotFit& e) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, b.line, std::string("G74.1: ") + e.what());
  }
  out.resumeAt = call.blockIndex + 1;
  return out;
}

}  // namespace cyclecert
