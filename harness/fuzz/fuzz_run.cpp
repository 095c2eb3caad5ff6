#include "harness/fuzz/fuzz_run.h"

#include <chrono>
#include <climits>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "harness/engine_diff.h"
#include "harness/failure_plot.h"
#include "harness/fuzz/fuzz_relations.h"
#include "harness/fuzz/regression_case.h"
#include "harness/judging.h"
#include "harness/reproduce.h"
#include "harness/spec_check.h"
#include "reference/model/alarms.h"
#include "reports/svg/plot_json.h"

namespace cyclecert {

std::uint64_t fuzzCaseSeed(std::uint64_t runSeed, long index) {
  return runSeed + static_cast<std::uint64_t>(index) * 0x9E3779B97F4A7C15ull;
}

namespace {

// RapidCheck's size (0…100) comes from the seed too, so a case seed alone regenerates the case.
rc::Shrinkable<FuzzCase> shrinkTree(std::uint64_t caseSeed, const CycleFormats& formats, const FuzzCycles& cycles) {
  return genFuzzCase(formats, cycles)(rc::Random(caseSeed), static_cast<int>(caseSeed % 101));
}

// fuzzReproduceCommand's, with the run's --formats and --cycles when they are not the defaults.
std::string reproduceCommand(const std::string& engine, const std::string& vs, std::uint64_t caseSeed,
                             const FuzzOptions& options) {
  std::string command = fuzzReproduceCommand(engine, vs, caseSeed);
  if (options.formats != kDefaultCycleFormats) command += " --formats " + cycleFormatsText(options.formats);
  if (options.cycles != kDefaultFuzzCycles) command += " --cycles " + fuzzCyclesText(options.cycles);
  if (options.metamorphic) command += " --metamorphic";
  return command;
}

// A result judged as the run judges it: by the oracles (and `vs`), and with --metamorphic by the
// relations too, counted in `tally` when it is given.
FuzzVerdict judged(EngineResult r, Engine& engine, Engine* vs, const SpecCase& c, const FuzzOptions& options,
                   MetamorphicTally* tally) {
  if (!options.metamorphic) return judgeFuzzResult(std::move(r), engine, vs, c, options.tolerance);
  return judgeFuzzResultWithRelations(std::move(r), engine, vs, c, options.tolerance, tally);
}

}  // namespace

std::string caseSeedTag(std::uint64_t caseSeed) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << caseSeed;
  return s.str();
}

FuzzCase generateFuzzCase(std::uint64_t caseSeed, const CycleFormats& formats, const FuzzCycles& cycles) {
  return shrinkTree(caseSeed, formats, cycles).value();
}

FuzzVerdict judgeFuzzCase(Engine& engine, Engine* vs, const SpecCase& c, double tolerance) {
  return judgeFuzzResult(engine.run(c), engine, vs, c, tolerance);
}

FuzzVerdict judgeFuzzResult(EngineResult r, const Engine& engine, Engine* vs, const SpecCase& c, double tolerance) {
  FuzzVerdict v;
  v.seconds = r.seconds;
  if (r.kind == EngineResult::Failed || r.kind == EngineResult::NotApplicable) {
    v.verdict = kindName(r.kind);  // "engine-failure", "not-applicable"
    if (r.kind == EngineResult::Failed) v.kind = v.verdict;
    v.detail = r.detail;
    return v;
  }
  if (c.expectedAlarm) {  // a case with one invalid parameter (G73): the alarm its rule names
    if (const auto unmet = unmetExpectation(c, r.path, false)) {
      v.verdict = "fail";
      v.kind = "expected-alarm";
      v.detail = "expected-alarm: " + *unmet;
      return v;
    }
  }
  std::optional<std::string> refused;  // why the oracles do not judge the case
  JudgeInput input;
  bool pathMoved = false;
  try {
    JudgeRequest request = judgeRequestFor(c);
    request.settings.epsilon = tolerance;
    // The program read first, the path moved in after: a refusal keeps it for the comparison with `vs`.
    input = judgeInputFor(request, Toolpath{});
    input.path = std::move(r.path);
    pathMoved = true;
    v.findings = judge(input);
    r.path = std::move(input.path);  // for the comparison with `vs` below
  } catch (const NotSupported& e) {
    if (pathMoved) r.path = std::move(input.path);
    refused = std::string("the oracles cannot judge this case: ") + e.what();
    if (!vs) {
      v.verdict = c.expectedAlarm ? "pass" : "not-applicable";
      if (!c.expectedAlarm) v.detail = *refused;
      return v;
    }
  } catch (const std::exception& e) {
    // A generated program the oracles cannot read is the generator's fault, not the engine's.
    v.verdict = "not-applicable";
    v.detail = std::string("the oracles cannot judge this case: ") + e.what();
    return v;
  }
  if (!v.findings.empty()) {
    v.verdict = "fail";
    v.kind = v.findings.front().oracle;
    v.detail = v.findings.front().oracle + ": " + v.findings.front().message;
    return v;
  }
  if (vs) {
    const EngineResult theirs = vs->run(c);
    if (auto d = compareEngineResults(r, engine.name(), theirs, vs->name(), tolerance)) {
      v.verdict = "fail";
      v.kind = "diverges";
      v.detail = d->text;
      return v;
    }
  }
  if (refused && !c.expectedAlarm) {
    v.verdict = "not-applicable";
    v.detail = *refused + (vs ? " (it agrees with " + vs->name() + ")" : "");
    return v;
  }
  v.verdict = "pass";
  return v;
}

