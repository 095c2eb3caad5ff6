#include "reference/siemens/siemens_roughing_cycle.h"

#include "reference/model/offset.h"

namespace cyclecert {

namespace {

const SiemensContour& requireContour(const SiemensCycleCall& call) {
  if (call.contour == nullptr) throw NotSupported(call.line, "the stock-removal cycle was called without a contour");
  return *call.contour;
}

// The path finishing follows, in the plane: the contour itself, or with a nose radius the path of
// the tool's control point under G41/G42 on the stock side (offset.h).
std::vector<Segment> finishingPathInPlane(const SiemensContour& contour, const SiemensCycleCall& call,
                                          const StockRemovalFrame& frame) {
  if (call.tool.noseRadius <= 0) return contour.segments;
  try {
    return compensatedPath(contour.segments, call.tool, frame.stockSideInPlane());
  } catch (const OffsetError& e) {
    throw CycleAlarm(siemens_alarm::kContour, call.line,
                     "the nose radius " + std::to_string(call.tool.noseRadius) + " does not fit contour " +
                         contour.name + " at its line " + std::to_string(e.sourceLine) + "; use a smaller radius");
  }
}

}  // namespace

SiemensCycleOutcome planStockRemovalCycle(const SiemensCycleCall& call, const StockRemovalSettings& s) {
  const SiemensContour& contour = requireContour(call);
  const StockRemovalFrame frame = frameOf(s.type);
  checkContour(contour, frame, call.line);

  StockRemoval cycle;
  cycle.profile = roughingProfile(frame.toFrame(contour.segments), s.allowance, frame, call.line);
  cycle.finishPath = frame.toFrame(finishingPathInPlane(contour, call, frame));
  cycle.clearance = {s.clearance, s.clearance};
  cycle.maxInfeed = s.maxInfeed;
  cycle.infeedAngle = s.infeedAngle;
  cycle.infeedKind = s.infeedKind;
  cycle.roughingFeed = s.roughingFeed;
  cycle.finishingFeed = s.finishingFeed;
  cycle.interruptLength = s.interruptLength;
  cycle.axesReturnOneAfterTheOther = s.axesReturnOneAfterTheOther;
  cycle.roughUndercuts = s.roughUndercuts;
  cycle.undercutFeed = s.undercutFeed;
  cycle.technology = s.type.technology;
  cycle.rules = s.rules;

  SiemensCycleOutcome out;
  for (Move& m : planStockRemoval(cycle, frame.toFrame(call.position))) out.moves.push_back(frame.toPlane(std::move(m)));
  out.end = out.moves.empty() ? call.position : out.moves.back().to;
  return out;
}

}  // namespace cyclecert
