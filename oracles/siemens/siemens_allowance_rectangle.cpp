// The profile grown by the rectangle ±FALZ × ±FALX, read as two sweeps of the part, which lies
// below its profile (the contour runs towards −z in the frame, so every vertical line meets the
// profile's top once): the rectangle is the sum of its vertical edge and its horizontal edge.
// - The vertical edge (±FALX) lifts every point of the top by FALX.
// - The horizontal edge (±FALZ) widens the part in z: each rising piece moves towards +z (its stock
//   lies in front of it), each falling piece towards −z, a flat stays; where two moved pieces part
//   (a top: rising or flat, then flat or falling) a flat at the corner's height joins them, where they
//   overlap (a bottom: falling or flat, then flat or rising) both end where they cross.
// The part's face stands below the contour's first point, and the walls the contour begins with at
// that z stand on it (LCYC95.ROUGH note): they face +z whichever way they run.
#include "oracles/siemens/siemens_allowance_rectangle.h"

#include <algorithm>
#include <cmath>

#include "reference/model/offset.h"

namespace cyclecert {

namespace {

enum class Slope { Rising, Flat, Falling };

struct MovedPiece {
  Segment segment;
  Slope slope = Slope::Flat;
};

Slope slopeOf(const Segment& piece) {
  const double rise = piece.to.x - piece.from.x;
  if (rise > kGeomEps) return Slope::Rising;
  if (rise < -kGeomEps) return Slope::Falling;
  return Slope::Flat;
}

// Each element cut at the points where its height turns (an arc's apexes), so that every piece rises,
// falls or stays level all along.
std::vector<Segment> monotonePiecesOf(const std::vector<Segment>& profile) {
  std::vector<Segment> pieces;
  for (const Segment& s : profile) {
    Point from = s.from;
    std::vector<Point> cuts = apexesAlong(s);
    cuts.push_back(s.to);
    for (const Point& cut : cuts) {
      if (distance(from, cut) <= kGeomEps) continue;
      Segment piece = s;
      piece.from = from;
      piece.to = cut;
      pieces.push_back(piece);
      from = cut;
    }
  }
  return pieces;
}

bool isWallAtZ(const Segment& s, double z) {
  return !s.isArc() && std::abs(s.from.z - z) <= kGeomEps && std::abs(s.to.z - z) <= kGeomEps;
}

// Where the piece (rising or falling all along) is at height `x`, its ends' z beyond them.
double zAtHeight(const Segment& piece, double x) {
  const double low = std::min(piece.from.x, piece.to.x), high = std::max(piece.from.x, piece.to.x);
  if (x <= low) return piece.from.x <= piece.to.x ? piece.from.z : piece.to.z;
  if (x >= high) return piece.from.x >= piece.to.x ? piece.from.z : piece.to.z;
  const std::vector<Point> hits = intersectWithLevelX(piece, x);
  return hits.empty() ? piece.from.z : hits.front().z;
}

Segment flatBetween(Point from, Point to, int sourceLine) {
  Segment s;
  s.from = from;
  s.to = to;
  s.sourceLine = sourceLine;
  return s;
}

// A bottom where a falling piece meets a rising one: the height where the falling piece (in front)
// comes level in z with the rising one, found by halving the heights both reach (the gap between
// them shrinks as both climb). `index` names the rising piece in an interference.
Point crossingOfSides(const Segment& falling, const Segment& rising, int index) {
  double low = falling.to.x;
  double high = std::min(falling.from.x, rising.to.x);
  const auto gap = [&](double x) { return zAtHeight(falling, x) - zAtHeight(rising, x); };
  if (gap(high) < -kGeomEps) throw OffsetError(OffsetProblem::Interference, index, rising.sourceLine);
  for (int i = 0; i < 200 && high - low > 1e-13; ++i) {
    const double mid = 0.5 * (low + high);
    (gap(mid) < 0 ? low : high) = mid;
  }
  const double x = 0.5 * (low + high);
  return {0.5 * (zAtHeight(falling, x) + zAtHeight(rising, x)), x};
}

class RectangleGrowth {
 public:
  explicit RectangleGrowth(Point allowance) : allowance_(allowance) {}

