#include "oracles/oracles.h"

namespace cyclecert {

std::vector<std::unique_ptr<Oracle>> makeOracles() {
  std::vector<std::unique_ptr<Oracle>> all;
  all.push_back(makeAlarmOracle());
  all.push_back(makeNoGougeOracle());
  all.push_back(makeRapidsInAirOracle());
  all.push_back(makeCompleteOracle());
  all.push_back(makeDepthPerPassOracle());
  all.push_back(makePassLevelsOracle());
  all.push_back(makeRetractOracle());
  all.push_back(makeReturnsToStartOracle());
  all.push_back(makeFeedsOracle());
  return all;
}

Finding finding(const Oracle& o, std::optional<std::size_t> move, std::string message) {
  Finding f;
  f.oracle = o.id();
  f.rules = o.rules();
  f.move = move;
  f.message = std::move(message);
  return f;
}

Point inFrame(const CycleSpec& c, Point p) { return c.cutsAlongZ() ? p : transposed(p); }

}  // namespace cyclecert
