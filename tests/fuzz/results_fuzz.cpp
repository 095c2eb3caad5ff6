// libFuzzer target: a results file (OUT/results.jsonl) as `--resume`, `merge` and `report` read
// it: readResultLines (harness/results/results_file.h) keeps the complete result lines, and the report is
// built from every line as writeReportFiles does (ReportBuilder, report.json, junit.xml, the HTML
// page with its inline plots). A line that is not a result is skipped (std::exception caught, as
// harness/results/report_files.cpp does); nothing may escape the report's building and rendering.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>

#include "harness/results/results_file.h"
#include "reports/html/report_html.h"
#include "reports/junit/junit_xml.h"
#include "reports/model/report_model.h"
#include "tests/fuzz/fuzz_input.h"

namespace {

// The input as a results file, written once per process into /tmp.
const std::string& resultsPath() {
  static const std::string path = "/tmp/cyclecert-fuzz-results-" + std::to_string(::getpid()) + ".jsonl";
  return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  const std::string text = fuzz::textOf(data, size);
  {
    std::ofstream out(resultsPath(), std::ios::binary | std::ios::trunc);
    out << text;
  }
  readResultLines(resultsPath());

  ReportBuilder builder({}, {});
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    try {
      builder.add(nlohmann::json::parse(line));
    } catch (const std::exception&) {  // not a result: skipped and counted by `report`
    }
  }
  const nlohmann::json report = builder.build();
  report.dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
  junitXml(report);
  renderReportHtml(report);
  return 0;
}
