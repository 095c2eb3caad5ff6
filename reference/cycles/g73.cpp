// G73 — pattern repeating cycle (FANUC 0i-F, GSK; seed 004's example): `G73 U(Δi) W(Δk) R(d);`
// `G73 P(ns) Q(nf) U(Δu) W(Δw) F S T;` (or the Series 10/11 one block `G73 P Q U W I K D F S T`).
// One function per documented step; each cites its rule of specs/rules.json
// (reference/cycles/README.md, "G73").
#include "reference/cycles/g73.h"

#include <cmath>
#include <string>

#include "reference/cycles/cycles.h"
#include "reference/cycles/move_emitter.h"
#include "reference/cycles/roughing_cycle.h"
#include "reference/cycles/series10_format.h"
#include "reference/gcode/program_limits.h"
#include "reference/gcode/address_ranges.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// The passes, one after the other, from A and back to A.
class G73Planner {
 public:
  explicit G73Planner(const G73Cycle& c) : c_(c), moves_(c.start, c.feed) {}

  std::vector<Move> plan() {
    for (int k = 1; k <= c_.divisions; ++k) {
      const Point shift = passShift(c_, k);
      rapidToShiftedStart(k, shift);
      followShiftedHead(k, shift);
      followShiftedBody(k, shift);
      rapidBackToStart(k);
    }
    return moves_.take();
  }

 private:
  // G73.APPROACH: each pass starts with a rapid from A to A shifted for the pass. The first one is
  // the cycle's approach (as G71's A → A'); the later ones belong to their pass.
  void rapidToShiftedStart(int k, Point shift) {
    const bool first = k == 1;
    moves_.emit(MoveKind::Rapid, c_.start + shift, first ? MovePhase::Approach : MovePhase::Pass, first ? 0 : k,
                {"G73.APPROACH", "G73.PASS.SHIFT"});
  }

  // G73.HEAD: the shifted block ns moves as programmed: rapid for G00, cutting feed for G01 (as G71's
  // infeed follows the head block's G00/G01, G71.HEAD.G0G1).
  void followShiftedHead(int k, Point shift) {
    moves_.emit(c_.headIsRapid ? MoveKind::Rapid : MoveKind::Feed, c_.headEnd + shift, MovePhase::Pass, k,
                {"G73.HEAD", "G71.HEAD.G0G1", "G73.PASS.SHIFT"});
  }

  // G73.PASS: the rest of the shape, shifted (arcs keep their radius, their centre moves with the
  // shape), in cutting feed F; the shape need not be monotone (G73.SHAPE).
  void followShiftedBody(int k, Point shift) {
    for (const Segment& s : c_.body) {
      moves_.emitAlong(MoveKind::Feed, s.shifted(shift), MovePhase::Pass, k, {"G73.PASS", "G73.PASS.SHIFT"});
    }
  }

  // G73.RETURN: after each pass a rapid straight back to A; after the last, that is the cycle's return.
  void rapidBackToStart(int k) {
    const bool last = k == c_.divisions;
    moves_.emit(MoveKind::Rapid, c_.start, last ? MovePhase::Return : MovePhase::Pass, last ? 0 : k, {"G73.RETURN"});
  }

  const G73Cycle& c_;
  MoveEmitter moves_;
};

// G73.FMT: the reliefs are given with the plane's incremental addresses, Δi with the 2nd axis's (U
// in G18, a radius value: never halved), Δk with the 1st axis's (W in G18) — the addresses of Δu and
// Δw in the block with P and Q (as G71.ADDR.SHARED).
RoughingFormat g73Format(const CycleCall& call) {
  return {"G73", call.modal.axes().secondInc, RoughingFormat::OneBlockWords::PatternRepeating};
}

// G73.D.RANGE: d is a whole number of passes, at least 1: R0 or a negative R is PS0062, a fraction
// or more than 8 digits PS0003.
double divisionsWord(const Word& r) {
  if (r.value < 1) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, r.line,
                          r.text + " at column " + std::to_string(r.column) +
                              ": the number of divisions d of G73 must be at least 1");
  }
  if (r.value != std::floor(r.value) || r.value > 99'999'999) {
    throw cycleBlockAlarm(alarm::kOutOfRange, r.line,
                          r.text + " at column " + std::to_string(r.column) +
                              " is outside 1…99999999 (the number of divisions d of G73, a whole number)");
  }
  return r.value;
}

