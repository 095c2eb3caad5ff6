#pragma once
// OUT/results.jsonl: one JSON line per case result (spec case or fuzz case), appended and flushed
// as each result is known, so that a killed run keeps every result written so far. `check`,
// `fuzz` and `merge` write it; `--resume` reads it back; reports are made from it.
#include <cstdint>
#include <stdexcept>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "oracles/judgement.h"

namespace cyclecert {

// What a run's expectation file (harness/results/expectations.h) made of a result: "expected-failure",
// "new-failure" or "unexpected-pass", the entry's reason and where it stands (FILE:LINE, FILE: /path).
struct ResultExpectation {
  std::string status, reason, source;
};

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
  std::optional<ResultExpectation> expectation = std::nullopt;  // runs with --expectations
};

std::string resultLine(const CaseResult& r);  // one JSON line, with its newline

// A result that could not be written (disk full, I/O error, file size limit): the run stops. The
// message names the file, the error and how many results are safely in the file.
struct ResultsWriteError : std::runtime_error {
  ResultsWriteError(const std::string& what, std::size_t safe) : std::runtime_error(what), safe(safe) {}
  std::size_t safe;  // complete results in the file
};

// The results file of a run in `outDir` (created). Without `resume` it starts empty; with it, the
// results already there are kept — a last line cut short by a killed run is dropped — and their
// (engine, case) pairs returned in `done`. An existing results file that is not a regular file
// is refused (std::runtime_error).
class ResultsFile {
 public:
  ResultsFile(const std::string& outDir, bool resume);
  ~ResultsFile();
  ResultsFile(const ResultsFile&) = delete;
  ResultsFile& operator=(const ResultsFile&) = delete;

  const std::set<std::pair<std::string, std::string>>& done() const { return done_; }
  // Written at once (one write(2), no buffer): throws ResultsWriteError when the system refuses it.
  void append(const CaseResult& r);
  void appendLine(const std::string& jsonLine);  // a result line as read (without its newline)
  std::size_t safe() const { return safe_; }     // the results in the file
  const std::string& path() const { return path_; }

 private:
  void write(const std::string& bytes);

  std::string path_;
  std::set<std::pair<std::string, std::string>> done_;
  int fd_ = -1;
  std::size_t safe_ = 0;
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
