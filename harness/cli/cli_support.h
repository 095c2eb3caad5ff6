#pragma once
// What every `cyclecert` subcommand shares: exit codes, usage errors, reading and writing files,
// and a small option table so that each command lists its options once.
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace cyclecert::cli {

// Exit codes (for CI): 0 success · 1 the controller alarmed / a case failed / findings · 2 bad
// usage or unreadable input · 3 the program needs something the reference does not plan yet.
constexpr int kExitOk = 0, kExitAlarm = 1, kExitUsage = 2, kExitNotSupported = 3;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One option of a command: a flag (no value) or an option that takes the next argument.
struct Option {
  std::string name;
  std::function<void(const std::string&)> withValue;
  std::function<void()> flag;

  Option(std::string n, std::function<void(const std::string&)> f) : name(std::move(n)), withValue(std::move(f)) {}
  Option(std::string n, std::function<void()> f) : name(std::move(n)), flag(std::move(f)) {}
};

// Applies the options in `args` and returns the positional arguments ("-" counts as one). An
// unknown option or a missing value is a UsageError that names the command's --help.
std::vector<std::string> parseOptions(const std::vector<std::string>& args, const std::vector<Option>& table,
                                      const std::string& command);

bool wantsHelp(const std::vector<std::string>& args);
std::string readFile(const std::string& path);  // a regular file up to input_file.h's cap, else exit 2
void writeFile(const std::string& path, const std::string& text);  // "-" is standard output

// A number option within [min, max]; names the option when the text is not one.
double numberArg(const std::string& option, const std::string& text, double min, double max);

// --jobs N: a whole number of workers from 1 to kMaxJobs; the message names the default (the cores).
inline constexpr int kMaxJobs = 1024;
int jobsArg(const std::string& text);

// --shard K/N or --shard auto (harness/run/ci_shard.h) as (K, N); a bad value or no shard in the
// environment is a UsageError saying what is read and what would be accepted.
std::pair<int, int> shardArg(const std::string& text);

// --param NAME=VALUE texts, validated, as (name, value) settings.
std::vector<std::pair<std::string, double>> parsedParams(const std::vector<std::string>& texts);

// A subcommand: its name, its --help text (printed by the dispatcher whenever the arguments ask for
// help) and what it does otherwise. One file each.
struct Command {
  const char* name;
  const char* help;
  int (*run)(const std::vector<std::string>& args);
};

extern const Command kPlanCommand, kJudgeCommand, kCheckCommand, kEnginesCommand, kDiffCommand, kFuzzCommand,
    kMergeCommand, kReportCommand, kRulesCommand, kParamsCommand, kProfilesCommand, kBaselineCommand;

// The report files of the run in `outDir` (`cyclecert report`; `check` and `fuzz` at the end of a
// run), with one line on standard output saying the headline numbers and where they are.
void writeRunReport(const std::string& outDir, const std::string& specsDir);

}  // namespace cyclecert::cli
