#include "oracles/groove/groove_bounds.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>

namespace cyclecert {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kSlack = 1e-9;  // mm: equal depths computed two ways

// w on the segment p → q at u (p.x ≤ u ≤ q.x, p.x < q.x).
double depthOn(Point p, Point q, double u) { return p.z + (q.z - p.z) * (u - p.x) / (q.x - p.x); }

}  // namespace

namespace {

// The extent grown to hold the tool at p.
void extendBy(ToolExtent& e, Point p, double width) {
  e.uFrom = std::min(e.uFrom, p.x - width);
  e.uTo = std::max(e.uTo, p.x);
  e.wShallowest = std::min(e.wShallowest, p.z);
  e.wDeepest = std::max(e.wDeepest, p.z);
}

bool isFinite(Point p) { return std::isfinite(p.z) && std::isfinite(p.x); }

// A line flatten would take (finite, a valid chord tolerance): its points are its two ends.
bool isPlainLine(const Segment& s, double chordTolerance) {
  return !s.isArc() && isFinite(s.from) && isFinite(s.to) && chordTolerance > 0 && std::isfinite(chordTolerance);
}

}  // namespace

ToolExtent toolExtent(const Segment& localMove, double width, double chordTolerance) {
  ToolExtent e{kInf, -kInf, kInf, -kInf};
  if (isPlainLine(localMove, chordTolerance)) {  // no vector per move
    extendBy(e, localMove.from, width);
    extendBy(e, localMove.to, width);
    return e;
  }
  for (Point p : flatten(localMove, chordTolerance)) extendBy(e, p, width);  // (throws for what it refuses)
  return e;
}

std::optional<PartTop> PartTop::of(const GrooveOutline& target, const BandFrame& band, double chordTolerance) {
  PartTop top;
  top.band_ = band;
  for (const Segment& s : target.chain) appendFlattened(top.chain_, s, chordTolerance);
  if (top.chain_.empty()) return std::nullopt;
  for (std::size_t k = 1; k < top.chain_.size(); ++k) {
    if (top.chain_[k].x < top.chain_[k - 1].x - kSlack) return std::nullopt;
  }
  return top;
}

double PartTop::shallowestOver(double u0, double u1) const {
  const double a = std::max(u0, band_.uLo), b = std::min(u1, band_.uHi);
  if (a > b) return kInf;
  if (a == b) return std::max(sideOf(a, -1), sideOf(a, +1));
  const double c0 = chain_.front().x, c1 = chain_.back().x;
  double top = kInf;
  // Beside the groove the part begins at the mouth (the band's top).
  // Ends within a nanometre of the span's are beside it (coordinates computed two ways).
  if (a < c0 - kSlack) top = std::min(top, band_.shallowestMouth(a, std::min(b, c0)));
  if (b > c1 + kSlack) top = std::min(top, band_.shallowestMouth(std::max(a, c1), b));
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    const Point p = chain_[k - 1], q = chain_[k];
    const double lo = std::min(p.x, q.x), hi = std::max(p.x, q.x);
    if (hi <= a + kSlack || lo >= b - kSlack) continue;  // a wall at an end of the span stands beside it
    if (hi - lo <= kSlack) {
      top = std::min({top, p.z, q.z});
      continue;
    }
    top = std::min({top, depthOn(p, q, std::max(a, lo)), depthOn(p, q, std::min(b, hi))});
  }
  return top;
}

bool PartTop::liesBelow(const std::vector<Point>& outline, double slack) const {
  for (std::size_t k = 1; k < outline.size(); ++k) {
    const Point p = outline[k - 1], q = outline[k];
    if (!(p.x < q.x)) return false;  // no graph over u: not proven
    const double a = std::max(p.x, band_.uLo), b = std::min(q.x, band_.uHi);
    if (a > b) continue;  // beyond the band: no part
    const auto below = [&](double u, double top) { return top >= depthOn(p, q, u) - slack; };
    // The piece's ends: the part's side within the piece; an outline's inner vertex: both sides.
    const bool innerStart = k > 1 && a == p.x, innerEnd = k + 1 < outline.size() && b == q.x;
    if (!below(a, innerStart ? std::min(sideOf(a, -1), sideOf(a, +1)) : sideOf(a, +1))) return false;
    if (!below(b, innerEnd ? std::min(sideOf(b, -1), sideOf(b, +1)) : sideOf(b, -1))) return false;
    for (Point c : chain_) {
      if (c.x > a && c.x < b && !below(c.x, std::min(sideOf(c.x, -1), sideOf(c.x, +1)))) return false;
    }
  }
  return outline.size() >= 2;
}

