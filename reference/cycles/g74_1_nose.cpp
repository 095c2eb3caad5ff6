// G74.1 with a pointed tool under G41/G42: the groove the nose centre sees (docs/g74_1.md I26, I27).
#include "reference/cycles/g74_1_nose.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

std::string mm(double v) { return shortDecimalText(v); }

// The groove's interior angle between the edge arriving along `in` and the one leaving along `out`.
double interiorAngle(Point in, Point out) {
  return std::acos(std::clamp(-(in.z * out.z + in.x * out.x), -1.0, 1.0));
}

// Whether a nose of radius R pushed into a floor corner (interior angle θ) touches the corner's cut:
// a round only when it is larger than the nose; a chamfer (legs c) when it comes nearer to the
// corner's vertex along the bisector (c·cos θ/2) than the nose does (R/sin θ/2 − R). A cut the nose
// does not touch leaves the centre's path where the sharp corner leaves it — the offset of a round
// smaller than R would vanish (I26).
bool theNoseTouchesTheCut(const GrooveCorner& c, double theta, double noseRadius) {
  if (c.size <= kGeomEps) return false;
  if (c.kind == GrooveCornerKind::Round) return c.size > noseRadius + kGeomEps;
  const double half = theta / 2;
  return c.size * std::cos(half) > noseRadius / std::sin(half) - noseRadius + kGeomEps;
}

GrooveShape withUntouchedFloorCornersSharp(const GrooveShape& g, const GrooveProfile& exact, double noseRadius) {
  GrooveShape sharp = g;
  const Point floorDir = grooveLocal(1, 0);
  if (!theNoseTouchesTheCut(g.corners[kCornerR3], interiorAngle(exact.nearDirection, floorDir), noseRadius)) {
    sharp.corners[kCornerR3].size = 0;
  }
  if (!theNoseTouchesTheCut(g.corners[kCornerR4], interiorAngle(floorDir, exact.farDirection), noseRadius)) {
    sharp.corners[kCornerR4].size = 0;
  }
  return sharp;
}

// I27: the nose does not fit (the flanks' offsets cross before the floor, or the groove is shallower
// than the nose).
NoseDoesNotFit tooLargeANose(const GrooveProfile& p, double noseRadius) {
  return NoseDoesNotFit("the tool nose radius R " + mm(noseRadius) + " does not fit the groove (floor " +
                          mm(p.floorTo - p.floorFrom) + " mm wide between its corners, " + mm(p.floorDepth) +
                          " mm deep): the nose centre has no path " + mm(noseRadius) +
                          " mm from its flanks and floor; a pointed tool under G41/G42 needs a nose radius smaller "
                          "than half the floor's width and than the depth");
}

// The nose touching the near flank's line and, from above, the start level (A11 for a pointed tool,
// I12 with r = 0), by its lowest point: the offset flank line (moved R along h) at w = 0.
Point offsetNearFlankAtTheStartLevel(const GrooveProfile& p, double noseRadius) {
  const Point through = p.start + noseRadius * sideNormal(p.nearDirection, CompensationSide::Left) +
                        grooveLocal(0, noseRadius);
  const double t = -through.z / p.nearDirection.z;  // the near flank goes down: its w component is > 0
  return grooveLocal(through.x + t * p.nearDirection.x, 0);
}

// The chain up to its last crossing of the start level w = 0 where its far end lies above it (in the
// air over the mouth), and its end lines drawn on to the start level where they end below it: the
// passes begin and end on the start level, as the point tool's — but where its start lies above the
// start level (an r1 on a mouth rising behind S, ∠p > 0) the pass follows the whole corner from
// there, as the point tool's does from P0 (I26).
std::vector<Segment> toTheStartLevels(std::vector<Segment> chain) {
  const auto crossing = [](const Segment& s) -> std::optional<Point> {
    const std::vector<Point> hits = intersectWithLevelX(transposed(s), 0);
    if (hits.empty()) return std::nullopt;
    return transposed(hits.front());
  };
  while (!chain.empty() && chain.back().to.z < -kGeomEps) {
    const std::optional<Point> hit = crossing(chain.back());
    if (hit && distance(chain.back().from, *hit) > kGeomEps) {
      chain.back().to = *hit;
      break;
    }
    chain.pop_back();
  }
  if (chain.empty()) return chain;
  Segment& first = chain.front();
  if (!first.isArc() && first.from.z > kGeomEps && first.to.z > first.from.z + kGeomEps) {
    first.from = first.from + (-first.from.z / (first.to.z - first.from.z)) * (first.to - first.from);
  }
  Segment& last = chain.back();
  if (!last.isArc() && last.to.z > kGeomEps && last.from.z > last.to.z + kGeomEps) {
    last.to = last.to + (last.to.z / (last.from.z - last.to.z)) * (last.to - last.from);
  }
  return chain;
}

}  // namespace

GrooveProfile noseCentreProfile(const GrooveShape& g, double flankAllowance, double floorAllowance, double noseRadius) {
  const GrooveProfile exact = buildGrooveProfile(g, flankAllowance, floorAllowance);
  const GrooveProfile p = buildGrooveProfile(withUntouchedFloorCornersSharp(g, exact, noseRadius), flankAllowance,
                                             floorAllowance);
  std::vector<Segment> tagged = p.chain;
  for (std::size_t i = 0; i < tagged.size(); ++i) tagged[i].sourceLine = static_cast<int>(i);
  std::vector<Segment> offset;
  try {
    offset = offsetPath(tagged, noseRadius, CompensationSide::Left);  // the inside is on the chain's left (§2)
  } catch (const OffsetError&) {
    throw tooLargeANose(exact, noseRadius);
  }
  // The nose's lowest point: the centre R further along h, on the start level when the nose
  // touches it from above.
  const Point down = grooveLocal(0, noseRadius);
  for (Segment& s : offset) s = s.shifted(down);
  GrooveProfile nose;
  nose.start = offsetNearFlankAtTheStartLevel(p, noseRadius);
  nose.nearDirection = p.nearDirection;
  nose.farDirection = p.farDirection;
  bool floorFound = false;
  for (const Segment& s : toTheStartLevels(offset)) {
    const GroovePart part = p.parts[static_cast<std::size_t>(s.sourceLine)];
    if (part == GroovePart::Floor && !s.isArc()) {
      floorFound = true;
      nose.floorDepth = s.from.z;
      nose.floorFrom = s.from.x;
      nose.floorTo = s.to.x;
    }
    nose.chain.push_back(s);
    nose.parts.push_back(part);
  }
  if (!floorFound || nose.floorDepth <= noseRadius + kGeomEps) throw tooLargeANose(exact, noseRadius);
  return nose;
}

CompensationSide grooveInsideSide(const GrooveFrame& frame) {
  return frame.depthSign * frame.widthSign > 0 ? CompensationSide::Left : CompensationSide::Right;
}

}  // namespace cyclecert
