#include "reference/cycles/roughing_cycle.h"

#include "reference/gcode/address_ranges.h"
#include "reference/gcode/program_limits.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"
#include "reference/cycles/roughing_rules.h"
#include "reference/cycles/series10_format.h"
#include "reference/cycles/type2_roughing.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace cyclecert {

void applyFirstBlock(const CycleCall& call, const RoughingFormat& format) {
  const Block& b = call.block();
  const bool inch = call.modal.inch;
  if (const Word* dd = b.find(format.depthOfCutAddress)) {
    checkCycleAddress(*dd, CycleAddress::DepthOfCut, inch);
    call.params.set("5132", dd->value * call.modal.unitScale());  // Δd: radius, unsigned
  }
  if (const Word* e = b.find('R')) {
    checkCycleAddress(*e, CycleAddress::Retract, inch);
    call.params.set("5133", e->value * call.modal.unitScale());  // e: radius, unsigned
  }
}

SecondBlock readSecondBlock(const CycleCall& call, const RoughingFormat& format) {
  const Block& b = call.block();
  const PlaneAxes axes = call.modal.axes();
  SecondBlock s;
  s.p = b.find('P');
  s.q = b.find('Q');
  if (!s.p || !s.q) {
    CycleAlarm a(alarm::kPQMissing, b.line,
                 format.code + " block has " + (s.p ? "P but no Q" : "Q but no P") + " (both are required)");
    a.setWhen("cycle block");
    throw a;
  }
  checkCycleAddress(*s.p, CycleAddress::SequenceNumber, call.modal.inch);
  checkCycleAddress(*s.q, CycleAddress::SequenceNumber, call.modal.inch);
  // G71.ALLOW.UNITS: Δu along the 2nd axis and Δw along the 1st, each in that axis's programming.
  if (const Word* du = b.find(axes.secondInc)) {
    checkCycleAddress(*du, CycleAddress::Allowance, call.modal.inch);
    s.allowanceSecond = physicalLength(du->value, axes.secondDiameter, call.modal);
  }
  if (const Word* dw = b.find(axes.firstInc)) {
    checkCycleAddress(*dw, CycleAddress::Allowance, call.modal.inch);
    s.allowanceFirst = physicalLength(dw->value, axes.firstDiameter, call.modal);
  }
  // G71.FS10.FMT, HAAS.G71.FMT: the one-block forms' D (and Haas's I, K, R1), or D's refusal;
  // G73.FS10.FMT: G73's I, K, D.
  if (format.oneBlockWords == RoughingFormat::OneBlockWords::PatternRepeating) {
    readG73OneBlockWords(call);
  } else {
    readOneBlockWords(call, format.code, s);
  }
  // G71.FST: the F of the cycle blocks, or the modal F before them (the runner keeps it).
  s.feed = call.modal.feed;
  if (s.feed <= 0) {
    CycleAlarm a(alarm::kFeedZero, b.line, "no cutting feed F in the cycle blocks or before them");
    a.setWhen("cycle block");
    throw a;
  }
  return s;
}

double depthOfCut(const CycleCall& call, const std::string& code) {
  const double dd = call.params.get("5132");
  if (dd <= 0) {
    CycleAlarm a(alarm::kCuttingAmount, call.block().line,
                 "depth of cut Δd is 0: program it in the first " + code + " block or set parameter 5132");
    a.setWhen("cycle block");
    throw a;
  }
  return dd;
}

namespace {

Point toFrame(Point p, const RoughingFrame& f) { return f.transposed ? transposed(p) : p; }

std::vector<Segment> toFrame(const std::vector<Segment>& segments, const RoughingFrame& f) {
  if (!f.transposed) return segments;
  std::vector<Segment> out;
  out.reserve(segments.size());
  for (const Segment& s : segments) out.push_back(transposed(s));
  return out;
}

// Moves planned in the cycle frame, back in the plane.
std::vector<Move> movesInPlane(std::vector<Move> moves, const RoughingFrame& f) {
  if (!f.transposed) return moves;
  for (Move& m : moves) {
    m.to = transposed(m.to);
    if (m.center) m.center = transposed(*m.center);
    m.shape = reversedKind(m.shape);
  }
  return moves;
}

// PROG.CAP.PASSES, PROG.CAP.WORK: refuses a cycle whose passes (depth / Δd), moves or work (passes
// × the shape's segments: each pass meets the shape) would exceed the caps.
void checkPlanSize(const CycleCall& call, const std::string& code, double depth, double dd, double movesPerPass,
                   std::size_t segments) {
  const double passes = depth / dd;
  const double work = passes * static_cast<double>(segments);
  if (passes <= kMostRoughingPasses && passes * movesPerPass <= kMostCycleMoves && work <= kMostPassSegments) return;
  std::ostringstream why;
  why << std::setprecision(6) << " (Δd " << dd << " mm over " << depth << " mm)";
  if (passes > kMostRoughingPasses) {
    throw NotSupported(call.block().line, code + " would make " + countText(passes) + " roughing passes" + why.str() +
                                              "; cyclecert plans at most " + countText(kMostRoughingPasses));
  }
  if (passes * movesPerPass > kMostCycleMoves) {
    throw NotSupported(call.block().line, code + " would make up to " + countText(passes * movesPerPass) + " moves" +
                                              why.str() + "; cyclecert plans at most " + countText(kMostCycleMoves) +
                                              " per cycle");
  }
  requireWorkWithinTheCap(code, passes, segments, [&] { return why.str(); }, call.block().line);
}

// How deep the shape reaches below its start along the depth direction (the cycle frame's x).
double deepestBelowStart(const std::vector<Segment>& shape, Point start, int depthDirection) {
  double deepest = 0;
  for (const Segment& s : shape) {
    const Extent e = extent(s);
    deepest = std::max({deepest, depthDirection * (e.xMin - start.x), depthDirection * (e.xMax - start.x)});
  }
  return deepest;
}

CycleOutcome outcome(const CycleCall& call, const ShapeProgram& shape, const SecondBlock& sb, std::vector<Move> moves) {
  CycleOutcome out;
  out.moves = std::move(moves);
  out.resumeAt = resumeIndexAfterCycle(call, shape);
  out.shape = shape.finishShape();
  out.allowance = sb.leftByRoughing();
  out.compensated = shape.compensated;
  return out;
}

}  // namespace