namespace {

// Walks RapidCheck's shrink tree: the first smaller case that still fails the same way becomes the
// current one, until no smaller case does or the budget is spent.
FuzzFailure shrinkFailure(Engine& engine, Engine* vs, std::uint64_t caseSeed, const FuzzVerdict& first,
                          const FuzzOptions& options) {
  FuzzFailure f;
  f.caseSeed = caseSeed;
  f.kind = first.kind;
  f.detail = first.detail;
  const auto rulesOf = [](const FuzzVerdict& v) {
    return v.findings.empty() ? std::vector<std::string>{} : v.findings.front().rules;
  };
  f.rules = rulesOf(first);
  rc::Shrinkable<FuzzCase> current = shrinkTree(caseSeed, options.formats, options.cycles);
  bool smaller = true;
  while (smaller && f.shrinkRuns < options.shrinkBudget) {
    smaller = false;
    auto candidates = current.shrinks();
    while (auto candidate = candidates.next()) {
      if (f.shrinkRuns++ >= options.shrinkBudget) break;
      const SpecCase c = fuzzSpecCase(candidate->value(), caseSeedTag(caseSeed));
      const FuzzVerdict v = judged(engine.run(c), engine, vs, c, options, nullptr);
      if (v.verdict == first.verdict && v.kind == first.kind) {
        current = *candidate;
        f.detail = v.detail;
        f.rules = rulesOf(v);
        smaller = true;
        break;
      }
    }
  }
  f.shrunk = current.value();
  return f;
}

// One campaign: cases in batches (one engine call each), each judged, recorded and — the first
// failure of each kind — shrunk, printed and kept.
class FuzzCampaign {
 public:
  FuzzCampaign(Engine& engine, Engine* vs, const FuzzOptions& options, std::ostream& progress)
      : engine_(engine), vs_(vs), options_(options), progress_(progress), results_(options.outDir, options.resume) {}

  FuzzSummary run() {
    const long total = options_.cases ? *options_.cases : options_.seconds ? LONG_MAX : kDefaultFuzzCases;
    for (long next = options_.shard - 1; next < total;) {
      if (options_.seconds && elapsed() >= *options_.seconds) break;
      if (options_.maxFailures && summary_.fail + summary_.engineFailure >= *options_.maxFailures) break;
      std::vector<std::uint64_t> seeds;
      std::vector<SpecCase> batch;
      // With --max-failures one case at a time, so that the run stops at the failure itself.
      const std::size_t batchSize = options_.maxFailures ? 1 : kFuzzBatch;
      for (; next < total && batch.size() < batchSize; next += options_.shards) {
        const std::uint64_t caseSeed = fuzzCaseSeed(options_.seed, next);
        if (results_.done().count({engine_.name(), "fuzz-" + caseSeedTag(caseSeed)})) {
          ++summary_.skipped;
          continue;
        }
        seeds.push_back(caseSeed);
        batch.push_back(fuzzSpecCase(generateFuzzCase(caseSeed, options_.formats, options_.cycles), caseSeedTag(caseSeed)));
      }
      std::vector<EngineResult> planned = engine_.runBatch(batch);
      for (std::size_t k = 0; k < batch.size(); ++k) {
        // The time budget holds within a batch too: cases planned but not judged are not recorded
        // (a resumed run runs them).
        if (options_.seconds && elapsed() >= *options_.seconds) break;
        record(seeds[k], batch[k], std::move(planned[k]));
      }
    }
    summary_.seconds = elapsed();
    return summary_;
  }

