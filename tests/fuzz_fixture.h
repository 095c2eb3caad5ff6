#pragma once
// Helpers the fuzz tests of each cycle family share: a sample of generated cases and a scratch
// folder of the test process's own.
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "harness/fuzz/case_generator.h"
#include "harness/run/check_run.h"

namespace cyclecert {

// Cases 0 … n − 1 drawn from `seed` for `cycles`, as `fuzz --seed` draws them.
inline std::vector<FuzzCase> fuzzSample(std::uint64_t seed, long n, const FuzzCycles& cycles) {
  std::vector<FuzzCase> out;
  for (long i = 0; i < n; ++i) out.push_back(generateFuzzCase(fuzzCaseSeed(seed, i), kDefaultCycleFormats, cycles));
  return out;
}

// An empty folder under the temporary directory named after the family, `name` and this process.
inline std::string scratchFolder(const std::string& family, const std::string& name) {
  const std::filesystem::path p =
      std::filesystem::temp_directory_path() / ("cyclecert-fuzz-" + family + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(p);
  return p.string();
}

// The spec suite (specs/) run through `engine` by `check` in `outDir`, removed afterwards: the
// summary and the progress text (to print when an expectation on the summary fails).
struct SpecSuiteRun {
  CheckSummary summary;
  std::string progress;
};
inline SpecSuiteRun checkTheSpecSuite(Engine& engine, const std::string& outDir) {
  const CheckOptions options{CYCLECERT_SOURCE_DIR "/specs", "", outDir, false};
  std::ostringstream progress;
  SpecSuiteRun run{runCheck(engine, options, progress), {}};
  run.progress = progress.str();
  std::filesystem::remove_all(outDir);
  return run;
}

}  // namespace cyclecert
