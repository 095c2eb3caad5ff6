#include "harness/fuzz/fuzz_run.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "harness/fuzz/fuzz_relations.h"
#include "harness/fuzz/regression_case.h"
#include "harness/judge/engine_diff.h"
#include "harness/judge/judging.h"
#include "harness/judge/spec_check.h"
#include "harness/results/failure_plot.h"
#include "harness/run/parallel_run.h"
#include "harness/run/reproduce.h"
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
  // Called three times per case: a stream with its locale cost more than the rest of the tag's uses.
  std::string tag(16, '0');
  for (std::size_t k = tag.size(); k-- > 0 && caseSeed != 0; caseSeed >>= 4) tag[k] = "0123456789abcdef"[caseSeed & 0xF];
  return tag;
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

// One campaign: cases in batches (one engine call each) generated, planned and judged by the
// workers, then recorded in case order — the first failure of each kind shrunk, printed and kept.
// --time: the first chunk of cases an engine is given, to measure how long a case takes it; then
// chunks planned in this share of the time left (the rest for judging them).
constexpr std::size_t kFirstTimedChunk = 1;
constexpr double kTimedChunkShare = 0.8;

class FuzzCampaign {
 public:
  // One worker's engines: worker w uses workers[w].
  struct Worker {
    Engine* engine;
    Engine* vs;
  };

  FuzzCampaign(std::vector<Worker> workers, const FuzzOptions& options, std::ostream& progress)
      : workers_(std::move(workers)), options_(options), progress_(progress), results_(options.outDir, options.resume),
        positions_(shardPositions(options)), batchSize_(batchSize(options, positions_, workers_.size())) {
    if (options.expectations) matcher_.emplace(*options.expectations);
  }

  FuzzSummary run() {
    runInItemOrder<JudgedBatch>(
        static_cast<int>(workers_.size()), [this](int worker, long item) { return judgeBatch(worker, item); },
        [this](int worker, JudgedBatch& batch) { return recordBatch(worker, batch); });
    summary_.seconds = elapsed();
    return summary_;
  }

 private:
  // A case judged by a worker, with its result and its results line made there too (the line is
  // made again when the case is the first failure of its kind, shrunk and drawn when recorded).
  struct JudgedCase {
    std::uint64_t caseSeed;
    SpecCase c;
    FuzzVerdict verdict;
    CaseResult result;
    std::string line;  // resultLine(result), without its newline
    MetamorphicTally tally;  // --metamorphic: the case's follow-ups, counted when it is recorded
  };
  struct JudgedBatch {
    long skipped = 0;  // cases already in the results (--resume)
    std::vector<JudgedCase> cases;
    bool cut = false;  // the time budget ran out before every case was judged
  };

  // Cases per batch: kFuzzBatch; with --max-failures one, so that the run stops at the failure
  // itself; with several workers and few cases, fewer, so that each worker gets a few batches.
  static long batchSize(const FuzzOptions& o, long positions, std::size_t workers) {
    if (o.maxFailures) return 1;
    const long batch = static_cast<long>(kFuzzBatch);
    if (workers <= 1) return batch;
    return std::clamp(positions / (4 * static_cast<long>(workers)), 1L, batch);
  }

  // How many cases of the campaign this shard runs: the i < total with i mod N = K − 1.
  static long shardPositions(const FuzzOptions& o) {
    const long total = o.cases ? *o.cases : o.seconds ? LONG_MAX : kDefaultFuzzCases;
    return total < o.shard ? 0 : (total - o.shard) / o.shards + 1;
  }

