// mutant:NAME — the reference with one seeded fault of a kind real engines get wrong, to measure
// what the suite detects (README: detection table). Each fault is a change to the program the
// reference plans, to its parameters or profile, or to the toolpath it returns; the reference
// itself stays clean.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "harness/engines/engines.h"
#include "harness/engines/reference_plan.h"
#include "reference/cycles/cycles.h"
#include "reference/gcode/parser.h"
#include "reference/gcode/writer.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/cycle_family.h"
#include "reference/model/offset.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"
#include "reference/siemens/siemens_roughing_cycle.h"
#include "reference/siemens/siemens_roughing_steps.h"
#include "reference/siemens/siemens_runner.h"

namespace cyclecert {

namespace {

bool cites(const Move& m, const std::string& rule) { return std::find(m.rules.begin(), m.rules.end(), rule) != m.rules.end(); }
bool isG72(const Move& m) {
  return std::any_of(m.rules.begin(), m.rules.end(), [](const std::string& r) { return r.rfind("G72.", 0) == 0; });
}

int lastPass(const Toolpath& t) {
  int last = 0;
  for (const Move& m : t.moves) {
    if (m.phase == MovePhase::Pass) last = std::max(last, m.pass);
  }
  return last;
}

void eraseIf(Toolpath& t, const std::function<bool(const Move&)>& drop) {
  t.moves.erase(std::remove_if(t.moves.begin(), t.moves.end(), drop), t.moves.end());
}

// The toolpath faults.
void retractStraight(Toolpath& t) {  // 45° retracts made along the depth axis only
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    Move& m = t.moves[i];
    if (!cites(m, "G71.T1.RETRACT45") && !cites(m, "G72.RETRACT")) continue;
    const Point from = t.from(i);
    if (isG72(m)) m.to.x = from.x;
    else m.to.z = from.z;
  }
}

void retractTwice(Toolpath& t) {  // retract 2e instead of e
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    Move& m = t.moves[i];
    if (cites(m, "G71.T1.RETRACT45") || cites(m, "G72.RETRACT")) m.to = t.from(i) + 2.0 * (m.to - t.from(i));
  }
}

void lastPassDeeper(Toolpath& t) {  // the last pass 0.3 mm too deep
  const int last = lastPass(t);
  if (last == 0) return;
  for (Move& m : t.moves) {
    if (m.phase != MovePhase::Pass || m.pass != last) continue;
    if (isG72(m)) m.to.z -= 0.3;  // deeper for the usual facing towards −z
    else m.to.x -= 0.3;           // deeper for outer turning
  }
}

void feedsAsRapids(Toolpath& t) {  // the cuts along the cut axis made at rapid traverse
  for (Move& m : t.moves) {
    if (m.phase == MovePhase::Pass && (cites(m, "G72.STEP3") || cites(m, "G71.OP"))) {
      m.kind = MoveKind::Rapid;
      m.feed.reset();
    }
  }
}

void arcsReversed(Toolpath& t) {
  for (Move& m : t.moves) {
    if (m.shape == SegmentKind::ArcCW) m.shape = SegmentKind::ArcCCW;
    else if (m.shape == SegmentKind::ArcCCW) m.shape = SegmentKind::ArcCW;
  }
}

void noFinalReturn(Toolpath& t) {
  while (!t.moves.empty() && t.moves.back().phase == MovePhase::Return) t.moves.pop_back();
}

// Type II: the approach into a pocket made at rapid all the way to the entry point, without the
// cutting feed from the clearance height (5134) that G71.T2.POCKET.EXIT asks for.
void pocketEntriesAtRapid(Toolpath& t) {
  for (Move& m : t.moves) {
    if (m.kind != MoveKind::Feed || !cites(m, "G71.T2.POCKET.EXIT")) continue;
    m.kind = MoveKind::Rapid;
    m.feed.reset();
  }
}

