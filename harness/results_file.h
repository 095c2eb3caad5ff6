#pragma once
// OUT/results.jsonl: one JSON line per case result (spec case or fuzz case), appended and flushed
// as each result is known, so that a killed run keeps every result written so far. `check`,
// `fuzz` and `merge` write it; `--resume` reads it back; reports are made from it.
#include <cstdint>
#include <fstream>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracles/judgement.h"

namespace cyclecert {

struct CaseResult {
  std::string engine, caseId, file;
  std::vector<std::string> rules;
  std::string verdict;  // "pass", "fail", "not-applicable", "engine-failure"
  std::string detail;
  std::vector<Finding> findings;
  double seconds = 0;
  std::optional<std::uint64_t> seed;  // fuzz cases: the seed that regenerates the case
  std::string program;                // fuzz failures: the shrunk case's program
  std::string vs;                     // fuzz --vs: the engine compared with
  std::optional<nlohmann::json> plot;  // failures: the picture (reports/svg/plot_json.h)
  std::string reproduce;              // failures: the command that shows it again
};

std::string resultLine(const CaseResult& r);  // one JSON line, with its newline

// The results file of a run in `outDir` (created). Without `resume` it starts empty; with it, the
// results already there are kept — a last line cut short by a killed run is dropped — and their
// (engine, case) pairs returned in `done`.
class ResultsFile {
 public:
  ResultsFile(const std::string& outDir, bool resume);
  const std::set<std::pair<std::string, std::string>>& done() const { return done_; }
  void append(const CaseResult& r);  // written and flushed at once
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::set<std::pair<std::string, std::string>> done_;
  std::ofstream out_;
};

// Every complete line of a results file, with the (engine, case) it is the result of; a torn or
// garbled line is skipped and counted.
struct ResultLines {
  struct Line {
    std::string text;
    std::pair<std::string, std::string> key;  // engine, case
  };
  std::vector<Line> lines;
  std::size_t skipped = 0;
};
ResultLines readResultLines(const std::string& file);

}  // namespace cyclecert
