// LCYC95 (SINUMERIK 802S/C, seed 004 §2): R105…R112 read into the shared stock-removal steps.
#include <cmath>

#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_roughing_cycle.h"

namespace cyclecert {

std::optional<MachiningType> machiningTypeOf(double value) {
  if (!(value >= 1 && value <= 12) || value != std::floor(value)) return std::nullopt;
  const int n = static_cast<int>(value) - 1;  // 0…11
  static constexpr SiemensTechnology kTechnology[] = {SiemensTechnology::Roughing, SiemensTechnology::Finishing,
                                                      SiemensTechnology::Complete};
  MachiningType t;
  t.technology = kTechnology[n / 4];
  t.cut = n % 2 == 0 ? SiemensCut::Longitudinal : SiemensCut::Face;
  t.side = (n % 4) < 2 ? SiemensSide::External : SiemensSide::Internal;
  return t;
}

StockRemovalSettings lcyc95Settings(const Lcyc95Parameters& p) {
  StockRemovalSettings s;
  s.type = p.type;
  s.allowance.alongContour = p.allowance;
  s.clearance = p.retract;
  s.maxInfeed = p.maxInfeed;
  s.names = kLcyc95ParameterNames;
  s.infeedAngle = p.infeedAngle;
  s.infeedKind = MoveKind::Feed;  // "depth infeed at R109" (interpretation: at R111)
  s.roughingFeed = p.roughingFeed;
  s.finishingFeed = p.finishingFeed;
  s.axesReturnOneAfterTheOther = false;
  s.rules = {"LCYC95.ROUGH", "LCYC95.START", "LCYC95.DEPTH", "LCYC95.FINISH", "LCYC95.COMPLETE", "", ""};
  return s;
}

SiemensCycleOutcome planLcyc95(const SiemensCycleCall& call, const Lcyc95Parameters& p) {
  return planStockRemovalCycle(call, lcyc95Settings(p));
}

}  // namespace cyclecert