// The F that running the first cycle's shape program ns…nf leaves modal (its last F word, as
// written), if it has one.
std::optional<double> shapeProgramFeed(const std::string& text) {
  const Program p = parseProgram(text, "mutant");
  for (const Block& b : p.blocks) {
    if (!(b.hasG(710) || b.hasG(720)) || !b.has('P') || !b.has('Q')) continue;
    const auto ns = p.findSequence(static_cast<long>(b.find('P')->value));
    const auto nf = p.findSequence(static_cast<long>(b.find('Q')->value));
    std::optional<double> feed;
    for (std::size_t i = ns.value_or(0); ns && nf && i <= *nf && i < p.blocks.size(); ++i) {
      if (const Word* f = p.blocks[i].find('F')) feed = f->value;
    }
    return feed;
  }
  return std::nullopt;
}

// The program faults: the allowances' signs flipped in the block with P and Q.
std::string allowancesFlipped(const std::string& text) {
  Program p = parseProgram(text, "mutant");
  for (Block& b : p.blocks) {
    if (!(b.hasG(710) || b.hasG(720)) || !b.has('P')) continue;
    for (Word& w : b.words) {
      if (w.letter == 'U' || w.letter == 'W') w = makeWord(w.letter, -w.value);
    }
  }
  return writeProgram(p);
}

// The program fault: G41 and G42 exchanged, so that compensation offsets the shape to the other side.
std::string compensationSidesSwapped(const std::string& text) {
  Program p = parseProgram(text, "mutant");
  for (Block& b : p.blocks) {
    for (Word& w : b.words) {
      if (w.letter == 'G' && (w.value == 41 || w.value == 42)) w = makeWord('G', w.value == 41 ? 42 : 41);
    }
  }
  return writeProgram(p);
}

// The case's G code system (PROG.GSYS.*): G73 is the pattern repeating cycle in systems A and B,
// G75 in system C (where G73 is G71's roughing).
GCodeSystem gCodeSystemOf(const SpecCase& c) {
  const Profile* profile = findProfile(profileNameOrDefault(c.profile));
  if (!profile) return GCodeSystem::A;
  MachineParams params = profile->defaults;
  for (const auto& [name, value] : c.params) {
    try {
      params.set(name, value);
    } catch (const std::exception&) {  // the reference names a bad parameter when it plans the case
    }
  }
  return gCodeSystemOf(*profile, params);
}

// A G73 block of the program — the first (Δi, Δk, d: no P) or the one with P (the Series 10/11 one
// block carries I, K and D there) — as its G code system reads it.
bool isG73(const Block& b, GCodeSystem system) {
  return std::any_of(b.words.begin(), b.words.end(), [&](const Word& w) {
    const GCode* g = w.letter == 'G' ? findGCode(system, gCode10(w.value)) : nullptr;
    return g && g->function == 730;
  });
}

// The G73 fault "one pass too few": d read as d − 1 (R in the first block, D in the Series 10/11
// block, parameter 5137), so the passes are shared out over one division less.
SpecCase g73DivisionsLessOne(SpecCase c) {
  Program p = parseProgram(c.program, "mutant");
  const GCodeSystem system = gCodeSystemOf(c);
  for (Block& b : p.blocks) {
    if (!isG73(b, system)) continue;
    const char letter = b.has('P') ? 'D' : 'R';
    for (Word& w : b.words) {
      if (w.letter == letter) w = makeWord(letter, w.value - 1);
    }
  }
  c.program = writeProgram(p);
  for (auto& [name, value] : c.params) {
    if (name == "5137") value -= 1;
  }
  return c;
}

// The G73 fault "relief towards the part": Δi and Δk with their signs flipped (U/W of the first
// block, I/K of the Series 10/11 block, parameters 5135/5136), so each pass is shifted into the part.
SpecCase g73ReliefFlipped(SpecCase c) {
  Program p = parseProgram(c.program, "mutant");
  const GCodeSystem system = gCodeSystemOf(c);
  for (Block& b : p.blocks) {
    if (!isG73(b, system)) continue;
    const bool oneBlock = b.has('P');
    for (Word& w : b.words) {
      const bool relief = oneBlock ? (w.letter == 'I' || w.letter == 'K') : (w.letter == 'U' || w.letter == 'W');
      if (relief) w = makeWord(w.letter, -w.value);
    }
  }
  c.program = writeProgram(p);
  for (auto& [name, value] : c.params) {
    if (name == "5135" || name == "5136") value = -value;
  }
  return c;
}

