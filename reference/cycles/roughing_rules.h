#pragma once
// The rule IDs a G71 or G72 roughing move cites, one table per family, chosen once when a planner
// starts (type I: type1_roughing.cpp, type II: type2_roughing.cpp, the checks: roughing_cycle.cpp).
// G72's are seed 001's eight steps; G71 follows the same steps with the axes exchanged, under its
// own IDs (reference/cycles/README.md, "The eight steps").
#include <array>
#include <string>

#include "reference/model/cycle_family.h"

namespace cyclecert {

struct RoughingRules {
  std::array<std::string, 9> step;  // step[k]: type I's STEPk (G72.STEPk, G71.T1.STEPk), k = 1…8
  std::string allowance;            // STEP1's shift by the allowances: G72.ALLOW, G71.ALLOW.UNITS
  std::string infeed;               // the infeeds' G00/G01 mode: G72.STEP2, G71.HEAD.G0G1
  std::string depthOfCut;           // the first infeed's Δd: G72.DD, G71.DD.MODAL
  std::string cut;                  // type I's cut along the cut axis: G72.STEP3, G71.OP
  std::string retract;              // type I's 45° retract: G72.RETRACT, G71.T1.RETRACT45
  std::string typeIICut;            // type II's cut at a level: G72.T2, G71.OP
  std::string sideWall;             // type II's warning about a cut-axis allowance with pockets: G72.T2, G71.T2.DW0
};

// G72's table for G72, G71's for G71 (G73 plans by its own rules, g73.cpp, and is given G71's).
const RoughingRules& roughingRulesOf(CycleFamily family);

}  // namespace cyclecert
