// cyclecert — the command line: dispatches to one file per command (cli_support.h lists them).
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include "cyclecert_version.h"
#include "harness/cli/cli_support.h"
#include "reference/model/alarms.h"
#include "reference/model/program.h"

namespace {

using namespace cyclecert;
using namespace cyclecert::cli;

const char* kMainHelp = R"HELP(cyclecert — conformance and differential testing of lathe roughing canned cycles

Usage: cyclecert <command> [options]

Commands:
  plan       plan every cycle of a program (or a spec case) with the reference engine;
             write the toolpath as JSON and SVG
  check      run every spec case against an engine (reference, process:COMMAND, mutant:NAME)
  engines    list the engines
  diff       run two engines on one program or case; show the first divergence and an SVG overlay
  fuzz       generated cases through an engine and every oracle (--vs: against a second
             engine); failures shrunk, printed with their seed, kept in corpus/regressions
  merge      join the results.jsonl of several runs (fuzz shards)
  report     write a run's report.json, junit.xml and index.html from its results
  baseline   write an expectation file (the known failures) from a run's results
  judge      judge a toolpath (any engine's, as JSON) with every oracle
  rules      list the rule catalogue with, per rule, how many spec cases cite it
  params     list the machine parameters, their defaults and the rules they serve
  profiles   list the controller profiles
  help       show this help, or `cyclecert help <command>`

Options: --help (on every command), --version.
Exit codes: 0 ok, 1 the controller alarmed, 2 bad usage or input, 3 not supported yet.
)HELP";

int run(const std::vector<std::string>& argv) {
  if (argv.empty()) {
    std::cerr << kMainHelp;
    return kExitUsage;
  }
  const std::string command = argv.front();
  const std::vector<std::string> args(argv.begin() + 1, argv.end());
  if (command == "--help" || command == "-h") {
    std::cout << kMainHelp;
    return kExitOk;
  }
  if (command == "help") {
    if (args.empty()) std::cout << kMainHelp;
    else return run({args.front(), "--help"});
    return kExitOk;
  }
  if (command == "--version") {
    std::cout << "cyclecert " << CYCLECERT_VERSION << "\n";
    return kExitOk;
  }
  for (const Command* c : {&kPlanCommand, &kParamsCommand, &kRulesCommand, &kJudgeCommand, &kCheckCommand,
                           &kEnginesCommand, &kDiffCommand, &kFuzzCommand, &kMergeCommand, &kReportCommand,
                           &kProfilesCommand, &kBaselineCommand}) {
    if (command != c->name) continue;
    if (wantsHelp(args)) {
      std::cout << c->help;
      return kExitOk;
    }
    return c->run(args);
  }
  throw UsageError("unknown command '" + command + "' (try `cyclecert --help`)");
}

std::string commandLine(int argc, char** argv) {
  std::string line;
  for (int i = 1; i < argc; ++i) line += std::string(" ") + argv[i];
  return line;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  } catch (const ParseError& e) {
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  } catch (const NotSupported& e) {
    std::cerr << "cyclecert: not supported yet: " << e.what() << "\n";
    return kExitNotSupported;
  } catch (const std::bad_alloc&) {
    std::cerr << "cyclecert " << commandLine(argc, argv)
              << ": out of memory (std::bad_alloc). The inputs are limited (64 MiB a file, the planner's passes and "
                 "moves: README \"What the reference reads, and its limits\"), so this is a defect of cyclecert: please report it with the command line\n";
    return kExitUsage;
  } catch (const std::exception& e) {  // unknown profile or parameter, bad spec case, I/O
    std::cerr << "cyclecert: " << e.what() << "\n";
    return kExitUsage;
  }
}
