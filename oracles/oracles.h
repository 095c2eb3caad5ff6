#pragma once
// The oracles, one file each; judgement.cpp lists them.
#include <memory>
#include <vector>

#include "oracles/judgement.h"

namespace cyclecert {

std::unique_ptr<Oracle> makeAlarmOracle();
std::unique_ptr<Oracle> makeFeedsOracle();
std::unique_ptr<Oracle> makeReturnsToStartOracle();
std::unique_ptr<Oracle> makeRetractOracle();
std::unique_ptr<Oracle> makeNoGougeOracle();
std::unique_ptr<Oracle> makeRapidsInAirOracle();
std::unique_ptr<Oracle> makeCompleteOracle();
std::unique_ptr<Oracle> makeDepthPerPassOracle();
std::unique_ptr<Oracle> makePassLevelsOracle();

std::vector<std::unique_ptr<Oracle>> makeOracles();

// Shared helpers.
Finding finding(const Oracle& o, std::optional<std::size_t> move, std::string message);
// Point in the cycle frame (cut along z, steps along x): G72 exchanges the axes.
Point inFrame(const CycleSpec& c, Point p);

}  // namespace cyclecert