  // The shard's cases batchSize_·b … batchSize_·(b + 1) − 1 generated, planned and judged; nothing
  // past the last case or the time budget.
  std::optional<JudgedBatch> judgeBatch(int worker, long b) {
    if (b >= positions_ / batchSize_ + (positions_ % batchSize_ != 0)) return std::nullopt;  // no overflow at LONG_MAX
    if (budgetSpent()) return std::nullopt;
    const Worker& w = workers_[static_cast<std::size_t>(worker)];
    JudgedBatch out;
    std::vector<std::uint64_t> seeds;
    std::vector<SpecCase> batch;
    for (long j = b * batchSize_; j < std::min(positions_, (b + 1) * batchSize_); ++j) {
      const std::uint64_t caseSeed = fuzzCaseSeed(options_.seed, options_.shard - 1 + j * options_.shards);
      if (results_.done().count({w.engine->name(), "fuzz-" + caseSeedTag(caseSeed)})) {
        ++out.skipped;
        continue;
      }
      seeds.push_back(caseSeed);
      batch.push_back(fuzzSpecCase(generateFuzzCase(caseSeed, options_.formats, options_.cycles), caseSeedTag(caseSeed)));
    }
    for (std::size_t k = 0; k < batch.size() && !out.cut;) {
      const std::size_t n = chunkThatFits(worker, batch.size() - k);
      std::vector<EngineResult> planned = planChunk(worker, batch, k, n);
      for (std::size_t i = 0; i < n; ++i, ++k) {
        // The time budget holds within a batch too: cases planned but not judged in time are not
        // recorded (a resumed run runs them).
        if (budgetSpent()) {
          out.cut = true;
          break;
        }
        MetamorphicTally tally;
        FuzzVerdict v = judged(std::move(planned[i]), *w.engine, w.vs, batch[k], options_, &tally);
        CaseResult r = resultOf(w, seeds[k], batch[k], v);
        std::string line = resultLine(r);
        line.pop_back();
        out.cases.push_back({seeds[k], std::move(batch[k]), std::move(v), std::move(r), std::move(line), std::move(tally)});
      }
    }
    return out;
  }

  bool budgetSpent() const { return options_.seconds && elapsed() >= *options_.seconds; }

  // --time bounds a batch too. An engine that plans a batch in one go (LinuxCNC: one rs274 per
  // batch) or case after case (a process engine) is given it in chunks that fit in the time left,
  // by the seconds a case has taken this worker so far; the first chunk is small, to measure.
  // Without --time, the whole batch.
  std::size_t chunkThatFits(int worker, std::size_t rest) const {
    if (!options_.seconds) return rest;
    const double perCase = secondsPerCase_[static_cast<std::size_t>(worker)];
    if (perCase <= 0) return std::min(rest, kFirstTimedChunk);
    const double left = kTimedChunkShare * (*options_.seconds - elapsed());
    return std::clamp(static_cast<std::size_t>(std::max(left, 0.0) / perCase), std::size_t{1}, rest);
  }

