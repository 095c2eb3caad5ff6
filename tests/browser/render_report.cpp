// cyclecert-render-report REPORT_JSON INDEX_HTML: writes the page renderReportHtml draws from a
// report.json, so that the browser check (check_report_in_chromium.py --render-with) can open the
// fixture's page without a whole run behind it.
#include <fstream>
#include <iostream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "reports/html/report_html.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: cyclecert-render-report REPORT_JSON INDEX_HTML\n";
    return 2;
  }
  std::ifstream in(argv[1]);
  if (!in) {
    std::cerr << "cyclecert-render-report: cannot read " << argv[1] << "\n";
    return 2;
  }
  nlohmann::json report;
  try {
    report = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    std::cerr << "cyclecert-render-report: " << argv[1] << " is not JSON: " << e.what() << "\n";
    return 2;
  }
  std::ofstream out(argv[2], std::ios::binary);
  out << cyclecert::renderReportHtml(report);
  if (!out.flush()) {
    std::cerr << "cyclecert-render-report: cannot write " << argv[2] << "\n";
    return 2;
  }
  return 0;
}
