#pragma once
// The contour rules both stock-removal cycles check before any move (LCYC95.CONTOUR, CYCLE95's
// the same), the parameter alarms, and the roughing profile: the contour plus its finishing
// allowance, in the stock-removal frame.
//
// Alarm numbers (interpretation, LCYC95.ALARMS in specs/rules.json): taken from our reading of
// Siemens' 802S/840D cycle alarm lists, not confirmed by a stored page — 61002 for a machining type
// outside 1…12, 10931 for a contour the cycle cannot use, 61610 for no infeed depth, 10860 for a
// cutting feed (R111/R112, FF1/FF2/FF3) the call uses that is not positive.
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/alarms.h"
#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_roughing_frame.h"

namespace cyclecert {

namespace siemens_alarm {
inline constexpr std::string_view kMachiningType = "61002";  // R105 / VARI not 1…12
inline constexpr std::string_view kContour = "10931";        // arc > quarter circle, wrong direction, empty
inline constexpr std::string_view kNoInfeedDepth = "61610";  // R108 / MID not positive when roughing
inline constexpr std::string_view kNoFeedrate = "10860";    // a cutting feed the call uses not positive (SIEMENS.FEED)
}  // namespace siemens_alarm


// R108 / MID must be positive when the type roughs (roughing or complete): else alarm 61610.
void requireInfeedDepth(double depth, const MachiningType& type, std::string_view parameter, int line);

// The names each cycle gives its infeed depth and its feeds, for the alarms (the planner and the
// oracles' reading use the same).
struct StockRemovalParameterNames {
  std::string_view depth, roughingFeed, finishingFeed;
};
inline constexpr StockRemovalParameterNames kLcyc95ParameterNames{"R108", "R111", "R112"};
inline constexpr StockRemovalParameterNames kCycle95ParameterNames{"MID", "FF1", "FF3"};

// A cycle parameter's value and its name in the call (R111, FF1, …), for the alarms.
struct NamedParameter {
  double value = 0;
  std::string_view name;
};

// SIEMENS.FEED: the feeds the type cuts at must be above 0 — `roughing` (R111 / FF1) when it roughs
// or machines completely, `finishing` (R112 / FF3) when it finishes or machines completely — else
// alarm 10860 naming the parameter. (The seed: R111 has no effect when finishing, R112 none when
// roughing.)
void requireFeedsInUse(const MachiningType& type, NamedParameter roughing, NamedParameter finishing, int line);

// SIEMENS.FEED: FF2 must be above 0 where CYCLE95 roughs an undercut; else alarm 10860.
void requireUndercutFeed(double feed, int line);

// LCYC95.PARAMS (interpretation): the reference plans an infeed angle R109 of 0 up to, not
// including, 90 degrees from the infeed axis; neither the seed nor a manual we hold gives its range
// or what another angle does, so NotSupported rather than a guess.
void requirePlannableInfeedAngle(double angle, int line);

// LCYC95.CONTOUR: at least one segment, each arc at most a quarter circle, and the contour
// programmed in the finishing direction (towards −z in the frame: longitudinal towards −Z, face
// towards −X). Alarm 10931 naming the contour's file and line otherwise.
void checkContour(const SiemensContour& contour, const StockRemovalFrame& frame, int line);

// The profile the roughing passes follow, in the frame: the contour offset by the contour-parallel
// allowance `alongContour` on the stock side (offset.h), then shifted by the axis-parallel
// allowances (CYCLE95's FALZ/FALX; zero for LCYC95) towards the stock. An allowance the contour
// cannot take (an arc vanishing, corners not meeting) is alarm 10931.
struct FinishingAllowance {
  double alongContour = 0;  // R106, FAL
  double longitudinal = 0;  // FALZ (plane Z)
  double transverse = 0;    // FALX (plane X, radius)
};
std::vector<Segment> roughingProfile(const std::vector<Segment>& frameContour, const FinishingAllowance& allowance,
                                     const StockRemovalFrame& frame, int line);

}  // namespace cyclecert
