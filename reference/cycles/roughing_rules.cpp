#include "reference/cycles/roughing_rules.h"

namespace cyclecert {

namespace {

RoughingRules g71Rules() {
  RoughingRules r;
  for (int k = 1; k <= 8; ++k) r.step[static_cast<std::size_t>(k)] = "G71.T1.STEP" + std::to_string(k);
  r.allowance = "G71.ALLOW.UNITS";
  r.infeed = "G71.HEAD.G0G1";
  r.depthOfCut = "G71.DD.MODAL";
  r.cut = "G71.OP";
  r.retract = "G71.T1.RETRACT45";
  r.typeIICut = "G71.OP";
  r.sideWall = "G71.T2.DW0";
  return r;
}

RoughingRules g72Rules() {
  RoughingRules r;
  for (int k = 1; k <= 8; ++k) r.step[static_cast<std::size_t>(k)] = "G72.STEP" + std::to_string(k);
  r.allowance = "G72.ALLOW";
  r.infeed = "G72.STEP2";
  r.depthOfCut = "G72.DD";
  r.cut = "G72.STEP3";
  r.retract = "G72.RETRACT";
  r.typeIICut = "G72.T2";
  r.sideWall = "G72.T2";
  return r;
}

}  // namespace

const RoughingRules& roughingRulesOf(CycleFamily family) {
  static const RoughingRules g71 = g71Rules(), g72 = g72Rules();
  return family == CycleFamily::G72 ? g72 : g71;
}

}  // namespace cyclecert
