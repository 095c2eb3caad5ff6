#include "reference/cycles/pocket_profile.h"

#include <algorithm>
#include <cmath>

namespace cyclecert {

namespace {

// Splits an arc at its apexes so that every piece is monotonic on both axes.
void appendMonotonicPieces(const Segment& s, std::vector<Segment>& out) {
  Point from = s.from;
  for (Point apex : apexesAlong(s)) {
    // An apex at an end point (within rounding) splits nothing: no sliver pieces.
    if (distance(apex, from) <= 1e-7 || distance(apex, s.to) <= 1e-7) continue;
    Segment piece = s;
    piece.from = from;
    piece.to = apex;
    out.push_back(piece);
    from = apex;
  }
  Segment last = s;
  last.from = from;
  out.push_back(last);
}

Segment partOf(const Segment& s, Point from, Point to) {
  Segment part = s;
  part.from = from;
  part.to = to;
  return part;
}
}  // namespace

PocketProfile::PocketProfile(const std::vector<Segment>& segments, std::size_t headCount, Point origin,
                             int depthSign, int cutSign)
    : origin_(origin), d_(depthSign), c_(cutSign) {
  for (std::size_t i = 0; i < segments.size(); ++i) {
    if (segments[i].length() <= kGeomEps) continue;
    appendMonotonicPieces(segments[i], pieces_);
    if (i + 1 == headCount) headPieces_ = pieces_.size();
  }
  findValleyBottoms();
}

bool PocketProfile::isAlongCut(std::size_t i) const { return std::abs(pieces_[i].to.x - pieces_[i].from.x) <= kGeomEps; }

double PocketProfile::deepest() const {
  double best = 0;
  for (const Segment& s : pieces_) best = std::max({best, depth(s.from), depth(s.to)});
  return best;
}

double PocketProfile::shallowestAfterHead() const {
  double best = INFINITY;
  for (std::size_t i = headPieces_; i < pieces_.size(); ++i) best = std::min({best, depth(pieces_[i].from), depth(pieces_[i].to)});
  return best;
}

bool PocketProfile::hasPocketWall() const {
  bool cameBack = false;
  for (std::size_t i = headPieces_; i < pieces_.size(); ++i) {
    const double change = depth(pieces_[i].to) - depth(pieces_[i].from);
    if (change < -kGeomEps) cameBack = true;
    if (change > kGeomEps && cameBack) return true;
  }
  return false;
}

std::optional<Point> PocketProfile::crossing(std::size_t piece, double level) const {
  const std::vector<Point> hits = intersectWithLevelX(pieces_[piece], xAtDepth(level));
  if (hits.empty()) return std::nullopt;
  return hits.front();
}

std::vector<ProfileInterval> PocketProfile::intervalsAt(double level) const {
  std::vector<ProfileInterval> out;
  std::optional<ProfilePos> openedAt;
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    const Segment& s = pieces_[i];
    const bool fromDeeper = depth(s.from) > level + kGeomEps;
    const bool toDeeper = depth(s.to) > level + kGeomEps;
    if (!fromDeeper && toDeeper) openedAt = ProfilePos{i, crossing(i, level).value_or(s.from)};
    if (fromDeeper && !toDeeper && openedAt) {
      out.push_back({*openedAt, {i, crossing(i, level).value_or(s.to)}, false});
      openedAt.reset();
    }
  }
  // Still deeper at C': the interval ends at C' on the cut axis, at the level (the edge of the stock).
  if (openedAt) out.push_back({*openedAt, {pieces_.size() - 1, {pieces_.back().to.z, xAtDepth(level)}}, true});
  return out;
}

void PocketProfile::findValleyBottoms() {
  for (std::size_t i = 0; i < pieces_.size(); ++i) {
    if (isAlongCut(i)) {
      // Consecutive blocks along the cut axis at one depth are one valley bottom, however the
      // program splits it (the metamorphic split-segment relation found the difference).
      const std::size_t first = i;
      while (i + 1 < pieces_.size() && isAlongCut(i + 1) && std::abs(depth(pieces_[i + 1].from) - depth(pieces_[first].from)) <= kGeomEps) ++i;
      bottoms_.push_back({{first, pieces_[first].from}, {i, pieces_[i].to}, depth(pieces_[first].from)});
      continue;
    }
    // A vertex where the profile stops going deeper and comes back (a V, or an arc's apex).
    if (i + 1 >= pieces_.size() || isAlongCut(i + 1)) continue;
    const bool goesDeeper = depth(pieces_[i].to) > depth(pieces_[i].from) + kGeomEps;
    const bool comesBack = depth(pieces_[i + 1].to) < depth(pieces_[i + 1].from) - kGeomEps;
    if (goesDeeper && comesBack) bottoms_.push_back({{i, pieces_[i].to}, {i + 1, pieces_[i].to}, depth(pieces_[i].to)});
  }
}

std::vector<Segment> PocketProfile::wallAbove(const ProfilePos& from, double level) const {
  std::vector<Segment> path;  // built backwards
  Point at = from.p;
  for (std::size_t i = from.piece + 1; i-- > 0;) {
    const Segment& s = pieces_[i];
    // Walking back along piece i from `at` towards s.from, the profile rises (or the walk stops).
    if (depth(s.from) < level - kGeomEps) {
      const Point top = crossing(i, level).value_or(s.from);
      if (distance(top, at) > kGeomEps) path.push_back(partOf(s, top, at));
      break;
    }
    if (distance(s.from, at) > kGeomEps) path.push_back(partOf(s, s.from, at));
    at = s.from;
    // Stop at the top of the wall: going further back, the profile would not rise any more.
    if (i == 0 || depth(pieces_[i - 1].from) >= depth(pieces_[i - 1].to) - kGeomEps) break;
  }
  std::reverse(path.begin(), path.end());
  return path;
}

std::vector<Segment> PocketProfile::wallAfter(const ProfilePos& from, double level, bool followAlongCut) const {
  std::vector<Segment> path;
  Point at = from.p;
  for (std::size_t i = from.piece; i < pieces_.size(); ++i) {
    const Segment& s = pieces_[i];
    if (distance(at, s.to) <= kGeomEps) continue;  // the crossing is this piece's end
    const bool rises = depth(s.to) < depth(s.from) - kGeomEps;
    if (isAlongCut(i) && !followAlongCut) break;  // G71.CHAMFER: retract instead (R16 = 0)
    if (!rises && !isAlongCut(i)) break;          // a peak: the profile goes deeper again
    if (depth(s.to) < level - kGeomEps) {
      path.push_back(partOf(s, at, crossing(i, level).value_or(s.to)));
      break;
    }
    path.push_back(partOf(s, at, s.to));
    at = s.to;
  }
  return path;
}

}  // namespace cyclecert
