#pragma once
// The page's parts, one file each, in the order they appear. Each returns an HTML fragment; all
// text taken from the report goes through htmlEscape.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "reports/html/report_index.h"

namespace cyclecert::html {

// Engines, versions, revision, suite hash, date, totals, the rules not conformed to.
std::string certificationSection(const nlohmann::json& report, const ReportIndex& index);
// Per engine: case verdict counts, fuzz campaign counts and seeds, rule verdict counts.
std::string engineSummarySection(const nlohmann::json& report, const ReportIndex& index);
// The metamorphic relations' counts of a run with --metamorphic; empty without them.
std::string metamorphicSection(const nlohmann::json& report);
// Every rule × every engine, coloured by verdict, with links to the failures behind each cell.
std::string matrixSection(const nlohmann::json& report, const ReportIndex& index);
// Each failed or engine-failed case: findings, plot (at most maxPlotsPerEngine per engine),
// program, reproducing command.
std::string failuresSection(const nlohmann::json& report, const ReportIndex& index, std::size_t maxPlotsPerEngine);

// The document around the sections: head, inline style and script, navigation.
std::string htmlPage(std::string_view title, std::string_view body);

}  // namespace cyclecert::html
