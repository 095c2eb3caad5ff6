#include "oracles/groove/groove_bounds.h"

#include <algorithm>
#include <array>
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
  const std::size_t n = top.chain_.size();
  top.maxUpTo_.resize(n);
  top.minFrom_.resize(n);
  for (std::size_t k = 0; k < n; ++k) top.maxUpTo_[k] = std::max(k ? top.maxUpTo_[k - 1] : -kInf, top.chain_[k].x);
  for (std::size_t k = n; k-- > 0;) top.minFrom_[k] = std::min(k + 1 < n ? top.minFrom_[k + 1] : kInf, top.chain_[k].x);
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
  const auto [first, end] = segmentsWithin(a, b);
  for (std::size_t k = first; k < end; ++k) {
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
    // The chain's vertices strictly inside (a, b): none before the first whose running maximum
    // passes a, none from the first whose running minimum onwards reaches b.
    const std::size_t from = static_cast<std::size_t>(
        std::upper_bound(maxUpTo_.begin(), maxUpTo_.end(), a) - maxUpTo_.begin());
    const std::size_t to = static_cast<std::size_t>(
        std::lower_bound(minFrom_.begin() + static_cast<long>(from), minFrom_.end(), b) - minFrom_.begin());
    for (std::size_t j = from; j < to; ++j) {
      const Point c = chain_[j];
      if (c.x > a && c.x < b && !below(c.x, std::min(sideOf(c.x, -1), sideOf(c.x, +1)))) return false;
    }
  }
  return outline.size() >= 2;
}

std::pair<std::size_t, std::size_t> PartTop::segmentsWithin(double lo, double hi) const {
  // Segment k (chain_[k − 1] → chain_[k]) reaches no further along u than maxUpTo_[k] and starts
  // no sooner than minFrom_[k − 1]; both are sorted.
  const auto first = std::lower_bound(maxUpTo_.begin() + 1, maxUpTo_.end(), lo);
  const auto end = std::upper_bound(minFrom_.begin() + (first - maxUpTo_.begin()) - 1, minFrom_.end() - 1, hi);
  return {static_cast<std::size_t>(first - maxUpTo_.begin()), static_cast<std::size_t>(end - minFrom_.begin()) + 1};
}

