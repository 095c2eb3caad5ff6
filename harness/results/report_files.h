#pragma once
// A run's report files from its OUT/results.jsonl, OUT/run.json and the rule catalogue:
// OUT/report.json, and from it OUT/junit.xml and OUT/index.html (reports/). `cyclecert report`
// writes them, and so do `check` and `fuzz` at the end of a run.
#include <cstddef>
#include <iosfwd>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

namespace cyclecert {

// A results file that cannot be read at all, or a run.json that is not one.
struct ReportInputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ReportFiles {
  std::size_t lines = 0;    // results read
  std::size_t corrupt = 0;  // lines skipped: not JSON or not a result (a killed run's torn last line)
  nlohmann::json totals;    // certification.totals: the spec and regression cases
  nlohmann::json fuzzTotals;  // the engines' generated cases, summed
  std::size_t nonconformingRules = 0;
  std::string indexHtml;    // the path of index.html
};

// Warnings (each skipped line as file:line, plots left out) and progress for long inputs go to `log`.
ReportFiles writeReportFiles(const std::string& outDir, const std::string& specsDir, std::ostream& log);

// One line for a person: the headline numbers and where the report is.
std::string reportHeadline(const ReportFiles& r);

}  // namespace cyclecert
