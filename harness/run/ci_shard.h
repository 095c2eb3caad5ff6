#pragma once
// --shard K/N and --shard auto: which shard of a campaign this run is. `auto` reads the CI
// system's own variables, first found wins:
//   CYCLECERT_SHARD=K/N                          set by hand (a GitHub Actions matrix, anything else)
//   CI_NODE_INDEX / CI_NODE_TOTAL                GitLab CI `parallel: N` (the index is 1-based)
//   JOB_COMPLETION_INDEX + CYCLECERT_SHARD_COUNT a Kubernetes Indexed Job (0-based index; Kubernetes
//                                                does not export the Job's completions, so the
//                                                manifest sets CYCLECERT_SHARD_COUNT to them)
//   SLURM_ARRAY_TASK_ID / SLURM_ARRAY_TASK_COUNT a Slurm job array (--array=0-3 or 1-4, with a step
//                                                too: shard (ID − SLURM_ARRAY_TASK_MIN) /
//                                                SLURM_ARRAY_TASK_STEP + 1)
#include <functional>
#include <optional>
#include <string>

namespace cyclecert {

struct Shard {
  int index = 1, count = 1;  // shard K of N, 1-based
  std::string text() const;  // "K/N"
};

inline constexpr int kMaxShards = 100000;

// A variable of the environment, or nothing when it is not set.
using EnvironmentLookup = std::function<std::optional<std::string>(const std::string& name)>;
std::optional<std::string> processEnvironment(const std::string& name);

// "K/N" with 1 ≤ K ≤ N ≤ kMaxShards. Throws std::invalid_argument saying what was expected.
Shard parseShard(const std::string& text);

// The shard the CI system's variables name (see above). Throws std::invalid_argument naming the
// variable and its value when one is malformed or out of range, and listing the variables read when
// none is set.
Shard shardFromEnvironment(const EnvironmentLookup& env = processEnvironment);

// --shard's value: "auto" (shardFromEnvironment) or "K/N".
Shard shardOption(const std::string& text, const EnvironmentLookup& env = processEnvironment);

}  // namespace cyclecert
