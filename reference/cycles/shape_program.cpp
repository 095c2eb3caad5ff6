#include "reference/cycles/shape_program.h"

#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/block_words.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"
#include "reference/model/offset.h"

namespace cyclecert {

std::size_t findSequenceBlock(const CycleCall& call, const Word& w, char which) {
  const auto index = call.program.findSequence(static_cast<long>(w.value));
  if (!index) {
    CycleAlarm a(alarm::kSequenceNotFound, call.block().line,
                 std::string(1, which) + " names sequence number N" + w.text.substr(1) + ", which is not in the program");
    // The cycle starts at block P, so a missing P is found at once; a missing Q only when the shape
    // runs out, unless QSR or FCK check it first (G71.CHECK.QSR, G71.CHECK.FCK).
    const bool preChecked = which == 'P' || call.params.bit("QSR") || call.params.bit("FCK");
    a.setWhen(preChecked ? "before the cycle" : "during the cycle");
    throw a;
  }
  return *index;
}

namespace {

bool isTnrcCode(const GCode& code) { return code.group == GGroup::NoseRadiusComp; }

// HAAS.TNRC.SHAPE: G41/G42 start compensation in block ns, G40 ends it in block nf (or ns). Elsewhere
// compensation would change in the middle of the roughed shape, which the plan does not model.
void readShapeCompensation(const Block& b, std::size_t i, ShapeProgram& shape) {
  const bool starts = b.hasG(410) || b.hasG(420);
  if (starts && i == shape.nsIndex) {
    shape.compensationInShape = b.hasG(410) ? 41 : 42;
    return;
  }
  if (starts || (b.hasG(400) && i != shape.nfIndex && i != shape.nsIndex)) {
    throw NotSupported(b.line, std::string(starts ? "G41/G42" : "G40") + " in the middle of the shape program: "
                               "cyclecert compensates a roughing shape from G41/G42 in its first block (P) to G40 "
                               "in its last (Q) only");
  }
}

}  // namespace

void checkUsableInShape(const Block& b, GCodeSystem system, bool tnrcAllowed) {
  for (const Word* g : b.all('G')) {
    const GCode* code = findGCode(system, gCode10(g->value));
    if (!code || !usableInShapeProgram(*code)) {
      throw CycleAlarm(alarm::kUnavailableInShape, b.line,
                       g->text + (code ? " (" + std::string(code->name) + " in " + gCodeSystemName(system) + ")" : "") +
                           " cannot be used between P and Q");
    }
    // G71.TNRC.PLACE: G40/G41/G42 belong before the cycle and after the shape (NT1 is issue 3).
    if (isTnrcCode(*code) && !tnrcAllowed) {
      throw CycleAlarm(alarm::kUnavailableInShape, b.line,
                       g->text + ": nose-radius compensation must be commanded outside the shape program");
    }
  }
  for (const Word* m : b.all('M')) {
    if (m->value == 98 || m->value == 99) {
      throw CycleAlarm(alarm::kUnavailableInShape, b.line, m->text + ": no subprogram call inside a shape program");
    }
  }
}

void applyShapeModes(const Block& b, ModalState& s) {
  s.motion = motionCode(b, s.motion);
  applyGroupCodes(b, GGroup::Programming, s);  // PROG.GSYS.B: G90/G91 of systems B/C
}

int motionCode(const Block& b, int modal) {
  for (const Word* g : b.all('G')) {
    const int g10 = gCode10(g->value);
    if (g10 == 0 || g10 == 10 || g10 == 20 || g10 == 30) return g10 / 10;
  }
  return modal;
}

ShapeProgram readShapeProgram(const CycleCall& call, const Word& p, const Word& q) {
  ShapeProgram shape;
  shape.nsIndex = findSequenceBlock(call, p, 'P');
  shape.nfIndex = findSequenceBlock(call, q, 'Q');
  if (shape.nfIndex < shape.nsIndex) {
    throw CycleAlarm(alarm::kSequenceNotFound, call.block().line,
                     "block Q (N" + q.text.substr(1) + ") stands before block P (N" + p.text.substr(1) + ")");
  }
  const Block& head = call.program.blocks[shape.nsIndex];
  shape.nsLine = head.line;

  // G71.HEAD.G0G1: the head block itself must command G00 or G01.
  const bool g00 = head.hasG(0), g01 = head.hasG(10);
  if (!g00 && !g01) {
    throw CycleAlarm(alarm::kHeadNotG00G01, head.line, "block N" + p.text.substr(1) + " has no G00 or G01");
  }
  shape.headIsRapid = g00;
  const PlaneAxes axes = call.modal.axes();
  shape.headHasFirstAxis = head.has(axes.first) || head.has(axes.firstInc);
  shape.headHasSecondAxis = head.has(axes.second) || head.has(axes.secondInc);

  // Walk the shape with a private modal state: the shape only describes geometry (F, S, T, M and
  // the rapid/feed distinction are ignored by the roughing cycle: G71.FST, G72.FST).
  ModalState s = call.modal;
  shape.start = s.planePoint();
  shape.headEnd = shape.start;  // a head block without motion leaves B at A
  for (std::size_t i = shape.nsIndex; i <= shape.nfIndex; ++i) {
    const Block& b = call.program.blocks[i];
    // G71.TNRC.NT1: with NT1 = 1 compensation codes in a roughing shape are ignored without alarm.
    checkUsableInShape(b, s.gCodeSystem,
                       call.profile.toleratesTnrcInShape || call.profile.compensatesTnrcInShape || call.params.bit("NT1"));
    if (call.profile.compensatesTnrcInShape) readShapeCompensation(b, i, shape);
    applyShapeModes(b, s);
    checkShapeBlockWords(b, s);  // PROG.RANGE, PROG.ADDRESS
    if (!hasAxisWord(b)) continue;
    const auto seg = motionSegment(b, s.motion, s);
    s.position = targetPosition(b, s);
    if (i == shape.nsIndex) {
      shape.headEnd = s.planePoint();
      continue;
    }
    if (seg) shape.body.push_back(*seg);
  }
  return shape;
}

void compensateShape(const CycleCall& call, ShapeProgram& shape) {
  const int tnrc = shape.compensationInShape != 40 ? shape.compensationInShape : call.modal.tnrc;
  if (tnrc == 40 || call.tool.noseRadius <= 0 || shape.body.empty()) return;
  const CompensationSide side = tnrc == 41 ? CompensationSide::Left : CompensationSide::Right;
  try {
    shape.headEnd = startUpPoint(shape.headEnd, shape.body.front(), call.tool, side);
    shape.body = compensatedPath(shape.body, call.tool, side);
  } catch (const OffsetError& e) {
    CycleAlarm a(alarm::kInterference, e.sourceLine,
                 e.problem == OffsetProblem::ArcVanishes ? "an arc is smaller than the tool-nose radius"
                                                         : "the tool-nose radius does not fit a concave corner");
    throw a;
  }
  // The compensated path joins B (the start-up end) exactly.
  if (!shape.body.empty()) shape.body.front().from = shape.headEnd;
  shape.compensated = true;
}

std::vector<Segment> ShapeProgram::finishShape() const {
  std::vector<Segment> all;
  all.reserve(body.size() + 1);
  Segment head;
  head.from = start;
  head.to = headEnd;
  head.sourceLine = nsLine;
  all.push_back(head);
  all.insert(all.end(), body.begin(), body.end());
  return all;
}

std::size_t resumeIndexAfterCycle(const CycleCall& call, const ShapeProgram& shape) {
  return shape.nsIndex == call.blockIndex + 1 ? shape.nfIndex + 1 : call.blockIndex + 1;
}

}  // namespace cyclecert
