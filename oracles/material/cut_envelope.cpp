#include "oracles/material/cut_envelope.h"

#include <algorithm>
#include <cmath>

namespace cyclecert {

namespace {

using Piece = CutEnvelope::Piece;

// Depths closer than this are the same envelope (a feed retracing an earlier one lowers nothing).
constexpr double kSameDepth = 1e-12;

Piece part(const Piece& p, double a, double b) { return {a, p.depthAt(a), b, p.depthAt(b)}; }

bool collinear(const Piece& left, const Piece& right) {
  if (std::abs(right.c0 - left.c1) > kTidyDistance || std::abs(right.d0 - left.d1) > kSameDepth) return false;
  const double slopeLeft = (left.d1 - left.d0) / (left.c1 - left.c0);
  const double slopeRight = (right.d1 - right.d0) / (right.c1 - right.c0);
  return std::abs(slopeLeft - slopeRight) <= 1e-12 * std::max(1.0, std::abs(slopeLeft));
}

// Appends a piece of some length; collinear neighbours become one piece, so that the envelope grows
// with the feeds' shape, not with their number.
void push(std::vector<Piece>& out, const Piece& p) {
  if (p.c1 - p.c0 <= kTidyDistance) return;
  if (!out.empty() && collinear(out.back(), p)) {
    out.back().c1 = p.c1;
    out.back().d1 = p.d1;
  } else {
    out.push_back(p);
  }
}

// On [a, b] the lower of two pieces, split where they cross. `lowered` says whether the new piece
// came lower than the old one anywhere.
// (The depths at a and b, once found, make the parts: part() would find them again.)
void pushLower(std::vector<Piece>& out, const Piece& old, const Piece& fresh, double a, double b, bool& lowered) {
  const double oa = old.depthAt(a), ob = old.depthAt(b), fa = fresh.depthAt(a), fb = fresh.depthAt(b);
  if (fa >= oa - kSameDepth && fb >= ob - kSameDepth) return push(out, {a, oa, b, ob});
  lowered = true;
  if (fa <= oa && fb <= ob) return push(out, {a, fa, b, fb});
  // They cross between a and b: the gaps fa − oa and fb − ob have opposite signs.
  const double t = (fa - oa) / ((fa - oa) - (fb - ob));
  const double c = a + t * (b - a);
  const Piece& first = fa < oa ? fresh : old;
  const Piece& second = fa < oa ? old : fresh;
  push(out, {a, fa < oa ? fa : oa, c, first.depthAt(c)});
  push(out, {c, second.depthAt(c), b, fa < oa ? ob : fb});
}

// Replaces [first, last) of `pieces` by `with`, moving the pieces after them once (an erase and an
// insert would move them twice).
void splice(std::vector<Piece>& pieces, std::vector<Piece>::iterator first, std::vector<Piece>::iterator last,
            const std::vector<Piece>& with) {
  const std::size_t replaced = static_cast<std::size_t>(last - first);
  if (with.size() <= replaced) {
    pieces.erase(std::copy(with.begin(), with.end(), first), last);
  } else {
    const auto overwritten = with.begin() + static_cast<std::ptrdiff_t>(replaced);
    pieces.insert(std::copy(with.begin(), overwritten, first), overwritten, with.end());
  }
}

}  // namespace

double CutEnvelope::Piece::depthAt(double c) const {
  if (c <= c0) return d0;
  if (c >= c1) return d1;
  return d0 + (c - c0) / (c1 - c0) * (d1 - d0);
}

bool CutEnvelope::lower(const std::vector<Point>& path, const DepthFrame& frame) {
  std::vector<Piece>& fresh = fresh_;  // the path's chords, left to right (a graph's chords do not overlap)
  fresh.clear();
  for (std::size_t i = 1; i < path.size(); ++i) {
    double c0 = frame.cut(path[i - 1]), d0 = frame.depth(path[i - 1]);
    double c1 = frame.cut(path[i]), d1 = frame.depth(path[i]);
    if (std::abs(c1 - c0) <= kTidyDistance) continue;
    if (c0 > c1) {
      std::swap(c0, c1);
      std::swap(d0, d1);
    }
    fresh.push_back({c0, d0, c1, d1});
  }
  if (fresh.empty()) return false;
  if (fresh.size() > 1 && fresh.front().c0 > fresh.back().c0) std::reverse(fresh.begin(), fresh.end());
  return lowerTo(fresh);
}

// Merges the path's pieces into the envelope's in one sweep over the stretches where either list
// has a piece: the old piece where no new one lies, the new one where no old one does (no feed was
// there yet), the lower of the two where both do. Only the old pieces the new ones reach change
// (with a neighbour each side, which a new piece may continue in a line): those are merged, and
// the result spliced in.
bool CutEnvelope::lowerTo(const std::vector<Piece>& fresh) {
  const auto byEnd = [](const Piece& p, double c) { return p.c1 < c; };
  const auto byStart = [](double c, const Piece& p) { return c < p.c0; };
  auto first = std::lower_bound(pieces_.begin(), pieces_.end(), fresh.front().c0, byEnd);
  auto last = std::upper_bound(first, pieces_.end(), fresh.back().c1, byStart);
  if (first != pieces_.begin()) --first;
  if (last != pieces_.end()) ++last;
  bool lowered = false;
  std::vector<Piece>& out = spare_;
  out.clear();
  auto i = first;
  std::size_t j = 0;
  double merged = -INFINITY;  // everything left of here is in `out`
  while (i != last || j < fresh.size()) {
    const Piece* old = i != last ? &*i : nullptr;
    const Piece* now = j < fresh.size() ? &fresh[j] : nullptr;
    const double oldStart = old ? std::max(old->c0, merged) : INFINITY;
    const double nowStart = now ? std::max(now->c0, merged) : INFINITY;
    const double start = std::min(oldStart, nowStart);
    const bool inOld = old && oldStart <= start, inNow = now && nowStart <= start;
    // The stretch ends where a piece over it ends or the next piece begins.
    const double end = std::min(old ? (inOld ? old->c1 : old->c0) : INFINITY, now ? (inNow ? now->c1 : now->c0) : INFINITY);
    if (inOld && inNow) {
      pushLower(out, *old, *now, start, end, lowered);
    } else if (inOld) {
      push(out, part(*old, start, end));
    } else {
      push(out, part(*now, start, end));
      lowered = lowered || end - start > kTidyDistance;
    }
    merged = end;
    if (old && old->c1 <= merged) ++i;
    if (now && now->c1 <= merged) ++j;
  }
  splice(pieces_, first, last, out);
  return lowered;
}


std::vector<std::pair<double, double>> CutEnvelope::belowTop(double cMin, double cMax, double dBottom,
                                                             double dTop) const {
  // (cut, depth) from cMin to cMax, written in place: a piece gives at most three points, and each
  // gap before a piece or after the last two.
  std::vector<std::pair<double, double>> top(5 * pieces_.size() + 2);
  auto* end = top.data();
  const auto at = [&](double c, double d) { *end++ = {c, std::clamp(d, dBottom, dTop)}; };
  walk(
      cMin, cMax,
      [&](const Piece& p) {
        if (p.c1 <= p.c0) return;  // touches the box only
        at(p.c0, p.d0);
        // Where the piece rises through the top, the top takes over.
        if ((p.d0 - dTop) * (p.d1 - dTop) < 0) at(p.c0 + (dTop - p.d0) / (p.d1 - p.d0) * (p.c1 - p.c0), dTop);
        at(p.c1, p.d1);
      },
      [&](double g0, double g1) {
        if (g1 - g0 <= kTidyDistance) return;
        at(g0, dTop);  // a gap: up to the top and along it
        at(g1, dTop);
      });
  top.resize(static_cast<std::size_t>(end - top.data()));
  return top;
}

BgRegion CutEnvelope::below(const DepthFrame& frame, double cMin, double cMax, double dBottom, double dTop) const {
  std::vector<Point> outline;
  for (const auto& [c, d] : belowTop(cMin, cMax, dBottom, dTop)) outline.push_back(frame.point(c, d));
  outline.push_back(frame.point(cMax, dBottom));
  outline.push_back(frame.point(cMin, dBottom));
  return regionFromSimpleOutline(outline);  // a graph over the cut axis above a flat bottom
}

}  // namespace cyclecert