double PartTop::sideOf(double u, int side) const {
  const double c0 = chain_.front().x, c1 = chain_.back().x;
  // Within a nanometre of a vertex, u is that vertex: the segment ending there is on its left,
  // the one starting there on its right (their coordinates are computed, not exact).
  const bool left = side < 0;
  double top = kInf;
  if (left ? u <= c0 + kSlack : u < c0 - kSlack) top = band_.mouthAt(u);
  if (left ? u > c1 + kSlack : u >= c1 - kSlack) top = band_.mouthAt(u);
  for (std::size_t k = 1; k < chain_.size(); ++k) {
    const Point p = chain_[k - 1], q = chain_[k];
    const double lo = std::min(p.x, q.x), hi = std::max(p.x, q.x);
    if (hi - lo <= kSlack) continue;  // a wall: between the sides
    if (left ? (lo < u - kSlack && u <= hi + kSlack) : (lo - kSlack <= u && u < hi - kSlack)) {
      top = std::min(top, depthOn(p, q, std::clamp(u, lo, hi)));
    }
  }
  return top;
}

double ClearedStaircase::depthAt(std::map<double, double>::const_iterator it) const {
  return it == steps_.begin() ? -kInf : std::prev(it)->second;
}

double ClearedStaircase::snapped(double u) const {
  const auto next = steps_.lower_bound(u);
  if (next != steps_.end() && next->first - u <= kSlack) return next->first;
  if (next != steps_.begin() && u - std::prev(next)->first <= kSlack) return std::prev(next)->first;
  return u;
}

void ClearedStaircase::clearDownTo(double u0, double u1, double w) {
  // The edges of neighbouring pecks computed two ways (u − r of one, u of the other) differ in the
  // last bits: snapped together, no sliver of "not cleared" stands between them.
  const double a = snapped(std::max(u0, band_.uLo)), b = snapped(std::min(u1, band_.uHi));
  if (!(a < b)) return;
  steps_.try_emplace(b, depthAt(steps_.upper_bound(b)));
  steps_.try_emplace(a, depthAt(steps_.upper_bound(a)));
  for (auto it = steps_.find(a); it->first < b; ++it) it->second = std::max(it->second, w);
  // Neighbouring steps of one depth are one step.
  auto it = steps_.find(a);
  if (it != steps_.begin()) --it;
  while (it != steps_.end() && it->first <= b) {
    const auto next = std::next(it);
    if (next != steps_.end() && next->second == it->second) {
      steps_.erase(next);
    } else {
      it = next;
    }
  }
}

bool ClearedStaircase::clearOver(double u0, double u1, double w) const {
  if (u0 != u1) return goneAbove(u0, u1, w);
  // A point on a step's edge lies on the boundary of what stands: it crosses nothing when either
  // side is gone.
  const double u = u0;
  if (u < band_.uLo || u > band_.uHi) return true;
  const auto gone = [&](double cleared) { return cleared >= w - kSlack || band_.mouthAt(u) >= w - kSlack; };
  return gone(depthAt(steps_.upper_bound(u))) || gone(depthAt(steps_.lower_bound(u)));
}

bool ClearedStaircase::goneAbove(double u0, double u1, double w) const {
  double a = std::max(u0, band_.uLo), b = std::min(u1, band_.uHi);
  if (a > b) return true;
  // A span's ends computed two ways (a blade's u − r, a step's edge) differ in the last bits: a
  // nanometre inside them, the span does not reach into the neighbouring step.
  if (b - a > 2 * kSlack) a += kSlack, b -= kSlack;
  const auto gone = [&](double s, double e, double cleared) {
    return cleared >= w - kSlack || band_.shallowestMouth(s, e) >= w - kSlack;
  };
  const auto first = steps_.upper_bound(a);
  if (a == b) return gone(a, a, depthAt(first)) && gone(a, a, depthAt(steps_.lower_bound(a)));
  double s = a, cleared = depthAt(first);
  for (auto it = first; it != steps_.end() && it->first < b; ++it) {
    if (!gone(s, it->first, cleared)) return false;
    s = it->first;
    cleared = it->second;
  }
  return gone(s, b, cleared);
}

std::vector<std::vector<Point>> ClearedStaircase::outlines(double top) const {
  std::vector<std::vector<Point>> rings;
  std::vector<std::pair<double, double>> run;  // (u where a step starts, its depth)
  const auto close = [&](double end) {
    if (run.empty()) return;
    std::vector<Point> ring{grooveUW(run.front().first, top), grooveUW(end, top)};
    for (auto k = run.size(); k-- > 0;) {
      ring.push_back(grooveUW(k + 1 < run.size() ? run[k + 1].first : end, run[k].second));
      ring.push_back(grooveUW(run[k].first, run[k].second));
    }
    rings.push_back(std::move(ring));
    run.clear();
  };
  for (auto it = steps_.begin(); it != steps_.end(); ++it) {
    if (it->second > top) {
      run.emplace_back(it->first, it->second);
    } else {
      close(it->first);
    }
  }
  return rings;
}

}  // namespace cyclecert