 private:
  void record(std::uint64_t caseSeed, const SpecCase& c, EngineResult planned) {
    const FuzzVerdict v = judged(std::move(planned), engine_, vs_, c, options_, &summary_.metamorphic);
    CaseResult r{engine_.name(), "fuzz-" + caseSeedTag(caseSeed), "", c.rules, v.verdict, v.detail, v.findings, v.seconds,
                 caseSeed, "", vs_ ? vs_->name() : "", std::nullopt, ""};
    ++summary_.run;
    if (v.verdict == "pass") ++summary_.pass;
    else if (v.verdict == "not-applicable") ++summary_.notApplicable;
    else (v.verdict == "fail" ? summary_.fail : summary_.engineFailure)++;
    if (v.verdict == "fail" || v.verdict == "engine-failure") {
      r.reproduce = reproduceCommand(engine_.name(), vs_ ? vs_->name() : "", caseSeed, options_);
      if (shrunkKinds_.insert(v.kind).second) keepFailure(caseSeed, c, v, r);
    }
    results_.append(r);  // a killed run keeps every result written so far
    reportProgress();
  }

  void keepFailure(std::uint64_t caseSeed, const SpecCase& c, const FuzzVerdict& v, CaseResult& r) {
    FuzzFailure f = shrinkFailure(engine_, vs_, caseSeed, v, options_);
    const std::string& reproduce = r.reproduce;
    if (!options_.regressionsDir.empty()) {
      // The rules behind the failure: the oracle's on the shrunk case, else the case's.
      const std::vector<std::string>& rules = f.rules.empty() ? c.rules : f.rules;
      f.regressionFile = writeRegressionCase(options_.regressionsDir, f, engine_.name(), vs_ ? vs_->name() : "", rules,
                                             reproduce);
    }
    r.program = fuzzProgram(f.shrunk);
    r.file = f.regressionFile;
    r.detail = v.detail + " | shrunk in " + std::to_string(f.shrinkRuns) + " runs: " + f.detail;
    drawShrunk(f, r);
    progress_ << "FAIL " << v.kind << " (seed " << caseSeed << "): " << f.detail << "\n  shrunk case ("
              << describeFuzzCase(f.shrunk) << "):\n";
    std::istringstream lines(r.program);
    for (std::string line; std::getline(lines, line);) progress_ << "    " << line << "\n";
    progress_ << "  reproduce: " << reproduce << "\n";
    if (!f.regressionFile.empty()) progress_ << "  kept as " << f.regressionFile << "\n";
    summary_.failures.push_back(std::move(f));
  }

  // The shrunk case run again (engines are deterministic), judged, and drawn — with --vs, the other
  // engine's toolpath over it. The result then shows the shrunk case throughout: its program, its
  // findings and its plot (the detail keeps the first finding of the case as generated).
  void drawShrunk(const FuzzFailure& f, CaseResult& r) {
    const SpecCase shrunk = fuzzSpecCase(f.shrunk, caseSeedTag(f.caseSeed));
    const EngineResult mine = engine_.run(shrunk);
    const FuzzVerdict v = judged(mine, engine_, nullptr, shrunk, options_, nullptr);
    std::optional<PlotComparison> theirs;
    if (vs_) {
      const EngineResult other = vs_->run(shrunk);
      if (other.kind == EngineResult::Planned || other.kind == EngineResult::Alarmed) {
        const auto d = compareEngineResults(mine, engine_.name(), other, vs_->name(), options_.tolerance);
        theirs = PlotComparison{vs_->name(), other.path, d ? d->move : std::nullopt};
      }
    }
    r.findings = v.findings;
    if (v.violation) {
      if (const auto plot = metamorphicPlot(*v.violation, engine_.name(), options_.tolerance)) r.plot = plotToJson(*plot);
    } else if (const auto plot = failurePlot(shrunk, mine, engine_.name(), v.findings, options_.tolerance, theirs)) {
      r.plot = plotToJson(*plot);
    }
  }

  void reportProgress() {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastReport_ <= std::chrono::seconds(2)) return;
    const double t = elapsed();
    progress_ << "  " << summary_.run << " cases in " << std::fixed << std::setprecision(1) << t << " s ("
              << std::setprecision(0) << summary_.run / t << "/s), " << summary_.fail + summary_.engineFailure
              << " failing\n"
              << std::defaultfloat;
    lastReport_ = now;
  }

  double elapsed() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count(); }

  Engine& engine_;
  Engine* vs_;
  const FuzzOptions& options_;
  std::ostream& progress_;
  ResultsFile results_;
  FuzzSummary summary_;
  std::set<std::string> shrunkKinds_;  // each kind of failure is shrunk (and kept) once per run
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastReport_ = started_;
};

}  // namespace

FuzzSummary runFuzz(Engine& engine, Engine* vs, const FuzzOptions& options, std::ostream& progress) {
  return FuzzCampaign(engine, vs, options, progress).run();
}

}  // namespace cyclecert
