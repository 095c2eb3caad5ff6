#include "reference/siemens/siemens_roughing_contour.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "reference/model/number_text.h"
#include "reference/model/offset.h"
#include "reference/siemens/siemens_axis_allowance.h"

namespace cyclecert {

namespace {

std::string where(const SiemensContour& contour, const Segment& s) {
  return contour.name + " (" + contour.file + " line " + std::to_string(s.sourceLine) + ")";
}

void requireQuarterCircles(const SiemensContour& contour, int line) {
  constexpr double kQuarter = std::numbers::pi / 2 + 1e-9;
  for (const Segment& s : contour.segments) {
    if (s.isArc() && std::abs(sweep(s)) > kQuarter) {
      const double degrees = std::abs(sweep(s)) * 180 / std::numbers::pi;
      throw CycleAlarm(siemens_alarm::kContour, line,
                       "contour " + where(contour, s) + ": an arc of " + std::to_string(degrees) +
                           " degrees; the cycle takes arcs of at most a quarter circle (split it at 90 degrees)");
    }
  }
}

void requireFinishingDirection(const SiemensContour& contour, const StockRemovalFrame& frame, int line) {
  const Point start = frame.toFrame(contour.segments.front().from);
  const Point end = frame.toFrame(contour.segments.back().to);
  if (end.z < start.z - kGeomEps) return;
  const std::string axis = frame.transposed ? "X" : "Z";
  throw CycleAlarm(siemens_alarm::kContour, line,
                   "contour " + contour.name + " (" + contour.file + ") ends no further towards -" + axis +
                       " than it starts; it must be programmed in the finishing direction, towards -" + axis +
                       " (reverse the contour's blocks)");
}

}  // namespace

void requireInfeedDepth(double depth, const MachiningType& type, std::string_view parameter, int line) {
  if (type.technology == SiemensTechnology::Finishing || depth > 0) return;
  throw CycleAlarm(siemens_alarm::kNoInfeedDepth, line,
                   std::string(parameter) + "=" + std::to_string(depth) +
                       ": roughing needs an infeed depth greater than 0");
}

void requireFeedsInUse(const MachiningType& type, NamedParameter roughing, NamedParameter finishing, int line) {
  const auto require = [line](bool used, NamedParameter feed) {
    if (!used || feed.value > 0) return;
    throw CycleAlarm(siemens_alarm::kNoFeedrate, line,
                     std::string(feed.name) + " = " + shortDecimalText(feed.value) +
                         ": the cycle cuts at this feed; give a feed above 0");
  };
  require(type.technology != SiemensTechnology::Finishing, roughing);
  require(type.technology != SiemensTechnology::Roughing, finishing);
}

void requireUndercutFeed(double feed, int line) {
  if (feed > 0) return;
  throw CycleAlarm(siemens_alarm::kNoFeedrate, line,
                   "FF2 = " + shortDecimalText(feed) + ": the cycle roughs an undercut at this feed; give a feed above 0");
}

void requirePlannableInfeedAngle(double angle, int line) {
  if (angle >= 0 && angle < 90) return;
  throw NotSupported(line, "R109 = " + shortDecimalText(angle) +
                               ": the reference plans infeed angles 0 <= R109 < 90 degrees (from the infeed axis); "
                               "the seed gives no range and no meaning for others");
}

void checkContour(const SiemensContour& contour, const StockRemovalFrame& frame, int line) {
  const bool moves = std::any_of(contour.segments.begin(), contour.segments.end(),
                                 [](const Segment& s) { return s.length() > kGeomEps; });
  if (!moves) {
    throw CycleAlarm(siemens_alarm::kContour, line,
                     "contour " + contour.name + " (" + contour.file + ") has no moves; it needs lines or arcs");
  }
  requireQuarterCircles(contour, line);
  requireFinishingDirection(contour, frame, line);
}

std::vector<Segment> roughingProfile(const std::vector<Segment>& frameContour, const FinishingAllowance& allowance,
                                     const StockRemovalFrame& frame, int line) {
  std::vector<Segment> profile;
  try {
    profile = offsetPath(frameContour, allowance.alongContour, CompensationSide::Right);
  } catch (const OffsetError& e) {
    throw CycleAlarm(siemens_alarm::kContour, line,
                     "the finishing allowance " + std::to_string(allowance.alongContour) +
                         " does not fit the contour at its line " + std::to_string(e.sourceLine) +
                         " (an arc vanishes or two offset pieces do not meet); use a smaller allowance");
  }
  // FALZ / FALX in the frame's axes (face machining exchanges them), on each element's stock side.
  const Point planeAllowance{allowance.longitudinal, allowance.transverse};
  const Point axisAllowance = frame.transposed ? Point{planeAllowance.x, planeAllowance.z} : planeAllowance;
  try {
    profile = withAxisAllowances(profile, axisAllowance);
  } catch (const OffsetError& e) {
    throw CycleAlarm(siemens_alarm::kContour, line,
                     "the axis allowances FALZ " + std::to_string(allowance.longitudinal) + " and FALX " +
                         std::to_string(allowance.transverse) + " do not fit the contour at its line " +
                         std::to_string(e.sourceLine) + " (a groove narrower than the allowances); use smaller ones");
  }
  return profile;
}

}  // namespace cyclecert
