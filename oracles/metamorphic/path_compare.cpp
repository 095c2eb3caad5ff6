#include "oracles/metamorphic/path_compare.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "reference/model/toolpath_json.h"

namespace cyclecert {

namespace {

std::string describe(Point p) {
  std::ostringstream s;
  s.precision(10);
  s << "(z " << p.z << ", x " << p.x << ")";
  return s.str();
}

std::string describe(const Move& m) {
  std::ostringstream s;
  s.precision(10);
  s << kindName(m.kind) << " " << shapeName(m.shape) << " to " << describe(m.to);
  if (m.center) s << " centre " << describe(*m.center);
  if (m.feed) s << " F" << *m.feed;
  if (m.phase != MovePhase::None) s << " [" << phaseName(m.phase) << (m.pass ? " " + std::to_string(m.pass) : "") << "]";
  return s.str();
}

bool sameFeed(const std::optional<double>& e, const std::optional<double>& a, double tol) {
  if (!e || !a) return e.has_value() == a.has_value();
  return std::abs(*e - *a) <= tol * std::max(1.0, std::abs(*e));
}

bool sameMove(const Move& e, const Move& a, double tol) {
  if (e.kind != a.kind || e.shape != a.shape || !nearlyEqual(e.to, a.to, tol)) return false;
  if (e.center.has_value() != a.center.has_value()) return false;
  if (e.center && !nearlyEqual(*e.center, *a.center, tol)) return false;
  return sameFeed(e.feed, a.feed, tol);
}

std::string describeAlarm(const std::optional<Alarm>& a) {
  return a ? "alarm " + a->code + " (line " + std::to_string(a->line) + ": " + a->message + ")" : "no alarm";
}

// True when `next` continues `last` (which starts at `from`) as one line or one arc.
bool continues(Point from, const Move& last, const Move& next, double tol) {
  if (last.kind != next.kind || last.shape != next.shape || !sameFeed(last.feed, next.feed, tol)) return false;
  if (last.shape == SegmentKind::Line) {
    const Point a = last.to - from, b = next.to - last.to;
    const Point whole = next.to - from;
    const double length = std::hypot(whole.z, whole.x);
    if (length <= tol) return false;
    const double offLine = std::abs(a.z * whole.x - a.x * whole.z) / length;  // last.to from the joined line
    return offLine <= tol && a.z * b.z + a.x * b.x > 0;
  }
  return last.center && next.center && nearlyEqual(*last.center, *next.center, tol);
}

// The indices of the moves that end farther than tol from where they start.
std::vector<std::size_t> movesThatMove(const Toolpath& path, double tol) {
  std::vector<std::size_t> kept;
  Point at = path.start;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    if (nearlyEqual(at, path.moves[i].to, tol)) continue;
    kept.push_back(i);
    at = path.moves[i].to;
  }
  return kept;
}

}  // namespace

std::optional<std::string> compareToolpaths(const Toolpath& expected, const Toolpath& actual, double tol) {
  if (expected.alarm.has_value() != actual.alarm.has_value() ||
      (expected.alarm && expected.alarm->code != actual.alarm->code)) {
    return "expected " + describeAlarm(expected.alarm) + ", got " + describeAlarm(actual.alarm);
  }
  // Without moves (no cycle reached, or an alarm before it) the start point is not set.
  const bool anyMoves = !expected.moves.empty() || !actual.moves.empty();
  if (anyMoves && !nearlyEqual(expected.start, actual.start, tol)) {
    return "start point: expected " + describe(expected.start) + ", got " + describe(actual.start);
  }
  const std::vector<std::size_t> e = movesThatMove(expected, tol), a = movesThatMove(actual, tol);
  const auto label = [](const char* which, std::size_t i) { return std::string(which) + " move " + std::to_string(i); };
  const std::size_t n = std::min(e.size(), a.size());
  for (std::size_t k = 0; k < n; ++k) {
    const Move& em = expected.moves[e[k]];
    const Move& am = actual.moves[a[k]];
    if (!sameMove(em, am, tol)) {
      return label("expected", e[k]) + ": " + describe(em) + "; " + label("actual", a[k]) + ": " + describe(am);
    }
  }
  if (e.size() != a.size()) {
    std::string s = "expected " + std::to_string(e.size()) + " moves, got " + std::to_string(a.size());
    if (a.size() > n) return s + "; first extra: " + label("actual", a[n]) + ": " + describe(actual.moves[a[n]]);
    return s + "; first missing: " + label("expected", e[n]) + ": " + describe(expected.moves[e[n]]);
  }
  return std::nullopt;
}

Toolpath mergeContinuations(const Toolpath& path, double tol) {
  Toolpath merged = path;
  merged.moves.clear();
  Point lastFrom = path.start;  // where the last merged move starts
  for (const Move& m : path.moves) {
    const Point from = merged.moves.empty() ? path.start : merged.moves.back().to;
    if (nearlyEqual(from, m.to, tol)) continue;  // a negligible move (a full circle is no lathe move)
    if (!merged.moves.empty() && continues(lastFrom, merged.moves.back(), m, tol)) {
      merged.moves.back().to = m.to;
      continue;
    }
    lastFrom = from;
    merged.moves.push_back(m);
  }
  return merged;
}

std::optional<std::string> compareGeometry(const Toolpath& expected, const Toolpath& actual, double tol) {
  return compareToolpaths(mergeContinuations(expected, tol), mergeContinuations(actual, tol), tol);
}

}  // namespace cyclecert
