#include "reports/html/verdict_style.h"

namespace cyclecert::html {

VerdictStyle verdictStyle(std::string_view verdict) {
  if (verdict == "pass") return {"v-pass", "\u2713", "pass", "pass"};
  if (verdict == "fail") return {"v-fail", "\u2717", "fail", "fail"};
  if (verdict == "engine-failure") return {"v-engine-failure", "\u26a0", "engine failure", "eng. failure"};
  if (verdict == "not-applicable") return {"v-not-applicable", "\u2013", "not applicable", "n/a"};
  if (verdict == "expected-failure") return {"v-expected", "\u2298", "expected failure", "expected"};
  if (verdict == "untested") return {"v-untested", "\u25cb", "untested", "untested"};
  return {"v-unknown", "?", "unknown verdict", "unknown"};
}

std::string verdictBadge(std::string_view verdict) {
  const VerdictStyle s = verdictStyle(verdict);
  return "<span class=\"badge " + std::string(s.cssClass) + "\">" + std::string(s.symbol) + " " +
         std::string(s.label) + "</span>";
}

std::string verdictPill(std::string_view verdict, std::uint64_t count) {
  const VerdictStyle s = verdictStyle(verdict);
  return "<span class=\"pill " + std::string(s.cssClass) + (count == 0 ? " zero" : "") + "\">" +
         std::string(s.symbol) + " <b>" + std::to_string(count) + "</b> " + std::string(s.label) + "</span>";
}

}  // namespace cyclecert::html
