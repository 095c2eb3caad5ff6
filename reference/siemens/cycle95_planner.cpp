// CYCLE95 (SINUMERIK 802D, seed 004 §3): NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM,
// _VRT read into the shared stock-removal steps.
#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_roughing_cycle.h"

namespace cyclecert {

StockRemovalSettings cycle95Settings(const Cycle95Parameters& p) {
  StockRemovalSettings s;
  s.type = p.type;
  s.allowance = {p.allowance, p.allowanceZ, p.allowanceX};
  s.clearance = p.retract;
  s.maxInfeed = p.infeed;
  s.names = kCycle95ParameterNames;
  s.infeedAngle = 0;
  s.infeedKind = MoveKind::Rapid;  // CYCLE95.ROUGH: "the infeed to the current depth ... with G0"
  s.roughingFeed = p.roughingFeed;
  s.finishingFeed = p.finishingFeed;
  s.interruptLength = p.interruptLength;
  s.dwell = p.dwell;
  s.axesReturnOneAfterTheOther = true;
  s.roughUndercuts = true;
  s.undercutFeed = p.undercutFeed;
  s.rules = {"CYCLE95.ROUGH", "CYCLE95.START", "CYCLE95.DEPTH", "CYCLE95.FINISH", "CYCLE95.COMPLETE", "CYCLE95.DAM", "CYCLE95.UNDERCUT"};
  return s;
}

SiemensCycleOutcome planCycle95(const SiemensCycleCall& call, const Cycle95Parameters& p) {
  return planStockRemovalCycle(call, cycle95Settings(p));
}

}  // namespace cyclecert
