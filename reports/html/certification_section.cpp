// The certification summary: what a release review reads first — who was tested, with which
// cyclecert and spec suite, when, how many cases, and which rules are not conformed to.
#include <map>
#include <vector>

#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"
#include "reports/html/sections.h"
#include "reports/html/verdict_style.h"

namespace cyclecert::html {

namespace {

// "2026-11-21T11:33:42Z" reads as "2026-11-21 11:33:42 UTC"; anything else is shown as given.
std::string readableDate(const std::string& iso) {
  if (iso.size() >= 20 && iso[10] == 'T' && iso.back() == 'Z') {
    return iso.substr(0, 10) + " " + iso.substr(11, iso.size() - 12) + " UTC";
  }
  return iso;
}

std::string fact(std::string_view term, const std::string& valueHtml) {
  return "<dt>" + std::string(term) + "</dt><dd>" + valueHtml + "</dd>\n";
}

std::string codeOrUnknown(const std::string& text) {
  if (text.empty() || text == "unknown") return "<span class=\"muted\">unknown</span>";
  return "<code class=\"hash\">" + htmlEscape(text) + "</code>";
}

std::string runFacts(const nlohmann::json& cert) {
  const std::string date = textMember(cert, "date");
  std::string out = "<section class=\"card\"><h2>Run</h2>\n<dl class=\"facts\">\n";
  out += fact("cyclecert", htmlEscape(textMember(cert, "cyclecert_version", "unknown")));
  out += fact("Git revision", codeOrUnknown(textMember(cert, "git_revision")));
  out += fact("Spec suite (SHA-256)", codeOrUnknown(textMember(cert, "spec_suite_hash")));
  out += fact("Date", date.empty() ? "<span class=\"muted\">no run record</span>"
                                   : "<time datetime=\"" + htmlEscape(date) + "\">" +
                                         htmlEscape(readableDate(date)) + "</time>");
  return out + "</dl></section>\n";
}

std::string engineList(const nlohmann::json& cert) {
  std::string out = "<section class=\"card\"><h2>Engines under test</h2>\n";
  const nlohmann::json& engines = listMember(cert, "engines");
  if (engines.empty()) return out + "<p class=\"muted\">No engine in this report.</p></section>\n";
  out += "<table class=\"plain\"><thead><tr><th>Engine</th><th>Version</th></tr></thead><tbody>\n";
  for (const nlohmann::json& e : engines) {
    const std::string version = textMember(e, "version");
    out += "<tr><td><b>" + htmlEscape(textMember(e, "name", "(unnamed)")) + "</b></td><td>" +
           (version.empty() ? "<span class=\"muted\">unknown</span>" : htmlEscape(version)) + "</td></tr>\n";
  }
  return out + "</tbody></table></section>\n";
}

std::string totalsCard(const nlohmann::json& cert) {
  const nlohmann::json& t = member(cert, "totals");
  std::string out = "<section class=\"card\"><h2>Spec and regression cases</h2>\n";
  out += "<p class=\"big-number\"><b>" + std::to_string(countMember(t, "cases")) + "</b> cases over all engines</p>\n";
  out += "<p class=\"pills\">" + verdictPill("pass", countMember(t, "pass")) + " " +
         verdictPill("fail", countMember(t, "fail")) + " " +
         verdictPill("engine-failure", countMember(t, "engine_failure")) + " " +
         verdictPill("not-applicable", countMember(t, "not_applicable")) + "</p>\n";
  return out + "</section>\n";
}

// Engine failures count the generated cases too: a hang found by the fuzzer is as much news.
std::string headline(const nlohmann::json& report) {
  const nlohmann::json& cert = member(report, "certification");
  const std::size_t rules = listMember(cert, "nonconforming_rules").size();
  const std::size_t engineCount = listMember(report, "engines").size();
  std::uint64_t engineFailures = countMember(member(cert, "totals"), "engine_failure");
  for (const nlohmann::json& e : listMember(report, "engines")) engineFailures += countMember(member(e, "fuzz"), "engine_failure");
  if (rules == 0 && engineFailures == 0) {
    return "<p class=\"headline v-pass\">\u2713 Every tested rule is conformed to by every engine (" +
           std::to_string(engineCount) + " engine" + (engineCount == 1 ? "" : "s") + ").</p>\n";
  }
  std::string text = std::to_string(rules) + " rule" + (rules == 1 ? " is" : "s are") + " not conformed to";
  if (engineFailures > 0) {
    text += "; " + std::to_string(engineFailures) + " case" + (engineFailures == 1 ? "" : "s") +
            " ended in an engine failure";
  }
  std::uint64_t expected = 0;
  for (const nlohmann::json& e : listMember(report, "engines")) expected += countMember(member(e, "expectations"), "expected_failure");
  if (expected > 0) {
    text += "; " + std::to_string(expected) + " failing case" + (expected == 1 ? " was" : "s were") +
            " expected (--expectations: listed apart under Failures)";
  }
  return "<p class=\"headline v-fail\">\u2717 " + text + ".</p>\n";
}

// Grouped by engine, each rule a chip linking to its matrix row (its summary as the tooltip): a
// long list stays a few lines, and the matrix below has the summaries in full.
std::string nonconformingRules(const nlohmann::json& report, const ReportIndex& index) {
  const nlohmann::json& rules = listMember(member(report, "certification"), "nonconforming_rules");
  std::string out = "<section class=\"nonconforming\" id=\"nonconforming\">\n<h2>Rules not conformed to (" +
                    std::to_string(rules.size()) + ")</h2>\n";
  if (rules.empty()) return out + "<p class=\"muted\">None: no case fails any rule.</p>\n</section>\n";
  std::map<std::string, std::string> summaries;
  for (const nlohmann::json& r : listMember(report, "rules")) summaries.emplace(textMember(r, "id"), textMember(r, "summary"));
  std::vector<std::string> engines;  // in the order the list first names them
  std::map<std::string, std::vector<std::string>> rulesOf;
  for (const nlohmann::json& r : rules) {
    for (const nlohmann::json& e : listMember(r, "engines")) {
      const std::string engine = scalarText(e);
      if (!rulesOf.count(engine)) engines.push_back(engine);
      rulesOf[engine].push_back(textMember(r, "rule"));
    }
  }
  out += "<dl class=\"nonconforming-list\">\n";
  for (const std::string& engine : engines) {
    const std::vector<std::string>& ids = rulesOf[engine];
    out += "<dt><b>" + htmlEscape(engine) + "</b> <span class=\"muted\">" + std::to_string(ids.size()) + " rule" +
           (ids.size() == 1 ? "" : "s") + "</span></dt><dd>";
    for (const std::string& id : ids) {
      const std::string anchor = index.anchorOfRule(id);
      const std::string chip = "<code>" + htmlEscape(id) + "</code>";
      out += anchor.empty() ? "<span class=\"rule-chip\">" + chip + "</span> "
                            : "<a class=\"rule-chip\" href=\"#" + anchor + "\" title=\"" + htmlEscape(summaries[id]) +
                                  "\">" + chip + "</a> ";
    }
    out += "</dd>\n";
  }
  return out + "</dl>\n</section>\n";
}

}  // namespace

std::string certificationSection(const nlohmann::json& report, const ReportIndex& index) {
  const nlohmann::json& cert = member(report, "certification");
  std::string out = "<header class=\"certification\" id=\"certification\">\n";
  out += "<h1>cyclecert conformance report</h1>\n";
  out += headline(report);
  out += "<div class=\"cards\">\n" + runFacts(cert) + engineList(cert) + totalsCard(cert) + "</div>\n";
  out += nonconformingRules(report, index);
  return out + "</header>\n";
}

}  // namespace cyclecert::html
