#include "oracles/judgement.h"

#include "oracles/material_replay.h"
#include "oracles/oracles.h"

namespace cyclecert {

const std::vector<std::unique_ptr<Oracle>>& allOracles() {
  static const std::vector<std::unique_ptr<Oracle>> oracles = makeOracles();
  return oracles;
}

std::vector<Finding> judge(const JudgeInput& in) {
  const std::optional<MaterialReplay> replay = replayMaterial(in);
  const JudgeContext ctx{in, replay ? &*replay : nullptr};
  std::vector<Finding> findings;
  const std::optional<CycleFamily> family = in.program.judgedFamily();
  for (const auto& oracle : allOracles()) {
    if (!family || oracle->judges(*family)) oracle->judge(ctx, findings);
  }
  return findings;
}

}  // namespace cyclecert
