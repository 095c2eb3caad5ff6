#include "oracles/judgement.h"

#include "oracles/groove/groove_replay.h"
#include "oracles/material_replay.h"
#include "oracles/oracles.h"

namespace cyclecert {

const std::vector<std::unique_ptr<Oracle>>& allOracles() {
  static const std::vector<std::unique_ptr<Oracle>> oracles = makeOracles();
  return oracles;
}

std::vector<Finding> judge(const JudgeInput& in) {
  const std::optional<CycleFamily> family = in.program.judgedFamily();
  const bool groove = family == CycleFamily::G74_1;
  const std::optional<MaterialReplay> replay = groove ? std::nullopt : replayMaterial(in);
  const std::optional<GrooveReplay> grooveReplay = groove ? replayGroove(in) : std::nullopt;
  const JudgeContext ctx{in, replay ? &*replay : nullptr, grooveReplay ? &*grooveReplay : nullptr};
  std::vector<Finding> findings;
  for (const auto& oracle : allOracles()) {
    if (!family || oracle->judges(*family)) oracle->judge(ctx, findings);
  }
  return findings;
}

}  // namespace cyclecert