// The G73 fault "last pass without the allowance": each G73 cycle's last pass (its approach, block
// ns and shape) follows the finish shape itself instead of the shape shifted by (Δw, Δu/2).
void g73LastPassOnTheShape(Toolpath& t) {
  for (const CycleRecord& cycle : t.cycles) {
    if (cycleFamilyOfCode(cycle.code) != CycleFamily::G73) continue;
    const std::size_t begin = cycle.firstMove, end = std::min(t.moves.size(), cycle.firstMove + cycle.moveCount);
    int last = 0;
    for (std::size_t i = begin; i < end; ++i) {
      if (t.moves[i].phase == MovePhase::Pass) last = std::max(last, t.moves[i].pass);
    }
    std::size_t first = begin;
    while (first < end && !(t.moves[first].phase == MovePhase::Pass && t.moves[first].pass == last)) ++first;
    if (first == end) continue;  // no pass (nothing to cut)
    if (first > begin && cites(t.moves[first - 1], "G73.APPROACH") && !cites(t.moves[first], "G73.APPROACH")) --first;
    for (std::size_t i = first; i < end && t.moves[i].phase != MovePhase::Return && !cites(t.moves[i], "G73.RETURN"); ++i) {
      t.moves[i].to = t.moves[i].to - cycle.allowance;
      if (t.moves[i].center) *t.moves[i].center = *t.moves[i].center - cycle.allowance;
    }
  }
}

// --- G74.1 faults (GSK axial trapezoid groove, G74_1.*) ---

// The case with `edit` applied to each G74.1 block of its program — the groove block (X, Z) when
// `grooveBlock`, else the block that cuts it — and the program written back; a case without such a
// block is left as it is (its text untouched).
SpecCase withG74_1BlocksEdited(SpecCase c, bool grooveBlock, const std::function<void(Word&)>& edit) {
  if (c.program.find("74.1") == std::string::npos) return c;
  Program p = parseProgram(c.program, "mutant");
  bool edited = false;
  for (Block& b : p.blocks) {
    if (!b.hasG(741) || isG74_1GrooveBlock(b) != grooveBlock) continue;
    for (Word& w : b.words) edit(w);
    edited = true;
  }
  if (edited) c.program = writeProgram(p);
  return c;
}

// "g74_1-retract-to-bottom": each peck's retract e (G74_1.STEP4) made towards the groove's floor
// instead of away from it; the next feed still ends where the reference's does.
void g74_1RetractsTowardsTheFloor(Toolpath& t) {
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    Move& m = t.moves[i];
    if (cites(m, "G74_1.STEP4")) m.to = t.from(i) + (t.from(i) - m.to);
  }
}

// "g74_1-radial-step-full": the axial cycles stepped across by Δi instead of Δi/2 (P of the groove
// block doubled: Δi is a diameter, G74_1.STEP7 steps its half along the radius).
SpecCase g74_1RadialStepDoubled(SpecCase c) {
  return withG74_1BlocksEdited(std::move(c), true, [](Word& w) {
    if (w.letter == 'P') w = makeWord('P', 2 * w.value, w.hasDecimalPoint);
  });
}

// "g74_1-tool-width-ignored": the grooving tool's width I read as 0 — the cycle planned for a
// pointed tool's point (I0 in the second block), so the blade cuts r beyond the groove's start side.
SpecCase g74_1ToolWidthIgnored(SpecCase c) {
  return withG74_1BlocksEdited(std::move(c), false, [](Word& w) {
    if (w.letter == 'I') w = makeWord('I', 0);
  });
}

// --- SINUMERIK faults (LCYC95, CYCLE95): the Siemens runner with a planner that has the fault ---

