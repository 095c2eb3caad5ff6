// `cyclecert fuzz` (generated cases through an engine and the oracles, shrinking failures) and
// `cyclecert merge` (the results of shards joined into one run).
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <random>
#include <set>
#include <tuple>

#include "harness/cli/cli_support.h"
#include "harness/engines/engine.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/results/expectations.h"
#include "harness/results/results_file.h"
#include "harness/run/campaign.h"
#include "harness/run/parallel_run.h"
#include "harness/run/run_lock.h"
#include "harness/run/run_record.h"
#include "harness/spec/rule_catalogue.h"

namespace cyclecert::cli {

namespace {

const char* kFuzzHelp = R"HELP(Usage: cyclecert fuzz --engine E [--vs B] [--cases N | --time SECONDS] [--seed S] [--jobs N]
                      [--shard K/N | --shard auto] [--out DIR] [--regressions DIR | --no-save] [--resume [--mix-campaigns]]
                      [--timeout S] [--formats LIST] [--cycles LIST] [--metamorphic] [--expectations FILE [--strict]]

Generates G71/G72 cases (lines, chamfers and arcs; monotone and with pockets; all four quadrants;
degenerate segments; Δd, e, Δu, Δw valid, on their boundary and out of range; RF1, DTP, R16, NSP,
RF2; profiles fanuc-0i-f, fanuc-0i-c, gsk; with --formats the one-block formats and G code systems
B/C too) and runs each through engine E and every oracle and, with --vs, compares E's result with
engine B's. The first failure of each kind (an oracle,
"diverges", "engine-failure") is shrunk to a minimal case, printed with the seed that regenerates
it, and written as a spec case to the regressions directory, which `check` runs from then on.

Each result is appended to OUT/results.jsonl as it is known (a killed run keeps every result);
--resume continues a run, skipping the cases already there. One run at a time writes into OUT (it
holds OUT/run.lock; a second is refused). A result that cannot be written (disk full) stops the run
with exit 2, saying how many results are safe. OUT/run.json records the run (engines
and versions, git revision, spec suite hash, start, seed, command line), and at the end the report
is written: OUT/report.json, OUT/junit.xml, OUT/index.html (`cyclecert report`). Shards split one
campaign: run --shard 1/4 … --shard 4/4 with the same --seed and --cases, then `cyclecert merge`
(in CI, --shard auto reads the shard from the CI system; examples/ci/ has GitHub Actions, GitLab,
Kubernetes and Slurm set-ups). --jobs runs the cases on N threads, each with its own engine (one
child process or rs274 each): the results are those of --jobs 1, written in the same order.

Options:
  --engine E          reference | linuxcnc | process:COMMAND | mutant:NAME (`cyclecert engines`)
  --vs B              compare every case with engine B (toolpaths move by move, alarms)
  --cases N           the campaign's number of cases (default 2000 unless --time is given)
  --time SECONDS      stop after this long (a slow engine gets its batch in chunks that fit)
  --seed S            the run's seed (default: random, printed); case i uses S + i·0x9E3779B97F4A7C15,
                      so `--seed <case seed> --cases 1` regenerates one case
  --jobs N            workers, each with its own engine (default: the number of cores); the same
                      results as --jobs 1
  --shard K/N         run only the cases i with i mod N = K−1
  --shard auto        K/N from the environment: CYCLECERT_SHARD=K/N, else GitLab's CI_NODE_INDEX
                      and CI_NODE_TOTAL, else a Kubernetes Indexed Job's JOB_COMPLETION_INDEX
                      (0-based) with CYCLECERT_SHARD_COUNT (Kubernetes does not export the count),
                      else a Slurm array's SLURM_ARRAY_TASK_ID, _COUNT and _MIN (and _STEP)
  --out DIR           where results.jsonl, run.json and the report go (default build/fuzz)
  --regressions DIR   where shrunk failures are written (default corpus/regressions)
  --no-save           do not write shrunk failures
  --shrink-budget R   engine runs spent shrinking one failure at most (default 400)
  --tolerance T       mm, for the oracles, --vs and --metamorphic (default 0.001)
  --metamorphic       also judge the engine against itself, no reference needed: on each case the
                      oracles (and --vs) pass, every metamorphic relation that applies (mirror,
                      translate, scale, split, absolute/incremental, R/IK, planes, units, formats,
                      transpose, …: oracles/metamorphic) writes a follow-up program, E runs it, and
                      its toolpath must be the relation's transformation of the case's. A violation
                      fails the case as "metamorphic:<relation>" (shrunk like any failure); a
                      follow-up E fails on is an engine failure; relations that do not apply, or
                      that E answers "not applicable" to, are skipped. Counts per relation go to
                      OUT/metamorphic.json. Off by default: each relation that applies is one more
                      engine run per case
  --max-failures N    stop once N cases have failed
  --resume            continue the run in OUT (--cases may grow); refused when OUT holds another
                      campaign (another --engine, --vs, engine version, --seed, --formats, --cycles, --shard or
                      spec suite)
  --mix-campaigns     with --resume: continue even so (the report then mixes the two)
  --timeout S         per-case timeout for engines in another process (default 10)
  --formats LIST      the cycle formats drawn, comma-separated (default two-block, which keeps the
                      cases of a seed as they were): two-block (G71 U R; G71 P Q U W F), fs10 (the
                      Series 10/11 one block G71 P Q U W D F, --param FCV=1 and 5133 = e; FANUC
                      profiles), hnc (Huazhong G71 U R P Q X Z F, profile hnc, G71 type I, its
                      finishing run of ns…nf after the cycle), haas (G71 P Q U W D1.5 [R1] F, profile
                      haas, 5133 = e, G41/G42 in block ns), gsys-b / gsys-c (the two blocks in G code
                      system B / C: --param 3401#6=1 / 3401#7=1, G90 G95, in C G73/G74 and G72), or all
  --cycles LIST       the cycles drawn, comma-separated (default g71,g72, which keeps the cases of a
                      seed as they were): g71, g72, g73 (pattern repeating: shapes that need not be
                      monotone, d, Δi, Δk, the four quadrants, G70 after it, and one at a time R0,
                      R2.5, no Q or block ns in G02 with the alarm expected; two-block format),
                      lcyc95 (SINUMERIK 802S/C: _CNAME, R105…R112, LCYC95) and cycle95 (802D:
                      CYCLE95(NPP, MID, FALZ, FALX, FAL, FF1, FF2, FF3, VARI, DT, DAM, _VRT)) — a main
                      program and its contour subprogram L1 (lines, quarter and shallow arcs with CR=
                      or I/K, CHF=/CHR=/RND= corners, for cycle95 undercuts), machining types 1…12,
                      and one at a time a type outside 1…12, no infeed depth, the contour against the
                      finishing direction or a half circle with the alarm expected —, g74.1 (or
                      g74_1: GSK's axial trapezoid groove, profile gsk: h and d both ways, ∠a ∠b ∠p,
                      corners r1…r4, Δi Δk e Δv Δu Δw, the tool width I or none, J0/1/2, 182#7 both
                      ways, and one value at a time out of its range with the alarm expected); all
                      (every FANUC family: g71,g72,g73, as before the Siemens cycles, so a seed keeps
                      its cases) and siemens (lcyc95,cycle95); all,siemens,g74.1 for every cycle. With g73 and
                      g71/g72, one case in three (two) is G73; each family is drawn in proportion
                      to the cycles asked of it
  --expectations FILE the engine's known failures (JSON or `ID OUTCOME # reason` lines; README
                      "Expectation files"): entries by failure kind ("kind": "pass-levels",
                      "diverges", "engine-failure", …; `kind:KIND` in text), rule, or case id
                      (fuzz-<case seed>, as `cyclecert baseline` writes them). A case failing as an
                      entry says is an expected failure: counted apart, not shrunk, not kept, and
                      it does not fail the run; a case an entry names that passes now is reported
                      as unexpectedly passing
  --strict            with --expectations: exit 1 on an unexpectedly passing case too
Exit: 0 no failure (or only expected ones), 1 a case failed or the engine failed (not as expected),
or with --strict a case passed unexpectedly, 2 bad usage, an unreadable expectation file, OUT in
use by another run, another campaign in OUT, or a result not written.
)HELP";

