// `cyclecert check` and `cyclecert engines`: the spec suite against one engine.
#include <iostream>
#include <tuple>

#include "harness/cli/cli_support.h"
#include "harness/engines/engine.h"
#include "harness/results/expectations.h"
#include "harness/run/campaign.h"
#include "harness/run/check_run.h"
#include "harness/run/parallel_run.h"
#include "harness/run/run_lock.h"
#include "harness/run/run_record.h"
#include "harness/spec/rule_catalogue.h"

namespace cyclecert::cli {

namespace {

const char* kCheckHelp = R"HELP(Usage: cyclecert check --engine E [--specs DIR] [--out DIR] [--resume [--mix-campaigns]]
                       [--timeout S] [--jobs N] [--shard K/N | --shard auto] [--metamorphic]
                       [--expectations FILE [--strict]]

Runs every spec case under DIR/cases (default: the repository's specs/), then every shrunk fuzz
failure kept as a spec case under corpus/regressions/, against engine E
(`cyclecert engines`). A case passes when the engine meets its expectation — the toolpath within
the case's tolerance, or the alarm — and every oracle finds nothing on its toolpath. Each result
is appended to OUT/results.jsonl (default build/check) as soon as it is known, so a killed run keeps
every result; --resume skips the cases already there. One run at a time writes into OUT (it holds
OUT/run.lock; a second is refused). A result that cannot be written (disk full) stops the run with
exit 2, saying how many results are safe. OUT/run.json records the run (engine and its
version, cyclecert's version and git revision, the spec suite's hash, the start, the command line;
--resume adds a record), and at the end the report is written: OUT/report.json, OUT/junit.xml and
OUT/index.html (`cyclecert report`). --jobs runs the cases on N threads, each with its own engine:
the results are those of --jobs 1, in the same order. --shard splits the suite between runs
(`cyclecert merge` joins them).

Options:
  --engine E     reference | linuxcnc | process:COMMAND | mutant:NAME
  --specs DIR    the spec suite: DIR/cases and DIR/rules.json (default: the repository's specs/)
  --out DIR      where results.jsonl, run.json and the report go (default build/check)
  --resume       continue the run in OUT, skipping the cases it has; refused when OUT holds a run
                 of another engine or engine version, or a check of another spec suite
  --mix-campaigns   with --resume: continue even so (the report then mixes the two)
  --timeout S    per-case timeout for engines in another process (default 10)
  --regressions DIR   the regression cases to run after the specs (default corpus/regressions)
  --no-regressions    run the spec cases only
  --jobs N       workers, each with its own engine (default: the number of cores)
  --shard K/N    run only case i (of the spec cases, then the regressions, in file-name order) when
                 i mod N = K−1
  --shard auto   K/N from the environment: CYCLECERT_SHARD=K/N, else GitLab's CI_NODE_INDEX and
                 CI_NODE_TOTAL, else a Kubernetes Indexed Job's JOB_COMPLETION_INDEX (0-based) with
                 CYCLECERT_SHARD_COUNT, else a Slurm array's SLURM_ARRAY_TASK_ID, _COUNT and _MIN
  --expectations FILE the engine's known failures (JSON or `ID OUTCOME # reason` lines; README
                 "Expectation files"; `cyclecert baseline` writes one): a case failing as its entry
                 says is an expected failure, counted apart, and does not fail the run; an entry
                 whose case passes now, or that matches nothing, is reported as unexpectedly passing
  --strict       with --expectations: exit 1 on an unexpectedly passing entry too
  --metamorphic  also judge the engine against itself: for each case, every metamorphic relation
                 (oracles/metamorphic: mirror, translate, scale, split, formats, …) that applies to
                 its program writes a follow-up program, the engine runs it, and its toolpath must
                 be the relation's transformation of the case's. A violation is a finding
                 metamorphic:<relation>; a follow-up the engine fails on is an engine failure; a
                 relation that does not apply, or that the engine answers "not applicable" to, is
                 skipped. Counts per relation go to OUT/metamorphic.json. Off by default: each
                 relation that applies is one more engine run per case
Exit: 0 every case passes (or is not applicable, or fails as expected), 1 a case fails or the engine
failed (not as expected), or with --strict an entry passes unexpectedly, 2 bad usage, unreadable
input or expectation file, OUT in use by another run, another campaign in OUT, or a result not
written.
)HELP";

const char* kEnginesHelp = R"HELP(Usage: cyclecert engines

Lists the engines `check` can run: the reference, any external program speaking JSON lines
(process:COMMAND, see the README), and the mutants (the reference with one seeded fault).
)HELP";

}  // namespace