// A SINUMERIK case planned with `planners` in place of the real LCYC95 / CYCLE95 planners (the
// runner and everything else as the reference); a FANUC case as the reference plans it.
EngineResult plannedWithSiemensPlanners(const SpecCase& c, const SiemensPlanners& planners) {
  const Profile* profile = findProfile(profileNameOrDefault(c.profile));
  if (!profile || profile->dialect != Dialect::Siemens) return EngineResult::planned(planSpecCase(c));
  const PlanRequest r = planRequestFor(c);
  return EngineResult::planned(planSiemensProgram(
      {r.programText, r.file, r.subprograms, r.subprogramDirectory, r.options.tool}, *profile, planners));
}

// "siemens-retract-45": each retract after a roughing cut (a G0 of the pass that moves R110 / _VRT
// in each axis, LCYC95.ROUGH) made R110 long at 45° — R110/√2 in each axis. The moves after it keep
// their shape: a G0 along one axis stays on that axis from where the tool now is, until a move with
// both axes (or a cut) ends where the reference's ends.
bool shifted(Point shift) { return std::abs(shift.z) > kGeomEps || std::abs(shift.x) > kGeomEps; }

// A move after the tool was left `shift` away from where the reference had it (`from` is where the
// reference's move starts): a G0 along one axis stays on that axis from where the tool is (the
// shift along the other axis remains), any other move ends where the reference's does. Returns the
// shift after it.
Point keepingItsAxis(Move& m, Point from, Point shift) {
  if (!shifted(shift)) return shift;
  const Point d = m.to - from;
  if (m.kind == MoveKind::Rapid && std::abs(d.z) <= kGeomEps) {
    m.to.z += shift.z;
    return {shift.z, 0};
  }
  if (m.kind == MoveKind::Rapid && std::abs(d.x) <= kGeomEps) {
    m.to.x += shift.x;
    return {0, shift.x};
  }
  return {0, 0};
}

void retractsAt45(std::vector<Move>& moves, Point position, double retract) {
  if (!(retract > kGeomEps)) return;
  Point shift{0, 0};      // where the tool is now minus where the reference has it
  Point from = position;  // the reference's start of the move
  for (Move& m : moves) {
    const Point to = m.to;
    const Point d = to - from;
    const bool isRetract = m.kind == MoveKind::Rapid && m.phase == MovePhase::Pass &&
                           std::abs(std::abs(d.z) - retract) <= kGeomEps && std::abs(std::abs(d.x) - retract) <= kGeomEps;
    if (isRetract) {
      m.to = from + shift + (1 / std::sqrt(2.0)) * d;
      shift = m.to - to;
    } else {
      shift = keepingItsAxis(m, from, shift);
    }
    from = to;
  }
}

SiemensCycleOutcome withRetractsAt45(SiemensCycleOutcome out, const SiemensCycleCall& call, double retract) {
  retractsAt45(out.moves, call.position, std::abs(retract));
  out.end = out.moves.empty() ? call.position : out.moves.back().to;
  return out;
}

const SiemensPlanners& retract45Planners() {
  static const SiemensPlanners planners{
      [](const SiemensCycleCall& call, const Lcyc95Parameters& p) { return withRetractsAt45(planLcyc95(call, p), call, p.retract); },
      [](const SiemensCycleCall& call, const Cycle95Parameters& p) { return withRetractsAt45(planCycle95(call, p), call, p.retract); },
      machiningTypeOf};
  return planners;
}

// "siemens-undercut-ff1": CYCLE95's undercuts roughed at FF1 (the roughing feed) instead of FF2.
const SiemensPlanners& undercutAtFf1Planners() {
  static const SiemensPlanners planners{planLcyc95,
                                        [](const SiemensCycleCall& call, Cycle95Parameters p) {
                                          p.undercutFeed = p.roughingFeed;
                                          return planCycle95(call, p);
                                        },
                                        machiningTypeOf};
  return planners;
}

// "siemens-max-infeed": the main roughing levels stepped down by R108 / MID from the top, the last
// step smaller (to the profile's lowest point), instead of the fewest equal steps not above it
// (LCYC95.DEPTH). Everything else is the reference's: its planner with this levels rule.
std::vector<double> levelsByMaxInfeed(double top, double bottom, double maxInfeed, int line) {
  const int count = equalInfeedSteps(top - bottom, maxInfeed, line).count;
  std::vector<double> levels{top};
  for (int k = 1; k < count; ++k) levels.push_back(top - k * maxInfeed);
  if (count > 0) levels.push_back(bottom);
  return levels;
}

