#pragma once
// How a verdict looks everywhere on the page: one CSS class (its colour), and a symbol and a word
// so that the page reads the same without colour (printed, colour-blind readers).
#include <cstdint>
#include <string>
#include <string_view>

namespace cyclecert::html {

struct VerdictStyle {
  std::string_view cssClass;    // v-pass, v-fail, v-engine-failure, v-not-applicable, v-untested, v-expected, v-unknown
  std::string_view symbol;
  std::string_view label;       // "engine failure"
  std::string_view shortLabel;  // for the matrix cells: "eng. failure", "n/a"
};

// "pass", "fail", "engine-failure", "not-applicable", "untested", "expected-failure" (a failure the
// run's expectation file names); anything else is v-unknown.
VerdictStyle verdictStyle(std::string_view verdict);

// <span class="badge v-…">✗ fail</span>
std::string verdictBadge(std::string_view verdict);
// <span class="pill v-…">✗ 42 fail</span>, dimmed when the count is 0.
std::string verdictPill(std::string_view verdict, std::uint64_t count);

}  // namespace cyclecert::html
