#pragma once
// Judging a toolpath with the oracles, for a spec case or a program: builds the oracles' input
// from the program alone (never from the reference planner), runs them, and presents findings for
// people (text, SVG witnesses) and machines (JSON).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "harness/spec/spec_case.h"
#include "oracles/judgement.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

struct JudgeRequest {
  PlanRequest program;                 // text, file, profile, parameters, MDI mode, tool
  std::optional<CaseStock> stock;      // else implied by the cycle
  JudgeSettings settings;
};

JudgeRequest judgeRequestFor(const SpecCase& c);

// The oracles' input for a toolpath (throws ParseError / std::invalid_argument for bad input).
JudgeInput judgeInputFor(const JudgeRequest& request, Toolpath path);

std::string findingsText(const std::vector<Finding>& findings);
nlohmann::json findingsJson(const std::vector<Finding>& findings);

// The plot of a judged toolpath: contour, rough contour, stock, path and each finding's witness.
// With `materialAfterMove`, the plot's grey region is the material standing after that move
// instead of the stock.
PlotInput judgePlot(const JudgeInput& in, const std::vector<Finding>& findings, const std::string& title,
                    std::optional<std::size_t> materialAfterMove = std::nullopt);

}  // namespace cyclecert
