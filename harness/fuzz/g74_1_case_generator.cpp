// The fuzzer's G74.1 cases (g74_1_case_generator.h says what is drawn and how it is written).
//
// A groove is drawn in its own frame (docs/g74_1.md §2: u across along d, w down along h) as
// magnitudes — the depth |h|, the floor width |d|/2, the angles, the corners — and the signs of h and
// d give its direction in the machine. fitTheGroove() keeps a valid draw cuttable by bounds worked
// out by hand from §3–§5 (not by asking the reference), and fitTheWork() keeps each case to a few
// thousand moves; a fault then replaces one word as the program is written (g74_1Program()).
#include "harness/fuzz/g74_1_case_generator.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "harness/fuzz/generator_parts.h"
#include "harness/fuzz/named_choices.h"

namespace cyclecert {

namespace {

// --- what is drawn ---

// The fifteen choices 0…9 a G74.1 case draws first (field by field in the order drawn), by the
// decision each makes.
struct GrooveChoices {
  int depthSign;     // h < 0 (feeds towards −Z) when even
  int widthSign;     // d < 0 (steps towards −X) when even
  int angleA;        // ∠a 90° when < 5, else the sharp angle drawn
  int angleB;        // ∠b likewise
  int slope;         // ∠p 0 when < 7, else the slope drawn (below ∠a)
  int corners;       // no corners when < 4, else each corner drawn (a 0 drawn is a sharp corner)
  int cornerKinds;   // P(abde) written when ≥ 5 (else every corner a chamfer, by default)
  int layers;        // no V when < 5, else V for (choice − 4) layers: 1…5
  int allowances;    // none when < 4; Δu 4–5, Δw 6–7, both 8–9
  int tool;          // a pointed tool (no I) when < 3 — with a nose radius under G41/G42 when 2 and
                     // the variant 0 —
                     // else the grooving tool drawn
  int pathType;      // J absent 0–2, J0 written 3, J1 4–6, J2 7–9
  int stepsInMm;     // parameter 182#7 = 1 (P, Q in mm) when odd
  int fault;         // one invalid value when 9 (one case in ten)
  int whichFault;    // which: 10 · this + variant, mod the faults' count (kFaults)
  int variant;       // the fault's spelling; the allowances and the angles written negative or explicit when ≥ 8
};

GrooveChoices grooveChoicesFrom(const std::vector<int>& drawn) {
  const auto at = [&](std::size_t i) { return choiceAt(drawn, i); };
  return {at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), at(8), at(9), at(10), at(11), at(12), at(13), at(14)};
}
constexpr std::size_t kGrooveChoices = 15;

// The groove's sizes as drawn (hundredths of a mm, whole degrees), before they are fitted.
struct GrooveSizes {
  int depth;       // |h|, radius
  int floorWidth;  // |d| / 2, radius
  int sharpA, sharpB, slope;
  std::vector<int> corners;  // r1 r2 r3 r4
  int cornerKinds;           // four bits a b d e
};

// How the groove is cut, as drawn (hundredths).
struct CuttingSizes {
  int radialStep, peck, retract;  // Δi (diameter), Δk, e
  int allowanceX, allowanceZ;     // Δu (diameter), Δw
  int toolWidth;                  // I; a pointed tool's nose radius and tip (tool choice 2) are read from it
};

// Where the groove and the tool stand (hundredths).
struct Placing {
  int base;   // S's radius beyond what the groove needs
  int z;      // S's Z
  int clear;  // the tool before the cycle stands this far on the air side of the start level
  int along;  // … and this far across the groove from S
};

constexpr int kLargestCornerDrawn = 200;

rc::Gen<GrooveSizes> genGrooveSizes() {
  return rc::gen::apply(
      [](int depth, int floorWidth, int a, int b, int p, std::vector<int> corners, int kinds) {
        return GrooveSizes{depth, floorWidth, a, b, p, std::move(corners), kinds};
      },
      rc::gen::inRange(100, 2000), rc::gen::inRange(100, 2000), wholeRange(20, 90), wholeRange(20, 90), wholeRange(1, 45),
      rc::gen::container<std::vector<int>>(4, wholeRange(0, kLargestCornerDrawn + 1)), wholeRange(0, 16));
}

rc::Gen<CuttingSizes> genCuttingSizes() {
  return rc::gen::apply(
      [](int di, int dk, int e, int du, int dw, int r) { return CuttingSizes{di, dk, e, du, dw, r}; },
      rc::gen::inRange(20, 800), rc::gen::inRange(20, 1000), rc::gen::inRange(0, 200), rc::gen::inRange(1, 200),
      rc::gen::inRange(1, 200), rc::gen::inRange(10, 600));
}

rc::Gen<Placing> genPlacing() {
  return rc::gen::apply([](int base, int z, int clear, int along) { return Placing{base, z, clear, along}; },
                        rc::gen::inRange(100, 3000), rc::gen::inRange(-3000, 3000), rc::gen::inRange(50, 1000),
                        rc::gen::inRange(0, 1000));
}

double tanDegrees(int degrees) { return std::tan(degrees * std::numbers::pi / 180.0); }
double cotDegrees(int degrees) { return degrees >= 90 ? 0.0 : 1.0 / tanDegrees(degrees); }

// The far end of the groove's mouth at ∠p = 0 (u of M2, docs/g74_1.md §3): a slope only brings it
// nearer. Hundredths.
double mouthFarEnd(const G74_1FuzzCase& g) {
  const double h = std::abs(g.depth), floor = std::abs(g.width) / 2.0;
  return h * cotDegrees(g.angleA) + floor + h * cotDegrees(g.angleB);
}

// The groove's words from the sizes and the choices: the directions, the angles, the corners.
void chooseTheGroove(G74_1FuzzCase& g, const GrooveChoices& choice, const GrooveSizes& sizes) {
  g.depth = choice.depthSign % 2 == 0 ? -sizes.depth : sizes.depth;
  g.width = (choice.widthSign % 2 == 0 ? -2 : 2) * sizes.floorWidth;
  g.angleA = choice.angleA < 5 ? 90 : sizes.sharpA;
  g.angleB = choice.angleB < 5 ? 90 : sizes.sharpB;
  g.slope = choice.slope < 7 ? 0 : sizes.slope;
  g.writeAngles = choice.variant >= 8;
  if (choice.corners >= 4) {
    for (std::size_t k = 0; k < 4 && k < sizes.corners.size(); ++k) g.corners[k] = sizes.corners[k];
  }
  if (choice.cornerKinds >= 5) g.cornerKinds = sizes.cornerKinds;
}

// How it is cut: the steps, e, the layers, the allowances, the tool, J, the units of P and Q.
void chooseTheCutting(G74_1FuzzCase& g, const GrooveChoices& choice, const CuttingSizes& sizes) {
  g.radialStep = sizes.radialStep;
  g.peck = sizes.peck;
  g.retract = sizes.retract;
  if (choice.layers >= 5) g.layerDepth = (std::abs(g.depth) + (choice.layers - 4) - 1) / (choice.layers - 4);
  const int sign = choice.variant >= 8 ? -1 : 1;  // I4: U and W are read as magnitudes
  if (choice.allowances >= 4 && choice.allowances != 6 && choice.allowances != 7) g.allowanceX = sign * sizes.allowanceX;
  if (choice.allowances >= 6) g.allowanceZ = sign * sizes.allowanceZ;
  if (choice.tool >= 3) g.toolWidth = sizes.toolWidth;
  g.pathType = choice.pathType < 4 ? 0 : choice.pathType < 7 ? 1 : 2;
  g.writeJ = choice.pathType == 3;
  g.stepsInMm = choice.stepsInMm % 2 == 1;
}

// A valid groove the tool can cut (docs/g74_1.md §3–§5, bounds worked out by hand): Δu at most half
// the floor width and Δw a third of the depth, so the rough floor keeps half the width and two
// thirds of the depth; the slope at least 10° below ∠a and low enough that the mouth stays in the
// upper half of the rough flanks (I9); each corner (drawn 0…2 mm) scaled to within a ninth of the
// depth and an eighth of the floor (a chamfer or round sets back at most its size from its corner:
// the flanks open towards the mouth, so no corner is sharper than 90°); the tool within a fifth of
// the floor, which leaves it the quarter the corners r3, r4 leave of the rough floor (I12).
// The widest grooving tool a case draws: a fifth of the floor (fitTheGroove).
int widestTool(const G74_1FuzzCase& g) { return std::abs(g.width) / 2 / 5; }

void fitTheGroove(G74_1FuzzCase& g) {
  const int h = std::abs(g.depth), floor = std::abs(g.width) / 2;
  g.allowanceX = std::clamp(g.allowanceX, -floor / 2, floor / 2);
  g.allowanceZ = std::clamp(g.allowanceZ, -h / 3, h / 3);
  if (g.slope > 0) {
    g.slope = std::min(g.slope, g.angleA - 10);
    const double roughDepth = h - std::abs(g.allowanceZ);
    if (g.slope <= 0 || mouthFarEnd(g) * tanDegrees(g.slope) > 0.5 * roughDepth) g.slope = 0;
  }
  const int largestCorner = std::min(h / 9, floor / 8);
  for (int& r : g.corners) r = r * largestCorner / kLargestCornerDrawn;  // as drawn, scaled to fit
  g.toolWidth = std::min(g.toolWidth, widestTool(g));
}

// A case of a few thousand moves at most: about 25 axial cycles a layer (Δi/2 at least a 25th of
// the mouth's width), 10 pecks a cycle (Δk at least a tenth of the depth), 5 layers (Δv).
// A grooving tool steps across by at most its width (Δi/2 ≤ r): wider steps leave ribs between the
// axial cycles, which the seed's cycle does not cut and its later rapids cross (rapids-in-air flags
// them: a program error, not what the generator is for) — the tool widened to the step where the
// floor leaves room, else the step narrowed to the tool.
void fitTheWork(G74_1FuzzCase& g) {
  const int h = std::abs(g.depth);
  g.radialStep = std::max(g.radialStep, static_cast<int>(std::ceil(2 * mouthFarEnd(g) / 25)));
  g.peck = std::max(g.peck, (h + 9) / 10);
  if (g.toolWidth > 0 && g.radialStep > 2 * g.toolWidth) {
    g.toolWidth = std::min((g.radialStep + 1) / 2, widestTool(g));  // wider than before: it was within widestTool
    g.radialStep = std::min(g.radialStep, 2 * g.toolWidth);
  }
}

constexpr double kDegree = 3.14159265358979323846 / 180;

// S and the tool's place before the cycle: every radius at least 1 mm (x = X/2 + sd·u over the
// groove's u, from the mouth corner r1 behind S to the far end of the mouth), the tool on the air
// side of the start level over the mouth (docs/g74_1.md I7: the start level is in air over the
// whole groove), so its straight rapids to A11 and back (I18, I20) stay in air.
// A nose of radius R (I26) comes down onto A11 whole: it stands 3R further on the air side and at
// least 3R inside the groove's width (its centre and tip within 2R of the point), so that ① sweeps
// it across neither the stock nor the mouth's corners.
void placeTheGroove(G74_1FuzzCase& g, const Placing& place, int noseRadius) {
  const int sh = g.depth > 0 ? 1 : -1, sd = g.width > 0 ? 1 : -1;
  const int farEnd = static_cast<int>(std::ceil(mouthFarEnd(g)));
  const int radius = place.base + (sd < 0 ? farEnd : 2 * g.corners[0]) + 100;
  g.startX = 2 * radius;
  g.startZ = place.z;
  const int margin = 3 * noseRadius;
  const int across = std::clamp(std::min(place.along, farEnd * 9 / 10), margin, std::max(margin, farEnd * 9 / 10 - margin));
  g.beforeX = 2 * (radius + sd * across);
  // A grooving tool's blade reaches up to its width beyond that point across the mouth, which rises
  // behind S at ∠p: the tool stands that much further on the air side, or its blade would stand in
  // the part before the cycle (no-gouge on move 0, fuzz seeds 5 and 8 × 20,000).
  const int bladeRise = g.toolWidth > 0 && g.slope > 0
                            ? static_cast<int>(std::ceil((across + g.toolWidth) * std::tan(g.slope * kDegree)))
                            : 0;
  g.beforeZ = place.z - sh * (place.clear + margin + bladeRise);
}

constexpr G74_1Fault kFaults[] = {
    G74_1Fault::DepthOut,         G74_1Fault::WidthOut,           G74_1Fault::AngleAOut,
    G74_1Fault::AngleBOut,        G74_1Fault::SlopeOut,           G74_1Fault::StepNotPositive,
    G74_1Fault::StepTooLarge,     G74_1Fault::MissingPeck,        G74_1Fault::DecimalPoint,
    G74_1Fault::WordNotTaken,     G74_1Fault::RetractOut,         G74_1Fault::LayerNotPositive,
    G74_1Fault::AllowanceOut,     G74_1Fault::ToolWidthOut,       G74_1Fault::PathTypeOut,
    G74_1Fault::CornerOut,        G74_1Fault::CornerDigitOut,     G74_1Fault::ToolWiderThanFloor,
    G74_1Fault::SlopeNotBelowFlank};
constexpr int kFaultCount = static_cast<int>(sizeof kFaults / sizeof kFaults[0]);

// The wider of the groove's two floors, hundredths (radius): the finish floor |d|/2, the rough one
// raised by Δw and so widened along sloping flanks by Δw·(cot ∠a + cot ∠b) (less Δu, which moves
// the flanks in). A blade wider than both does not fit whichever the cycle cuts (I12, I24).
int widestFloor(const G74_1FuzzCase& g) {
  const auto cot = [&](int degrees) { return degrees == 90 ? 0.0 : 1 / std::tan(degrees * kDegree); };
  const double widening = std::abs(g.allowanceZ) * (cot(g.angleA) + cot(g.angleB));
  return std::abs(g.width) / 2 + static_cast<int>(std::ceil(widening));
}

// One invalid value, one case in ten. Most faults are one word spelt out of range as the program
// is written; two are values in range the groove cannot take: a tool wider than the floor (I12),
// a slope as steep as the near flank (I9).
void drawFault(G74_1FuzzCase& g, const GrooveChoices& choice) {
  if (choice.fault != 9) return;
  g.fault = kFaults[(10 * choice.whichFault + choice.variant) % kFaultCount];  // 100 values over the faults
  g.faultVariant = choice.variant;
  if (g.fault == G74_1Fault::DecimalPoint) g.stepsInMm = false;  // a decimal point is an alarm in increments only
  if (g.fault == G74_1Fault::ToolWiderThanFloor) g.toolWidth = widestFloor(g) + 50 + 10 * choice.variant;
  if (g.fault == G74_1Fault::SlopeNotBelowFlank) {
    if (g.angleA == 90) g.angleA = 60;
    g.slope = std::min(89, g.angleA + choice.variant % 3);
  }
}

// A pointed tool with a nose radius under G41/G42 (docs/g74_1.md I26), one case in a hundred (tool
// choice 2 with variant 0: a nose's replay, a disc swept as exact regions, costs the oracles about
// fourteen times a point's, and G74.1's fuzz rate must hold): its radius and tip read from the tool
// width drawn (unused by a pointed tool, so the other cases draw as before), the radius kept within 15 % of the floor and 20 % of the depth — well inside what the
// rough groove holds (the floor keeps half its width and two thirds of its depth: fitTheGroove) —
// and at least 0.05 mm; the compensation on the groove's inside (G41 when h and d have the same sign).
void chooseTheNose(FuzzCase& c, const GrooveChoices& choice, const CuttingSizes& sizes) {
  const G74_1FuzzCase& g = c.groove;
  if (choice.tool != 2 || choice.variant != 0) return;
  const int largest = std::min(std::abs(g.width) / 2 * 15 / 100, std::abs(g.depth) * 20 / 100);
  if (largest < 5) return;
  c.noseRadius = std::clamp(sizes.toolWidth / 4, 5, largest);
  c.tip = (sizes.toolWidth / 10) % 10;
}

FuzzCase grooveCaseFrom(const GrooveChoices& choice, const GrooveSizes& groove, const CuttingSizes& cutting,
                        const Placing& place) {
  FuzzCase c;
  c.cycle = 741;
  c.profile = "gsk";  // G74_1.ADDR: a GSK cycle
  G74_1FuzzCase& g = c.groove;
  chooseTheGroove(g, choice, groove);
  chooseTheCutting(g, choice, cutting);
  fitTheGroove(g);
  fitTheWork(g);
  chooseTheNose(c, choice, cutting);
  placeTheGroove(g, place, c.noseRadius);
  drawFault(g, choice);
  return c;
}

// --- how it is written ---

// P and Q (I5): in mm with 182#7 = 1, else in IS-C least increments (0.0001 mm: 100 a hundredth).
std::string stepWord(char letter, int hundredths, bool inMm) {
  return std::string(1, letter) + (inMm ? mm(hundredths) : std::to_string(100L * hundredths));
}

std::string angleWord(char letter, int degrees, int byDefault, bool explicitly) {
  return degrees != byDefault || explicitly ? std::string(" ") + letter + std::to_string(degrees) : "";
}

bool odd(int variant) { return variant % 2 == 1; }

// The groove block (line 2), with the fault's word when it is this block's.
std::string grooveBlock(const G74_1FuzzCase& g) {
  const G74_1Fault f = g.fault;
  const bool v = odd(g.faultVariant);
  std::string b = "G74.1 X" + mm(g.startX) + " Z" + mm(g.startZ);
  if (f == G74_1Fault::StepNotPositive && !v) b += " P0";
  else if (f == G74_1Fault::StepTooLarge) b += g.stepsInMm ? " P10000" : " P100000000";
  else if (f == G74_1Fault::DecimalPoint) b += " " + stepWord('P', g.radialStep, false) + ".";
  else b += " " + stepWord('P', g.radialStep, g.stepsInMm);
  if (f == G74_1Fault::StepNotPositive && v) b += " Q-" + stepWord('Q', g.peck, g.stepsInMm).substr(1);
  else if (f != G74_1Fault::MissingPeck) b += " " + stepWord('Q', g.peck, g.stepsInMm);
  if (f == G74_1Fault::DepthOut) {
    const int spelling = g.faultVariant % 3;
    b += spelling == 0 ? " H0" : spelling == 1 ? (g.depth < 0 ? " H-10000" : " H10000") : "";
  } else {
    b += " H" + mm(g.depth);
  }
  if (f == G74_1Fault::WidthOut) b += v ? " D-10000" : " D0";
  else b += " D" + mm(g.width);
  if (f == G74_1Fault::AngleAOut) b += v ? " A95" : " A0";
  else b += angleWord('A', g.angleA, 90, g.writeAngles);
  if (f == G74_1Fault::AngleBOut) b += v ? " B90.5" : " B0";
  else b += angleWord('B', g.angleB, 90, g.writeAngles);
  if (f == G74_1Fault::SlopeOut) b += v ? " L-1" : " L90";
  else b += angleWord('L', g.slope, 0, g.writeAngles);
  if (f == G74_1Fault::WordNotTaken) b += " R1";
  return b + ";\n";
}

// P(abde): four digits, a b d e from the left.
std::string cornerDigits(int bits) {
  std::string digits;
  for (int k = 3; k >= 0; --k) digits += (bits >> k) & 1 ? '1' : '0';
  return digits;
}

// The second block (line 3), with the fault's word when it is this block's.
std::string cuttingBlock(const G74_1FuzzCase& g) {
  const G74_1Fault f = g.fault;
  const bool v = odd(g.faultVariant);
  std::string b = "G74.1 R" + (f == G74_1Fault::RetractOut ? std::string(v ? "-1" : "100") : mm(g.retract));
  if (f == G74_1Fault::LayerNotPositive) b += v ? " V-1" : " V0";
  else if (g.layerDepth > 0) b += " V" + mm(g.layerDepth);
  if (f == G74_1Fault::AllowanceOut && !v) b += " U10000";
  else if (g.allowanceX != 0) b += " U" + mm(g.allowanceX);
  if (f == G74_1Fault::AllowanceOut && v) b += " W-10000";
  else if (g.allowanceZ != 0) b += " W" + mm(g.allowanceZ);
  if (f == G74_1Fault::ToolWidthOut) b += v ? " I-10000" : " I10000";
  else if (g.toolWidth > 0) b += " I" + mm(g.toolWidth);
  if (f == G74_1Fault::PathTypeOut) b += v ? " J-1" : " J3";
  else if (g.pathType != 0 || g.writeJ) b += " J" + std::to_string(g.pathType);
  const char letters[4] = {'A', 'B', 'D', 'E'};  // r1 r2 r3 r4
  for (std::size_t k = 0; k < 4; ++k) {
    if (f == G74_1Fault::CornerOut && k == 0 && !v) b += " A100";
    else if (f == G74_1Fault::CornerOut && k == 3 && v) b += " E-1";
    else if (g.corners[k] > 0) b += std::string(" ") + letters[k] + mm(g.corners[k]);
  }
  if (f == G74_1Fault::CornerDigitOut) b += v ? " P11111" : " P2";
  else if (g.cornerKinds >= 0) b += " P" + cornerDigits(g.cornerKinds);
  return b + ";\n";
}

// Is the fault's word in the groove block (line 2), or in the second block (line 3)?
bool faultInTheGrooveBlock(G74_1Fault f) {
  switch (f) {
    case G74_1Fault::DepthOut:
    case G74_1Fault::WidthOut:
    case G74_1Fault::AngleAOut:
    case G74_1Fault::AngleBOut:
    case G74_1Fault::SlopeOut:
    case G74_1Fault::StepNotPositive:
    case G74_1Fault::StepTooLarge:
    case G74_1Fault::MissingPeck:
    case G74_1Fault::DecimalPoint:
    case G74_1Fault::WordNotTaken: return true;
    default: return false;
  }
}

// docs/g74_1.md I6b: the code each fault raises.
const char* faultCode(G74_1Fault f) {
  switch (f) {
    case G74_1Fault::StepNotPositive:
    case G74_1Fault::LayerNotPositive:
    case G74_1Fault::ToolWiderThanFloor:
    case G74_1Fault::SlopeNotBelowFlank: return "PS0062";
    case G74_1Fault::MissingPeck: return "PS0061";
    case G74_1Fault::DecimalPoint: return "PS0007";
    case G74_1Fault::WordNotTaken: return "PS0009";
    default: return "PS0003";
  }
}

const char* faultText(G74_1Fault f) {
  switch (f) {
    case G74_1Fault::None: return "";
    case G74_1Fault::DepthOut: return ", h out of range or missing (PS0003)";
    case G74_1Fault::WidthOut: return ", d out of range (PS0003)";
    case G74_1Fault::AngleAOut: return ", ∠a out of range (PS0003)";
    case G74_1Fault::AngleBOut: return ", ∠b out of range (PS0003)";
    case G74_1Fault::SlopeOut: return ", ∠p out of range (PS0003)";
    case G74_1Fault::StepNotPositive: return ", Δi or Δk not positive (PS0062)";
    case G74_1Fault::StepTooLarge: return ", Δi over its range (PS0003)";
    case G74_1Fault::MissingPeck: return ", no Q (PS0061)";
    case G74_1Fault::DecimalPoint: return ", a decimal point in P read in increments (PS0007)";
    case G74_1Fault::WordNotTaken: return ", R in the groove block (PS0009)";
    case G74_1Fault::RetractOut: return ", e out of range (PS0003)";
    case G74_1Fault::LayerNotPositive: return ", Δv not positive (PS0062)";
    case G74_1Fault::AllowanceOut: return ", Δu or Δw out of range (PS0003)";
    case G74_1Fault::ToolWidthOut: return ", I out of range (PS0003)";
    case G74_1Fault::PathTypeOut: return ", J out of range (PS0003)";
    case G74_1Fault::CornerOut: return ", r1 or r4 out of range (PS0003)";
    case G74_1Fault::CornerDigitOut: return ", P(abde) out of range (PS0003)";
    case G74_1Fault::ToolWiderThanFloor: return ", the tool wider than the floor (PS0062)";
    case G74_1Fault::SlopeNotBelowFlank: return ", ∠p not below ∠a: no groove (PS0062)";
  }
  return "";
}

std::vector<std::string> grooveRules(const G74_1FuzzCase& g) {
  std::vector<std::string> rules{"G74_1.FMT", "G74_1.ADDR"};
  if (g.fault != G74_1Fault::None) {
    rules.push_back("G74_1.RANGE");
    return rules;
  }
  if (g.pathType != 2) rules.push_back("G74_1.STEP9");
  if (g.pathType != 0) rules.push_back("G74_1.STEP10");
  return rules;
}

}  // namespace

