// The fuzzer's G73 cases (pattern repeating, rules G73.*): drawn in G71's frame (cut along −z,
// depth along +x, each axis mirrored for the four quadrants, so that the allowances and reliefs
// carry the quadrant's signs), written by fuzzProgram() in the two-block format.
//
// What is drawn: a shape that need not be monotone along the depth axis (G73.SHAPE) — lines, 45°
// chamfers, convex and concave quarter arcs, going up or down, steps up, zero-length lines — from B
// (block ns moves both axes from A, in G01, or G00 when Δk = 0) to C, which is its highest point (a
// last step up when the drawn shape ends lower: each pass's rapid back to A then stays above what is
// left); the number of divisions d (1 one time in five: G73.D1), the reliefs Δi and Δk (0 on their
// boundary now and then), the allowances Δu/2 and Δw (0 now and then); the profiles fanuc-0i-f,
// fanuc-0i-c and gsk; G70 after the cycle one time in three; and, one case in ten, one invalid
// parameter with the alarm it raises (G73Fault: R0, R2.5, no Q, block ns in G02). The reliefs and
// allowances point away from the part on every segment (shiftAwayFromThePart): the shift of a pass
// otherwise cuts into the part, a programmer's collision on any controller.
#include "harness/fuzz/case_generator.h"

#include <algorithm>

#include "harness/fuzz/generator_parts.h"
#include "harness/fuzz/named_choices.h"

namespace cyclecert {

namespace {

// A G73 segment: genSegment()'s kinds, going down (−x of the frame) when `down` says so — except
// a step, which only goes up (down and up again at one cut coordinate is a slot of no width).
FuzzSegment g73Segment(int shape, int along, int up, bool down) {
  FuzzSegment s;
  switch (shape) {
    case 0: s = {FuzzSegment::Line, along, up}; break;
    case 1: s = {FuzzSegment::Line, along, along}; break;  // chamfer
    case 2: s = {FuzzSegment::ConvexArc, along, along}; break;
    case 3: s = {FuzzSegment::ConcaveArc, along, along}; break;
    case 4: s = {FuzzSegment::Line, along, 0}; break;  // along the cut axis
    case 5: return {FuzzSegment::Line, 0, up};         // a step (up)
    default: return {FuzzSegment::Line, 0, 0};         // zero length
  }
  if (down) s.up = -s.up;
  return s;
}

rc::Gen<FuzzSegment> genG73Segment() {
  return rc::gen::apply(g73Segment,
                        rc::gen::weightedElement<int>({{6, 0}, {3, 1}, {3, 2}, {3, 3}, {3, 4}, {3, 5}, {1, 6}}),
                        rc::gen::inRange(10, 600), rc::gen::inRange(10, 300), rc::gen::arbitrary<bool>());
}

// C at the shape's highest point: a step up from where the drawn shape ends when it ends lower.
void endAtTheTop(FuzzCase& c) {
  int depth = 0, top = 0;
  for (const FuzzSegment& s : c.segments) {
    depth += s.up;
    top = std::max(top, depth);
  }
  if (c.segments.empty() || depth < top) c.segments.push_back({FuzzSegment::Line, 0, top - depth + 50});
}

// The ten choices 0…9 a G73 case draws first (field by field in the order drawn), by the decision
// each makes.
struct G73Choices {
  int profile;      // the profile (profileChosen)
  int mirrorCut;    // the cut axis runs the other way when 1 (mod 4)
  int mirrorDepth;  // the depth axis runs the other way when 1 (mod 4)
  int headMotion;   // block ns in G00 (even) or G01 (odd), G00 only without Δk
  int fault;        // one invalid parameter when 9 (one case in ten)
  int whichFault;   // which one (mod 4: kFaults)
  int finish;       // G70 after the cycle when 0 (mod 3)
  int noRelief;     // no relief along the depth axis (Δi) when 0, along the cut axis (Δk) when 1
  int noAllowance;  // no allowance (Δu, Δw) when 0
  int oneDivision;  // d = 1 when < 2
};

G73Choices g73ChoicesFrom(const std::vector<int>& drawn) {
  const auto at = [&](std::size_t i) { return choiceAt(drawn, i); };
  return {at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), at(8), at(9)};
}

// The choices made: profile, quadrant, head motion, the invalid parameter and which, G70, boundaries.
void chooseG73(FuzzCase& c, const G73Choices& choice) {
  c.profile = profileChosen(choice.profile);
  c.mirrorCut = choice.mirrorCut % 4 == 1;
  c.mirrorDepth = choice.mirrorDepth % 4 == 1;
  static constexpr G73Fault kFaults[] = {G73Fault::NoDivisions, G73Fault::FractionalDivisions, G73Fault::MissingQ,
                                         G73Fault::ArcHead};
  c.g73Fault = choice.fault == 9 ? kFaults[choice.whichFault % 4] : G73Fault::None;  // one case in ten
  c.finish = choice.finish % 3 == 0;
  if (choice.noRelief == 0) c.reliefDepth = 0;  // no relief along a axis: the passes differ along the other only
  if (choice.noRelief == 1) c.reliefCut = 0;
  if (choice.noAllowance == 0) c.allowanceDepth = c.allowanceCut = 0;  // no allowance: the last pass on the shape
  if (choice.oneDivision < 2) c.divisions = 1;  // G73.D1: one pass, at the allowance
  // Block ns in G00 or G01 (G73.HEAD) — G00 only without Δk: with Δk each pass's B lies behind the
  // last pass's, and a G00 block ns would end in the material that pass left (where the shape near B
  // is flat or rises): the programmer's collision on any controller, so not drawn.
  c.headMotion = c.reliefCut == 0 ? choice.headMotion % 2 : 1;
}

// The largest shift along the cut axis (towards A) that keeps a shape shifted by (it, `depthShift`)
// out of the part: a programmer's relief and allowance point away from the part on every segment,
// or each pass shifted by them cuts into it — on any controller (G73.PASS.SHIFT). A segment going
// down by u over a length a allows a·depthShift/u; an arc going down reaches a vertical tangent and
// allows none; segments going up or along the cut axis allow any.
int largestCutShiftAwayFromThePart(const std::vector<FuzzSegment>& segments, int depthShift, int drawn) {
  int largest = drawn;
  for (const FuzzSegment& s : segments) {
    if (s.up >= 0) continue;
    if (s.kind != FuzzSegment::Line || s.along == 0) return 0;
    largest = std::min(largest, s.along * depthShift / -s.up);
  }
  return largest;
}

// Relief and allowance away from the part (largestCutShiftAwayFromThePart): the cut-axis shares
// are cut back to what the shape allows.
void shiftAwayFromThePart(FuzzCase& c) {
  c.reliefCut = largestCutShiftAwayFromThePart(c.segments, c.reliefDepth, c.reliefCut);
  c.allowanceCut = largestCutShiftAwayFromThePart(c.segments, c.allowanceDepth, c.allowanceCut);
}

}  // namespace

