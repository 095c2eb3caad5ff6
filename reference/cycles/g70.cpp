// G70 — finishing cycle (G70.EX): runs the shape program ns…nf as programmed, with the F, S and T
// written inside it (which the roughing cycles ignored), then returns to the start point by rapid.
#include "reference/cycles/cycles.h"
#include "reference/cycles/shape_program.h"
#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/block_words.h"
#include "reference/model/alarms.h"
#include "reference/model/offset.h"

#include <algorithm>

namespace cyclecert {

namespace {

// G71.TNRC.NT2: with NT2 = 1 compensation may be commanded inside the G70 shape if the modal state
// at G70 is G40 (else PS0325), the end block Q has no G41/G42 (PS0325) and has G40 (else PS0538).
void checkCompensationInG70(const CycleCall& call, std::size_t ns, std::size_t nf) {
  bool anyInside = false;
  for (std::size_t i = ns; i <= nf; ++i) {
    const Block& b = call.program.blocks[i];
    anyInside = anyInside || b.hasG(400) || b.hasG(410) || b.hasG(420);
  }
  if (!anyInside || !call.params.bit("NT2")) return;
  const Block& q = call.program.blocks[nf];
  if (call.modal.tnrc != 40) {
    throw CycleAlarm(alarm::kUnavailableInShape, call.block().line,
                     "G70 with compensation in its shape must be commanded in G40 mode (NT2)");
  }
  if (q.hasG(410) || q.hasG(420)) {
    throw CycleAlarm(alarm::kUnavailableInShape, q.line, "G41/G42 in the end block of a G70 shape (NT2)");
  }
  if (!q.hasG(400)) {
    throw CycleAlarm(alarm::kTnrcNotCancelled, q.line, "the end block of a G70 shape must command G40 (NT2)");
  }
}

// One motion of the finishing shape, with the compensation in force for it.
struct FinishMotion {
  Segment seg;
  MoveKind kind;
  double feed;
  int compensation;  // 40, 41, 42 during this block
  bool startUp;      // compensation starts with this block
};

std::vector<FinishMotion> readFinishMotions(const CycleCall& call, std::size_t ns, std::size_t nf) {
  std::vector<FinishMotion> motions;
  ModalState s = call.modal;
  int compensation = call.modal.tnrc;
  bool startUpPending = compensation != 40;  // in force at G70: the first motion is the start-up
  for (std::size_t i = ns; i <= nf; ++i) {
    const Block& block = call.program.blocks[i];
    checkUsableInShape(block, s.gCodeSystem, call.profile.toleratesTnrcInShape || call.params.bit("NT2"));
    applyShapeModes(block, s);
    checkShapeBlockWords(block, s);  // PROG.RANGE, PROG.ADDRESS
    if (const Word* f = block.find('F')) s.feed = f->value * s.unitScale();  // G70.EX: F inside ns…nf applies
    if (call.params.bit("NT2")) {
      if (block.hasG(410) || block.hasG(420)) {
        compensation = block.hasG(410) ? 41 : 42;
        startUpPending = true;
      }
      if (block.hasG(400)) compensation = 40;
    }
    if (!hasAxisWord(block)) continue;
    if (const auto seg = motionSegment(block, s.motion, s)) {
      if (s.motion != 0 && s.feed <= 0) throw CycleAlarm(alarm::kFeedZero, block.line, "cutting feed with F = 0");
      motions.push_back({*seg, s.motion == 0 ? MoveKind::Rapid : MoveKind::Feed, s.feed, compensation,
                         startUpPending && compensation != 40});
      if (compensation != 40) startUpPending = false;
    }
    s.position = targetPosition(block, s);
  }
  return motions;
}

Move finishMove(const Segment& seg, MoveKind kind, double feed) {
  Move m;
  m.kind = kind;
  m.shape = seg.kind;
  m.to = seg.to;
  if (seg.isArc()) m.center = seg.center;
  if (kind == MoveKind::Feed) m.feed = feed;
  m.phase = MovePhase::Finish;
  m.rules = {"G70.EX"};
  return m;
}

// The motions with compensation applied: each start-up block ends at the compensated position for
// the block after it, the blocks of a compensated run follow the imaginary tool-nose path, and a
// block with G40 ends at its programmed point (G71.TNRC.NT2, G71.TNRC.CANCEL).
std::vector<Move> compensatedFinish(const CycleCall& call, const std::vector<FinishMotion>& motions,
                                    std::vector<Segment>& shape) {
  std::vector<Move> moves;
  std::size_t i = 0;
  while (i < motions.size()) {
    const FinishMotion& m = motions[i];
    if (!m.startUp || call.tool.noseRadius <= 0) {
      moves.push_back(finishMove(m.seg, m.kind, m.feed));
      shape.push_back(m.seg);
      ++i;
      continue;
    }
    std::size_t end = i + 1;
    while (end < motions.size() && motions[end].compensation == m.compensation && !motions[end].startUp) ++end;
    const CompensationSide side = m.compensation == 41 ? CompensationSide::Left : CompensationSide::Right;
    std::vector<Segment> run;
    for (std::size_t k = i + 1; k < end; ++k) run.push_back(motions[k].seg);
    Segment startUp = m.seg;
    try {
      if (!run.empty()) {
        startUp.to = startUpPoint(m.seg.to, run.front(), call.tool, side);
        run = compensatedPath(run, call.tool, side);
      }
    } catch (const OffsetError& e) {
      throw CycleAlarm(alarm::kInterference, e.sourceLine, "the tool-nose radius does not fit the finishing shape");
    }
    moves.push_back(finishMove(startUp, m.kind, m.feed));
    shape.push_back(startUp);
    for (Segment seg : run) {
      seg.from = moves.back().to;
      // Each compensated piece moves like the block it comes from.
      const FinishMotion* source = &m;
      for (std::size_t k = i + 1; k < end; ++k) {
        if (motions[k].seg.sourceLine == seg.sourceLine) source = &motions[k];
      }
      moves.push_back(finishMove(seg, source->kind, source->feed));
      shape.push_back(seg);
    }
    i = end;
  }
  return moves;
}

}  // namespace

CycleOutcome planG70(const CycleCall& call) {
  const Block& b = call.block();
  const Word* p = b.find('P');
  const Word* q = b.find('Q');
  if (!p || !q) throw CycleAlarm(alarm::kPQMissing, b.line, std::string("G70 block has ") + (p ? "P but no Q" : "Q but no P"));
  const std::size_t ns = findSequenceBlock(call, *p, 'P');
  const std::size_t nf = findSequenceBlock(call, *q, 'Q');
  if (nf < ns) throw CycleAlarm(alarm::kSequenceNotFound, b.line, "block Q stands before block P");
  checkCompensationInG70(call, ns, nf);

  CycleOutcome out;
  const std::vector<FinishMotion> motions = readFinishMotions(call, ns, nf);
  out.moves = compensatedFinish(call, motions, out.shape);
  out.compensated = call.tool.noseRadius > 0 &&
                    std::any_of(motions.begin(), motions.end(), [](const FinishMotion& m) { return m.startUp; });
  const Point start = call.modal.planePoint();
  // Back to the start point by rapid; compensation is cancelled on the way (G71.TNRC.CANCEL).
  Move back;
  back.to = start;
  back.phase = MovePhase::Return;
  back.rules = {"G70.EX"};
  if (out.moves.empty() || distance(out.moves.back().to, start) > kGeomEps) out.moves.push_back(back);
  out.resumeAt = call.blockIndex + 1;
  return out;
}

}  // namespace cyclecert