rc::Gen<FuzzCase> genG74_1Case() {
  return rc::gen::apply(
      [](const std::vector<int>& choice, const GrooveSizes& groove, const CuttingSizes& cutting, const Placing& place) {
        return grooveCaseFrom(grooveChoicesFrom(choice), groove, cutting, place);
      },
      // RapidCheck scales inRange by the case's size: the choices are drawn over their whole range
      // at every size (they shrink towards 0 all the same).
      rc::gen::container<std::vector<int>>(kGrooveChoices, wholeRange(0, 10)), genGrooveSizes(), genCuttingSizes(),
      genPlacing());
}

// I26: G41 when h and d have the same sign (the groove's inside left of its passes), else G42.
int grooveCompensationCode(const G74_1FuzzCase& g) { return (g.depth > 0) == (g.width > 0) ? 41 : 42; }

std::string g74_1Program(const FuzzCase& c) {
  const G74_1FuzzCase& g = c.groove;
  const std::string compensation = c.noseRadius > 0 ? "G" + std::to_string(grooveCompensationCode(g)) + ";\n" : "";
  return "G00 X" + mm(g.beforeX) + " Z" + mm(g.beforeZ) + " F0.1;\n" + compensation + grooveBlock(g) + cuttingBlock(g) +
         "M30;\n";
}