void refuseWorkBeyondTheCap(std::string_view cycle, double passes, std::size_t segments, const std::string& why,
                            int line) {
  throw NotSupported(line, std::string(cycle) + " would cut " + countText(passes) + " passes across a shape of " +
                               countText(static_cast<double>(segments)) + " segments" + why +
                               "; cyclecert plans at most " + countText(kMostPassSegments) +
                               " passes × segments per cycle");
}

CycleOutcome planTypeI(const CycleCall& call, const ShapeProgram& shape, const SecondBlock& sb,
                       const RoughingFrame& frame) {
  const std::string code(cycleCode(frame.family));
  Type1Cycle cycle;
  cycle.family = frame.family;
  cycle.start = toFrame(shape.start, frame);
  cycle.headEnd = toFrame(shape.headEnd, frame);
  cycle.body = toFrame(shape.body, frame);
  cycle.allowance = toFrame(sb.leftByRoughing(), frame);
  cycle.headIsRapid = shape.headIsRapid;
  cycle.feed = sb.feed;
  cycle.depthOfCut = depthOfCut(call, code);
  cycle.retract = call.params.get("5133");
  cycle.semiFinish = !call.params.bit("RF1");
  cycle.directReturn = call.params.bit("DTP");
  // Type I: four moves a pass (infeed, cut, retract, back), each pass meeting the shape.
  checkPlanSize(call, code, std::abs(cycle.headEnd.x - cycle.start.x), cycle.depthOfCut, 4, cycle.body.size() + 1);
  // G71.T1.MONO, G71.CHECK: checked on the finish shape before any move.
  checkType1Monotonic(cycle, frame.cutAxis, frame.depthAxis);
  return outcome(call, shape, sb, movesInPlane(planType1(cycle), frame));
}

CycleOutcome planTypeII(const CycleCall& call, const ShapeProgram& shape, const SecondBlock& sb,
                        const RoughingFrame& frame) {
  const std::string code(cycleCode(frame.family));
  Type2Cycle cycle;
  cycle.family = frame.family;
  cycle.start = toFrame(shape.start, frame);
  cycle.shape = toFrame(shape.finishShape(), frame);
  cycle.allowance = toFrame(sb.leftByRoughing(), frame);
  cycle.headIsRapid = shape.headIsRapid;
  cycle.feed = sb.feed;
  cycle.depthOfCut = depthOfCut(call, code);
  cycle.retract = call.params.get("5133");
  cycle.clearance = call.params.get("5134");
  cycle.semiFinish = !call.params.bit("RF2");
  cycle.followAlongCut = call.params.bit("R16") || call.params.bit("NSP");  // G71.NSP: NSP implies R16
  cycle.noRepeatedPath = call.params.bit("NSP");
  cycle.levelByLevel = call.profile.pocketsLevelByLevel;
  // Type II: a cut at a level may follow every segment of the shape, plus its travel and leave.
  checkPlanSize(call, code, deepestBelowStart(cycle.shape, cycle.start, cycle.depthDirection()),
                cycle.depthOfCut, static_cast<double>(cycle.shape.size()) + 8, cycle.shape.size());
  // G71.T2.MONO: only the cut axis must be monotonic.
  checkMonotonicAlongCut(cycle.shape, cycle.cutDirection(), frame.cutAxis);
  CycleOutcome out = outcome(call, shape, sb, movesInPlane(planType2(cycle), frame));
  // G71.T2.DW0 / G72.T2: an allowance along the cut axis with pockets may cut into a side wall.
  if (std::abs(cycle.allowance.z) > kGeomEps && type2HasPocketWall(cycle)) {
    const std::string& rule = roughingRulesOf(frame.family).sideWall;
    out.warnings.push_back({call.block().line, rule + ": type II with pockets and a finishing allowance along the "
                                                   "cut axis: the tool may cut into a side wall (normally the allowance is 0)"});
  }
  return out;
}

}  // namespace cyclecert
