#include "reference/engine/program_runner.h"

#include <map>
#include <set>

#include "reference/cycles/cycles.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// G codes of a FANUC lathe (system A) that the reference knows but does not model: it warns and
// leaves the position where it was.
const std::map<int, std::string>& unmodelledGCodes() {
  static const std::map<int, std::string> codes = {
      {280, "G28 reference position return"}, {500, "G50 coordinate system setting"}, {320, "G32 threading"},
      {650, "G65 macro call"}, {530, "G53 machine coordinate system"}, {540, "G54 work coordinate system"},
      {100, "G10 data setting"}, {270, "G27 reference position check"}, {300, "G30 2nd reference return"},
  };
  return codes;
}

// Canned cycles the reference cannot plan yet: the program is reported as not supported, never
// planned without them.
const std::map<int, std::string>& unplannedCycles() {
  static const std::map<int, std::string> codes = {
      {730, "G73 pattern repeating cycle"}, {740, "G74 end-face peck drilling cycle"},
      {741, "G74.1 axial groove cycle"},    {750, "G75 outer diameter grooving cycle"},
      {760, "G76 threading cycle"},         {900, "G90 outer diameter cutting cycle"},
      {920, "G92 threading cycle"},         {940, "G94 end-face turning cycle"},
  };
  return codes;
}

// Codes the runner applies itself (motion, plane, units, compensation, speed/feed modes, dwell)
// and the cycles it plans.
const std::set<int>& modelledGCodes() {
  static const std::set<int> codes = {0, 10, 20, 30, 40, 170, 180, 190, 200, 210, 400, 410, 420,
                                      960, 970, 980, 990, 700, 710, 720};
  return codes;
}

class ProgramRunner {
 public:
  ProgramRunner(const Program& program, const Profile& profile, const MachineParams& params, const RunOptions& options)
      : program_(program), profile_(profile), params_(params), options_(options) {
    path_.profile = profile.name;
  }

  Toolpath run() {
    try {
      std::size_t i = 0;
      while (i < program_.blocks.size() && !ended_) i = execute(i);
    } catch (const CycleAlarm& a) {
      path_.alarm = a.alarm();
    }
    return std::move(path_);
  }

 private:
  // Executes block i and returns the index of the next block.
  std::size_t execute(std::size_t i) {
    const Block& b = program_.blocks[i];
    int cycle = 0;
    for (const Word* g : b.all('G')) {
      const int g10 = gCode10(g->value);
      if (const auto it = unplannedCycles().find(g10); it != unplannedCycles().end()) {
        throw NotSupported(b.line, it->second + " is not planned by the reference yet");
      }
      if (!modelledGCodes().count(g10) && !unmodelledGCodes().count(g10)) {
        throw CycleAlarm(alarm::kImproperGCode, b.line, g->text + " is not a G code of this controller");
      }
      applyModalCode(g10);
      if (g10 == 700 || g10 == 710 || g10 == 720) cycle = g10;
    }
    if (const Word* f = b.find('F')) {
      state_.feed = f->value * state_.unitScale();
    }
    if (cycle) return executeCycle(i, cycle);
    for (const Word* g : b.all('G')) {
      if (auto it = unmodelledGCodes().find(gCode10(g->value)); it != unmodelledGCodes().end()) {
        path_.warnings.push_back({b.line, it->second + " is not modelled by the reference; position unchanged"});
        return i + 1;
      }
    }
    for (const Word* m : b.all('M')) {
      if (m->value == 30 || m->value == 2) ended_ = true;
      if (m->value == 98) path_.warnings.push_back({b.line, "subprogram calls are not followed by the reference"});
    }
    executeMotion(b);
    return i + 1;
  }

  void applyModalCode(int g10) {
    if (g10 == 0 || g10 == 10 || g10 == 20 || g10 == 30) state_.motion = g10 / 10;
    if (g10 == 170 || g10 == 180 || g10 == 190) state_.plane = g10 / 10;
    if (g10 == 200) state_.inch = true;
    if (g10 == 210) state_.inch = false;
    if (g10 == 400 || g10 == 410 || g10 == 420) state_.tnrc = g10 / 10;
  }

  std::size_t executeCycle(std::size_t i, int cycle) {
    const Block& b = program_.blocks[i];
    const CycleCall call{program_, i, state_, params_, profile_, options_.tool};
    // G72.MDI, HNC.G71.MDI: the shape program must be in memory.
    if (options_.mdi) {
      CycleAlarm a(alarm::kNotInMdi, b.line, "G" + std::to_string(cycle / 10) + " cannot run in MDI mode");
      a.setWhen("cycle block");
      throw a;
    }
    if (cycle != 700 && !b.has('P') && !b.has('Q')) {
      cycle == 710 ? applyG71FirstBlock(call) : applyG72FirstBlock(call);
      return i + 1;
    }
    if (state_.tnrc != 40 && options_.tool.noseRadius <= 0) {
      path_.warnings.push_back({b.line, "G4" + std::to_string(state_.tnrc % 10) +
                                            " is active but the tool's nose radius is 0: the shape is not offset "
                                            "(give the tool offset: --nose-radius and --tip, or the case's \"tool\")"});
    }
    if (!started_) startPath();
    CycleOutcome out = cycle == 700 ? planG70(call) : cycle == 710 ? planG71(call) : planG72(call);
    CycleRecord record{"G" + std::to_string(cycle / 10), b.line, state_.planePoint(), path_.moves.size(),
                       out.moves.size(), std::move(out.shape), out.allowance, out.compensated};
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

  // A positioning or cutting block outside the cycles: once the path has started, it is a move.
  void executeMotion(const Block& b) {
    if (!hasAxisWord(b)) return;
    if (started_) {
      if (const auto seg = motionSegment(b, state_.motion, state_)) {
        Move m;
        m.kind = state_.motion == 0 ? MoveKind::Rapid : MoveKind::Feed;
        m.shape = seg->kind;
        m.to = seg->to;
        if (seg->isArc()) m.center = seg->center;
        if (m.kind == MoveKind::Feed) m.feed = state_.feed;
        m.phase = "program";
        path_.moves.push_back(std::move(m));
      }
    }
    state_.position = targetPosition(b, state_);
  }

  const Program& program_;
  const Profile& profile_;
  MachineParams params_;
  RunOptions options_;
  ModalState state_;
  Toolpath path_;
  bool started_ = false;
  bool ended_ = false;
};

}  // namespace

Toolpath planProgram(const Program& program, const Profile& profile, const MachineParams& params,
                     const RunOptions& options) {
  return ProgramRunner(program, profile, params, options).run();
}

}  // namespace cyclecert
