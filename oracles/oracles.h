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
std::unique_ptr<Oracle> makePocketEntryOracle();
// SINUMERIK LCYC95 / CYCLE95 (oracles/siemens/; siemens-alarm in alarm_oracle.cpp).
std::unique_ptr<Oracle> makeSiemensAlarmOracle();
std::unique_ptr<Oracle> makeSiemensRetractOracle();
std::unique_ptr<Oracle> makeSiemensInfeedStepsOracle();
std::unique_ptr<Oracle> makeSiemensInfeedOracle();
std::unique_ptr<Oracle> makeSiemensFeedsOracle();
std::unique_ptr<Oracle> makeSiemensChipBreakingOracle();
std::unique_ptr<Oracle> makeSiemensReturnsOracle();
// GSK G74.1 (oracles/groove/).
std::unique_ptr<Oracle> makeGroovePeckOracle();
std::unique_ptr<Oracle> makeGrooveRetractOracle();
std::unique_ptr<Oracle> makeGrooveRadialStepOracle();
std::unique_ptr<Oracle> makeGrooveLayerOracle();
std::unique_ptr<Oracle> makeGrooveReturnsOracle();

std::vector<std::unique_ptr<Oracle>> makeOracles();

// Shared helpers.
Finding finding(const Oracle& o, std::optional<std::size_t> move, std::string message);
// Point in the cycle frame (cut along z, steps along x): G72 exchanges the axes.
Point inFrame(const CycleSpec& c, Point p);
// Whether move i is a cut along the cycle's cut axis: a line in cutting feed, level along the depth
// axis and forward along the cut (within tol).
bool isCutAlongCutAxis(const JudgeInput& in, const CycleSpec& c, std::size_t i, double tol);
// G73.HEAD, G73.PASS.SHIFT: whether move i is block ns shifted for a pass — the move A → B as
// programmed (same vector, within tol), ending on B + (Δw, Δu/2) + t·(Δk, Δi), t ∈ [0, 1] — or
// at B itself with a G70 after the cycle (G73.G70). False for other families.
bool isShiftedG73Head(const JudgeInput& in, const CycleSpec& c, std::size_t i, double tol);
// Whether move i runs on the rough profile (the semi-finish pass, type II's bottom cuts) or, with a
// G70, on the finish shape: its middle lies within tol of either. Such a cut is no roughing pass.
bool runsOnProfile(const JudgeInput& in, const CycleSpec& c, const std::vector<Segment>& rough, std::size_t i,
                   double tol);
// pocket-entry (pocket_entry_oracle.cpp): whether it judges the cycle (type II with 5134 above the
// tolerance), and the continuations of move i that may cross no material — none for a move it
// does not judge. The material replay measures them.
bool judgesPocketEntries(const CycleSpec& c, const JudgeSettings& settings);
std::vector<Segment> pocketEntryProbes(const JudgeInput& in, const CycleSpec& c, std::size_t i);

}  // namespace cyclecert
