// index.html drawn from report.json (reports/html): self-contained, every rule in the matrix with
// each engine's verdict, each failure with its plot, program and command, every piece of report
// text escaped, and a broken plot or document reported in place instead of aborting the page.
#include <gtest/gtest.h>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "reports/html/html_text.h"
#include "reports/html/report_html.h"

namespace cyclecert {
namespace {

using nlohmann::json;

json loadFixture() {
  std::ifstream in(std::string(CYCLECERT_SOURCE_DIR) + "/tests/data/report/report.json");
  return json::parse(in);
}

std::size_t countOf(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

std::vector<std::string> allMatches(const std::string& text, const std::regex& re, int group = 1) {
  std::vector<std::string> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator(); ++it) {
    out.push_back((*it)[group].str());
  }
  return out;
}

// The part of `text` from the first `from` to the next `to` after it ("" when absent).
std::string between(const std::string& text, const std::string& from, const std::string& to) {
  const auto start = text.find(from);
  if (start == std::string::npos) return "";
  const auto end = text.find(to, start + from.size());
  return text.substr(start, end == std::string::npos ? std::string::npos : end - start);
}

// The matrix row of a rule, "" when there is none.
std::string matrixRow(const std::string& html, const std::string& ruleId) {
  const std::string marker = "data-rule=\"" + html::htmlEscape(ruleId) + "\"";
  for (auto row = html.find("<tr class=\"rule\""); row != std::string::npos; row = html.find("<tr class=\"rule\"", row + 1)) {
    const std::string line = html.substr(row, html.find("</tr>", row) - row);
    if (line.find(marker) != std::string::npos) return line;
  }
  return "";
}

// Each failure <article>, by the case id it shows.
std::map<std::string, std::string> failureArticles(const std::string& html) {
  std::map<std::string, std::string> out;
  const std::regex caseId("<code class=\"case-id\">([^<]*)</code>");
  for (auto at = html.find("<article "); at != std::string::npos; at = html.find("<article ", at + 1)) {
    const std::string article = html.substr(at, html.find("</article>", at) - at);
    std::smatch m;
    if (std::regex_search(article, m, caseId)) out[m[1].str()] = article;
  }
  return out;
}

// Every element opened is closed, in order (void elements and `/>` aside; the text of <style> and
// <script> skipped). Returns "" or what is wrong.
std::string unbalancedTags(const std::string& html) {
  static const std::set<std::string> voidElements{"meta", "input", "br", "hr", "img", "link", "wbr", "source"};
  const std::regex tag(R"re(<(/?)([a-zA-Z][a-zA-Z0-9-]*)([^>]*)>)re");
  std::vector<std::string> open;
  std::smatch m;
  auto from = html.cbegin();
  while (std::regex_search(from, html.cend(), m, tag)) {
    from = m[0].second;
    const std::string name = m[2].str();
    const std::string rest = m[3].str();
    if (m[1].length() == 0) {
      if (voidElements.count(name) || (!rest.empty() && rest.back() == '/')) continue;
      if (name == "style" || name == "script") {  // raw text up to its end tag
        const auto end = html.find("</" + name + ">", static_cast<std::size_t>(from - html.cbegin()));
        if (end == std::string::npos) return "<" + name + "> never closed";
        from = html.cbegin() + static_cast<std::ptrdiff_t>(end + name.size() + 3);
        continue;
      }
      open.push_back(name);
    } else if (open.empty() || open.back() != name) {
      return "</" + name + "> closes " + (open.empty() ? std::string("nothing") : "<" + open.back() + ">");
    } else {
      open.pop_back();
    }
  }
  return open.empty() ? "" : "<" + open.back() + "> never closed";
}

std::vector<std::string> svgFragments(const std::string& html) {
  std::vector<std::string> out;
  for (auto at = html.find("<svg "); at != std::string::npos; at = html.find("<svg ", at + 1)) {
    out.push_back(html.substr(at, html.find("</svg>", at) + 6 - at));
  }
  return out;
}

json& engineNamed(json& report, const std::string& name) {
  for (json& e : report["engines"]) {
    if (e["name"] == name) return e;
  }
  throw std::runtime_error("no engine " + name);
}

json& caseWithPlot(json& engine) {
  for (json& c : engine["cases"]) {
    if (c.contains("plot")) return c;
  }
  throw std::runtime_error("no case with a plot");
}

// ---- the fixture ------------------------------------------------------------------------------

TEST(ReportHtml, TheFixtureCoversEveryVerdict) {
  // The other tests lean on this: both engines, every rule verdict, a plotted failure, an engine
  // failure and a generated failure with its seed, program and command.
  const json report = loadFixture();
  std::set<std::string> ruleVerdicts, caseVerdicts;
  bool fuzzWithProgram = false;
  for (const json& e : report["engines"]) {
    for (const json& r : e["rules"]) ruleVerdicts.insert(r["verdict"].get<std::string>());
    for (const json& c : e["cases"]) {
      caseVerdicts.insert(c["verdict"].get<std::string>());
      fuzzWithProgram = fuzzWithProgram || (c["kind"] == "fuzz" && c.contains("program") && c.contains("seed") &&
                                            c.contains("reproduce") && c.contains("plot"));
    }
  }
  EXPECT_EQ(report["engines"].size(), 2u);
  EXPECT_EQ(ruleVerdicts, (std::set<std::string>{"pass", "fail", "engine-failure", "not-applicable", "untested"}));
  EXPECT_EQ(caseVerdicts, (std::set<std::string>{"pass", "fail", "engine-failure", "not-applicable"}));
  EXPECT_TRUE(fuzzWithProgram);
}

// ---- the page ---------------------------------------------------------------------------------

TEST(ReportHtml, SectionsComeInReadingOrder) {
  const std::string page = renderReportHtml(loadFixture());
  ASSERT_EQ(page.rfind("<!DOCTYPE html>\n", 0), 0u);
  const auto certification = page.find("id=\"certification\"");
  const auto engines = page.find("id=\"engines\"");
  const auto matrix = page.find("id=\"matrix\"");
  const auto failures = page.find("id=\"failures\"");
  ASSERT_NE(certification, std::string::npos);
  ASSERT_NE(engines, std::string::npos);
  ASSERT_NE(matrix, std::string::npos);
  ASSERT_NE(failures, std::string::npos);
  EXPECT_LT(certification, engines);
  EXPECT_LT(engines, matrix);
  EXPECT_LT(matrix, failures);
}

TEST(ReportHtml, TagsAreBalancedAndIdsUnique) {
  const std::string page = renderReportHtml(loadFixture());
  EXPECT_EQ(unbalancedTags(page), "");
  const std::vector<std::string> ids = allMatches(page, std::regex(R"re( id="([^"]*)")re"));
  EXPECT_GT(ids.size(), 30u);
  std::set<std::string> seen;
  for (const std::string& id : ids) EXPECT_TRUE(seen.insert(id).second) << "id used twice: " << id;
  // The checker itself: it finds what it is for.
  EXPECT_NE(unbalancedTags("<div><p>text</div>"), "");
  EXPECT_NE(unbalancedTags("<table><tr>"), "");
}

TEST(ReportHtml, EveryInPageLinkHasItsTarget) {
  const std::string page = renderReportHtml(loadFixture());
  const std::vector<std::string> ids = allMatches(page, std::regex(R"re( id="([^"]*)")re"));
  const std::set<std::string> targets(ids.begin(), ids.end());
  const std::vector<std::string> links = allMatches(page, std::regex(R"re(href="#([^"]*)")re"));
  EXPECT_GT(links.size(), 20u);
  for (const std::string& link : links) EXPECT_TRUE(targets.count(link)) << "no element with id " << link;
}

TEST(ReportHtml, LoadsNothingFromOutside) {
  const std::string page = renderReportHtml(loadFixture());
  EXPECT_EQ(page.find("<script src"), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
  EXPECT_EQ(page.find("@import"), std::string::npos);
  EXPECT_EQ(page.find("url("), std::string::npos);
  EXPECT_EQ(page.find("http://"), std::string::npos);  // not even the SVG namespace: inline SVG needs none
  EXPECT_EQ(page.find("https://"), std::string::npos);
  EXPECT_TRUE(allMatches(page, std::regex(R"re(\ssrc\s*=)re"), 0).empty());
  for (const std::string& href : allMatches(page, std::regex(R"re(href="([^"]*)")re"))) {
    EXPECT_EQ(href.rfind('#', 0), 0u) << "a link out of the page: " << href;
  }
  EXPECT_EQ(countOf(page, "<script>"), 1u);  // the one inline script
}

TEST(ReportHtml, IsDeterministic) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  EXPECT_EQ(renderReportHtml(json::parse(report.dump())), page);
  EXPECT_EQ(renderReportHtml(report), page);
}

// ---- certification summary and engines --------------------------------------------------------

TEST(ReportHtml, CertificationNamesWhoWhatAndWhen) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  const std::string header = between(page, "id=\"certification\"", "</header>");
  const json& cert = report["certification"];
  EXPECT_NE(header.find(cert["git_revision"].get<std::string>()), std::string::npos);
  EXPECT_NE(header.find(cert["spec_suite_hash"].get<std::string>()), std::string::npos);
  EXPECT_NE(header.find(">" + cert["cyclecert_version"].get<std::string>() + "<"), std::string::npos);
  EXPECT_NE(header.find("2026-11-21 09:06:00 UTC"), std::string::npos);
  for (const json& e : cert["engines"]) {
    EXPECT_NE(header.find(html::htmlEscape(e["name"].get<std::string>())), std::string::npos);
    EXPECT_NE(header.find(html::htmlEscape(e["version"].get<std::string>())), std::string::npos);
  }
  EXPECT_NE(header.find("<b>" + std::to_string(cert["totals"]["cases"].get<int>()) + "</b>"), std::string::npos);
  // Every rule some engine fails, under each engine failing it, linked to its matrix row.
  const std::string nonconforming = between(header, "id=\"nonconforming\"", "</section>");
  std::map<std::string, std::vector<std::string>> expected;
  for (const json& r : cert["nonconforming_rules"]) {
    for (const json& e : r["engines"]) expected[e.get<std::string>()].push_back(r["rule"]);
  }
  ASSERT_FALSE(expected.empty());
  for (const auto& [engine, rules] : expected) {
    const std::string list = between(nonconforming, "<dt><b>" + html::htmlEscape(engine) + "</b>", "</dd>");
    EXPECT_EQ(allMatches(list, std::regex(R"re(<a class="rule-chip" href="#rule-[^"]*" title="[^"]*"><code>([^<]*)</code>)re")), rules)
        << engine;
  }
  EXPECT_EQ(nonconforming.find("<dt><b>reference</b>"), std::string::npos);  // it fails no rule
}

TEST(ReportHtml, HeadlineSaysWhetherEveryRuleConforms) {
  json report = loadFixture();
  EXPECT_NE(renderReportHtml(report).find("<p class=\"headline v-fail\">\u2717 10 rules are not conformed to; 1 case "
                                          "ended in an engine failure.</p>"),
            std::string::npos);
  engineNamed(report, "linuxcnc")["fuzz"]["engine_failure"] = 2;  // a fuzzer's hang counts too
  EXPECT_NE(renderReportHtml(report).find("; 3 cases ended in an engine failure."), std::string::npos);
  report["certification"]["nonconforming_rules"] = json::array();
  report["certification"]["totals"]["engine_failure"] = 0;
  engineNamed(report, "linuxcnc")["fuzz"]["engine_failure"] = 0;
  EXPECT_NE(renderReportHtml(report).find("<p class=\"headline v-pass\">\u2713 Every tested rule is conformed to by "
                                          "every engine (2 engines).</p>"),
            std::string::npos);
}

TEST(ReportHtml, EngineSummaryCountsMatchTheReport) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  const std::string table = between(page, "<table class=\"engine-summary\">", "</table>");
  for (const json& e : report["engines"]) {
    const std::string row = between(table, "<th scope=\"row\" class=\"engine\">" + html::htmlEscape(e["name"].get<std::string>()), "</tr>");
    ASSERT_FALSE(row.empty()) << e["name"];
    std::vector<std::string> expected;
    for (const char* group : {"totals", "fuzz"}) {
      for (const char* field : {"cases", "pass", "fail", "engine_failure", "not_applicable"}) {
        expected.push_back(std::to_string(e[group][field].get<int>()));
      }
    }
    std::map<std::string, int> rules;
    for (const json& r : e["rules"]) ++rules[r["verdict"]];
    for (const char* v : {"pass", "fail", "engine-failure", "not-applicable", "untested"}) expected.push_back(std::to_string(rules[v]));
    EXPECT_EQ(allMatches(row, std::regex(R"re(<td class="num[^"]*">(\d+)</td>)re")), expected) << e["name"];
    for (const json& seed : e["fuzz"]["seeds"]) EXPECT_NE(row.find("<code>" + seed.dump() + "</code>"), std::string::npos);
  }
}

// ---- the matrix -------------------------------------------------------------------------------

TEST(ReportHtml, MatrixHasARowPerRuleAndAColumnPerEngine) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  const std::string head = between(page, "<table id=\"matrix\"", "</thead>");
  std::vector<std::string> engines;
  for (const json& e : report["engines"]) engines.push_back(e["name"]);
  EXPECT_EQ(allMatches(head, std::regex(R"re(<th scope="col" class="engine" data-engine="([^"]*)")re")), engines);
  EXPECT_EQ(countOf(page, "<tr class=\"rule\""), report["rules"].size());
  for (const json& rule : report["rules"]) {
    const std::string row = matrixRow(page, rule["id"]);
    ASSERT_FALSE(row.empty()) << rule["id"];
    EXPECT_EQ(allMatches(row, std::regex(R"re(<td class="cell [^"]*" data-engine="([^"]*)")re")), engines) << rule["id"];
    EXPECT_NE(row.find(html::htmlEscape(rule["summary"].get<std::string>())), std::string::npos);
  }
}

TEST(ReportHtml, MatrixRowsAreGroupedByCycle) {
  const std::string page = renderReportHtml(loadFixture());
  EXPECT_EQ(allMatches(page, std::regex(R"re(<tbody class="cycle-group" data-cycle="([^"]*)")re")),
            (std::vector<std::string>{"G71", "G72", "G70"}));
  const std::string g72 = between(page, "data-cycle=\"G72\"", "</tbody>");
  EXPECT_NE(g72.find("data-rule=\"G72.RETRACT\""), std::string::npos);
  EXPECT_EQ(g72.find("data-rule=\"G71.OP\""), std::string::npos);
}

TEST(ReportHtml, CellVerdictClassesMatchTheFixture) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  const std::regex cell(R"re(<td class="cell v-([a-z-]+)" data-engine="([^"]*)" data-verdict="([^"]*)")re");
  for (const json& e : report["engines"]) {
    for (const json& r : e["rules"]) {
      const std::string row = matrixRow(page, r["id"]);
      std::smatch m;
      auto from = row.cbegin();
      bool found = false;
      while (std::regex_search(from, row.cend(), m, cell)) {
        from = m[0].second;
        if (m[2].str() != e["name"]) continue;
        found = true;
        EXPECT_EQ(m[1].str(), r["verdict"].get<std::string>()) << e["name"] << " " << r["id"];
        EXPECT_EQ(m[3].str(), r["verdict"].get<std::string>());
      }
      EXPECT_TRUE(found) << e["name"] << " " << r["id"];
    }
  }
}

TEST(ReportHtml, CellsReadWithoutColour) {
  const std::string page = renderReportHtml(loadFixture());
  const std::string failed = matrixRow(page, "G72.RETRACT");
  EXPECT_NE(failed.find("<span class=\"sym\">\u2717</span> <span class=\"word\">fail</span>"), std::string::npos);
  const std::string engineFailed = matrixRow(page, "G71.QUAD");
  EXPECT_NE(engineFailed.find("<span class=\"word\">eng. failure</span>"), std::string::npos);
  EXPECT_NE(matrixRow(page, "G72.T2.MONO").find("<span class=\"word\">untested</span>"), std::string::npos);
  EXPECT_NE(matrixRow(page, "G70.EX").find("<span class=\"word\">n/a</span>"), std::string::npos);
}

TEST(ReportHtml, FailedCellsLinkTheirFailures) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  const std::map<std::string, std::string> articles = failureArticles(page);
  json fixture = report;  // engineNamed wants a mutable document
  for (const json& r : engineNamed(fixture, "linuxcnc")["rules"]) {
    if (r["verdict"] != "fail") continue;
    const std::string row = matrixRow(page, r["id"]);
    const std::string cell = between(row, "data-engine=\"linuxcnc\"", "</td>");
    // Each link's tooltip names the failing case, and the link leads to that case's article.
    std::set<std::string> linked;
    const std::regex link(R"re(<a href="#([^"]*)" title="([^"]*)">F\d+</a>)re");
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), link); it != std::sregex_iterator(); ++it) {
      linked.insert((*it)[2].str());
      ASSERT_TRUE(articles.count((*it)[2].str())) << (*it)[2].str();
      EXPECT_NE(articles.at((*it)[2].str()).find("id=\"" + (*it)[1].str() + "\""), std::string::npos);
    }
    std::set<std::string> failing;
    for (const json& id : r["failing"]) failing.insert(id.get<std::string>());
    EXPECT_EQ(linked, failing) << r["id"];
  }
  // An engine-failed cell links the case that hit the engine failure.
  const std::string quad = between(matrixRow(page, "G71.QUAD"), "data-engine=\"linuxcnc\"", "</td>");
  EXPECT_NE(quad.find("title=\"fanuc-0i-f/g71/fuzz-linuxcnc-41467b9476da404d\""), std::string::npos);
}

// ---- failures ---------------------------------------------------------------------------------

TEST(ReportHtml, EveryFailureHasItsSectionWithPlotProgramAndCommand) {
  const json report = loadFixture();
  const std::string page = renderReportHtml(report);
  std::size_t failures = 0, articleCount = 0;
  for (std::size_t engine = 0; engine < report["engines"].size(); ++engine) {
    const json& e = report["engines"][engine];
    // The engine's own failure section: both engines ran the same cases.
    const std::map<std::string, std::string> articles =
        failureArticles(between(page, "id=\"failures-" + std::to_string(engine + 1) + "\"", "</section>"));
    articleCount += articles.size();
    for (const json& c : e["cases"]) {
      const std::string verdict = c["verdict"];
      if (verdict != "fail" && verdict != "engine-failure") {
        EXPECT_FALSE(articles.count(c["id"])) << c["id"] << " is not a failure";
        continue;
      }
      ++failures;
      ASSERT_TRUE(articles.count(c["id"])) << c["id"];
      const std::string& a = articles.at(c["id"]);
      EXPECT_NE(a.find("class=\"badge v-" + verdict + "\""), std::string::npos);
      EXPECT_NE(a.find("<span class=\"kind\">" + c["kind"].get<std::string>() + "</span>"), std::string::npos);
      EXPECT_NE(a.find(html::htmlEscape(c["detail"].get<std::string>())), std::string::npos);
      for (const json& f : c["findings"]) EXPECT_NE(a.find(html::htmlEscape(f["message"].get<std::string>())), std::string::npos);
      for (const json& r : c["rules"]) EXPECT_NE(a.find("<code>" + r.get<std::string>() + "</code>"), std::string::npos);
      if (c.contains("plot")) {
        EXPECT_NE(a.find("<svg "), std::string::npos) << c["id"];
      } else {
        EXPECT_EQ(a.find("<svg"), std::string::npos);
        EXPECT_NE(a.find("No plot recorded for this case."), std::string::npos) << c["id"];
      }
      if (c.contains("reproduce")) {
        EXPECT_NE(a.find("<pre class=\"reproduce\">\n" + html::htmlEscape(c["reproduce"].get<std::string>()) + "</pre>"),
                  std::string::npos);
      }
      if (c.contains("program")) {
        EXPECT_NE(a.find("<pre class=\"program\">\n" + html::htmlEscape(c["program"].get<std::string>()) + "</pre>"),
                  std::string::npos);
      }
      if (c.contains("seed")) {
        EXPECT_NE(a.find("<dt>Seed</dt><dd><code>" + c["seed"].dump() + "</code>"), std::string::npos);
      }
    }
  }
  EXPECT_EQ(articleCount, failures);
  EXPECT_EQ(failures, 4u);
}

TEST(ReportHtml, PlotsAreWellFormedXmlWithTheirOverlays) {
  const std::string page = renderReportHtml(loadFixture());
  const std::vector<std::string> svgs = svgFragments(page);
  ASSERT_EQ(svgs.size(), 2u);
  for (const std::string& svg : svgs) {
    std::istringstream in(svg);
    boost::property_tree::ptree tree;
    EXPECT_NO_THROW(boost::property_tree::read_xml(in, tree)) << svg.substr(0, 200);
    EXPECT_EQ(svg.find("<?xml"), std::string::npos);
    EXPECT_NE(svg.find("class=\"plot-svg\""), std::string::npos);
    EXPECT_NE(svg.find("-toolpath\""), std::string::npos);  // the plot's own ids, prefixed
  }
  EXPECT_NE(svgs[0].find("-overlay\""), std::string::npos);  // the expected path drawn with the engine's
  EXPECT_NE(svgs[0].find("first divergence"), std::string::npos);
}

TEST(ReportHtml, AMalformedPlotIsReportedInPlace) {
  json report = loadFixture();
  json& bad = caseWithPlot(engineNamed(report, "linuxcnc"));
  bad["plot"]["finish"][0].erase("to");
  std::string page;
  ASSERT_NO_THROW(page = renderReportHtml(report));
  const std::string a = failureArticles(page).at(bad["id"]);
  EXPECT_NE(a.find("<p class=\"plot-error\">The plot of this case could not be read: "), std::string::npos);
  EXPECT_NE(a.find("/finish/0/to"), std::string::npos);  // the reader names the field
  EXPECT_EQ(a.find("<svg"), std::string::npos);
  EXPECT_EQ(svgFragments(page).size(), 1u);  // the other plot still drawn

  bad["plot"] = "not a plot";
  ASSERT_NO_THROW(page = renderReportHtml(report));
  EXPECT_NE(failureArticles(page).at(bad["id"]).find("class=\"plot-error\""), std::string::npos);
}

// `count` more failures of the engine, copies of one with a plot under new ids.
void addCopiesOfAPlottedFailure(json& engine, int count, const std::string& idPrefix) {
  const json plotted = caseWithPlot(engine);
  for (int i = 0; i < count; ++i) {
    json copy = plotted;
    copy["id"] = idPrefix + std::to_string(i);
    engine["cases"].push_back(copy);
  }
}

TEST(ReportHtml, PlotsAreCappedPerEngine) {
  json report = loadFixture();
  json& engine = engineNamed(report, "linuxcnc");
  addCopiesOfAPlottedFailure(engine, 4, "copy-");
  HtmlReportOptions options;
  options.maxPlotsPerEngine = 2;
  const std::string page = renderReportHtml(report, options);
  EXPECT_EQ(svgFragments(page).size(), 2u);
  EXPECT_EQ(countOf(page, "Plot left out: this page draws at most 2 plots per engine"), 4u);
  EXPECT_NE(page.find("This page draws the first 2 plots of this engine; 4 plots are left out"), std::string::npos);
  EXPECT_EQ(failureArticles(page).size(), 8u);  // every failure still listed
  EXPECT_EQ(svgFragments(renderReportHtml(report)).size(), 6u);
}

TEST(ReportHtml, AThousandFailuresMakeAPageOfReasonableSize) {
  json report = loadFixture();
  json& engine = engineNamed(report, "linuxcnc");
  addCopiesOfAPlottedFailure(engine, 1000, "bulk-");
  // (How long rendering takes is measured in bench/report_bench.cpp.)
  const std::string page = renderReportHtml(report);
  EXPECT_EQ(svgFragments(page).size(), 40u);  // the default cap
  EXPECT_LT(page.size(), 8u << 20) << page.size();
}

// ---- escaping and odd documents ---------------------------------------------------------------

TEST(ReportHtml, HostileTextIsEscaped) {
  json report = loadFixture();
  json& engine = engineNamed(report, "linuxcnc");
  json& c = caseWithPlot(engine);
  c["detail"] = std::string("</script><b>bold</b> \x01\x02\x7f end");
  c["id"] = "case\"' onmouseover=\"x";
  c["findings"][0]["message"] = "<img src=x onerror=alert(1)>";
  c["program"] = "</pre><script>alert(1)</script>";
  c["plot"]["title"] = "</svg><script>alert(2)</script>";
  report["rules"][0]["summary"] = "<i>summary</i> & \"quotes\"";
  report["certification"]["engines"][0]["version"] = "<b>v1</b>";
  report["certification"]["cyclecert_version"] = "</title><script>x</script>";
  for (json& other : engine["cases"]) {
    if (other["verdict"] == "engine-failure") other["detail"] = "bytes \xff\xfe, truncated \xe2\x82, surrogate \xed\xa0\x80";
  }
  const std::string page = renderReportHtml(report);

  EXPECT_EQ(page.find("<b>bold"), std::string::npos);
  EXPECT_NE(page.find("&lt;/script&gt;&lt;b&gt;bold&lt;/b&gt;"), std::string::npos);
  EXPECT_EQ(page.find("<img"), std::string::npos);
  EXPECT_EQ(page.find("<i>summary"), std::string::npos);
  EXPECT_NE(page.find("&lt;i&gt;summary&lt;/i&gt; &amp; &quot;quotes&quot;"), std::string::npos);
  EXPECT_EQ(page.find("<b>v1"), std::string::npos);
  EXPECT_EQ(page.find("case\"'"), std::string::npos);
  EXPECT_NE(page.find("case&quot;&apos; onmouseover=&quot;x"), std::string::npos);
  EXPECT_EQ(countOf(page, "<script"), 1u);  // only the page's own
  EXPECT_EQ(countOf(page, "</script>"), 1u);
  EXPECT_EQ(countOf(page, "</pre>"), countOf(page, "<pre "));
  for (char ch : page) {
    const auto u = static_cast<unsigned char>(ch);
    EXPECT_FALSE((u < 0x20 && ch != '\n' && ch != '\t' && ch != '\r') || u == 0x7f) << "control character " << int(u);
  }
  EXPECT_EQ(unbalancedTags(page), "");
  EXPECT_NO_THROW((void)json(page).dump()) << "the page is not valid UTF-8";  // dump() checks UTF-8
  EXPECT_NE(page.find("bytes \uFFFD\uFFFD, truncated \uFFFD\uFFFD, surrogate \uFFFD\uFFFD\uFFFD"), std::string::npos);
  for (const std::string& svg : svgFragments(page)) {
    std::istringstream in(svg);
    boost::property_tree::ptree tree;
    EXPECT_NO_THROW(boost::property_tree::read_xml(in, tree));
  }
}

TEST(ReportHtml, InvalidUtf8BecomesReplacementCharacters) {
  EXPECT_EQ(html::validUtf8("plain \u00e9 \u2713 \U0001F600"), "plain \u00e9 \u2713 \U0001F600");
  EXPECT_EQ(html::validUtf8("a\x80" "b"), "a\uFFFD" "b");          // a stray continuation byte
  EXPECT_EQ(html::validUtf8("\xc0\xaf"), "\uFFFD\uFFFD");          // overlong '/'
  EXPECT_EQ(html::validUtf8("\xf4\x90\x80\x80"), "\uFFFD\uFFFD\uFFFD\uFFFD");  // beyond U+10FFFF
  EXPECT_EQ(html::validUtf8("end \xe2\x9c"), "end \uFFFD\uFFFD");  // truncated
}

TEST(ReportHtml, EscapingIsSvgEscapeWithoutDel) {
  EXPECT_EQ(html::htmlEscape("a<b>&\"'\x7f\x01\t"), "a&lt;b&gt;&amp;&quot;&apos;??\t");
  EXPECT_EQ(html::anchorName("G71.T1 <x>/\u00e9"), "G71.T1__x____");  // \u00e9 is two bytes
}

TEST(ReportHtml, AnyDocumentGivesAPage) {
  for (const json& doc : {json::object(), json::array(), json("text"), json{{"format", "other/9"}},
                          json{{"engines", json::array({json{{"name", 5}, {"cases", "x"}, {"rules", json::array({1})}}})},
                               {"rules", json::array({json{{"id", json::array()}}})}, {"certification", 3}}}) {
    std::string page;
    ASSERT_NO_THROW(page = renderReportHtml(doc)) << doc.dump();
    EXPECT_NE(page.find("<table id=\"matrix\""), std::string::npos);
    EXPECT_NE(page.find("class=\"format-warning\""), std::string::npos);
    EXPECT_EQ(unbalancedTags(page), "") << doc.dump();
  }
  EXPECT_EQ(renderReportHtml(loadFixture()).find("class=\"format-warning\""), std::string::npos);
}

TEST(ReportHtml, RuleAnchorsStayUnique) {
  json report = loadFixture();
  report["rules"].push_back({{"id", "X/1"}, {"cycle", "G99"}, {"seed", "000"}, {"section", ""}, {"summary", "a"}});
  report["rules"].push_back({{"id", "X_1"}, {"cycle", "G99"}, {"seed", "000"}, {"section", ""}, {"summary", "b"}});
  report["rules"].push_back(report["rules"][0]);  // listed twice: one row
  const std::string page = renderReportHtml(report);
  EXPECT_NE(page.find("id=\"rule-X_1\""), std::string::npos);
  EXPECT_NE(page.find("id=\"rule-X_1-2\""), std::string::npos);
  EXPECT_EQ(countOf(page, "data-rule=\"" + report["rules"][0]["id"].get<std::string>() + "\""), 1u);
  EXPECT_EQ(unbalancedTags(page), "");
}

}  // namespace
}  // namespace cyclecert
