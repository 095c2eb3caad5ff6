#include "harness/judge/toolpath_compare.h"

#include <cmath>
#include <sstream>

#include "reference/model/toolpath_json.h"

namespace cyclecert {

std::string describeMove(const Move& m) {
  std::ostringstream s;
  s << kindName(m.kind) << " " << shapeName(m.shape) << " to (x " << m.to.x << ", z " << m.to.z << ")";
  if (m.center) s << " centre (x " << m.center->x << ", z " << m.center->z << ")";
  if (m.feed) s << " F" << *m.feed;
  if (m.dwell) s << " dwell " << *m.dwell << " s";
  if (m.singleBlockStop) s << " (single-block stop)";
  return s.str();
}

std::optional<MoveDivergence> firstMoveDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                                  double tol, const std::string& expectedName,
                                                  const std::string& actualName) {
  const std::size_t n = std::min(expected.size(), actual.size());
  for (std::size_t i = 0; i < n; ++i) {
    const Move& e = expected[i];
    const Move& a = actual[i];
    bool same = e.kind == a.kind && e.shape == a.shape && nearlyEqual(e.to, a.to, tol);
    if (same && e.center) same = a.center && nearlyEqual(*e.center, *a.center, tol);
    if (same && e.feed) same = a.feed && std::abs(*e.feed - *a.feed) <= tol;
    if (same && e.dwell) same = std::abs(*e.dwell - a.dwell.value_or(0)) <= tol;
    if (same && e.stopGiven) same = e.singleBlockStop == a.singleBlockStop;
    if (!same) {
      std::ostringstream s;
      s << "move " << i << ": " << expectedName << " " << describeMove(e) << ", " << actualName << " " << describeMove(a);
      return MoveDivergence{i, s.str()};
    }
  }
  if (expected.size() == actual.size()) return std::nullopt;
  std::ostringstream s;
  s << expectedName << " " << expected.size() << " moves, " << actualName << " " << actual.size();
  if (actual.size() > n) s << "; first extra move " << n << ": " << describeMove(actual[n]);
  else s << "; first missing move " << n << ": " << describeMove(expected[n]);
  return MoveDivergence{n, s.str()};
}

std::optional<std::string> firstDivergence(const std::vector<Move>& expected, const std::vector<Move>& actual,
                                           double tol) {
  if (auto d = firstMoveDivergence(expected, actual, tol)) return d->text;
  return std::nullopt;
}

}  // namespace cyclecert