  std::vector<Segment> grow(const std::vector<Segment>& profile) {
    const std::vector<Segment> pieces = monotonePiecesOf(profile);
    if (pieces.empty()) return profile;
    const double faceZ = pieces.front().from.z;
    startOnTheFace(pieces.front().from);
    bool onTheFace = true;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      onTheFace = onTheFace && isWallAtZ(pieces[i], faceZ);
      join(moved(pieces[i], onTheFace), static_cast<int>(i));
    }
    std::vector<Segment> out;
    for (const MovedPiece& p : grown_) {
      if (distance(p.segment.from, p.segment.to) <= kGeomEps) continue;
      if (!out.empty() && continuesStraight(out.back(), p.segment)) {
        out.back().to = p.segment.to;
      } else {
        out.push_back(p.segment);
      }
    }
    return out;
  }

 private:
  // The part's face below the contour's first point (LCYC95.ROUGH note) faces +z: its top moved by
  // the rectangle's corner (+FALZ, +FALX) is where the profile begins; the first piece joins it as
  // it would join a rising wall.
  void startOnTheFace(Point first) {
    const Point top = first + allowance_;
    grown_.push_back({flatBetween(top, top, 0), Slope::Rising});
  }

  MovedPiece moved(const Segment& piece, bool onTheFace) const {
    const Slope slope = onTheFace ? Slope::Rising : slopeOf(piece);
    const double dz = slope == Slope::Rising ? allowance_.z : slope == Slope::Falling ? -allowance_.z : 0.0;
    return {piece.shifted({dz, allowance_.x}), slope};
  }

  static bool continuesStraight(const Segment& a, const Segment& b) {
    if (a.isArc() || b.isArc()) return false;
    const Point u = a.to - a.from, v = b.to - b.from;
    return std::abs(u.z * v.x - u.x * v.z) <= 1e-12 * std::max(1.0, distance(a.from, a.to) * distance(b.from, b.to)) &&
           u.z * v.z + u.x * v.x > 0;
  }

  void join(MovedPiece next, int index) {
    MovedPiece& before = grown_.back();
    const Point end = before.segment.to, start = next.segment.from;
    if (std::abs(start.z - end.z) <= kGeomEps) {
      next.segment.from = end;
    } else if (start.z < end.z) {
      grown_.push_back({flatBetween(end, start, next.segment.sourceLine), Slope::Flat});
    } else {
      meetAtTheBottom(before, next, index);
    }
    grown_.push_back(next);
  }

  // The two moved pieces overlap in z at a bottom: each ends where they cross.
  static void meetAtTheBottom(MovedPiece& before, MovedPiece& next, int index) {
    Segment& a = before.segment;
    Segment& b = next.segment;
    Point meet;
    if (before.slope == Slope::Flat) {  // a flat, then a rising piece moved in front of its end
      meet = b.from;
      if (meet.z > a.from.z + kGeomEps) throw OffsetError(OffsetProblem::Interference, index, b.sourceLine);
    } else if (next.slope == Slope::Flat) {  // a falling piece moved behind the flat's start
      meet = a.to;
      if (meet.z < b.to.z - kGeomEps) throw OffsetError(OffsetProblem::Interference, index, b.sourceLine);
    } else {
      meet = crossingOfSides(a, b, index);
    }
    a.to = meet;
    b.from = meet;
  }

  Point allowance_;
  std::vector<MovedPiece> grown_;
};

}  // namespace

std::vector<Segment> grownByAllowanceRectangle(const std::vector<Segment>& profile, Point allowance) {
  if (allowance.z <= 0 && allowance.x <= 0) return profile;
  return RectangleGrowth(allowance).grow(profile);
}

}  // namespace cyclecert
