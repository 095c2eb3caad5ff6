#include "reference/siemens/siemens_roughing_undercut.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "reference/model/offset.h"

namespace cyclecert {

namespace {

// Whether `p` on the arc `s` is its circle's top (the highest point: the circle falls on both sides).
bool isTopOfCircle(const Segment& s, Point p) { return std::abs(p.z - s.center.z) <= 1e-7 && p.x > s.center.x; }

// The top of an arc strictly inside it (where it stops rising and starts falling).
std::optional<Point> arcTopInside(const Segment& s) {
  if (!s.isArc()) return std::nullopt;
  for (const Point& p : apexesAlong(s)) {
    if (isTopOfCircle(s, p) && distance(p, s.from) > kGeomEps && distance(p, s.to) > kGeomEps) return p;
  }
  return std::nullopt;
}

// An arc that starts at its top (a dome split at its apex, a rounding leaving a flat downwards): its
// start tangent runs along the cut axis, and from there on it falls (CYCLE95.UNDERCUT: "the top of
// an arc"). Not a sliver of an arc rising to its top that starts within the top's tolerance of it
// (a level a rounding error below a dome's top): it ends no lower, and the profile after it — a
// flat where FALZ joins the dome to a falling side — decides whether it turns down.
bool startsAtItsTop(const Segment& s) {
  return s.isArc() && isTopOfCircle(s, s.from) && s.to.x < s.from.x - kGeomEps;
}

// The lowest point of a segment (an arc's bottom when inside it).
Point lowestPointOf(const Segment& s) {
  Point low = s.from.x <= s.to.x ? s.from : s.to;
  if (s.isArc()) {
    for (const Point& p : apexesAlong(s)) {
      if (std::abs(p.z - s.center.z) <= 1e-7 && p.x < low.x) low = p;
    }
  }
  return low;
}

// Where the profile from `s` onwards first reaches `level` rising (the first crossing after the start).
std::optional<Point> reachesLevelOn(const Segment& s, double level) {
  for (const Point& p : intersectWithLevelX(s, level)) {
    if (distance(p, s.from) > kGeomEps) return p;
  }
  return std::nullopt;
}

// The pocket's pieces from the rim to where the profile is back at `top`, split at the lowest point.
// Returns the index of the segment after the pocket and the point it ends at.
struct PocketWalk {
  Undercut undercut;
  std::size_t nextSegment;
  Point end;
};

PocketWalk walkPocket(const std::vector<Segment>& profile, std::size_t i, Point rim, double top) {
  std::vector<Segment> pieces;
  std::size_t next = profile.size();
  Point end = profile.back().to;
  for (std::size_t j = i; j < profile.size(); ++j) {
    const Segment s = j == i ? portionOf(profile[j], rim, profile[j].to) : profile[j];
    if (hasNoLength(s)) continue;
    if (const auto back = reachesLevelOn(s, top)) {
      pieces.push_back(portionOf(s, s.from, *back));
      next = j;
      end = *back;
      break;
    }
    pieces.push_back(s);
  }
  if (pieces.empty()) return {Undercut{top, {}, {}}, next, end};  // nothing between the rim and the end
  // Split at the lowest point.
  std::size_t low = 0;
  Point lowPoint = pieces.front().from;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Point p = lowestPointOf(pieces[k]);
    if (p.x < lowPoint.x - kGeomEps) {
      low = k;
      lowPoint = p;
    }
  }
  Undercut u;
  u.top = top;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    if (k < low) u.down.push_back(pieces[k]);
    if (k > low) u.up.push_back(pieces[k]);
  }
  if (!pieces.empty()) {
    const Segment& s = pieces[low];
    if (distance(s.from, lowPoint) > kGeomEps) u.down.push_back(portionOf(s, s.from, lowPoint));
    if (distance(lowPoint, s.to) > kGeomEps) u.up.insert(u.up.begin(), portionOf(s, lowPoint, s.to));
  }
  return {u, next, end};
}

}  // namespace

Segment portionOf(const Segment& s, Point from, Point to) {
  Segment r = s;
  r.from = from;
  r.to = to;
  return r;
}

double lowestLevelAbove(const std::vector<double>& levels, double x) {
  double best = levels.front();
  for (double l : levels) {
    if (l > x + kGeomEps) best = std::min(best, l);
  }
  return best;
}

double Undercut::bottom() const {
  if (!up.empty()) return up.front().from.x;
  return down.empty() ? top : down.back().to.x;
}

bool hasNoLength(const Segment& portion) { return distance(portion.from, portion.to) <= kGeomEps; }

std::optional<Point> descentStartOn(const Segment& s) {
  if (hasNoLength(s)) return std::nullopt;
  if (unitTangentAtStart(s).x < -1e-9 || startsAtItsTop(s)) return s.from;
  return arcTopInside(s);
}

namespace {

// CYCLE95.UNDERCUT (interpretation): a descent from the contour's first point is no undercut —
// nothing of the profile stands before it, so the main passes reach it from the start side along
// their levels, as they reach a shoulder, and clean up through the front stretch's own descents
// (frontStretchEnd in siemens_roughing_steps.cpp).
bool fallsFromTheContoursStart(const std::vector<Segment>& profile, Point rim) {
  return distance(rim, profile.front().from) <= kGeomEps;
}

// Nor is a descent down a wall at the first point's z after the walls rising there (a spike of no
// width at the front: the part's face, stock on both sides, which the levels run through). It is
// only that wall: a pocket behind a later rim is one (issue 16, fuzz seed 6552314345380442963: the
// pocket behind a spike in the middle was taken into the front's walk and never roughed). A descent
// leaving the front from the top of the rising walls is an undercut: the walls stand before the
// stock behind their top, which the main passes, meeting them, do not reach (fuzz seed
// 14762804858427687941). `descent` is the element falling from `rim`.
bool fallsDownTheFace(const std::vector<Segment>& profile, Point rim, const Segment& descent) {
  const double frontZ = profile.front().from.z;
  return rim.z >= frontZ - kGeomEps && descent.to.z >= frontZ - kGeomEps;
}

}  // namespace

std::vector<Undercut> findUndercuts(const std::vector<Segment>& profile, const std::vector<double>& levels) {
  std::vector<Undercut> found;
  std::size_t i = 0;
  std::optional<Point> resumeFrom;  // inside segment i, after a pocket that ended there
  while (i < profile.size()) {
    const Segment s = resumeFrom ? portionOf(profile[i], *resumeFrom, profile[i].to) : profile[i];
    resumeFrom.reset();
    const auto rim = descentStartOn(s);
    if (!rim) {
      ++i;
      continue;
    }
    if (fallsDownTheFace(profile, *rim, s) && !fallsFromTheContoursStart(profile, *rim)) {
      ++i;
      continue;
    }
    const double top = lowestLevelAbove(levels, rim->x);
    PocketWalk walk = walkPocket(profile, i, *rim, top);
    if (walk.nextSegment == i && distance(walk.end, *rim) <= kGeomEps) {
      ++i;
      continue;
    }
    if (walk.undercut.bottom() < top - kGeomEps && !fallsFromTheContoursStart(profile, *rim)) {
      found.push_back(std::move(walk.undercut));
    }
    if (walk.nextSegment >= profile.size()) break;
    i = walk.nextSegment;
    resumeFrom = walk.end;
  }
  return found;
}

}  // namespace cyclecert
