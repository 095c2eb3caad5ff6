#include "harness/results_file.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "harness/judging.h"

namespace cyclecert {

std::string resultLine(const CaseResult& r) {
  nlohmann::json j{{"engine", r.engine},     {"case", r.caseId},   {"file", r.file},
                   {"rules", r.rules},       {"verdict", r.verdict}, {"detail", r.detail},
                   {"findings", findingsJson(r.findings)}, {"seconds", r.seconds}, {"seed", nullptr}};
  if (r.seed) j["seed"] = *r.seed;
  if (!r.program.empty()) j["program"] = r.program;
  if (!r.vs.empty()) j["vs"] = r.vs;
  if (r.plot) j["plot"] = *r.plot;
  if (!r.reproduce.empty()) j["reproduce"] = r.reproduce;
  // An engine's reply may hold anything (a process engine's message); the line must stay JSON.
  return j.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

ResultLines readResultLines(const std::string& file) {
  ResultLines out;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    try {
      const auto j = nlohmann::json::parse(line);
      out.lines.push_back({line, {j.at("engine").get<std::string>(), j.at("case").get<std::string>()}});
    } catch (const std::exception&) {  // not JSON, or not a result
      ++out.skipped;
    }
  }
  return out;
}

ResultsFile::ResultsFile(const std::string& outDir, bool resume) : path_(outDir + "/results.jsonl") {
  std::filesystem::create_directories(outDir);
  std::vector<ResultLines::Line> kept;
  if (resume) kept = readResultLines(path_).lines;
  for (const ResultLines::Line& line : kept) done_.insert(line.key);
  // Rewritten with the complete lines only, then appended to.
  {
    std::ofstream fresh(path_, std::ios::trunc);
    for (const ResultLines::Line& line : kept) fresh << line.text << "\n";
  }
  out_.open(path_, std::ios::app);
}

void ResultsFile::append(const CaseResult& r) { out_ << resultLine(r) << std::flush; }

}  // namespace cyclecert
