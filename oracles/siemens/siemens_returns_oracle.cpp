// siemens-returns: how the call comes and goes (in the frame; the infeed axis is x).
// - Roughing starts with G0 to the computed start S in both axes together (LCYC95.ROUGH,
//   CYCLE95.START).
// - After the last roughing cut's retract a roughing-only call (1…4) returns to S: LCYC95 with G0 in
//   both axes together (LCYC95.ROUGH), CYCLE95 the axes one after the other, the infeed axis first
//   (CYCLE95.ROUGH). Complete machining (9…12) makes no such return: the finishing approach follows
//   (LCYC95.COMPLETE, CYCLE95.COMPLETE).
// - Finishing (5…12): G0 to S axis by axis, the infeed axis first; G0 to the contour's start; the
//   contour to its end; G0 back to S, the call's last move (LCYC95.FINISH, CYCLE95.FINISH).
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

std::string planeText(const SiemensCycleSpec& c, Point frame) {
  const Point p = c.frame.toPlane(frame);
  return "Z" + shortDecimalText(p.z) + " X(radius)" + shortDecimalText(p.x);
}

class SiemensReturnsOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-returns"; }
  std::vector<std::string> rules() const override {
    return {"LCYC95.ROUGH", "LCYC95.START", "LCYC95.COMPLETE", "LCYC95.FINISH",
            "CYCLE95.ROUGH", "CYCLE95.START", "CYCLE95.COMPLETE", "CYCLE95.FINISH"};
  }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    const SiemensCycleSpec& c = m.c;
    std::size_t afterRoughing = m.range.begin;
    if (c.roughs()) {
      if (!judgeRoughingApproach(m, out) || m.roughing.empty()) return;
      afterRoughing = m.roughing.back().end + 1;  // after the last cut's retract
      if (!c.finishes()) {
        if (c.isCycle95()) {
          judgeAxisByAxis(m, afterRoughing, m.range.end, "the return after roughing", out);
        } else {
          judgeReturnBothAxes(m, afterRoughing, out);
        }
        return;
      }
    }
    judgeFinishing(m, afterRoughing, out);
  }

  bool judgeRoughingApproach(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    const std::size_t i = m.range.begin;
    if (i < m.range.end && nearlyEqual(m.from(i), m.c.start, m.tol)) return true;  // already there
    if (i < m.range.end && m.isRapid(i) && nearlyEqual(m.to(i), m.c.start, m.tol)) return true;
    out.push_back(m.report(*this, i, "the call does not begin with G0 to its computed start " + planeText(m.c, m.c.start) +
                                         " (" + m.c.rule("START") + ")"));
    return false;
  }

  // LCYC95.ROUGH: one G0 in both axes to S.
  void judgeReturnBothAxes(const SiemensCycleMoves& m, std::size_t begin, std::vector<Finding>& out) const {
    // The last retract ended at S (the previous level and the last cut's end are S less the
    // retract): the return is a move of no length, which is no move.
    if (begin == m.range.end && begin > 0 && nearlyEqual(m.to(begin - 1), m.c.start, m.tol)) return;
    if (begin + 1 == m.range.end && m.isRapid(begin) && nearlyEqual(m.to(begin), m.c.start, m.tol)) return;
    out.push_back(m.report(*this, std::min(begin, m.range.end - 1),
                           "after the last roughing cut's retract LCYC95 returns to its start " + planeText(m.c, m.c.start) +
                               " with one G0 in both axes; the path makes " + std::to_string(m.range.end - begin) +
                               " move(s) there" + (m.range.end > begin ? " ending at " + planeText(m.c, m.to(m.range.end - 1)) : "")));
  }

  // G0 to S one axis after the other, the infeed axis (x) first, over moves [begin, end).
  bool judgeAxisByAxis(const SiemensCycleMoves& m, std::size_t begin, std::size_t end, const std::string& what,
                       std::vector<Finding>& out) const {
    bool movedAlongCut = false;
    for (std::size_t i = begin; i < end; ++i) {
      const Point d = m.to(i) - m.from(i);
      const bool alongCut = std::abs(d.z) > m.tol, alongInfeed = std::abs(d.x) > m.tol;
      std::string wrong;
      if (!m.isRapid(i)) wrong = "is not a G0";
      else if (alongCut && alongInfeed) wrong = "moves both axes at once";
      else if (alongInfeed && movedAlongCut) wrong = "moves the infeed axis after the other";
      if (!wrong.empty()) {
        out.push_back(m.report(*this, i, what + " " + wrong + "; it goes to the start " + planeText(m.c, m.c.start) +
                                             " with G0 axis by axis, the infeed axis first"));
        return false;
      }
      movedAlongCut = movedAlongCut || alongCut;
    }
    const Point reached = end > begin ? m.to(end - 1) : m.from(begin);
    if (nearlyEqual(reached, m.c.start, m.tol)) return true;
    out.push_back(m.report(*this, end > begin ? end - 1 : begin,
                           what + " ends at " + planeText(m.c, reached) + ", not at the start " + planeText(m.c, m.c.start)));
    return false;
  }

  void judgeFinishing(const SiemensCycleMoves& m, std::size_t begin, std::vector<Finding>& out) const {
    const FeedRun& f = m.finishing;
    if (f.begin >= m.range.end || f.begin == begin) {
      out.push_back(m.report(*this, std::min(begin, m.in.path.moves.size() - 1),
                             "no finishing pass reached by G0 (" + m.c.rule("FINISH") + ")"));
      return;
    }
    if (!judgeAxisByAxis(m, begin, f.begin - 1, "the finishing approach", out)) return;
    const Point contourStart = m.c.finishPath.front().from, contourEnd = m.c.finishPath.back().to;
    const std::size_t entry = f.begin - 1;
    if (!m.isRapid(entry) || !nearlyEqual(m.to(entry), contourStart, m.tol)) {
      out.push_back(m.report(*this, entry, "the finishing pass is not entered with G0 to the contour's start " +
                                               planeText(m.c, contourStart)));
      return;
    }
    if (!nearlyEqual(m.to(f.end - 1), contourEnd, m.tol)) {
      out.push_back(m.report(*this, f.end - 1, "the finishing pass ends at " + planeText(m.c, m.to(f.end - 1)) +
                                                   ", not at the contour's end " + planeText(m.c, contourEnd)));
      return;
    }
    if (f.end + 1 == m.range.end && m.isRapid(f.end) && nearlyEqual(m.to(f.end), m.c.start, m.tol)) return;
    out.push_back(m.report(*this, std::min(f.end, m.range.end - 1),
                           "after the finishing pass the call ends with one G0 back to its start " + planeText(m.c, m.c.start)));
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensReturnsOracle() { return std::make_unique<SiemensReturnsOracle>(); }

}  // namespace cyclecert