static int commandCheck(const std::vector<std::string>& args) {
  std::string engineName;
  CheckOptions options{defaultSpecsDir(), defaultRegressionsDir(), "build/check", false};
  options.jobs = defaultJobs();
  EngineOptions engineOptions;
  bool mixCampaigns = false, strict = false;
  std::optional<Expectations> expectations;
  const auto positional = parseOptions(
      args,
      {{"--engine", [&](const std::string& v) { engineName = v; }},
       {"--specs", [&](const std::string& v) { options.specsDir = v; }},
       {"--out", [&](const std::string& v) { options.outDir = v; }},
       {"--regressions", [&](const std::string& v) { options.regressionsDir = v; }},
       {"--no-regressions", [&] { options.regressionsDir.clear(); }},
       {"--resume", [&] { options.resume = true; }},
       {"--metamorphic", [&] { options.metamorphic = true; }},
       {kMixCampaignsFlag, [&] { mixCampaigns = true; }},
       {"--expectations", [&](const std::string& v) { expectations = readExpectations(v); }},
       {"--strict", [&] { strict = true; }},
       {"--timeout", [&](const std::string& v) { engineOptions.timeoutSeconds = numberArg("--timeout", v, 0.01, 86400); }},
       {"--jobs", [&](const std::string& v) { options.jobs = jobsArg(v); }},
       {"--shard", [&](const std::string& v) { std::tie(options.shard, options.shards) = shardArg(v); }}},
      "check");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  if (engineName.empty()) throw UsageError("give --engine (see `cyclecert engines`)");
  if (mixCampaigns && !options.resume) throw UsageError(std::string(kMixCampaignsFlag) + " goes with --resume");
  if (strict && !expectations) throw UsageError("--strict goes with --expectations FILE");
  if (expectations) options.expectations = &*expectations;
  const auto engine = makeEngine(engineName, engineOptions);
  std::vector<std::string> argv{"cyclecert", "check"};
  argv.insert(argv.end(), args.begin(), args.end());
  const RunLock lock(options.outDir, commandLineText(argv));  // held until the report is written
  RunRecord record = startRunRecord("check", *engine, nullptr, options.specsDir, std::nullopt, argv);
  if (options.shards > 1) record.shard = std::to_string(options.shard) + "/" + std::to_string(options.shards);
  record.metamorphic = options.metamorphic;
  recordRun(options.outDir, record, options.resume, mixCampaigns);
  const CheckSummary s = runCheck(namedEngines(engineName, "", engineOptions), options, std::cerr);
  std::cout << "check " << engine->name() << ": " << s.pass << " pass, " << s.fail << " fail, " << s.notApplicable
            << " not applicable, " << s.engineFailure << " engine failure(s)"
            << expectationCountsText(s.expectedFailures, s.unexpectedPasses + static_cast<long>(s.unusedExpectations.size()));
  if (s.skipped) std::cout << ", " << s.skipped << " already done";
  std::cout << "; results in " << options.outDir << "/results.jsonl\n";
  for (const Expectation& x : s.unusedExpectations) std::cerr << unusedExpectationText(x) << "\n";
  if (options.metamorphic) {
    writeTallyFile(options.outDir, s.metamorphic, options.resume);
    std::cout << tallyText(s.metamorphic) << "; counts per relation in " << options.outDir << "/metamorphic.json\n";
  }
  writeRunReport(options.outDir, options.specsDir);
  return (strict ? s.strictClean() : s.clean()) ? kExitOk : kExitAlarm;
}

static int commandEngines(const std::vector<std::string>& args) {
  const auto positional = parseOptions(args, {}, "engines");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  std::cout << enginesListing();
  return kExitOk;
}

extern const Command kCheckCommand{"check", kCheckHelp, commandCheck};
extern const Command kEnginesCommand{"engines", kEnginesHelp, commandEngines};

}  // namespace cyclecert::cli
