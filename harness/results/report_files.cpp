#include "harness/results/report_files.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <ostream>

#include "harness/io/input_file.h"
#include "harness/run/run_record.h"
#include "harness/spec/rule_catalogue.h"
#include "reports/html/report_html.h"
#include "reports/junit/junit_xml.h"
#include "reports/model/report_model.h"

namespace cyclecert {

using nlohmann::json;

namespace {

constexpr std::size_t kCorruptLinesShown = 20;

std::vector<ReportRule> reportRules(const std::string& specsDir) {
  std::vector<ReportRule> rules;
  for (const RuleEntry& r : loadRuleCatalogue(specsDir + "/rules.json").rules) {
    rules.push_back({r.id, r.cycle, r.seed, r.section, r.summary});
  }
  return rules;
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::trunc);
  out << text;
  out.close();  // a full disk shows at the last flush: checked after it
  if (!out) throw std::runtime_error("cannot write " + path);
}

// Feeds every line of the results file to the builder; a line that is not a result is skipped,
// counted and named.
void readResults(const std::string& file, ReportBuilder& builder, ReportFiles& summary, std::ostream& log) {
  std::ifstream in(file);
  if (!in) throw ReportInputError("no results to report: cannot read " + file);
  auto lastProgress = std::chrono::steady_clock::now();
  std::string line;
  std::size_t number = 0;
  for (BoundedLine read; (read = readBoundedLine(in, line)) != BoundedLine::End;) {
    ++number;
    if (read == BoundedLine::Line && line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      if (read == BoundedLine::TooLong) {
        throw std::length_error("a line longer than " + byteSizeText(kMaxInputBytes) +
                                " (cyclecert writes result lines of at most that)");
      }
      builder.add(json::parse(line));
      ++summary.lines;
    } catch (const std::exception& e) {
      if (++summary.corrupt <= kCorruptLinesShown) {
        log << file << ":" << number << ": skipped, not a result: " << e.what() << "\n";
      }
    }
    if (number % 4096 == 0 && std::chrono::steady_clock::now() - lastProgress > std::chrono::seconds(2)) {
      log << "  report: " << number << " lines read\n";
      lastProgress = std::chrono::steady_clock::now();
    }
  }
  if (summary.corrupt > kCorruptLinesShown) {
    log << file << ": " << summary.corrupt - kCorruptLinesShown << " more line(s) skipped\n";
  }
}

// OUT/metamorphic.json (a run with --metamorphic: the relations' counts), for report.json; nothing
// when the run had no relations, or a torn file from a killed run (said in the log).
std::optional<json> metamorphicCounts(const std::string& outDir, std::ostream& log) {
  const std::string path = outDir + "/metamorphic.json";
  if (!std::filesystem::is_regular_file(path)) return std::nullopt;
  try {
    std::ifstream in(path);
    json counts = json::parse(in);
    if (counts.is_object() && counts.contains("relations") && counts["relations"].is_object()) return counts;
    log << path << ": skipped, not the relations' counts\n";
  } catch (const std::exception& e) {
    log << path << ": skipped, not JSON: " << e.what() << "\n";
  }
  return std::nullopt;
}

}  // namespace

ReportFiles writeReportFiles(const std::string& outDir, const std::string& specsDir, std::ostream& log) {
  const std::string results = outDir + "/results.jsonl";
  if (!std::filesystem::is_regular_file(results)) {
    throw ReportInputError("no results to report: " + results + " does not exist (run `cyclecert check` or " +
                           "`cyclecert fuzz` with --out " + outDir + " first)");
  }
  std::vector<json> runs;
  try {
    runs = readRunRecords(outDir);
  } catch (const std::runtime_error& e) {
    throw ReportInputError(e.what());
  }
  if (runs.empty()) log << outDir << "/run.json: no run records; versions and date are reported as unknown\n";

  ReportFiles summary;
  ReportBuilder builder(reportRules(specsDir), runs);
  readResults(results, builder, summary, log);
  for (const std::string& w : builder.warnings()) log << results << ": " << w << "\n";
  json report = builder.build();
  if (auto counts = metamorphicCounts(outDir, log)) report["metamorphic"] = std::move(*counts);
  summary.totals = report["certification"]["totals"];
  summary.fuzzTotals = {{"cases", 0}, {"pass", 0}, {"fail", 0}, {"not_applicable", 0}, {"engine_failure", 0}};
  for (const json& engine : report["engines"]) {
    for (auto& [key, count] : summary.fuzzTotals.items()) count = count.get<long>() + engine["fuzz"][key].get<long>();
  }
  summary.nonconformingRules = report["certification"]["nonconforming_rules"].size();

  writeText(outDir + "/report.json", report.dump(1, ' ', false, json::error_handler_t::replace) + "\n");
  writeText(outDir + "/junit.xml", junitXml(report));
  summary.indexHtml = outDir + "/index.html";
  writeText(summary.indexHtml, renderReportHtml(report));
  return summary;
}

namespace {

std::string countsText(const json& t) {
  return std::to_string(t["cases"].get<long>()) + " cases: " + std::to_string(t["pass"].get<long>()) + " pass, " +
         std::to_string(t["fail"].get<long>()) + " fail, " + std::to_string(t["not_applicable"].get<long>()) +
         " not applicable, " + std::to_string(t["engine_failure"].get<long>()) + " engine failure(s)";
}

}  // namespace

std::string reportHeadline(const ReportFiles& r) {
  std::string text;
  if (r.totals["cases"].get<long>() > 0 || r.fuzzTotals["cases"].get<long>() == 0) text = countsText(r.totals);
  if (r.fuzzTotals["cases"].get<long>() > 0) text += (text.empty() ? "fuzz " : "; fuzz ") + countsText(r.fuzzTotals);
  return text + "; " + std::to_string(r.nonconformingRules) + " rule(s) not conformed to";
}

}  // namespace cyclecert