std::optional<FuzzExpectedAlarm> g74_1ExpectedAlarm(const FuzzCase& c) {
  const G74_1Fault f = c.groove.fault;
  if (f == G74_1Fault::None) return std::nullopt;
  const int compensationLine = c.noseRadius > 0 ? 1 : 0;  // G41/G42 on its own line before the groove
  return FuzzExpectedAlarm{faultCode(f), (faultInTheGrooveBlock(f) ? 2 : 3) + compensationLine};
}

std::string describeG74_1Case(const FuzzCase& c) {
  const G74_1FuzzCase& g = c.groove;
  std::ostringstream o;
  o << "G74.1, h " << (g.depth < 0 ? "−" : "+") << " d " << (g.width < 0 ? "−" : "+") << ", |h| " << mm(std::abs(g.depth))
    << " |d| " << mm(std::abs(g.width)) << ", ∠a " << g.angleA << " ∠b " << g.angleB << " ∠p " << g.slope;
  const auto corners = std::count_if(g.corners.begin(), g.corners.end(), [](int r) { return r > 0; });
  if (corners > 0) o << ", " << corners << " corner(s)" << (g.cornerKinds >= 0 ? " P" + cornerDigits(g.cornerKinds) : "");
  o << ", Δi " << mm(g.radialStep) << " Δk " << mm(g.peck) << " e " << mm(g.retract);
  if (g.layerDepth > 0) o << ", Δv " << mm(g.layerDepth);
  if (g.allowanceX != 0 || g.allowanceZ != 0) o << ", Δu " << mm(g.allowanceX) << " Δw " << mm(g.allowanceZ);
  o << (g.toolWidth > 0 ? ", I " + mm(g.toolWidth) : ", pointed tool");
  if (c.noseRadius > 0) o << " under G" << grooveCompensationCode(g) << ", nose radius " << mm(c.noseRadius) << " tip " << c.tip;
  o << ", J" << g.pathType << ", P/Q in "
    << (g.stepsInMm ? "mm (182#7 = 1)" : "increments") << faultText(g.fault);
  return o.str();
}

nlohmann::json g74_1SpecJson(const FuzzCase& c, const std::string& tag) {
  nlohmann::json j = drawnCaseJson(c, tag, grooveRules(c.groove), g74_1Program(c), g74_1ExpectedAlarm(c),
                                   "generated by cyclecert fuzz with one invalid G74.1 value: the alarm docs/g74_1.md "
                                   "§1 (I6b) names, at its block");
  j["params"] = nlohmann::json::object();
  if (c.groove.stepsInMm) j["params"]["182#7"] = 1;
  return j;
}

}  // namespace cyclecert
