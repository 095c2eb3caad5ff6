#include "reference/siemens/siemens_runner.h"

#include <iterator>
#include <optional>

#include "reference/interpreter/known_position.h"
#include "reference/model/alarms.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_motion.h"
#include "reference/siemens/siemens_parser.h"

namespace cyclecert {

namespace {

// The one place the runner names a phase: the program's own moves.
void markProgramMove(Move& m) { m.phase = MovePhase::Program; }

// G codes the Siemens runner reads (SIEMENS.GCODES): motion, dwell, plane G18, the diameter mode
// (802S), work offsets, exact stop / continuous path, metric, absolute, feed and speed modes,
// spindle speed limits. Anything else is not supported.
bool isReadGCode(int g10) {
  switch (g10) {
    case 0: case 10: case 20: case 30: case 40: case 90: case 180: case 220: case 230: case 250: case 260:
    case 400: case 530: case 540: case 550: case 560: case 570: case 600: case 640: case 710: case 900:
    case 940: case 950: case 960: case 970:
      return true;
    default:
      return false;
  }
}

std::string controlName(SiemensControl c) { return c == SiemensControl::Sinumerik802D ? "802D" : "802S/C"; }

class SiemensRunner {
 public:
  SiemensRunner(const SiemensRunInput& input, const Profile& profile, const SiemensPlanners& planners)
      : input_(input), profile_(profile), planners_(planners), program_(parsedProgram(input)),
        subprograms_(*program_, input.subprograms, input.siblingDirectory, input.parsers.subprogram) {
    path_.profile = profile.name;
  }

  Toolpath run() {
    try {
      for (const SiemensBlock& b : program_->main.blocks) {
        execute(b);
        if (b.endsProgram()) break;
      }
    } catch (const CycleAlarm& a) {
      path_.alarm = a.alarm();
    }
    return std::move(path_);
  }

 private:
  static std::shared_ptr<const SiemensProgram> parsedProgram(const SiemensRunInput& input) {
    if (input.parsers.program) return input.parsers.program(input.text, input.file);
    return std::make_shared<const SiemensProgram>(parseSiemensProgram(input.text, input.file));
  }

  void execute(const SiemensBlock& b) {
    requireWordsOfTheControl(b);
    applySiemensModal(b, modal_);
    for (const RAssignment& r : b.rAssignments) r_[r.number] = r.value;
    for (const StringAssignment& s : b.strings) contourName_ = s;
    if (const SiemensWord* f = b.find("F"); f && !isDwell(b)) feed_ = f->value;
    if (hasSiemensAxisWord(b)) executeMotion(b);
    if (b.subprogramCall) {
      path_.warnings.push_back({b.line, "subprogram call " + b.subprogramCall->text +
                                            " is not followed by the reference (only contours named by a cycle are read)"});
    }
    if (b.cycle) executeCycle(b, *b.cycle);
  }

  static bool isDwell(const SiemensBlock& b) {
    for (const SiemensWord& w : b.words) {
      if (w.address == "G" && gCode10(w.value) == 40) return true;
    }
    return false;
  }

  // SIEMENS.GCODES, SIEMENS.DIAMETER: each control's own words.
  void requireWordsOfTheControl(const SiemensBlock& b) const {
    const bool is802S = profile_.siemensControl == SiemensControl::Sinumerik802S;
    for (const SiemensWord& w : b.words) {
      if (w.address != "G") continue;
      const int g = gCode10(w.value);
      if (!isReadGCode(g)) {
        throw NotSupported(b.line, w.text + " is not read by cyclecert's SINUMERIK runner (it reads G0–G4, G18, G22/G23, "
                                            "G25/G26, G40, G53–G57, G60, G64, G71, G90, G94–G97)");
      }
      if ((g == 220 || g == 230) && !is802S) {
        throw NotSupported(b.line, w.text + " switches diameter programming on the 802S/C; the 802D writes DIAMON/DIAMOF "
                                            "(--profile sinumerik-802s reads G22/G23)");
      }
    }
    for (const SiemensKeyword& k : b.keywords) {
      if ((k.name == "DIAMON" || k.name == "DIAMOF") && is802S) {
        throw NotSupported(b.line, k.name + " is the 802D's; the 802S/C writes G23 (diameter) / G22 (radius) "
                                            "(--profile sinumerik-802d reads DIAMON/DIAMOF)");
      }
    }
  }

  bool positionKnown() const { return known_.known('X') && known_.known('Z'); }

  void requireKnownPosition(const SiemensBlock& b, const std::string& why) const {
    for (char axis : {'X', 'Z'}) {
      if (!known_.known(axis)) {
        throw NotSupported(b.line, known_.describe(axis) + " (" + why + "); position the tool with G0 X.. Z.. before it");
      }
    }
  }

  // PROG.WHOLE: moves are drawn once the position is known in both axes.
  void executeMotion(const SiemensBlock& b) {
    if (isDwell(b)) return;
    if (modal_.motion == 2 || modal_.motion == 3) requireKnownPosition(b, "the arc at this line starts from it");
    if (started_) {
      if (const auto seg = siemensMotionSegment(b, position_, modal_, input_.file)) appendProgramMove(*seg);
    }
    position_ = siemensTarget(b, position_, modal_);
    if (b.find("X")) known_.learn('X');
    if (b.find("Z")) known_.learn('Z');
    startPathOnceThePositionIsKnown();
  }

