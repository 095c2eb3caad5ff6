#include "reference/engine/program_runner.h"

#include "reference/cycles/cycles.h"
#include "reference/interpreter/block_groups.h"
#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/block_words.h"
#include "reference/interpreter/g_codes.h"
#include "reference/interpreter/known_position.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

class ProgramRunner {
 public:
  ProgramRunner(const Program& program, const Profile& profile, const MachineParams& params, const RunOptions& options)
      : program_(program), profile_(profile), params_(params), options_(options),
        state_(initialModalState(profile, params)) {
    path_.profile = profile.name;
    if (!profile.gCodeSystemByParameters && (params.bit("GSB") || params.bit("GSC"))) {
      path_.warnings.push_back({0, "parameter 3401#6 GSB / #7 GSC is not read by the " + profile.name +
                                       " profile: the program is read in " + gCodeSystemName(state_.gCodeSystem) +
                                       " (the FANUC profiles fanuc-0i-f and fanuc-0i-c read it)"});
    }
  }

  Toolpath run() {
    requireProgramNameOfTheDialect();
    try {
      std::size_t i = 0;
      while (i < program_.blocks.size() && !ended_) i = execute(i);
    } catch (const CycleAlarm& a) {
      path_.alarm = a.alarm();
    }
    return std::move(path_);
  }

 private:
  // PROG.SHOP: "%3304" names a Huazhong program; in the other dialects it is not a program name.
  void requireProgramNameOfTheDialect() const {
    const auto& name = program_.percentName;
    if (!name || profile_.namesProgramsWithPercent) return;
    throw NotSupported(name->line, "'" + name->text + "' names the program as Huazhong writes it (--profile hnc); the " +
                                       profile_.name + " profile names it O" + name->text.substr(1) +
                                       " and reads '%' alone as the start or end of the program");
  }

  // Executes block i and returns the index of the next block.
  std::size_t execute(std::size_t i) {
    const Block& b = program_.blocks[i];
    const ModalState before = state_;
    int cycle = 0;
    // PROG.GSYS.*: each G number is read in the G code system in force.
    const GCodeSystem system = state_.gCodeSystem;
    for (const Word* g : b.all('G')) {
      const GCode* code = findGCode(system, gCode10(g->value));
      if (!code) throw improperGCode(b, *g, state_);
      if (code->support == GSupport::NotPlanned) throw NotSupported(b.line, notPlannedReason(b, *g, state_));
      if (code->group == GGroup::Units) unitsCommanded_ = true;
      applyModalGCode(*code, state_);
      if (code->function == 700 || code->function == 710 || code->function == 720 || code->function == 730 ||
          code->function == 741) {
        cycle = code->function;
      }
    }
    const AxisWordsMean meaning = axisWordsMeaning(b, system);
    checkCompensationChange(b, before, state_);
    checkWords(b, cycle, meaning);
    if (const Word* f = b.find('F')) {
      state_.feed = f->value * state_.unitScale();
    }
    if (cycle) {
      if (cycle != 741) refuseIncrementalAddressesInShape(b);  // G74.1's P and Q are amounts
      warnAssumedUnits(b);
      return executeCycle(i, cycle);
    }
    for (const Word* m : b.all('M')) {
      if (m->value == 30 || m->value == 2) ended_ = true;
      if (m->value == 98) path_.warnings.push_back({b.line, "subprogram calls are not followed by the reference"});
    }
    if (meaning == AxisWordsMean::Data) warnNotApplied(b);
    if (hasAxisWord(b)) executeAxisWords(b, meaning);
    startPathOnceThePositionIsKnown();
    return i + 1;
  }

  void executeAxisWords(const Block& b, AxisWordsMean meaning) {
    if (meaning != AxisWordsMean::Dwell && meaning != AxisWordsMean::Data) refuseIncrementalAddresses(b);
    switch (meaning) {
      case AxisWordsMean::Motion: warnAssumedUnits(b); executeMotion(b, state_.motion); break;
      case AxisWordsMean::Dwell: break;  // G04 X/U: the dwell time
      case AxisWordsMean::ReferenceCheck: executeMotion(b, 0); break;  // G27: positioning, then the check
      case AxisWordsMean::ReferenceReturn: returnToReferencePosition(b); break;
      case AxisWordsMean::MachineCoordinates: moveInMachineCoordinates(b); break;
      case AxisWordsMean::CoordinateSetting: setCoordinateSystem(b); break;
      case AxisWordsMean::Data: break;  // G10's values, G65's arguments
    }
    followKnownAxes(known_, b, meaning, state_);
  }