const SiemensPlanners& maxInfeedPlanners() {
  static const SiemensPlanners planners{
      [](const SiemensCycleCall& call, const Lcyc95Parameters& p) {
        StockRemovalSettings s = lcyc95Settings(p);
        s.mainLevels = levelsByMaxInfeed;
        return planStockRemovalCycle(call, s);
      },
      [](const SiemensCycleCall& call, const Cycle95Parameters& p) {
        StockRemovalSettings s = cycle95Settings(p);
        s.mainLevels = levelsByMaxInfeed;
        return planStockRemovalCycle(call, s);
      },
      machiningTypeOf};
  return planners;
}

struct Fault {
  std::string name, what;
  std::function<EngineResult(SpecCase)> run;
};

EngineResult planned(const SpecCase& c, const std::function<void(Toolpath&)>& change = {}) {
  Toolpath t = planSpecCase(c);
  if (change && !t.alarm) change(t);
  return EngineResult::planned(std::move(t));
}

// The roughing cycle's cutting moves (its passes and semi-finish, not G70's) at the F of its shape
// program, which G71.FST / G72.FST say the cycle ignores.
EngineResult roughedAtShapeFeed(const SpecCase& c) {
  const std::optional<double> feed = shapeProgramFeed(c.program);
  return planned(c, [&](Toolpath& t) {
    for (Move& m : t.moves) {
      if (feed && m.kind == MoveKind::Feed && (m.phase == MovePhase::Pass || m.phase == MovePhase::SemiFinish)) m.feed = *feed;
    }
  });
}