  // Cases k … k + n − 1 of the batch planned by the worker's engine (moved out for the call and
  // back), and the seconds per case measured.
  std::vector<EngineResult> planChunk(int worker, std::vector<SpecCase>& batch, std::size_t k, std::size_t n) {
    Engine& engine = *workers_[static_cast<std::size_t>(worker)].engine;
    const auto start = std::chrono::steady_clock::now();
    std::vector<EngineResult> planned;
    if (k == 0 && n == batch.size()) {
      planned = engine.runBatch(batch);
    } else {
      std::vector<SpecCase> chunk(std::make_move_iterator(batch.begin() + static_cast<std::ptrdiff_t>(k)),
                                  std::make_move_iterator(batch.begin() + static_cast<std::ptrdiff_t>(k + n)));
      planned = engine.runBatch(chunk);
      std::move(chunk.begin(), chunk.end(), batch.begin() + static_cast<std::ptrdiff_t>(k));
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (n > 0) secondsPerCase_[static_cast<std::size_t>(worker)] = seconds / static_cast<double>(n);
    return planned;
  }

  // The case's result as judged (a failure with the command that reproduces it).
  CaseResult resultOf(const Worker& w, std::uint64_t caseSeed, const SpecCase& c, const FuzzVerdict& v) const {
    const std::string engineName = w.engine->name(), vsName = w.vs ? w.vs->name() : "";
    CaseResult r{engineName, "fuzz-" + caseSeedTag(caseSeed), "", c.rules, v.verdict, v.detail, v.findings, v.seconds,
                 caseSeed, "", vsName, std::nullopt, ""};
    if (v.verdict == "fail" || v.verdict == "engine-failure") r.reproduce = reproduceCommand(engineName, vsName, caseSeed, options_);
    return r;
  }

  // The batch's cases recorded in order; false once the run is to stop: the batch was cut by the
  // time budget (the batches after it are not recorded, so the results stay the campaign's first
  // cases), or --max-failures is reached.
  bool recordBatch(int worker, JudgedBatch& batch) {
    summary_.skipped += batch.skipped;
    for (JudgedCase& j : batch.cases) {
      record(workers_[static_cast<std::size_t>(worker)], j);
      if (options_.maxFailures && summary_.fail + summary_.engineFailure >= *options_.maxFailures) return false;
    }
    return !batch.cut;
  }

  void record(const Worker& w, JudgedCase& j) {
    const FuzzVerdict& v = j.verdict;
    summary_.metamorphic.add(j.tally);
    // The expectations are matched here, on the one thread that records (the matcher counts uses).
    CaseResult& r = j.result;
    const ExpectationStatus expected = matcher_ ? matcher_->apply(r, v.kind) : ExpectationStatus::None;
    const bool known = expected == ExpectationStatus::Expected && v.verdict != "not-applicable";  // an expected failure
    if (matcher_) {
      j.line = resultLine(r);  // with its expectation
      j.line.pop_back();
    }
    ++summary_.run;
    if (expected == ExpectationStatus::UnexpectedPass) {
      ++summary_.unexpectedPasses;
      progress_ << unexpectedPassText(r) << "\n";
    }
    if (known) ++summary_.expectedFailures;
    else if (v.verdict == "pass") ++summary_.pass;
    else if (v.verdict == "not-applicable") ++summary_.notApplicable;
    else (v.verdict == "fail" ? summary_.fail : summary_.engineFailure)++;
    if ((v.verdict == "fail" || v.verdict == "engine-failure") && !known && shrunkKinds_.insert(v.kind).second) {
      keepFailure(w, j.caseSeed, j.c, v, j.result);
      j.line = resultLine(j.result);
      j.line.pop_back();
    }
    results_.appendLine(j.line);  // a killed run keeps every result written so far
    reportProgress();
  }

  void keepFailure(const Worker& w, std::uint64_t caseSeed, const SpecCase& c, const FuzzVerdict& v, CaseResult& r) {
    FuzzFailure f = shrinkFailure(*w.engine, w.vs, caseSeed, v, options_);
    const std::string& reproduce = r.reproduce;
    if (!options_.regressionsDir.empty()) {
      // The rules behind the failure: the oracle's on the shrunk case, else the case's.
      const std::vector<std::string>& rules = f.rules.empty() ? c.rules : f.rules;
      f.regressionFile = writeRegressionCase(options_.regressionsDir, f, w.engine->name(), w.vs ? w.vs->name() : "", rules,
                                             reproduce);
    }
    r.program = fuzzProgram(f.shrunk);
    r.file = f.regressionFile;
    r.detail = v.detail + " | shrunk in " + std::to_string(f.shrinkRuns) + " runs: " + f.detail;
    drawShrunk(w, f, r);
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
  void drawShrunk(const Worker& w, const FuzzFailure& f, CaseResult& r) {
    const SpecCase shrunk = fuzzSpecCase(f.shrunk, caseSeedTag(f.caseSeed));
    const EngineResult mine = w.engine->run(shrunk);
    const FuzzVerdict v = judged(mine, *w.engine, nullptr, shrunk, options_, nullptr);
    std::optional<PlotComparison> theirs;
    if (w.vs) {
      const EngineResult other = w.vs->run(shrunk);
      if (hasOutcome(other)) {
        const auto d = compareEngineResults(mine, w.engine->name(), other, w.vs->name(), options_.tolerance);
        theirs = PlotComparison{w.vs->name(), other.path, d ? d->move : std::nullopt};
      }
    }
    r.findings = v.findings;
    if (v.violation) {
      if (const auto plot = metamorphicPlot(*v.violation, w.engine->name(), options_.tolerance)) r.plot = plotToJson(*plot);
    } else if (const auto plot = failurePlot(shrunk, mine, w.engine->name(), v.findings, options_.tolerance, theirs)) {
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

  const std::vector<Worker> workers_;
  const FuzzOptions& options_;
  std::ostream& progress_;
  ResultsFile results_;  // read by the workers (done()), written by the one recording
  const long positions_, batchSize_;
  // --time: the seconds a case took each worker's engine in its last chunk (each worker writes its own).
  std::vector<double> secondsPerCase_ = std::vector<double>(workers_.size(), 0.0);
  FuzzSummary summary_;
  std::optional<ExpectationMatcher> matcher_;  // --expectations
  std::set<std::string> shrunkKinds_;  // each kind of failure is shrunk (and kept) once per run
  const std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point lastReport_ = started_;
};

}  // namespace

FuzzSummary runFuzz(const EnginesMaker& makeEngines, const FuzzOptions& options, std::ostream& progress) {
  std::vector<WorkerEngines> owned;
  std::vector<FuzzCampaign::Worker> workers;
  for (int w = 0; w < std::max(options.jobs, 1); ++w) {
    owned.push_back(makeEngines());
    workers.push_back({owned.back().engine.get(), owned.back().vs.get()});
  }
  return FuzzCampaign(std::move(workers), options, progress).run();
}

FuzzSummary runFuzz(Engine& engine, Engine* vs, const FuzzOptions& options, std::ostream& progress) {
  return FuzzCampaign({{&engine, vs}}, options, progress).run();
}

}  // namespace cyclecert
