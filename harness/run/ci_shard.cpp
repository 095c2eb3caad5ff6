#include "harness/run/ci_shard.h"

#include <cstdlib>
#include <stdexcept>

namespace cyclecert {

namespace {

// A whole number from `min` to `max` (decimal digits only), or nothing.
std::optional<long> wholeNumber(const std::string& text, long min, long max) {
  if (text.empty() || text.size() > 9) return std::nullopt;
  for (char ch : text) {
    if (ch < '0' || ch > '9') return std::nullopt;
  }
  const long v = std::stol(text);
  if (v < min || v > max) return std::nullopt;
  return v;
}

// The variable's value as a whole number from `min` to `max`; `what` says what it holds.
long variableNumber(const EnvironmentLookup& env, const std::string& name, long min, long max, const std::string& what) {
  const std::optional<std::string> text = env(name);
  if (!text) throw std::invalid_argument(name + " is not set (it should hold " + what + ")");
  if (const auto v = wholeNumber(*text, min, max)) return *v;
  throw std::invalid_argument(name + "='" + *text + "': expected " + what + ", a whole number from " +
                              std::to_string(min) + " to " + std::to_string(max));
}

// A shard read from variables: K of N, checked against N.
Shard checkedShard(long index, long count, const std::string& source) {
  if (index < 1 || index > count) {
    throw std::invalid_argument(source + " names shard " + std::to_string(index) + " of " + std::to_string(count) +
                                "; a shard is 1 to the shard count");
  }
  return Shard{static_cast<int>(index), static_cast<int>(count)};
}

Shard gitlabShard(const EnvironmentLookup& env) {
  const long count = variableNumber(env, "CI_NODE_TOTAL", 1, kMaxShards, "the number of parallel jobs (GitLab)");
  const long index = variableNumber(env, "CI_NODE_INDEX", 1, kMaxShards, "the job's 1-based index (GitLab)");
  return checkedShard(index, count, "CI_NODE_INDEX=" + std::to_string(index) + " / CI_NODE_TOTAL");
}

Shard kubernetesShard(const EnvironmentLookup& env) {
  if (!env("CYCLECERT_SHARD_COUNT")) {
    throw std::invalid_argument(
        "JOB_COMPLETION_INDEX is set (a Kubernetes Indexed Job) but CYCLECERT_SHARD_COUNT is not: Kubernetes does not "
        "export the Job's completions, so set CYCLECERT_SHARD_COUNT to them in the manifest (see examples/ci/)");
  }
  const long count = variableNumber(env, "CYCLECERT_SHARD_COUNT", 1, kMaxShards, "the Job's completions");
  const long index = variableNumber(env, "JOB_COMPLETION_INDEX", 0, kMaxShards - 1, "the 0-based completion index");
  return checkedShard(index + 1, count, "JOB_COMPLETION_INDEX=" + std::to_string(index) + " (0-based) / CYCLECERT_SHARD_COUNT");
}

// Array task IDs run from SLURM_ARRAY_TASK_MIN (0 or 1, or any other) in steps of
// SLURM_ARRAY_TASK_STEP.
Shard slurmShard(const EnvironmentLookup& env) {
  const long count = variableNumber(env, "SLURM_ARRAY_TASK_COUNT", 1, kMaxShards, "the number of array tasks (Slurm)");
  const long id = variableNumber(env, "SLURM_ARRAY_TASK_ID", 0, 99999999, "the array task's ID (Slurm)");
  const long min = variableNumber(env, "SLURM_ARRAY_TASK_MIN", 0, 99999999, "the array's first task ID (Slurm)");
  const long step = env("SLURM_ARRAY_TASK_STEP")
                        ? variableNumber(env, "SLURM_ARRAY_TASK_STEP", 1, 99999999, "the array's step (Slurm)")
                        : 1;
  const std::string source = "SLURM_ARRAY_TASK_ID=" + std::to_string(id) + " (first " + std::to_string(min) + ", step " +
                             std::to_string(step) + ") / SLURM_ARRAY_TASK_COUNT";
  if (id < min || (id - min) % step != 0) {
    throw std::invalid_argument(source + ": the ID is not one of the array's (from SLURM_ARRAY_TASK_MIN in steps of " +
                                "SLURM_ARRAY_TASK_STEP); give the shard as CYCLECERT_SHARD=K/N instead");
  }
  return checkedShard((id - min) / step + 1, count, source);
}

}  // namespace

std::string Shard::text() const { return std::to_string(index) + "/" + std::to_string(count); }

std::optional<std::string> processEnvironment(const std::string& name) {
  const char* value = std::getenv(name.c_str());
  if (!value) return std::nullopt;
  return std::string(value);
}

Shard parseShard(const std::string& text) {
  const auto slash = text.find('/');
  const auto count = slash == std::string::npos ? std::nullopt : wholeNumber(text.substr(slash + 1), 1, kMaxShards);
  const auto index = count ? wholeNumber(text.substr(0, slash), 1, *count) : std::nullopt;
  if (!index) {
    throw std::invalid_argument("expected K/N with 1 ≤ K ≤ N ≤ " + std::to_string(kMaxShards) + ", e.g. 2/4, got '" + text +
                                "'");
  }
  return Shard{static_cast<int>(*index), static_cast<int>(*count)};
}

Shard shardFromEnvironment(const EnvironmentLookup& env) {
  if (const auto text = env("CYCLECERT_SHARD")) {
    try {
      return parseShard(*text);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("CYCLECERT_SHARD: ") + e.what());
    }
  }
  if (env("CI_NODE_INDEX") || env("CI_NODE_TOTAL")) return gitlabShard(env);
  if (env("JOB_COMPLETION_INDEX")) return kubernetesShard(env);
  if (env("SLURM_ARRAY_TASK_ID")) return slurmShard(env);
  throw std::invalid_argument(
      "found no shard in the environment: it reads CYCLECERT_SHARD=K/N, GitLab's CI_NODE_INDEX and "
      "CI_NODE_TOTAL, a Kubernetes Indexed Job's JOB_COMPLETION_INDEX with CYCLECERT_SHARD_COUNT, or a Slurm array's "
      "SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT and SLURM_ARRAY_TASK_MIN; set one, or give --shard K/N");
}

Shard shardOption(const std::string& text, const EnvironmentLookup& env) {
  return text == "auto" ? shardFromEnvironment(env) : parseShard(text);
}

}  // namespace cyclecert