// G73.PARAMS, G73.D.RANGE: d from parameter 5137 (programmed values overwrite it); 0 is PS0062.
int divisions(const CycleCall& call) {
  const double d = call.params.get("5137");
  if (d < 1) {
    throw cycleBlockAlarm(alarm::kCuttingAmount, call.block().line,
                          "the number of divisions d of G73 is 0: program it with R in the first G73 block (or D "
                          "in the Series 10/11 block) or set parameter 5137");
  }
  return static_cast<int>(d);
}

// G73.PARAMS: the relief (Δk, Δi) in force, from parameters 5136/5135.
Point relief(const CycleCall& call) { return {call.params.get("5136"), call.params.get("5135")}; }

// G73.DIALECTS: the Huazhong and Haas G73 are other formats, not described in our sources.
void refuseOtherDialects(const CycleCall& call) {
  const RoughingBlockFormat f = call.profile.roughingFormat;
  if (f == RoughingBlockFormat::FanucTwoBlocks) return;
  throw NotSupported(call.block().line, "G73 of the " + call.profile.name +
                                            " profile is not modelled (its format is not in cyclecert's sources); "
                                            "the FANUC/GSK G73 is (--profile fanuc-0i-f or gsk)");
}

// PROG.CAP.PASSES: d passes of the whole shape (its segments, the approach and the return).
void checkPlanSize(const CycleCall& call, int d, std::size_t segments) {
  const double moves = static_cast<double>(d) * (static_cast<double>(segments) + 2);
  if (d <= kMostRoughingPasses && moves <= kMostCycleMoves) return;
  throw NotSupported(call.block().line, "G73 with d = " + countText(d) + " would make " + countText(moves) +
                                            " moves; cyclecert plans at most " + countText(kMostRoughingPasses) +
                                            " passes and " + countText(kMostCycleMoves) + " moves per cycle");
}

}  // namespace

Point passShift(const G73Cycle& cycle, int k) {
  if (cycle.divisions <= 1) return cycle.allowance;  // G73.D1
  const double share = static_cast<double>(cycle.divisions - k) / static_cast<double>(cycle.divisions - 1);
  return share * cycle.relief + cycle.allowance;
}

std::vector<Move> planG73Passes(const G73Cycle& cycle) { return G73Planner(cycle).plan(); }

void applyG73FirstBlock(const CycleCall& call) {
  refuseOtherDialects(call);
  const Block& b = call.block();
  const PlaneAxes axes = call.modal.axes();
  const bool inch = call.modal.inch;
  // G73.FMT, G73.PARAMS: Δi, Δk and d are modal: they overwrite parameters 5135/5136/5137.
  if (const Word* di = b.find(axes.secondInc)) {
    checkCycleAddress(*di, CycleAddress::Allowance, inch);
    call.params.set("5135", di->value * call.modal.unitScale());
  }
  if (const Word* dk = b.find(axes.firstInc)) {
    checkCycleAddress(*dk, CycleAddress::Allowance, inch);
    call.params.set("5136", dk->value * call.modal.unitScale());
  }
  if (const Word* r = b.find('R')) call.params.set("5137", divisionsWord(*r));
}

CycleOutcome planG73(const CycleCall& call) {
  refuseOtherDialects(call);
  // G73.FMT, G73.FS10.FMT: P, Q, Δu, Δw and F as G71's block (PS0061, ranges, PS0011); the
  // Series 10/11 block's I, K, D write parameters 5135/5136/5137.
  const SecondBlock sb = readSecondBlock(call, g73Format(call));
  const int d = divisions(call);
  return withShapeAlarmTiming(call, [&] {
    // G73.ALARMS: PS0063 (P/Q not found), PS0065 (ns without G00/G01), PS0325 (shape commands).
    ShapeProgram shape = readShapeProgram(call, *sb.p, *sb.q);
    compensateShape(call, shape);  // G73.TNRC: as G71 (G71.TNRC.CANCEL, G71.CHECK)
    checkPlanSize(call, d, shape.body.size());
    G73Cycle cycle;
    cycle.start = shape.start;
    cycle.headEnd = shape.headEnd;
    cycle.body = shape.body;
    cycle.relief = relief(call);
    cycle.allowance = sb.leftByRoughing();
    cycle.divisions = d;
    cycle.headIsRapid = shape.headIsRapid;
    cycle.feed = sb.feed;
    CycleOutcome out;
    out.moves = planG73Passes(cycle);
    out.resumeAt = resumeIndexAfterCycle(call, shape);
    out.shape = shape.finishShape();
    out.allowance = sb.leftByRoughing();
    out.compensated = shape.compensated;
    return out;
  });
}

}  // namespace cyclecert