  // PROG.WHOLE: the toolpath starts where the program first knows the tool's position in its plane
  // (after its first absolute positioning in both axes, or G50 X Z); from there every move of the
  // program is drawn (phase "program"), before, between and after the cycles. Moves before that
  // point start from a position the program does not give: they are not drawn.
  // Until a move is drawn, the start follows the tool (and its plane).
  void startPathOnceThePositionIsKnown() {
    if (!nothingDrawn()) return;
    started_ = false;
    if (planePositionKnown()) startPath();
  }

  bool nothingDrawn() const { return path_.moves.empty() && path_.cycles.empty(); }

  // One plane per toolpath: a move or cycle in another plane once moves are drawn is not modelled.
  // Before any move is drawn, the path starts afresh in the new plane.
  void keepThePathInOnePlane(const Block& b) {
    if (!started_ || path_.plane == state_.axes().name()) return;
    if (!nothingDrawn()) {
      throw NotSupported(b.line, "a move in another plane than the toolpath's " + path_.plane +
                                     ": cyclecert draws one plane per program (select the plane before the first "
                                     "positioning)");
    }
    started_ = false;
  }

  // PROG.RANGE, PROG.ADDRESS: the words as the controller reads them. A cycle block's own
  // addresses are read by its planner (G72.RANGE); its range alarm is dated "cycle block".
  void checkWords(const Block& b, int cycle, AxisWordsMean meaning) {
    const bool cycleBlock = cycle != 0;
    try {
      checkWordRanges(b, state_.inch);
    } catch (CycleAlarm& a) {
      if (cycleBlock) a.setWhen("cycle block");
      throw;
    }
    if (meaning == AxisWordsMean::Data) return;  // G10 and G65 give every address a meaning of their own
    if (cycle != 741) checkNoThreadLead(b);  // G74.1's E is the corner r4 (G74_1.FMT)
    if (!cycleBlock && hasAxisWord(b) && meaning == AxisWordsMean::Motion) {
      checkMotionBlockAddresses(b, state_.motion, state_);
    }
  }

  // PROG.GSYS.INCREMENTAL: U/V/W as incremental addresses in G code system B/C are not read (the
  // manual writes increments as G91 X/Z there; whether U/W also work depends on the machine).
  void refuseIncrementalAddresses(const Block& b) const {
    if (const Word* w = incrementalAddressOutsideItsSystem(b, state_)) {
      throw NotSupported(b.line, w->text + ": in " + gCodeSystemName(state_.gCodeSystem) +
                                     " the manual writes an incremental move as G91 with X/Z (U/W as incremental "
                                     "addresses depend on the machine and are not read); write G91 X.. Z.., or "
                                     "read the program in G code system A (--param 3401#6=0 --param 3401#7=0)");
    }
  }

  // The same for the shape program ns…nf a cycle block names.
  void refuseIncrementalAddressesInShape(const Block& cycleBlock) const {
    const Word* p = cycleBlock.find('P');
    const Word* q = cycleBlock.find('Q');
    if (!p || !q) return;
    const auto ns = program_.findSequence(static_cast<long>(p->value));
    const auto nf = program_.findSequence(static_cast<long>(q->value));
    if (!ns || !nf) return;  // the cycle's own alarm names the missing block
    for (std::size_t k = *ns; k <= *nf && k < program_.blocks.size(); ++k) refuseIncrementalAddresses(program_.blocks[k]);
  }

  // PROG.UNITS: a program that moves without G20/G21 before its first move is read in the
  // profile's default units; the toolpath says so once, naming the way to change it.
  void warnAssumedUnits(const Block& b) {
    if (unitsCommanded_ || unitsWarned_) return;
    unitsWarned_ = true;
    path_.warnings.push_back(
        {b.line, "no G20/G21 before the first move: the program is read in " + profile_.defaultUnitsName() + ", the " +
                     profile_.name + " profile's default; add " + (profile_.inchByDefault ? "G21 for millimetres" : "G20 for inch") +
                     " (or " + (profile_.inchByDefault ? "G20" : "G21") + " to state the default) at the start of the program"});
  }

  // The first block of G71/G72/G73 (no P, no Q): its modal values.
  static void applyFirstCycleBlock(const CycleCall& call, int cycle) {
    switch (cycle) {
      case 710: applyG71FirstBlock(call); break;
      case 720: applyG72FirstBlock(call); break;
      default: applyG73FirstBlock(call); break;
    }
  }