  void appendProgramMove(const Segment& seg) {
    Move m;
    m.kind = modal_.motion == 0 ? MoveKind::Rapid : MoveKind::Feed;
    m.shape = seg.kind;
    m.to = seg.to;
    if (seg.isArc()) m.center = seg.center;
    if (m.kind == MoveKind::Feed) m.feed = feed_;
    markProgramMove(m);
    path_.moves.push_back(std::move(m));
  }

  void startPathOnceThePositionIsKnown() {
    if (started_ || !positionKnown()) return;
    started_ = true;
    path_.start = position_;
  }

  void executeCycle(const SiemensBlock& b, const CycleCallText& call) {
    const bool is802S = profile_.siemensControl == SiemensControl::Sinumerik802S;
    if (call.name == "LCYC97" || call.name == "CYCLE97") {
      throw NotSupported(b.line, call.name + " (thread cutting) is called by seed 004's example but not described there "
                                             "(SEED004.THREAD): cyclecert does not plan it");
    }
    if (call.name != "LCYC95" && call.name != "CYCLE95") {
      throw NotSupported(b.line, call.name + " is not a cycle cyclecert reads (LCYC95 on the 802S/C, CYCLE95 on the 802D)");
    }
    const bool lcyc = call.name == "LCYC95";
    if (lcyc != is802S) {
      throw NotSupported(b.line, call.name + " is the SINUMERIK " + (lcyc ? "802S/C" : "802D") + "'s cycle, not the " +
                                     controlName(profile_.siemensControl) + "'s: read the program with --profile " +
                                     (lcyc ? "sinumerik-802s" : "sinumerik-802d"));
    }
    if (lcyc && call.withArguments) {
      throw ParseError({input_.file, call.line, call.column + 6}, "LCYC95 alone: it reads R105…R112, not arguments", "(");
    }
    if (!lcyc && !call.withArguments) {
      throw ParseError({input_.file, call.line, call.column + 7},
                       "CYCLE95's arguments (NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT)", "end of the call");
    }
    requireKnownPosition(b, call.name + " starts from it");
    if (!started_) startPathOnceThePositionIsKnown();
    // The contour is read before the parameters are checked: a program is read whole even while a
    // planner answers NotSupported.
    if (lcyc) {
      const SiemensContour contour = contourForLcyc95(call);
      const Lcyc95Parameters p = lcyc95ParametersFrom(r_, b.line, planners_.typeOf);
      appendCycle(b, call, contour, planners_.lcyc95(callAt(b, contour), p));
    } else {
      const CycleArgument& npp = cycle95ContourArgument(call, input_.file);
      const SiemensContour contour = contourNamed(*npp.text, npp.line, npp.column);
      const Cycle95Parameters p = cycle95ParametersFrom(call, input_.file, planners_.typeOf);
      appendCycle(b, call, contour, planners_.cycle95(callAt(b, contour), p));
    }
  }

  SiemensContour contourForLcyc95(const CycleCallText& call) {
    if (!contourName_) {
      throw ParseError({input_.file, call.line, call.column}, "_CNAME=\"NAME\" (the contour subprogram) before LCYC95",
                       "LCYC95 without _CNAME");
    }
    return contourNamed(contourName_->value, contourName_->line, contourName_->column);
  }

  SiemensContour contourNamed(const std::string& name, int line, int column) {
    const SiemensBlocks& blocks = subprograms_.find(name, input_.file, line, column);
    if (input_.parsers.contour) {
      if (const std::shared_ptr<const SiemensBlocks> kept = subprograms_.kept(name)) {
        return input_.parsers.contour(name, kept, modal_);
      }
    }
    return readSiemensContour(name, blocks, modal_);
  }

  SiemensCycleCall callAt(const SiemensBlock& b, const SiemensContour& contour) const {
    return {b.line, position_, &contour, input_.tool};
  }

  void appendCycle(const SiemensBlock& b, const CycleCallText& call, const SiemensContour& contour, SiemensCycleOutcome out) {
    if (path_.moves.size() + out.moves.size() > kMostMovesPerToolpath) {  // PROG.CAP.MOVES
      throw NotSupported(b.line, "the program would make more than " + std::to_string(kMostMovesPerToolpath) +
                                     " moves; cyclecert plans at most that many per program");
    }
    path_.cycles.push_back({call.name, b.line, position_, path_.moves.size(), out.moves.size(), contour.segments, Point{}, false, {}});
    path_.moves.insert(path_.moves.end(), std::make_move_iterator(out.moves.begin()),
                       std::make_move_iterator(out.moves.end()));
    for (Warning& w : out.warnings) path_.warnings.push_back(std::move(w));
    position_ = out.end;
  }

  const SiemensRunInput& input_;
  const Profile& profile_;
  const SiemensPlanners& planners_;
  std::shared_ptr<const SiemensProgram> program_;
  SiemensSubprograms subprograms_;
  SiemensModal modal_;
  RParameters r_;
  std::optional<StringAssignment> contourName_;
  std::optional<double> feed_;
  Point position_;
  KnownPosition known_;
  bool started_ = false;
  Toolpath path_;
};

}  // namespace

Toolpath planSiemensProgram(const SiemensRunInput& input, const Profile& profile, const SiemensPlanners& planners) {
  return SiemensRunner(input, profile, planners).run();
}

}  // namespace cyclecert