rc::Gen<FuzzCase> genG73Case() {
  return rc::gen::apply(
      [](const std::vector<int>& choice, std::vector<FuzzSegment> segments, int di, int dk, int d, int du, int dw, int above,
         int ahead, int along, int b) {
        FuzzCase c;
        c.cycle = 73;
        c.segments = std::move(segments);
        c.reliefDepth = di;
        c.reliefCut = dk;
        c.divisions = d;
        c.allowanceDepth = du;
        c.allowanceCut = dw;
        c.startAbove = above;
        c.startAhead = ahead;
        c.startAlong = along;
        c.b = b;
        chooseG73(c, g73ChoicesFrom(choice));
        shiftAwayFromThePart(c);
        endAtTheTop(c);
        return c;
      },
      // RapidCheck scales inRange by the case's size: the choices, the segments and d are drawn
      // over their whole range at every size (they shrink towards their first value all the same).
      rc::gen::container<std::vector<int>>(10, wholeRange(0, 10)),  // G73Choices
      // Up to 8 segments (the container's length follows the size 8), each over its whole range.
      rc::gen::resize(8, rc::gen::container<std::vector<FuzzSegment>>(rc::gen::resize(100, genG73Segment()))),
      rc::gen::inRange(0, 800),   // Δi (radius)
      rc::gen::inRange(0, 400),   // Δk
      wholeRange(1, 10),          // d
      rc::gen::inRange(0, 100),   // Δu/2
      rc::gen::inRange(0, 60),    // Δw
      rc::gen::inRange(1, 500),   // A above the blank's top
      rc::gen::inRange(1, 400),   // A ahead of the blank along the cut axis
      rc::gen::inRange(0, 400),   // B's cut coordinate
      rc::gen::inRange(0, 3000));  // B's depth coordinate
}

}  // namespace cyclecert
