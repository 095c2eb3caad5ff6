#include "harness/toolpath_compare.h"

#include <cmath>
#include <sstream>

#include "reference/model/toolpath_json.h"

namespace cyclecert {

namespace {
std::string describe(const Move& m) {
  std::ostringstream s;
  s << kindName(m.kind) << " " << shapeName(m.shape) << " to (x " << m.to.x << ", z " << m.to.z << ")";
  if (m.center) s << " centre (x " << m.center->x << ", z " << m.center->z << ")";
  if (m.feed) s << " F" << *m.feed;
  if (m.singleBlockStop) s << " (single-block stop)";
  return s.str();
}
}  // namespace

std::optional<std::string> firstDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                           double tol) {
  const std::size_t n = std::min(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Move& e = expected[i];
    const Move& a = actual[i];
    bool same = e.kind == a.kind && e.shape == a.shape && nearlyEqual(e.to, a.to, tol);
    if (same && e.center) same = a.center && nearlyEqual(*e.center, *a.center, tol);
    if (same && e.feed) same = a.feed && std::abs(*e.feed - *a.feed) <= tol;
    if (same && e.stopGiven) same = e.singleBlockStop == a.singleBlockStop;
    if (!same) {
      std::ostringstream s;
      s << "move " << i << ": expected " << describe(e) << ", got " << describe(a);
      return s.str();
    }
  }
  if (expected.size() != actual.size()) {
    std::ostringstream s;
    s << "expected " << expected.size() << " moves, got " << actual.size();
    if (actual.size() > n) s << "; first extra move " << n << ": " << describe(actual[n]);
    else s << "; first missing move " << n << ": " << describe(expected[n]);
    return s.str();
  }
  return std::nullopt;
}

}  // namespace cyclecert
