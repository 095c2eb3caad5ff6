#include "reference/siemens/siemens_roughing_cycle.h"

#include <cmath>
#include <string>
#include <utility>

#include "reference/model/offset.h"
#include "reference/siemens/siemens_roughing_undercut.h"

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

// The planner's own limits on the values it is given (the front end reads them from the program):
// every value finite, the tip 0…9. NotSupported naming the value otherwise.
void requirePlannableValues(const SiemensCycleCall& call, const StockRemovalSettings& s) {
  const std::pair<const char*, double> values[] = {
      {"the allowance along the contour", s.allowance.alongContour},
      {"the Z allowance", s.allowance.longitudinal},
      {"the X allowance", s.allowance.transverse},
      {"the retract", s.clearance},
      {"the infeed depth", s.maxInfeed},
      {"the infeed angle", s.infeedAngle},
      {"the roughing feed", s.roughingFeed},
      {"the finishing feed", s.finishingFeed},
      {"the undercut feed", s.undercutFeed},
      {"the interruption length", s.interruptLength},
      {"the dwell", s.dwell},
      {"the nose radius", call.tool.noseRadius},
  };
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value)) {
      throw NotSupported(call.line, std::string(name) + " is " + std::to_string(value) + "; the cycle needs a finite number");
    }
  }
  if (call.tool.noseRadius > 0 && (call.tool.tip < 0 || call.tool.tip > 9)) {
    throw NotSupported(call.line, "tool tip " + std::to_string(call.tool.tip) + ": the tip direction must be 0...9");
  }
}

// SIEMENS.FEED: every cutting move the plan makes has a positive feed; the roughing and finishing
// feeds are checked before planning (requireFeedsInUse), so one at F0 here is an undercut's FF2.
void requirePositiveCuttingFeeds(const std::vector<Move>& moves, const StockRemovalSettings& s, int line) {
  for (const Move& m : moves) {
    if (m.kind == MoveKind::Feed && !(m.feed.value_or(0) > 0)) requireUndercutFeed(s.undercutFeed, line);
  }
}

// The unsigned parameters (R106, R110, FALZ, FALX, FAL, _VRT: "无符号", entered without sign) are
// taken by their size (interpretation).
StockRemovalSettings withUnsignedSizes(StockRemovalSettings s) {
  s.allowance.alongContour = std::abs(s.allowance.alongContour);
  s.allowance.longitudinal = std::abs(s.allowance.longitudinal);
  s.allowance.transverse = std::abs(s.allowance.transverse);
  s.clearance = std::abs(s.clearance);
  s.interruptLength = std::abs(s.interruptLength);
  s.dwell = std::abs(s.dwell);
  return s;
}

// LCYC95 does not rough undercuts (LCYC95.ROUGH notes): each pocket on the profile is reported,
// with the contour line where the profile turns back towards the axis.
std::vector<Warning> undercutsLeftToFinishing(const std::vector<Segment>& profile, const SiemensContour& contour,
                                              const StockRemovalFrame& frame, int line) {
  std::vector<Warning> warnings;
  const double top = computedStart(profile, {0, 0}).x;
  for (const Undercut& u : findUndercuts(profile, {top})) {
    if (u.down.empty()) continue;
    const Point rim = frame.toPlane(u.down.front().from);
    warnings.push_back({line, "LCYC95 does not rough the undercut where contour " + contour.name + " (" + contour.file +
                                  " line " + std::to_string(u.down.front().sourceLine) +
                                  ") turns back towards the axis at Z" + std::to_string(rim.z) + " X(radius)" +
                                  std::to_string(rim.x) + "; the finishing pass cuts what is left there"});
  }
  return warnings;
}

}  // namespace

SiemensCycleOutcome planStockRemovalCycle(const SiemensCycleCall& call, const StockRemovalSettings& settings) {
  requireInfeedDepth(settings.maxInfeed, settings.type, settings.names.depth, call.line);
  requirePlannableValues(call, settings);
  requireFeedsInUse(settings.type, {settings.roughingFeed, settings.names.roughingFeed},
                    {settings.finishingFeed, settings.names.finishingFeed}, call.line);
  requirePlannableInfeedAngle(settings.infeedAngle, call.line);
  const StockRemovalSettings s = withUnsignedSizes(settings);
  const SiemensContour& contour = requireContour(call);
  const StockRemovalFrame frame = frameOf(s.type);
  checkContour(contour, frame, call.line);

  StockRemoval cycle;
  cycle.line = call.line;
  cycle.profile = roughingProfile(frame.toFrame(contour.segments), s.allowance, frame, call.line);
  cycle.finishPath = frame.toFrame(finishingPathInPlane(contour, call, frame));
  cycle.contourFront = frame.toFrame(contour.segments.front().from);
  cycle.clearance = {s.clearance, s.clearance};
  cycle.maxInfeed = s.maxInfeed;
  cycle.mainLevels = s.mainLevels;
  cycle.infeedAngle = s.infeedAngle;
  cycle.infeedKind = s.infeedKind;
  cycle.roughingFeed = s.roughingFeed;
  cycle.finishingFeed = s.finishingFeed;
  cycle.interruptLength = s.interruptLength;
  cycle.dwell = s.dwell;
  cycle.axesReturnOneAfterTheOther = s.axesReturnOneAfterTheOther;
  cycle.roughUndercuts = s.roughUndercuts;
  cycle.undercutFeed = s.undercutFeed;
  cycle.technology = s.type.technology;
  cycle.rules = s.rules;

  SiemensCycleOutcome out;
  if (s.type.technology != SiemensTechnology::Finishing && !s.roughUndercuts) {
    out.warnings = undercutsLeftToFinishing(cycle.profile, contour, frame, call.line);
  }
  out.moves = planStockRemoval(cycle, frame.toFrame(call.position));
  for (Move& m : out.moves) frame.mapToPlane(m);
  requirePositiveCuttingFeeds(out.moves, s, call.line);
  out.end = out.moves.empty() ? call.position : out.moves.back().to;
  return out;
}

}  // namespace cyclecert
