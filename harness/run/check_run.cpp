#include "harness/run/check_run.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <ostream>

#include "harness/judge/engine_diff.h"
#include "harness/judge/judging.h"
#include "harness/judge/spec_check.h"
#include "harness/judge/toolpath_compare.h"
#include "harness/results/failure_plot.h"
#include "harness/run/parallel_run.h"
#include "harness/run/reproduce.h"
#include "reports/svg/plot_json.h"

namespace cyclecert {

namespace {

// The engine's result against the case's expectation; nothing when it is met.
std::optional<std::string> unmet(const SpecCase& c, const EngineResult& r, const std::string& engineName) {
  // Warnings are judged for the in-process engines, which share the reference's annotations.
  const bool inProcess = engineName == "reference" || engineName.rfind("mutant:", 0) == 0;
  if (r.kind == EngineResult::Alarmed || r.kind == EngineResult::Planned) return unmetExpectation(c, r.path, inProcess);
  return std::string("no result");
}

// A case that must agree with a built-in engine: that engine runs the case now.
struct AgreementCheck {
  std::optional<std::string> disagreement;
  std::optional<PlotComparison> theirs;  // the other engine's toolpath, for the plot
};

AgreementCheck checkAgreement(const SpecCase& c, const EngineResult& r, const std::string& engineName) {
  AgreementCheck out;
  try {
    const auto other = makeEngine(*c.agreesWith);
    const EngineResult theirs = other->run(c);
    if (theirs.kind == EngineResult::Failed || theirs.kind == EngineResult::NotApplicable) {
      out.disagreement = "cannot compare with " + *c.agreesWith + ": " + kindName(theirs.kind) + ": " + theirs.detail;
      return out;
    }
    const auto d = compareEngineResults(theirs, *c.agreesWith, r, engineName, c.tolerance);
    if (d) out.disagreement = d->text;
    out.theirs = PlotComparison{*c.agreesWith, theirs.path, d ? d->move : std::nullopt};
  } catch (const std::exception& e) {
    out.disagreement = "cannot compare with " + *c.agreesWith + ": " + e.what();
  }
  return out;
}

// What the failure's plot draws over the engine's path: the expected toolpath, else the toolpath
// of the engine the case must agree with.
std::optional<PlotComparison> comparisonFor(const SpecCase& c, const EngineResult& r,
                                            const std::optional<PlotComparison>& agreement) {
  if (!c.expectedMoves) return agreement;
  PlotComparison expected{"expected", {}, std::nullopt};
  expected.path.start = r.path.start;
  expected.path.moves = *c.expectedMoves;
  if (const auto d = firstMoveDivergence(*c.expectedMoves, r.path.moves, c.tolerance)) expected.divergence = d->move;
  return expected;
}

// An expected toolpath not met, as a finding naming the rules the diverging move follows: the
// rules the reference annotates its move with there (its path is the expected one: it passes every
// spec case) — a wrong retract fails the retract rule, not the format rule the case is about.
// Nothing when the reference names none — then the failure stands against every rule the case
// cites.
std::optional<Finding> expectationFinding(const SpecCase& c, const EngineResult& r, const std::string& why) {
  if (!c.expectedMoves) return std::nullopt;
  const auto d = firstMoveDivergence(*c.expectedMoves, r.path.moves, c.tolerance);
  if (!d) return std::nullopt;
  std::vector<std::string> rules;
  try {
    const EngineResult reference = makeEngine("reference")->run(c);
    if (d->move >= reference.path.moves.size()) return std::nullopt;
    for (const std::string& rule : reference.path.moves[d->move].rules) {
      if (std::find(rules.begin(), rules.end(), rule) == rules.end()) rules.push_back(rule);
    }
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (rules.empty()) return std::nullopt;
  Finding f;
  f.oracle = "expectation";
  f.rules = rules;
  f.move = d->move;
  f.message = why;
  if (d->move < r.path.moves.size()) f.witness.segment = r.path.segment(d->move);
  return f;
}

}  // namespace

CaseResult checkCase(Engine& engine, const SpecCase& c, MetamorphicTally* relations) {
  CaseResult out;
  out.engine = engine.name();
  out.caseId = c.id;
  out.file = c.file;
  out.rules = c.rules;
  const std::string reproduce = caseReproduceCommand(engine.name(), c.file, c.agreesWith.value_or(""));
  const EngineResult r = engine.run(c);
  out.seconds = r.seconds;
  if (r.kind == EngineResult::Failed || r.kind == EngineResult::NotApplicable) {
    out.verdict = kindName(r.kind);  // "engine-failure", "not-applicable"
    out.detail = r.detail;
    if (r.kind == EngineResult::Failed) out.reproduce = reproduce;
    return out;
  }
  if (const auto why = unmet(c, r, engine.name())) {
    out.verdict = "fail";
    out.detail = *why;
    if (auto f = expectationFinding(c, r, *why)) out.findings.push_back(std::move(*f));
  }
  AgreementCheck agreement;
  if (c.agreesWith) {
    agreement = checkAgreement(c, r, engine.name());
    if (agreement.disagreement) {
      out.verdict = "fail";
      out.detail = *agreement.disagreement;
    }
  }
  // A planned toolpath is judged by every oracle; an alarm too when the case expects nothing in
  // particular (the alarm oracle says whether the rules call for it).
  if (r.kind == EngineResult::Planned || (r.kind == EngineResult::Alarmed && c.oraclesOnly)) {
    try {
      Toolpath path = r.path;
      const JudgeInput in = judgeInputFor(judgeRequestFor(c), std::move(path));
      for (Finding& f : judge(in)) out.findings.push_back(std::move(f));
    } catch (const std::exception& e) {
      out.detail += (out.detail.empty() ? "" : "; ") + std::string("the oracles could not judge it: ") + e.what();
    }
    if (!out.findings.empty()) {
      out.verdict = "fail";
      if (out.detail.empty()) out.detail = out.findings.front().oracle + ": " + out.findings.front().message;
    }
  }
  std::optional<MetamorphicViolation> violation;
  if (relations) violation = addRelationVerdicts(engine, c, r, out, *relations);
  if (out.verdict.empty()) {
    out.verdict = "pass";
    return out;
  }
  out.reproduce = relations ? metamorphicReproduceCommand(engine.name(), c.file, c.agreesWith.value_or(""))
                            : reproduce;
  if (violation && out.findings.front().oracle == metamorphicKind(violation->relation)) {
    if (const auto plot = metamorphicPlot(*violation, engine.name(), c.tolerance)) out.plot = plotToJson(*plot);
  } else if (const auto plot =
                 failurePlot(c, r, engine.name(), out.findings, c.tolerance, comparisonFor(c, r, agreement.theirs))) {
    out.plot = plotToJson(*plot);
  }
  return out;
}

namespace {

// One case of the run, checked by a worker, with its results line (made there too); no result when
// the results already hold it (--resume).
struct CheckedCase {
  std::string id;
  std::optional<CaseResult> result;
  std::string line;  // resultLine(*result), without its newline
  MetamorphicTally relations;  // --metamorphic: the case's follow-ups, counted when it is recorded
};

// The cases of the shard (every N-th case of the list, from the K-th) checked on the workers and
// recorded in list order.
CheckSummary checkOnWorkers(const std::vector<Engine*>& engines, const CheckOptions& options, std::ostream& progress) {
  ResultsFile results(options.outDir, options.resume);
  const auto& done = results.done();
  CheckSummary s;
  auto all = findSpecCaseFiles(options.specsDir + "/cases");
  if (!options.regressionsDir.empty() && std::filesystem::is_directory(options.regressionsDir)) {
    for (auto& f : findSpecCaseFiles(options.regressionsDir)) all.push_back(std::move(f));
  }
  std::optional<ExpectationMatcher> matcher;
  if (options.expectations) matcher.emplace(*options.expectations);
  std::vector<std::string> files;
  for (std::size_t i = static_cast<std::size_t>(options.shard - 1); i < all.size(); i += static_cast<std::size_t>(options.shards)) {
    files.push_back(std::move(all[i]));
  }
  const auto check = [&](int worker, long item) -> std::optional<CheckedCase> {
    if (item >= static_cast<long>(files.size())) return std::nullopt;
    Engine& engine = *engines[static_cast<std::size_t>(worker)];
    const SpecCase c = loadSpecCase(files[static_cast<std::size_t>(item)]);
    if (done.count({engine.name(), c.id})) return CheckedCase{c.id, std::nullopt, "", {}};
    MetamorphicTally relations;
    CaseResult r = checkCase(engine, c, options.metamorphic ? &relations : nullptr);
    std::string line = resultLine(r);
    line.pop_back();
    return CheckedCase{c.id, std::move(r), std::move(line), std::move(relations)};
  };
  const auto started = std::chrono::steady_clock::now();
  auto lastReport = started;
  long recorded = 0;
  const auto record = [&](int, CheckedCase& checked) {
    ++recorded;
    if (!checked.result) {
      ++s.skipped;
      return true;
    }
    CaseResult& r = *checked.result;
    s.metamorphic.add(checked.relations);
    // The expectations are matched here, on the one thread that records (the matcher counts uses).
    const ExpectationStatus expected = matcher ? matcher->apply(r) : ExpectationStatus::None;
    if (matcher) {
      checked.line = resultLine(r);  // with its expectation
      checked.line.pop_back();
    }
    results.appendLine(checked.line);  // a killed run keeps every result written so far
    if (expected == ExpectationStatus::UnexpectedPass) {
      ++s.unexpectedPasses;
      progress << unexpectedPassText(r) << "\n";
    }
    const bool known = expected == ExpectationStatus::Expected && r.verdict != "not-applicable";  // an expected failure
    if (known) ++s.expectedFailures;
    else if (r.verdict == "pass") ++s.pass;
    else if (r.verdict == "fail") ++s.fail;
    else if (r.verdict == "not-applicable") ++s.notApplicable;
    else ++s.engineFailure;
    if ((r.verdict == "fail" || r.verdict == "engine-failure") && !known) {
      progress << r.verdict << ": " << checked.id << ": " << r.detail << "\n";
    }
    const auto now = std::chrono::steady_clock::now();
    if (now - lastReport > std::chrono::seconds(2)) {
      progress << "  " << recorded << "/" << files.size() << " cases, " << s.fail << " failing\n";
      lastReport = now;
    }
    return true;
  };
  runInItemOrder<CheckedCase>(static_cast<int>(engines.size()), check, record);
  // An entry unused by a whole run is stale; a shard or a resumed run saw only some of the cases.
  if (matcher && s.skipped == 0 && options.shards == 1) {
    for (const Expectation* x : matcher->unused()) s.unusedExpectations.push_back(*x);
  }
  return s;
}

}  // namespace

CheckSummary runCheck(const EnginesMaker& makeEngines, const CheckOptions& options, std::ostream& progress) {
  std::vector<std::unique_ptr<Engine>> owned;
  std::vector<Engine*> engines;
  for (int w = 0; w < std::max(options.jobs, 1); ++w) {
    owned.push_back(makeEngines().engine);
    engines.push_back(owned.back().get());
  }
  return checkOnWorkers(engines, options, progress);
}

CheckSummary runCheck(Engine& engine, const CheckOptions& options, std::ostream& progress) {
  return checkOnWorkers({&engine}, options, progress);
}

}  // namespace cyclecert
