#include "harness/fuzz/fuzz_run.h"

#include <chrono>
#include <climits>
#include <iomanip>
#include <ostream>
#include <set>
#include <sstream>

#include "harness/engine_diff.h"
#include "harness/fuzz/regression_case.h"
#include "harness/judging.h"

namespace cyclecert {

std::uint64_t fuzzCaseSeed(std::uint64_t runSeed, long index) {
  return runSeed + static_cast<std::uint64_t>(index) * 0x9E3779B97F4A7C15ull;
}

namespace {

// RapidCheck's size (0…100) comes from the seed too, so a case seed alone regenerates the case.
rc::Shrinkable<FuzzCase> shrinkTree(std::uint64_t caseSeed) {
  return genFuzzCase()(rc::Random(caseSeed), static_cast<int>(caseSeed % 101));
}

std::string hex(std::uint64_t v) {
  std::ostringstream s;
  s << std::hex << std::setw(16) << std::setfill('0') << v;
  return s.str();
}

}  // namespace

FuzzCase generateFuzzCase(std::uint64_t caseSeed) { return shrinkTree(caseSeed).value(); }

FuzzVerdict judgeFuzzCase(Engine& engine, Engine* vs, const SpecCase& c, double tolerance) {
  FuzzVerdict v;
  const EngineResult r = engine.run(c);
  v.seconds = r.seconds;
  if (r.kind == EngineResult::Failed) {
    v.verdict = v.kind = "engine-failure";
    v.detail = r.detail;
    return v;
  }
  if (r.kind == EngineResult::NotApplicable) {
    v.verdict = "not-applicable";
    v.detail = r.detail;
    return v;
  }
  try {
    JudgeRequest request = judgeRequestFor(c);
    request.settings.epsilon = tolerance;
    v.findings = judge(judgeInputFor(request, r.path));
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
  rc::Shrinkable<FuzzCase> current = shrinkTree(caseSeed);
  bool smaller = true;
  while (smaller && f.shrinkRuns < options.shrinkBudget) {
    smaller = false;
    auto candidates = current.shrinks();
    while (auto candidate = candidates.next()) {
      if (f.shrinkRuns++ >= options.shrinkBudget) break;
      const FuzzVerdict v = judgeFuzzCase(engine, vs, fuzzSpecCase(candidate->value(), hex(caseSeed)), options.tolerance);
      if (v.verdict == first.verdict && v.kind == first.kind) {
        current = *candidate;
        f.detail = v.detail;
        smaller = true;
        break;
      }
    }
  }
  f.shrunk = current.value();
  return f;
}

std::string reproduceCommand(const Engine& engine, const Engine* vs, std::uint64_t caseSeed) {
  std::ostringstream s;
  s << "cyclecert fuzz --engine '" << engine.name() << "'" << (vs ? " --vs '" + vs->name() + "'" : "") << " --seed "
    << caseSeed << " --cases 1";
  return s.str();
}

}  // namespace

FuzzSummary runFuzz(Engine& engine, Engine* vs, const FuzzOptions& options, std::ostream& progress) {
  ResultsFile results(options.outDir, options.resume);
  FuzzSummary s;
  const long total = options.cases ? *options.cases : options.seconds ? LONG_MAX : kDefaultFuzzCases;
  const auto started = std::chrono::steady_clock::now();
  auto lastReport = started;
  const auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count(); };
  std::set<std::string> shrunkKinds;  // each kind of failure is shrunk (and kept) once per run
  for (long i = options.shard - 1; i < total; i += options.shards) {
    if (options.seconds && elapsed() >= *options.seconds) break;
    if (options.maxFailures && s.fail + s.engineFailure >= *options.maxFailures) break;
    const std::uint64_t caseSeed = fuzzCaseSeed(options.seed, i);
    const std::string id = "fuzz-" + hex(caseSeed);
    if (results.done().count({engine.name(), id})) {
      ++s.skipped;
      continue;
    }
    const SpecCase c = fuzzSpecCase(generateFuzzCase(caseSeed), hex(caseSeed));
    const FuzzVerdict v = judgeFuzzCase(engine, vs, c, options.tolerance);
    CaseResult r{engine.name(), id, "", c.rules, v.verdict, v.detail, v.findings, v.seconds, caseSeed, "", vs ? vs->name() : ""};
    ++s.run;
    if (v.verdict == "pass") ++s.pass;
    else if (v.verdict == "not-applicable") ++s.notApplicable;
    else (v.verdict == "fail" ? s.fail : s.engineFailure)++;
    if ((v.verdict == "fail" || v.verdict == "engine-failure") && shrunkKinds.insert(v.kind).second) {
      FuzzFailure f = shrinkFailure(engine, vs, caseSeed, v, options);
      const SpecCase shrunk = fuzzSpecCase(f.shrunk, hex(caseSeed));
      if (!options.regressionsDir.empty()) {
        // The rules behind the failure: the oracle's, recomputed on the shrunk case.
        const FuzzVerdict again = judgeFuzzCase(engine, vs, shrunk, options.tolerance);
        std::vector<std::string> rules = again.findings.empty() ? c.rules : again.findings.front().rules;
        f.regressionFile = writeRegressionCase(options.regressionsDir, f, engine.name(), vs ? vs->name() : "", rules,
                                               reproduceCommand(engine, vs, caseSeed));
      }
      r.program = shrunk.program;
      r.file = f.regressionFile;
      r.detail = v.detail + " | shrunk in " + std::to_string(f.shrinkRuns) + " runs: " + f.detail;
      progress << "FAIL " << v.kind << " (seed " << caseSeed << "): " << f.detail << "\n  shrunk case ("
               << describeFuzzCase(f.shrunk) << "):\n";
      std::istringstream lines(shrunk.program);
      for (std::string line; std::getline(lines, line);) progress << "    " << line << "\n";
      progress << "  reproduce: " << reproduceCommand(engine, vs, caseSeed) << "\n";
      if (!f.regressionFile.empty()) progress << "  kept as " << f.regressionFile << "\n";
      s.failures.push_back(std::move(f));
    }
    results.append(r);
    const auto now = std::chrono::steady_clock::now();
    if (now - lastReport > std::chrono::seconds(2)) {
      const double t = elapsed();
      progress << "  " << s.run << " cases in " << std::fixed << std::setprecision(1) << t << " s ("
               << std::setprecision(0) << s.run / t << "/s), " << s.fail + s.engineFailure << " failing\n"
               << std::defaultfloat;
      lastReport = now;
    }
  }
  s.seconds = elapsed();
  return s;
}

}  // namespace cyclecert