  static CycleOutcome planCycle(const CycleCall& call, int cycle) {
    switch (cycle) {
      case 700: return planG70(call);
      case 710: return planG71(call);
      case 720: return planG72(call);
      case 741: return planG74_1(call);
      default: return planG73(call);
    }
  }

  // The cycle's G code as programs write it: "G71", "G74.1".
  static std::string cycleName(int cycle) {
    return "G" + std::to_string(cycle / 10) + (cycle % 10 ? "." + std::to_string(cycle % 10) : "");
  }

  std::size_t executeCycle(std::size_t i, int cycle) {
    const Block& b = program_.blocks[i];
    const CycleCall call{program_, i, state_, params_, profile_, options_.tool};
    // G72.MDI, HNC.G71.MDI: the shape program must be in memory. G74.1 has none (seed 002 says
    // nothing of MDI).
    if (options_.mdi && cycle != 741) {
      CycleAlarm a(alarm::kNotInMdi, b.line, cycleName(cycle) + " cannot run in MDI mode");
      a.setWhen("cycle block");
      throw a;
    }
    if (cycle == 741 && isG74_1GrooveBlock(b)) {  // G74_1.FMT: the block that gives the groove
      applyG74_1FirstBlock(call);
      return i + 1;
    }
    if (cycle != 700 && cycle != 741 && !b.has('P') && !b.has('Q')) {
      applyFirstCycleBlock(call, cycle);
      return i + 1;
    }
    requireKnownPlanePosition(b, cycleName(cycle) + " starts from it");
    if (state_.tnrc != 40 && options_.tool.noseRadius <= 0) {
      path_.warnings.push_back({b.line, "G4" + std::to_string(state_.tnrc % 10) +
                                            " is active but the tool's nose radius is 0: the shape is not offset "
                                            "(give the tool offset: --nose-radius and --tip, or the case's \"tool\")"});
    }
    keepThePathInOnePlane(b);
    if (!started_) startPath();
    CycleOutcome out = planCycle(call, cycle);
    if (path_.moves.size() + out.moves.size() > kMostMovesPerToolpath) {  // PROG.CAP.MOVES
      throw NotSupported(b.line, "the program would make more than " + std::to_string(kMostMovesPerToolpath) +
                                     " moves; cyclecert plans at most that many per program");
    }
    CycleRecord record{cycleName(cycle), b.line, state_.planePoint(), path_.moves.size(),
                       out.moves.size(), std::move(out.shape), out.allowance, out.compensated,
                       std::move(out.roughShape)};
    path_.cycles.push_back(record);
    markSingleBlockStops(out.moves);
    for (Move& m : out.moves) path_.moves.push_back(std::move(m));
    for (Warning& w : out.warnings) path_.warnings.push_back(std::move(w));
    return out.resumeAt;  // the cycle ends at its start point: the position is unchanged
  }

  // G72.SINGLE: in single-block mode, CSB (5102#7) = 1 stops after every block the cycle makes;
  // CSB = 0 at the end of each cutting cycle: the last move of each pass, of the semi-finish pass,
  // of the finishing pass and of the return.
  void markSingleBlockStops(std::vector<Move>& moves) const {
    const bool everyBlock = params_.bit("CSB");
    for (std::size_t i = 0; i < moves.size(); ++i) {
      const bool lastOfItsCycle = i + 1 == moves.size() || moves[i + 1].phase != moves[i].phase ||
                                  moves[i + 1].pass != moves[i].pass;
      moves[i].singleBlockStop = everyBlock || lastOfItsCycle;
    }
  }

  void startPath() {
    started_ = true;
    path_.start = state_.planePoint();
    path_.plane = state_.axes().name();
  }

  // PROG.POSITION: a cycle, an arc, an incremental word or a move the toolpath shows needs the
  // position it starts from.
  void requireKnownPlanePosition(const Block& b, const std::string& why) const {
    const PlaneAxes axes = state_.axes();
    for (char axis : {axes.first, axes.second}) {
      if (known_.known(axis)) continue;
      throw NotSupported(b.line, known_.describe(axis) + " (" + why + "); position the tool with G00 " +
                                     axes.second + ".. " + axes.first + ".. before it");
    }
  }

  // After G28/G30 once the toolpath has started, the straight positioning blocks that follow are
  // drawn from the intermediate point, the last position the toolpath shows (PROG.POSITION): the
  // way to the reference position and back is not drawn (the block's warning says so), so the
  // common two-tool program (G71 …; G28 U0 W0; T0202; G00 X.. Z..; G70 …) is planned, not refused.
  bool returningFromReferencePosition() const {
    const PlaneAxes axes = state_.axes();
    for (char axis : {axes.first, axes.second}) {
      if (known_.known(axis)) continue;
      if (!known_.whyUnknown(axis).viaIntermediatePoint) return false;
    }
    return true;
  }

