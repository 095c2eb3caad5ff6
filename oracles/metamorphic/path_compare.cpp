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

// The distance of `p` from the line through `a` and `b` (from `a` when they coincide).
double offLine(Point p, Point a, Point b) {
  const Point whole = b - a, d = p - a;
  const double length = std::hypot(whole.z, whole.x);
  if (length == 0) return std::hypot(d.z, d.x);
  return std::abs(d.z * whole.x - d.x * whole.z) / length;
}

// True when `next` may continue `last` as one line: both lines of the same kind and feed, going on
// forwards, the joint within tol of the line from where `last` starts to where `next` ends — a test
// of the three points alone, so that it does not depend on how the moves around were merged.
bool linesMayJoin(Point from, const Move& last, const Move& next, double tol) {
  if (last.shape != SegmentKind::Line || next.shape != SegmentKind::Line) return false;
  if (last.kind != next.kind || !sameFeed(last.feed, next.feed, tol)) return false;
  const Point a = last.to - from, b = next.to - last.to;
  return a.z * b.z + a.x * b.x > 0 && offLine(last.to, from, next.to) <= tol;
}

// True when `next` continues the arc `last`: the same direction around the same centre (within tol).
bool arcContinues(const Move& last, const Move& next, double tol) {
  if (last.shape == SegmentKind::Line || last.shape != next.shape) return false;
  if (last.kind != next.kind || !sameFeed(last.feed, next.feed, tol)) return false;
  return last.center && next.center && nearlyEqual(*last.center, *next.center, tol);
}

// Douglas–Peucker over the points first…last of a run of lines: marks in `keep` the points the
// run needs so that every dropped point lies within tol of the line that replaces it. The point
// farthest from the chord is kept first, so a run and the same run with points added on its lines
// (a split block) keep the same corners.
void markCorners(const std::vector<Point>& points, std::size_t first, std::size_t last, double tol,
                 std::vector<bool>& keep) {
  if (last <= first + 1) return;
  std::size_t farthest = first;
  double distance = -1;
  for (std::size_t i = first + 1; i < last; ++i) {
    const double d = offLine(points[i], points[first], points[last]);
    if (d > distance) {
      distance = d;
      farthest = i;
    }
  }
  if (distance <= tol) return;
  keep[farthest] = true;
  markCorners(points, first, farthest, tol, keep);
  markCorners(points, farthest, last, tol, keep);
}

// The moves of a run of lines (moves[begin…end), starting at `from`) with the points Douglas–Peucker
// drops removed: each kept move is the run's move that ends at the kept point.
void appendSimplifiedRun(const std::vector<Move>& moves, std::size_t begin, std::size_t end, Point from, double tol,
                         std::vector<Move>& out) {
  std::vector<Point> points{from};
  for (std::size_t i = begin; i < end; ++i) points.push_back(moves[i].to);
  std::vector<bool> keep(points.size(), false);
  keep.back() = true;
  markCorners(points, 0, points.size() - 1, tol, keep);
  for (std::size_t i = begin; i < end; ++i) {
    if (keep[i - begin + 1]) out.push_back(moves[i]);
  }
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
  // The moves that move (a negligible move is dropped, as compareToolpaths does).
  std::vector<Move> moving;
  Point at = path.start;
  for (const Move& m : path.moves) {
    if (nearlyEqual(at, m.to, tol)) continue;
    moving.push_back(m);
    at = m.to;
  }
  Toolpath merged = path;
  merged.moves.clear();
  std::size_t i = 0;
  while (i < moving.size()) {
    const Point from = merged.moves.empty() ? path.start : merged.moves.back().to;
    // A run of lines each joint of which may be dropped (linesMayJoin), simplified as a whole.
    std::size_t end = i + 1;
    Point runFrom = from;
    while (end < moving.size() && linesMayJoin(end - 1 == i ? runFrom : moving[end - 2].to, moving[end - 1],
                                               moving[end], tol)) {
      ++end;
    }
    if (end > i + 1) {
      appendSimplifiedRun(moving, i, end, runFrom, tol, merged.moves);
      i = end;
      continue;
    }
    if (!merged.moves.empty() && arcContinues(merged.moves.back(), moving[i], tol)) {
      merged.moves.back().to = moving[i].to;
    } else {
      merged.moves.push_back(moving[i]);
    }
    ++i;
  }
  return merged;
}

std::optional<std::string> compareGeometry(const Toolpath& expected, const Toolpath& actual, double tol) {
  return compareToolpaths(mergeContinuations(expected, tol), mergeContinuations(actual, tol), tol);
}

}  // namespace cyclecert