const char* kMergeHelp = R"HELP(Usage: cyclecert merge --out DIR [--mix-campaigns] SHARD_DIR...

Joins the results.jsonl of several runs (the shards of one fuzz campaign, or check runs of
different engines) into DIR/results.jsonl, and their run.json records into DIR/run.json. A result
that appears in more than one input (the same engine and case) is kept once; torn lines of killed
runs are skipped and counted. `cyclecert report DIR` then writes the joined report.

The inputs' run.json records must be of one campaign: fuzz runs the shards of one --engine, --vs,
engine version, --seed, --formats, --cycles, shard count, spec suite and (their latest runs) --cases; check runs of one
spec suite (and one version per engine). Otherwise the merge is refused, naming the field that
differs and the inputs, unless --mix-campaigns. DIR is locked as `check` and `fuzz` lock their OUT.

Options:
  --out DIR          where the joined results.jsonl and run.json go
  --mix-campaigns    join runs of different campaigns (the report then mixes them)
Exit: 0 merged, 2 bad usage, an input without results.jsonl, a run.json that cannot be read, runs
of different campaigns, DIR in use by another run, or a result not written.
)HELP";

std::uint64_t randomSeed() {
  std::random_device device;
  return (static_cast<std::uint64_t>(device()) << 32) ^ device();
}

}  // namespace

