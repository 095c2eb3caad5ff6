// Rendering the HTML report of a long run: the fixture report (tests/data/report/report.json) with
// a thousand copies of one plotted failure added, as a nightly fuzz run against a poor engine can
// leave. (The size and the cap on plots are tested in tests/report_html_test.cpp; how long it
// takes is measured here.)
#include <benchmark/benchmark.h>

#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "reports/html/report_html.h"

namespace {

using nlohmann::json;

json reportWithAThousandFailures() {
  std::ifstream in(std::string(CYCLECERT_SOURCE_DIR) + "/tests/data/report/report.json");
  json report = json::parse(in);
  for (json& engine : report["engines"]) {
    if (engine["name"] != "linuxcnc") continue;
    json plotted;
    for (const json& c : engine["cases"]) {
      if (c.contains("plot")) plotted = c;
    }
    for (int i = 0; i < 1000; ++i) {
      json copy = plotted;
      copy["id"] = "bulk-" + std::to_string(i);
      engine["cases"].push_back(copy);
    }
  }
  return report;
}

void BM_RenderReportHtmlWithAThousandFailures(benchmark::State& state) {
  const json report = reportWithAThousandFailures();
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string page = cyclecert::renderReportHtml(report);
    bytes = page.size();
    benchmark::DoNotOptimize(page.data());
  }
  state.counters["page_MB"] = static_cast<double>(bytes) / (1 << 20);
}
BENCHMARK(BM_RenderReportHtmlWithAThousandFailures)->Unit(benchmark::kMillisecond);

}  // namespace
