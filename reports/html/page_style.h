#pragma once
// The page's inline style sheet and script, kept apart from the markup that uses them.
#include <string_view>

namespace cyclecert::html {

// Verdict colours (cells, pills, badges), cards, the matrix, the failure articles, print rules.
extern const std::string_view kPageStyle;
// Marks <html> with class "js" (which shows the matrix toolbar) and filters the matrix rows; the
// page is complete without it.
extern const std::string_view kPageScript;

}  // namespace cyclecert::html