static int commandFuzz(const std::vector<std::string>& args) {
  std::string engineName, vsName;
  FuzzOptions options;
  options.jobs = defaultJobs();
  options.regressionsDir = defaultRegressionsDir();
  std::optional<std::uint64_t> seed;
  EngineOptions engineOptions;
  bool mixCampaigns = false, strict = false;
  std::optional<Expectations> expectations;
  const auto positional = parseOptions(
      args,
      {{"--engine", [&](const std::string& v) { engineName = v; }},
       {"--expectations", [&](const std::string& v) { expectations = readExpectations(v); }},
       {"--strict", [&] { strict = true; }},
       {"--vs", [&](const std::string& v) { vsName = v; }},
       {"--cases", [&](const std::string& v) { options.cases = static_cast<long>(numberArg("--cases", v, 1, 1e12)); }},
       {"--time", [&](const std::string& v) { options.seconds = numberArg("--time", v, 0.001, 1e7); }},
       {"--seed",
        [&](const std::string& v) {
          try {
            std::size_t used = 0;
            if (v.empty() || v[0] == '-' || v[0] == '+') throw std::invalid_argument(v);  // stoull takes "-1"
            seed = std::stoull(v, &used, 0);
            if (used != v.size()) throw std::invalid_argument(v);
          } catch (const std::exception&) {
            throw UsageError("--seed expects a whole number from 0 to 2^64−1, got '" + v + "'");
          }
        }},
       {"--shard", [&](const std::string& v) { std::tie(options.shard, options.shards) = shardArg(v); }},
       {"--jobs", [&](const std::string& v) { options.jobs = jobsArg(v); }},
       {"--out", [&](const std::string& v) { options.outDir = v; }},
       {"--regressions", [&](const std::string& v) { options.regressionsDir = v; }},
       {"--no-save", [&] { options.regressionsDir.clear(); }},
       {"--shrink-budget",
        [&](const std::string& v) { options.shrinkBudget = static_cast<int>(numberArg("--shrink-budget", v, 0, 1e6)); }},
       {"--tolerance", [&](const std::string& v) { options.tolerance = numberArg("--tolerance", v, 1e-9, 10); }},
       {"--max-failures",
        [&](const std::string& v) { options.maxFailures = static_cast<long>(numberArg("--max-failures", v, 1, 1e12)); }},
       {"--resume", [&] { options.resume = true; }},
       {"--metamorphic", [&] { options.metamorphic = true; }},
       {kMixCampaignsFlag, [&] { mixCampaigns = true; }},
       {"--timeout", [&](const std::string& v) { engineOptions.timeoutSeconds = numberArg("--timeout", v, 0.01, 86400); }},
       {"--formats",
        [&](const std::string& v) {
          try {
            options.formats = parseCycleFormats(v);
          } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--formats: ") + e.what());
          }
        }},
       {"--cycles",
        [&](const std::string& v) {
          try {
            options.cycles = parseFuzzCycles(v);
          } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--cycles: ") + e.what());
          }
        }}},
      "fuzz");
  if (!positional.empty()) throw UsageError("unexpected argument '" + positional.front() + "'");
  if (engineName.empty()) throw UsageError("give --engine (see `cyclecert engines`)");
  if (strict && !expectations) throw UsageError("--strict goes with --expectations FILE");
  if (expectations) options.expectations = &*expectations;
  options.seed = seed ? *seed : randomSeed();
  const auto engine = makeEngine(engineName, engineOptions);
  const auto vs = vsName.empty() ? nullptr : makeEngine(vsName, engineOptions);
  if (mixCampaigns && !options.resume) throw UsageError(std::string(kMixCampaignsFlag) + " goes with --resume");
  std::cerr << "fuzz " << engine->name() << (vs ? " vs " + vs->name() : "") << ": seed " << options.seed;
  if (options.shards > 1) std::cerr << ", shard " << options.shard << "/" << options.shards;
  std::cerr << " (reproduce the run with --seed " << options.seed << ")\n";
  std::vector<std::string> argv{"cyclecert", "fuzz"};
  argv.insert(argv.end(), args.begin(), args.end());
  const RunLock lock(options.outDir, commandLineText(argv));  // held until the report is written
  RunRecord record = startRunRecord("fuzz", *engine, vs.get(), defaultSpecsDir(), options.seed, argv);
  record.cases = options.cases;
  if (options.shards > 1) record.shard = std::to_string(options.shard) + "/" + std::to_string(options.shards);
  if (options.formats != kDefaultCycleFormats) record.formats = cycleFormatsText(options.formats);
  if (options.cycles != kDefaultFuzzCycles) record.cycles = fuzzCyclesText(options.cycles);
  record.metamorphic = options.metamorphic;
  recordRun(options.outDir, record, options.resume, mixCampaigns);
  const FuzzSummary s = runFuzz(namedEngines(engineName, vsName, engineOptions), options, std::cerr);
  std::cout << "fuzz " << engine->name() << (vs ? " vs " + vs->name() : "") << ": " << s.run << " cases in "
            << s.seconds << " s (" << static_cast<long>(s.run / std::max(s.seconds, 1e-9)) << "/s): " << s.pass
            << " pass, " << s.fail << " fail, " << s.notApplicable << " not applicable, " << s.engineFailure
            << " engine failure(s)" << expectationCountsText(s.expectedFailures, s.unexpectedPasses);
  if (s.skipped) std::cout << ", " << s.skipped << " already done";
  std::cout << "; seed " << options.seed << "; results in " << options.outDir << "/results.jsonl\n";
  for (const FuzzFailure& f : s.failures) {
    std::cout << "  " << f.kind << ": seed " << f.caseSeed << (f.regressionFile.empty() ? "" : ", kept as " + f.regressionFile)
              << "\n";
  }
  if (options.metamorphic) {
    writeTallyFile(options.outDir, s.metamorphic, options.resume);
    std::cout << tallyText(s.metamorphic) << "; counts per relation in " << options.outDir << "/metamorphic.json\n";
  }
  writeRunReport(options.outDir, defaultSpecsDir());
  return s.clean() && !(strict && s.unexpectedPasses) ? kExitOk : kExitAlarm;
}