double PartTop::sideOf(double u, int side) const {
  const double c0 = chain_.front().x, c1 = chain_.back().x;
  // Within a nanometre of a vertex, u is that vertex: the segment ending there is on its left,
  // the one starting there on its right (their coordinates are computed, not exact).
  const bool left = side < 0;
  double top = kInf;
  if (left ? u <= c0 + kSlack : u < c0 - kSlack) top = band_.mouthAt(u);
  if (left ? u > c1 + kSlack : u >= c1 - kSlack) top = band_.mouthAt(u);
  const auto [first, end] = segmentsWithin(u - kSlack, u + kSlack);
  for (std::size_t k = first; k < end; ++k) {
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

// Adds a piece after the last one, merged with it when both are one flat step.
void PiecewiseMax::append(std::vector<Piece>& out, Piece piece) {
  if (!(piece.x0 < piece.x1)) return;
  if (!out.empty()) {
    Piece& last = out.back();
    if (last.x1 == piece.x0 && last.m0 == last.m1 && piece.m0 == piece.m1 && last.m1 == piece.m0) {
      last.x1 = piece.x1;
      return;
    }
  }
  out.push_back(piece);
}

void PiecewiseMax::raise(Point p, Point q) {
  const double a = p.x, b = q.x;
  if (!(a < b)) return;
  const Piece line{a, p.z, b, q.z};
  // The pieces the line overlaps are replaced by the new ones over their span (cut at its ends);
  // the pieces before and after it stay.
  const auto first = std::partition_point(pieces_.begin(), pieces_.end(), [&](const Piece& d) { return d.x1 <= a; });
  const auto last = std::partition_point(first, pieces_.end(), [&](const Piece& d) { return d.x0 < b; });
  std::vector<Piece>& out = scratch_;
  out.clear();
  if (first != last && first->x0 < a) append(out, {first->x0, first->m0, a, first->at(a)});
  // The line over [x0, x1] against the piece d there (nullptr: no line reaches): the greater of
  // the two, split where they cross.
  const auto merge = [&](double x0, double x1, const Piece* d) {
    if (!(x0 < x1)) return;
    const double l0 = line.at(x0), l1 = line.at(x1);
    if (!d) {
      append(out, {x0, l0, x1, l1});
      return;
    }
    const double d0 = d->at(x0), d1 = d->at(x1);
    const double e0 = l0 - d0, e1 = l1 - d1;
    if (e0 >= 0 && e1 >= 0) {
      append(out, {x0, l0, x1, l1});
    } else if (e0 <= 0 && e1 <= 0) {
      append(out, {x0, d0, x1, d1});
    } else {
      const double xc = x0 + (x1 - x0) * e0 / (e0 - e1), mc = line.at(xc);
      append(out, {x0, e0 > 0 ? l0 : d0, xc, mc});
      append(out, {xc, mc, x1, e1 > 0 ? l1 : d1});
    }
  };
  double x = a;
  for (auto it = first; it != last; ++it) {
    merge(x, std::max(x, it->x0), nullptr);  // a gap before the piece
    const double end = std::min(it->x1, b);
    merge(std::max(x, it->x0), end, &*it);
    x = std::max(x, end);
  }
  merge(x, b, nullptr);
  if (first != last && std::prev(last)->x1 > b) {
    const Piece& d = *std::prev(last);
    append(out, {b, d.at(b), d.x1, d.m1});
  }
  const auto at = pieces_.erase(first, last);
  pieces_.insert(at, out.begin(), out.end());
}

std::optional<std::pair<double, double>> PiecewiseMax::over(double x0, double x1) const {
  const auto it = std::partition_point(pieces_.begin(), pieces_.end(), [&](const Piece& d) { return d.x1 <= x0; });
  if (it == pieces_.end() || it->x0 > x0 || it->x1 < x1) return std::nullopt;
  return std::pair{it->at(x0), it->at(x1)};
}

std::optional<double> PiecewiseMax::greatestNear(double x, double near) const {
  std::optional<double> greatest;
  for (auto it = std::partition_point(pieces_.begin(), pieces_.end(), [&](const Piece& d) { return d.x1 < x - near; });
       it != pieces_.end() && it->x0 <= x + near; ++it) {
    const double m = it->at(std::clamp(x, it->x0, it->x1));
    greatest = greatest ? std::max(*greatest, m) : m;
  }
  return greatest;
}

void PiecewiseMax::breakpoints(double a, double b, std::vector<double>& out) const {
  for (auto it = std::partition_point(pieces_.begin(), pieces_.end(), [&](const Piece& d) { return d.x1 <= a; });
       it != pieces_.end() && it->x0 < b; ++it) {
    if (it->x0 > a) out.push_back(it->x0);
    if (it->x1 < b) out.push_back(it->x1);
  }
}

namespace {

// The points a..b with the breakpoints between them, sorted, each once.
std::vector<double> intervalEnds(double a, double b, std::vector<double> inner) {
  inner.push_back(a);
  inner.push_back(b);
  std::sort(inner.begin(), inner.end());
  inner.erase(std::unique(inner.begin(), inner.end()), inner.end());
  return inner;
}

}  // namespace

void ClearedOutline::clearDownTo(const std::vector<Point>& outline) {
  for (std::size_t k = 1; k < outline.size(); ++k) deepest_.raise(outline[k - 1], outline[k]);
}

bool ClearedOutline::covers(const std::vector<Point>& outline, double slack) const {
  for (std::size_t k = 1; k < outline.size(); ++k) {
    // A wall (within a nanometre of one: its ends computed two ways) is skipped.
    if (outline[k - 1].x > outline[k].x + kSlack) return false;  // no graph over u: not proven
    if (outline[k].x - outline[k - 1].x <= kSlack) continue;
    if (!coversLine(outline[k - 1], outline[k], slack)) return false;
  }
  return true;
}

// Over each interval between D's breakpoints, the line lies at or above the mouth or at or above
// D there at both ends (each linear there: then over the whole interval).
bool ClearedOutline::coversLine(Point p, Point q, double slack) const {
  const double a = std::max(p.x, band_.uLo), b = std::min(q.x, band_.uHi);
  if (!(a < b)) return true;  // beyond the band: no material
  const auto line = [&](double u) { return depthOn(p, q, u) - slack; };
  std::vector<double> inner;
  deepest_.breakpoints(a, b, inner);
  const std::vector<double> ends = intervalEnds(a, b, std::move(inner));
  for (std::size_t k = 1; k < ends.size(); ++k) {
    const double u0 = ends[k - 1], u1 = ends[k];
    if (u1 - u0 <= kSlack) continue;  // a sliver between edges computed two ways: thinner than that
    const double l0 = line(u0), l1 = line(u1);
    if (l0 <= band_.mouthAt(u0) && l1 <= band_.mouthAt(u1)) continue;
    const auto d = deepest_.over(u0, u1);
    if (!d || l0 > d->first || l1 > d->second) return false;
  }
  return true;
}

namespace {

// A point over the rows: x the row's depth w, z the value there.
Point rowPoint(double w, double value) {
  Point p;
  p.x = w;
  p.z = value;
  return p;
}

}  // namespace

void ShadowedRows::clearBehind(Point p, Point q, int side, double shadow) {
  if (p.z > q.z) std::swap(p, q);  // along w
  // The shadow must reach the band's side from every point of the chord.
  if (side < 0 ? std::max(p.x, q.x) - shadow > band_.uLo : std::min(p.x, q.x) + shadow < band_.uHi) return;
  if (side < 0) {
    left_.raise(rowPoint(p.z, p.x), rowPoint(q.z, q.x));
  } else {
    right_.raise(rowPoint(p.z, -p.x), rowPoint(q.z, -q.x));
  }
}

bool ShadowedRows::coversTarget(const std::vector<Point>& chain, double slack) const {
  if (chain.size() < 2) return false;
  // The chain down to its (first) deepest point, and up from its last deepest point, each a
  // function of w: the target's row at depth w runs from the near side's u to the far side's.
  std::size_t deepestFirst = 0, deepestLast = 0;
  for (std::size_t k = 0; k < chain.size(); ++k) {
    if (chain[k].z > chain[deepestFirst].z) deepestFirst = deepestLast = k;
    if (chain[k].z == chain[deepestFirst].z) deepestLast = k;
  }
  const double wFloor = chain[deepestFirst].z, wTop = band_.shallowestMouth(band_.uLo, band_.uHi);
  if (!(wTop < wFloor)) return false;
  PiecewiseMax nearSide, farSide;  // over w: u (near), −u (far)
  for (std::size_t k = 1; k <= deepestFirst; ++k) {
    if (chain[k].z < chain[k - 1].z - kSlack) return false;  // not down all the way: not proven
    nearSide.raise(rowPoint(chain[k - 1].z, chain[k - 1].x), rowPoint(chain[k].z, chain[k].x));
  }
  for (std::size_t k = deepestLast + 1; k < chain.size(); ++k) {
    if (chain[k].z > chain[k - 1].z + kSlack) return false;
    farSide.raise(rowPoint(chain[k].z, -chain[k].x), rowPoint(chain[k - 1].z, -chain[k - 1].x));
  }
  for (std::size_t k = deepestFirst; k < deepestLast; ++k) {
    if (chain[k].z < wFloor - kSlack) return false;  // the floor between them is flat
  }
  // Above the chain's ends, straight up.
  const Point front = chain.front(), back = chain.back();
  nearSide.raise(rowPoint(wTop - 1, front.x), rowPoint(front.z, front.x));
  farSide.raise(rowPoint(wTop - 1, -back.x), rowPoint(back.z, -back.x));
  std::vector<double> inner;
  for (const PiecewiseMax* m : std::array<const PiecewiseMax*, 4>{&left_, &right_, &nearSide, &farSide}) {
    m->breakpoints(wTop, wFloor, inner);
  }
  const std::vector<double> ends = intervalEnds(wTop, wFloor, std::move(inner));
  for (std::size_t k = 1; k < ends.size(); ++k) {
    const double w0 = ends[k - 1], w1 = ends[k];
    if (w1 - w0 <= kSlack) continue;  // a sliver between edges computed two ways: thinner than that
    const auto a = nearSide.over(w0, w1), minusB = farSide.over(w0, w1);
    if (!a || !minusB) return false;
    const auto l = left_.over(w0, w1), minusR = right_.over(w0, w1);
    // Each linear over the interval: a condition at both ends holds all along it. Above the mouth
    // (w < u·tan∠p) is air: with ∠p > 0 a row's material lies at u ≤ w/tan∠p, with ∠p < 0 at
    // u ≥ w/tan∠p.
    const double t = band_.tanSlope;
    const auto mouthU = [&](double w) { return w / t; };
    const bool air = (t > 0 && mouthU(w0) <= a->first + slack && mouthU(w1) <= a->second + slack) ||
                     (t < 0 && mouthU(w0) >= -minusB->first - slack && mouthU(w1) >= -minusB->second - slack);
    const bool leftReachesB =
        l && ((l->first >= -minusB->first - slack && l->second >= -minusB->second - slack) ||
              (t > 0 && l->first >= mouthU(w0) - slack && l->second >= mouthU(w1) - slack));
    const bool rightReachesA =
        minusR && ((-minusR->first <= a->first + slack && -minusR->second <= a->second + slack) ||
                   (t < 0 && -minusR->first <= mouthU(w0) + slack && -minusR->second <= mouthU(w1) + slack));
    const bool rowGone = l && minusR && l->first >= -minusR->first - slack && l->second >= -minusR->second - slack;
    if (!air && !leftReachesB && !rightReachesA && !rowGone) return false;
  }
  return true;
}

bool ShadowedRows::clears(Point p, Point q, double slack) const {
  if (p.z > q.z) std::swap(p, q);  // along w
  const double wTop = band_.shallowestMouth(band_.uLo, band_.uHi);
  if (q.z <= wTop) return true;  // above the band's top: air
  // The chord's u at w (a chord along u: its row, from the nearer end to the farther).
  const auto uAt = [&](double w, bool far) {
    if (q.z - p.z <= kSlack) return far ? std::max(p.x, q.x) : std::min(p.x, q.x);
    return p.x + (q.x - p.x) * (w - p.z) / (q.z - p.z);
  };
  // A chord along u: its row, where the shadows ending within a nanometre of it hold (its points
  // lie on or within that of the cleared rows' edge). Else the intervals between the bounds'
  // breakpoints over the chord's rows below the top.
  const bool row = q.z - p.z <= kSlack;
  const auto valuesOn = [&](const PiecewiseMax& m, double a, double b) -> std::optional<std::pair<double, double>> {
    if (!row) return m.over(a, b);
    const auto v = m.greatestNear(a, kSlack);
    if (!v) return std::nullopt;
    return std::pair{*v, *v};
  };
  std::vector<double> inner;
  const double w0 = row ? q.z : std::max(p.z, wTop), w1 = q.z;
  if (!row) {
    left_.breakpoints(w0, w1, inner);
    right_.breakpoints(w0, w1, inner);
  }
  const std::vector<double> ends = intervalEnds(w0, w1, std::move(inner));
  for (std::size_t k = 0; k + 1 < std::max<std::size_t>(ends.size(), 2); ++k) {
    const double a = ends[k], b = ends.size() > 1 ? ends[k + 1] : ends[k];
    const double uLo0 = uAt(a, false), uLo1 = uAt(b, false), uHi0 = uAt(a, true), uHi1 = uAt(b, true);
    if ((uHi0 <= band_.uLo && uHi1 <= band_.uLo) || (uLo0 >= band_.uHi && uLo1 >= band_.uHi)) continue;  // beside
    const auto l = valuesOn(left_, a, b), minusR = valuesOn(right_, a, b);
    const bool behindLeft = l && uHi0 <= l->first + slack && uHi1 <= l->second + slack;
    const bool behindRight = minusR && uLo0 >= -minusR->first - slack && uLo1 >= -minusR->second - slack;
    const bool rowGone = l && minusR && l->first >= -minusR->first - slack && l->second >= -minusR->second - slack;
    if (!behindLeft && !behindRight && !rowGone) return false;
  }
  return true;
}

}  // namespace cyclecert
