// G70 — finishing cycle (G70.EX): runs the shape program ns…nf as programmed, with the F, S and T
// written inside it (which the roughing cycles ignored), then returns to the start point by rapid.
#include "reference/cycles/cycles.h"
#include "reference/cycles/shape_program.h"
#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

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
  ModalState s = call.modal;
  const Point start = s.planePoint();
  for (std::size_t i = ns; i <= nf; ++i) {
    const Block& block = call.program.blocks[i];
    checkUsableInShape(block, call.profile.toleratesTnrcInShape || call.params.bit("NT2"));
    s.motion = motionCode(block, s.motion);
    if (const Word* f = block.find('F')) s.feed = f->value * s.unitScale();  // G70.EX: F inside ns…nf applies
    if (!hasAxisWord(block)) continue;
    if (const auto seg = motionSegment(block, s.motion, s)) {
      if (s.motion != 0 && s.feed <= 0) throw CycleAlarm(alarm::kFeedZero, block.line, "cutting feed with F = 0");
      Move m;
      m.kind = s.motion == 0 ? MoveKind::Rapid : MoveKind::Feed;
      m.shape = seg->kind;
      m.to = seg->to;
      if (seg->isArc()) m.center = seg->center;
      if (m.kind == MoveKind::Feed) m.feed = s.feed;
      m.phase = "finish";
      m.rules = {"G70.EX"};
      out.moves.push_back(m);
      out.shape.push_back(*seg);
    }
    s.position = targetPosition(block, s);
  }
  Move back;
  back.to = start;
  back.phase = "return";
  back.rules = {"G70.EX"};
  if (out.moves.empty() || distance(out.moves.back().to, start) > kGeomEps) out.moves.push_back(back);
  out.resumeAt = call.blockIndex + 1;
  return out;
}

}  // namespace cyclecert