const std::vector<Fault>& faults() {
  static const std::vector<Fault> all = {
      {"retract-angle", "retracts straight out instead of at 45°", [](SpecCase c) { return planned(c, retractStraight); }},
      {"retract-amount", "retracts 2e instead of e", [](SpecCase c) { return planned(c, retractTwice); }},
      {"last-pass-depth", "makes the last pass 0.3 mm too deep", [](SpecCase c) { return planned(c, lastPassDeeper); }},
      {"allowance-sign", "leaves the allowances on the wrong side (Δu, Δw signs flipped)",
       [](SpecCase c) {
         c.program = allowancesFlipped(c.program);
         return planned(c);
       }},
      {"semifinish-skipped", "skips the semi-finish pass",
       [](SpecCase c) { return planned(c, [](Toolpath& t) { eraseIf(t, [](const Move& m) { return m.phase == MovePhase::SemiFinish; }); }); }},
      {"rapid-for-feed", "makes the roughing cuts at rapid traverse", [](SpecCase c) { return planned(c, feedsAsRapids); }},
      {"pocket-order", "roughs pockets in the other controller's order (0i-F ⇄ 0i-C)",
       [](SpecCase c) {
         c.profile = c.profile == "fanuc-0i-c" ? "fanuc-0i-f" : "fanuc-0i-c";
         return planned(c);
       }},
      {"pass-count", "makes one roughing pass too few (drops the last one)",
       [](SpecCase c) {
         return planned(c, [](Toolpath& t) {
           const int last = lastPass(t);
           eraseIf(t, [&](const Move& m) { return m.phase == MovePhase::Pass && m.pass == last && last > 0; });
         });
       }},
      {"arc-direction", "cuts every arc the other way round (G02 ⇄ G03)", [](SpecCase c) { return planned(c, arcsReversed); }},
      {"alarm-missed", "never raises the monotonic alarms (tolerates any turn-back)",
       [](SpecCase c) {
         c.params.push_back({"5145", 1000});
         c.params.push_back({"5146", 1000});
         return planned(c);
       }},
      {"alarm-raised-wrongly", "raises PS0064 on any shape with an arc",
       [](SpecCase c) {
         Toolpath t = planSpecCase(c);
         const bool arcs = std::any_of(t.moves.begin(), t.moves.end(), [](const Move& m) { return m.shape != SegmentKind::Line; });
         if (arcs && !t.alarm && !t.cycles.empty()) {
           t.alarm = Alarm{"PS0064", alarmTitle("PS0064"), t.cycles.front().line, ""};
           t.moves.clear();
         }
         return EngineResult::planned(std::move(t));
       }},
      {"start-not-returned", "does not return to the cycle start point at the end", [](SpecCase c) { return planned(c, noFinalReturn); }},
      {"shape-feed-in-roughing", "roughs at the F given inside ns…nf instead of the cycle's",
       [](SpecCase c) { return roughedAtShapeFeed(c); }},
      {"tnrc-sides-swapped", "offsets the shape to the wrong side under compensation (G41 ⇄ G42)",
       [](SpecCase c) {
         c.program = compensationSidesSwapped(c.program);
         return planned(c);
       }},
      {"pocket-entry-rapid", "enters type II pockets at rapid, without the feed from the clearance height (5134)",
       [](SpecCase c) { return planned(c, pocketEntriesAtRapid); }},
      {"g73-divisions", "plans G73 with one division too few (d read as d − 1)",
       [](SpecCase c) { return planned(g73DivisionsLessOne(std::move(c))); }},
      {"g73-relief-sign", "shifts G73's passes towards the part (Δi, Δk signs flipped)",
       [](SpecCase c) { return planned(g73ReliefFlipped(std::move(c))); }},
      {"g73-last-pass-allowance", "cuts G73's last pass on the finish shape, without the allowance",
       [](SpecCase c) { return planned(c, g73LastPassOnTheShape); }},
      {"g74_1-retract-to-bottom", "retracts G74.1's pecks by e towards the groove's floor instead of away from it",
       [](SpecCase c) { return planned(c, g74_1RetractsTowardsTheFloor); }},
      {"g74_1-radial-step-full", "steps G74.1's axial cycles across by Δi instead of Δi/2",
       [](SpecCase c) { return planned(g74_1RadialStepDoubled(std::move(c))); }},
      {"g74_1-tool-width-ignored", "plans G74.1 as if the grooving tool had no width (I read as 0)",
       [](SpecCase c) { return planned(g74_1ToolWidthIgnored(std::move(c))); }},
      {"siemens-retract-45", "retracts R110 / _VRT long at 45° after each LCYC95/CYCLE95 roughing cut (R110/√2 in each axis) instead of R110 in each axis",
       [](SpecCase c) { return plannedWithSiemensPlanners(c, retract45Planners()); }},
      {"siemens-max-infeed", "steps LCYC95/CYCLE95's roughing levels down by R108 / MID with a smaller last step instead of equal steps",
       [](SpecCase c) { return plannedWithSiemensPlanners(c, maxInfeedPlanners()); }},
      {"siemens-undercut-ff1", "roughs CYCLE95's undercuts at FF1 instead of FF2",
       [](SpecCase c) { return plannedWithSiemensPlanners(c, undercutAtFf1Planners()); }},
  };
  return all;
}

class MutantEngine : public Engine {
 public:
  explicit MutantEngine(const Fault& f) : fault_(f) {}
  std::string name() const override { return "mutant:" + fault_.name; }
  std::string description() const override { return "the reference with one fault: " + fault_.what; }
  std::string version() const override { return name(); }
  EngineResult run(const SpecCase& c) override {
    try {
      return fault_.run(c);
    } catch (const NotSupported& e) {
      return EngineResult::notApplicable(e.what());
    } catch (const std::exception& e) {
      return EngineResult::failed(e.what());
    }
  }

 private:
  const Fault& fault_;
};

}  // namespace

std::unique_ptr<Engine> makeMutantEngine(const std::string& name) {
  for (const Fault& f : faults()) {
    if (f.name == name) return std::make_unique<MutantEngine>(f);
  }
  return nullptr;
}

const std::vector<std::pair<std::string, std::string>>& mutantFaults() {
  static const std::vector<std::pair<std::string, std::string>> list = [] {
    std::vector<std::pair<std::string, std::string>> l;
    for (const Fault& f : faults()) l.push_back({f.name, f.what});
    return l;
  }();
  return list;
}

}  // namespace cyclecert