  bool planePositionKnown() const {
    const PlaneAxes axes = state_.axes();
    return known_.known(axes.first) && known_.known(axes.second);
  }

  // The first axis that the block moves incrementally (U, or X under G91) from an unknown position,
  // or 0.
  char incrementalWordOnUnknownAxis(const Block& b) const {
    for (const char axis : {'X', 'Y', 'Z'}) {
      if (!known_.known(axis) && movesAxisIncrementally(b, axis, state_)) return axis;
    }
    return 0;
  }
  bool hasIncrementalWordOnUnknownAxis(const Block& b) const { return incrementalWordOnUnknownAxis(b) != 0; }

  void requireKnownForIncrementalWords(const Block& b) const {
    if (const char axis = incrementalWordOnUnknownAxis(b)) {
      const std::string word = b.has(incrementalAddressOf(axis)) ? std::string(1, incrementalAddressOf(axis))
                                                                : std::string("G91 ") + axis;
      throw NotSupported(b.line, known_.describe(axis) + " (" + word + " moves from it); position the tool with an absolute " +
                                     axis + " word");
    }
  }

  // A positioning or cutting block outside the cycles (PROG.WHOLE, PROG.GCODES: with any other modal
  // codes in the block, G54–G59 and G80 included): once the path has started, it is a move.
  void executeMotion(const Block& b, int motion) {
    keepThePathInOnePlane(b);
    requireKnownForIncrementalWords(b);
    if (motion == 2 || motion == 3 || (started_ && !returningFromReferencePosition())) {
      requireKnownPlanePosition(b, "the move at this line starts from it");
    }
    if (started_) {
      if (const auto seg = motionSegment(b, motion, state_)) {
        Move m;
        m.kind = motion == 0 ? MoveKind::Rapid : MoveKind::Feed;
        m.shape = seg->kind;
        m.to = seg->to;
        if (seg->isArc()) m.center = seg->center;
        if (m.kind == MoveKind::Feed) m.feed = state_.feed;
        m.phase = MovePhase::Program;
        path_.moves.push_back(std::move(m));
      }
    }
    state_.position = targetPosition(b, state_);
  }

  // G28/G30: by rapid through the intermediate point (the block's words) to a reference position,
  // whose work coordinates cyclecert does not know (PROG.POSITION).
  void returnToReferencePosition(const Block& b) {
    const std::string code = b.hasG(280) ? "G28" : "G30";
    if (started_ && planePositionKnown() && !hasIncrementalWordOnUnknownAxis(b)) executeMotion(b, 0);
    if (started_) {
      path_.warnings.push_back({b.line, code + ": the tool goes to a position whose work coordinates cyclecert does "
                                               "not model; the toolpath does not show that move, and draws the "
                                               "positioning that follows from the intermediate point"});
    }
  }

  // G53: a move in machine coordinates, whose work coordinates cyclecert does not know.
  void moveInMachineCoordinates(const Block& b) {
    if (started_) {
      path_.warnings.push_back({b.line, "G53: the tool goes to a position whose work coordinates cyclecert does not "
                                        "model; the toolpath does not show that move"});
    }
  }

  // G50 X Z: the current position takes the block's coordinates, without motion; U W shift them.
  void setCoordinateSystem(const Block& b) {
    state_.position = targetPosition(b, state_);
  }

  void warnNotApplied(const Block& b) {
    for (const Word* g : b.all('G')) {
      const int g10 = gCode10(g->value);
      if (const GCode* code = findGCode(state_.gCodeSystem, g10); code && code->support == GSupport::NotApplied) {
        path_.warnings.push_back({b.line, gCodeLabel(g10) + " " + code->name + " is not applied by the reference; position unchanged"});
      }
    }
  }

  const Program& program_;
  const Profile& profile_;
  MachineParams params_;
  RunOptions options_;
  ModalState state_;
  KnownPosition known_;
  Toolpath path_;
  bool started_ = false;
  bool ended_ = false;
  bool unitsCommanded_ = false;  // a G20 or G21 has been read
  bool unitsWarned_ = false;
};

}  // namespace

Toolpath planProgram(const Program& program, const Profile& profile, const MachineParams& params,
                     const RunOptions& options) {
  return ProgramRunner(program, profile, params, options).run();
}

}  // namespace cyclecert
