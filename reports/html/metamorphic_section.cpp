// The metamorphic relations of a run with --metamorphic (report.json "metamorphic", the tally of
// OUT/metamorphic.json): per relation, the follow-ups run, held, violated, failed and skipped. Nothing
// when the run had no relations.
#include "reports/html/html_text.h"
#include "reports/html/report_fields.h"
#include "reports/html/sections.h"

namespace cyclecert::html {

namespace {

constexpr const char* kCounts[] = {"run", "held", "violated", "engine_failure", "does_not_apply", "not_supported"};
constexpr const char* kHeads[] = {"run", "held", "violated", "engine failure", "not applicable to the program",
                                  "not supported by the engine"};

std::string countRow(const std::string& name, const nlohmann::json& counts, bool total) {
  std::string row = total ? "<tr><th scope=\"row\">" : "<tr><th scope=\"row\"><code>";
  row += htmlEscape(name) + (total ? "</th>" : "</code></th>");
  for (const char* field : kCounts) {
    const std::uint64_t n = countMember(counts, field);
    const bool bad = n > 0 && (std::string_view(field) == "violated" || std::string_view(field) == "engine_failure");
    row += std::string("<td class=\"num") + (bad ? " v-fail" : "") + (total ? " total" : "") + (n == 0 ? " zero" : "") +
           "\">" + std::to_string(n) + "</td>";
  }
  return row + "</tr>\n";
}

}  // namespace

std::string metamorphicSection(const nlohmann::json& report) {
  const auto it = report.find("metamorphic");
  if (it == report.end() || !it->is_object()) return "";
  const auto relations = it->find("relations");
  if (relations == it->end() || !relations->is_object()) return "";
  std::string out =
      "<section id=\"metamorphic-section\">\n<h2>Metamorphic relations</h2>\n<p class=\"muted\">Each relation's "
      "follow-up program ran through the same engine; its toolpath must be the relation's transformation of the "
      "source's (oracles/metamorphic). Skipped: the relation does not apply to the program, or the engine does not "
      "plan the follow-up.</p>\n<div class=\"table-wrap\"><table class=\"plain\">\n<thead><tr><th scope=\"col\">Relation</th>";
  for (const char* head : kHeads) out += std::string("<th scope=\"col\" class=\"num\">") + head + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (const auto& [id, counts] : relations->items()) out += countRow(id, counts, false);
  if (const auto total = it->find("total"); total != it->end()) out += countRow("all relations", *total, true);
  return out + "</tbody></table></div>\n</section>\n";
}

}  // namespace cyclecert::html
