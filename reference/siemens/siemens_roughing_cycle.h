#pragma once
// One stock-removal cycle from the call to its moves, for LCYC95 and CYCLE95: the contour checked
// (LCYC95.CONTOUR), mapped into the stock-removal frame, offset by the finishing allowance; the
// finishing path compensated for the nose radius (LCYC95.FINISH: switched on automatically); the
// shared steps planned (siemens_roughing_steps.h) and mapped back to the plane.
#include <vector>

#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_roughing_contour.h"
#include "reference/siemens/siemens_roughing_steps.h"

namespace cyclecert {

// What a cycle's parameters say, once read into the shared terms.
struct StockRemovalSettings {
  MachiningType type;
  FinishingAllowance allowance;
  double clearance = 0;       // R110 / _VRT, in each axis
  double maxInfeed = 0;       // R108 / MID
  StockRemovalParameterNames names = kLcyc95ParameterNames;  // R108 / MID, the feeds: for the alarms
  RoughingLevelsRule mainLevels = equalInfeedLevels;  // LCYC95.DEPTH
  double infeedAngle = 0;     // R109 (degrees from the infeed axis); CYCLE95: 0
  MoveKind infeedKind = MoveKind::Feed;
  double roughingFeed = 0;
  double finishingFeed = 0;
  double interruptLength = 0; // DAM
  double dwell = 0;           // DT, seconds at each interruption
  bool axesReturnOneAfterTheOther = false;
  bool roughUndercuts = false;
  double undercutFeed = 0;    // FF2
  StockRemovalRules rules;
};

SiemensCycleOutcome planStockRemovalCycle(const SiemensCycleCall& call, const StockRemovalSettings& settings);

// Each cycle's parameters read into the shared terms (planLcyc95, planCycle95 plan with them).
StockRemovalSettings lcyc95Settings(const Lcyc95Parameters& p);
StockRemovalSettings cycle95Settings(const Cycle95Parameters& p);

}  // namespace cyclecert