static int commandMerge(const std::vector<std::string>& args) {
  std::string outDir;
  bool mixCampaigns = false;
  const auto inputs = parseOptions(args,
                                   {{"--out", [&](const std::string& v) { outDir = v; }},
                                    {kMixCampaignsFlag, [&] { mixCampaigns = true; }}},
                                   "merge");
  if (outDir.empty()) throw UsageError("give --out DIR (see `cyclecert merge --help`)");
  if (inputs.empty()) throw UsageError("give the run directories to merge (see `cyclecert merge --help`)");
  std::vector<std::string> argv{"cyclecert", "merge"};
  argv.insert(argv.end(), args.begin(), args.end());
  const RunLock lock(outDir, commandLineText(argv));
  std::vector<std::string> merged;
  std::vector<nlohmann::json> runs;
  std::vector<std::vector<SourcedRecord>> campaigns;  // each input's records
  std::set<std::pair<std::string, std::string>> seen;
  std::size_t duplicates = 0, torn = 0;
  for (const std::string& dir : inputs) {
    const std::string file = dir + "/results.jsonl";
    if (!std::filesystem::is_regular_file(file)) throw UsageError("no results in '" + dir + "' (expected " + file + ")");
    campaigns.emplace_back();
    for (nlohmann::json& run : readRunRecords(dir)) {
      campaigns.back().push_back({run, dir + "/run.json"});
      if (std::find(runs.begin(), runs.end(), run) == runs.end()) runs.push_back(std::move(run));  // a dir given twice
    }
    const ResultLines lines = readResultLines(file);
    torn += lines.skipped;
    for (const ResultLines::Line& line : lines.lines) {
      if (seen.insert(line.key).second) merged.push_back(line.text);
      else ++duplicates;
    }
  }
  if (const auto d = mergeDifference(campaigns); d && !mixCampaigns) {
    throw UsageError("cannot merge runs of different campaigns: " + differenceText(*d) +
                     "; merge the shards of one campaign, or give " + kMixCampaignsFlag +
                     " to mix them in one report knowingly");
  }
  ResultsFile out(outDir, false);
  for (const std::string& line : merged) out.appendLine(line);
  writeRunRecords(outDir, runs);
  std::cout << "merged " << inputs.size() << " run(s): " << merged.size() << " results";
  if (duplicates) std::cout << ", " << duplicates << " duplicate(s) dropped";
  if (torn) std::cout << ", " << torn << " torn line(s) skipped";
  std::cout << "; in " << out.path() << "\n";
  return kExitOk;
}

extern const Command kFuzzCommand{"fuzz", kFuzzHelp, commandFuzz};
extern const Command kMergeCommand{"merge", kMergeHelp, commandMerge};

}  // namespace cyclecert::cli
