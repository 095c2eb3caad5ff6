#include "harness/check_run.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <set>

#include "harness/judging.h"
#include "harness/spec_check.h"

namespace cyclecert {

namespace {

// The engine's result against the case's expectation; nothing when it is met.
std::optional<std::string> unmet(const SpecCase& c, const EngineResult& r, const std::string& engineName) {
  // Warnings are judged for the in-process engines, which share the reference's annotations.
  const bool inProcess = engineName == "reference" || engineName.rfind("mutant:", 0) == 0;
  if (r.kind == EngineResult::Alarmed || r.kind == EngineResult::Planned) return unmetExpectation(c, r.path, inProcess);
  return std::string("no result");
}

}  // namespace

CaseResult checkCase(Engine& engine, const SpecCase& c) {
  CaseResult out;
  out.engine = engine.name();
  out.caseId = c.id;
  out.file = c.file;
  out.rules = c.rules;
  const EngineResult r = engine.run(c);
  out.seconds = r.seconds;
  if (r.kind == EngineResult::Failed) {
    out.verdict = "engine-failure";
    out.detail = r.detail;
    return out;
  }
  if (r.kind == EngineResult::NotApplicable) {
    out.verdict = "not-applicable";
    out.detail = r.detail;
    return out;
  }
  if (const auto why = unmet(c, r, engine.name())) {
    out.verdict = "fail";
    out.detail = *why;
  }
  if (r.kind == EngineResult::Planned) {
    try {
      Toolpath path = r.path;
      const JudgeInput in = judgeInputFor(judgeRequestFor(c), std::move(path));
      out.findings = judge(in);
    } catch (const std::exception& e) {
      out.detail += (out.detail.empty() ? "" : "; ") + std::string("the oracles could not judge it: ") + e.what();
    }
    if (!out.findings.empty()) {
      out.verdict = "fail";
      if (out.detail.empty()) out.detail = out.findings.front().oracle + ": " + out.findings.front().message;
    }
  }
  if (out.verdict.empty()) out.verdict = "pass";
  return out;
}

std::string resultLine(const CaseResult& r) {
  nlohmann::json j{{"engine", r.engine},     {"case", r.caseId},   {"file", r.file},
                   {"rules", r.rules},       {"verdict", r.verdict}, {"detail", r.detail},
                   {"findings", findingsJson(r.findings)}, {"seconds", r.seconds}, {"seed", nullptr}};
  return j.dump() + "\n";
}

namespace {

// The (engine, case) pairs already in results.jsonl. A line cut short by a killed run is dropped:
// the file is rewritten with the complete lines only.
std::set<std::pair<std::string, std::string>> alreadyDone(const std::string& file) {
  std::set<std::pair<std::string, std::string>> done;
  std::vector<std::string> kept;
  {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
      try {
        const auto j = nlohmann::json::parse(line);
        done.insert({j.at("engine").get<std::string>(), j.at("case").get<std::string>()});
        kept.push_back(line);
      } catch (const std::exception&) {
      }
    }
  }
  std::ofstream out(file, std::ios::trunc);
  for (const std::string& line : kept) out << line << "\n";
  return done;
}

}  // namespace

CheckSummary runCheck(Engine& engine, const CheckOptions& options, std::ostream& progress) {
  std::filesystem::create_directories(options.outDir);
  const std::string resultsFile = options.outDir + "/results.jsonl";
  const auto done = options.resume ? alreadyDone(resultsFile) : std::set<std::pair<std::string, std::string>>{};
  if (!options.resume) std::ofstream(resultsFile, std::ios::trunc);
  std::ofstream results(resultsFile, std::ios::app);
  CheckSummary s;
  const auto files = findSpecCaseFiles(options.specsDir + "/cases");
  const auto started = std::chrono::steady_clock::now();
  auto lastReport = started;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const SpecCase c = loadSpecCase(files[i]);
    if (done.count({engine.name(), c.id})) {
      ++s.skipped;
      continue;
    }
    const CaseResult r = checkCase(engine, c);
    results << resultLine(r) << std::flush;  // a killed run keeps every result written so far
    if (r.verdict == "pass") ++s.pass;
    else if (r.verdict == "fail") ++s.fail;
    else if (r.verdict == "not-applicable") ++s.notApplicable;
    else ++s.engineFailure;
    if (r.verdict == "fail" || r.verdict == "engine-failure") progress << r.verdict << ": " << c.id << ": " << r.detail << "\n";
    const auto now = std::chrono::steady_clock::now();
    if (now - lastReport > std::chrono::seconds(2)) {
      progress << "  " << i + 1 << "/" << files.size() << " cases, " << s.fail << " failing\n";
      lastReport = now;
    }
  }
  return s;
}

}  // namespace cyclecert
