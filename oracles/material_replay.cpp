#include "oracles/material_replay.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <span>
#include <unordered_map>

#include "oracles/material/boost_geometry.h"
#include "oracles/oracles.h"
#include "oracles/run_after_cycle.h"
#include "reference/model/offset.h"

namespace cyclecert {

// G71 steps along x, G72 along z; the shadow points back towards the start side. G73's passes stand
// apart along its relief (Δk, Δi) (G73.PASS.SHIFT): its material is measured along the relief (or,
// without one, along the allowance; without either, as G71's).
Point awayFrom(const CycleSpec& c) {
  if (c.patternRepeating()) {
    for (Point along : {c.relief, c.allowance}) {
      if (std::hypot(along.z, along.x) > kGeomEps) return along;
    }
  }
  const int d = c.depthDirection();
  return c.cutsAlongZ() ? Point{0, -static_cast<double>(d)} : Point{-static_cast<double>(d), 0};
}

// G73: the part stands behind its shape, on the side away from the start — not necessarily along
// the relief (a Z-only relief on a turned diameter, G73.PASS.SHIFT). The region behind it is swept
// along an axis over whose other axis the shape after block ns is a graph: the relief's larger
// component's axis first, then the other; the sense is the relief's (else the allowance's, else
// from the head's end towards A). A shape that is a graph over neither is swept along the relief.
Point partSideOf(const CycleSpec& c) {
  if (!c.patternRepeating() || c.shape.size() < 2) return awayFrom(c);
  const std::span<const Segment> profile = std::span(c.shape).subspan(1);
  const Point headEnd = c.shape.front().to;
  const auto senseAlong = [&](bool alongX) {
    const std::array<double, 3> candidates = alongX ? std::array{c.relief.x, c.allowance.x, c.start.x - headEnd.x}
                                                    : std::array{c.relief.z, c.allowance.z, c.start.z - headEnd.z};
    for (double v : candidates) {
      if (std::abs(v) > kGeomEps) return v > 0 ? 1.0 : -1.0;
    }
    return 0.0;
  };
  const bool xFirst = std::abs(c.relief.x) >= std::abs(c.relief.z);
  for (bool alongX : {xFirst, !xFirst}) {
    const double sense = senseAlong(alongX);
    if (sense == 0) continue;
    const Point away = alongX ? Point{0, sense} : Point{sense, 0};
    if (isGraphOverCutAxis(profile, DepthFrame(away))) return away;
  }
  return awayFrom(c);
}

BgRegion withoutSkins(const BgRegion& region, Point away, double width) {
  const DepthFrame frame(away);
  const auto shifted = [&](double by) {
    BgRegion moved;
    const Point step = frame.point(by, 0);
    boost::geometry::strategy::transform::translate_transformer<double, 2, 2> shift(step.z, step.x);
    boost::geometry::transform(region, moved, shift);
    return moved;
  };
  BgRegion once, twice;
  boost::geometry::intersection(region, shifted(width), once);
  boost::geometry::intersection(once, shifted(-width), twice);
  return twice;
}

bool mayStandThickerWithoutSkins(const MaterialModel& model, double c0, double c1, const std::vector<Segment>& profile,
                                 double skin, double limit) {
  // Of the tolerance (`skin`): how far below the limit the top must stay. The booleans round to
  // 1e-7 of the material's size (region.h), 1e-5 mm on a 100 mm part; a tenth of the oracles'
  // tolerance is 3e-4 mm.
  constexpr double kMargin = 0.1;
  // One top, read with its skins and without them.
  const std::optional<CutEnvelope> top = model.pointwiseTopWithin(c0 - skin, c1 + skin);
  if (!top) return true;
  const auto thicker = [&](double width) {
    return standsThickerThan(MaterialModel::withoutSkinsOf(*top, c0, c1, width), profile, model.away(),
                             kMeasuringChord, limit - kMargin * skin);
  };
  // The top with its skins stands above the top without them: where it stays below the limit (a
  // sloping stock's top), the copies are not needed.
  return thicker(0) && thicker(skin);
}

namespace {

// The part's outline: the (non-empty) profile flattened, then down to a bottom line `reach` beyond
// its deepest point, and back; and whether the profile is a graph over the cut axis.
struct PartOutline {
  std::vector<Point> profile;
  double bottom = 0;
  bool graph = false;
};

PartOutline partOutlineOf(const std::vector<Segment>& profile, const DepthFrame& frame, double reach, double chordTolerance) {
  PartOutline o;
  double deepest = INFINITY;
  for (const Segment& s : profile) {
    appendFlattened(o.profile, s, chordTolerance);
    for (Point p : {s.from, s.to}) deepest = std::min(deepest, frame.depth(p));
  }
  o.bottom = deepest - reach;
  o.graph = isGraphOverCutAxis(profile, frame);
  return o;
}

BgRegion partRegionFrom(const PartOutline& part, const std::vector<Segment>& profile, const DepthFrame& frame,
                        double reach, double chordTolerance) {
  std::vector<Point> outline = part.profile;
  outline.push_back(frame.atDepth(profile.back().to, part.bottom));
  outline.push_back(frame.atDepth(profile.front().from, part.bottom));
  // A graph over the cut axis closes into a simple outline: Boost's validity check, which costs
  // more than the rest, is not needed.
  if (part.graph) return regionFromSimpleOutline(outline);
  try {
    return regionFrom(outline);
  } catch (const std::invalid_argument&) {
    // A profile crossing itself: the union of its chords' regions.
    return partRegion(profile, frame.away(), reach, chordTolerance);
  }
}

}  // namespace

BgRegion partRegionOf(const std::vector<Segment>& profile, Point away, double reach, double chordTolerance) {
  if (profile.empty()) return {};
  const DepthFrame frame(away);
  return partRegionFrom(partOutlineOf(profile, frame, reach, chordTolerance), profile, frame, reach, chordTolerance);
}

namespace {

// The shallowest depth the path reaches between its two ends: a vertex, or the top of an arc that
// passes its highest point (where its radius points along `away`).
double highestBetweenEnds(const std::vector<Segment>& path, const DepthFrame& frame) {
  double highest = -INFINITY;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const Segment& s = path[i];
    if (i > 0) highest = std::max(highest, frame.depth(s.from));
    if (i + 1 < path.size()) highest = std::max(highest, frame.depth(s.to));
    if (s.isArc() && offsetAlongArc(s, std::atan2(frame.away().x, frame.away().z))) {
      highest = std::max(highest, frame.depth(s.center) + s.radius());
    }
  }
  return highest;
}

}  // namespace

namespace {

// The shape that bounds the implied stock. Type I's head runs along the depth axis from A's level
// (G71.T1: block ns moves X only); under compensation the start-up moves its end, A', off A's line
// (G71.TNRC.ZERO: the cycle runs on the start-up's compensated path), and the stock is taken to begin
// on the depth axis' line through that end — the start-up block builds the offset vector up on its
// way there and cuts nothing the cycle has to clear.
std::vector<Segment> stockBoundingShape(const CycleSpec& c, const DepthFrame& frame, double level) {
  std::vector<Segment> shape = c.shape;
  if (!c.typeII && !shape.empty()) shape.front().from = frame.atDepth(shape.front().to, level);
  return shape;
}

}  // namespace

namespace {

using BgBox = boost::geometry::model::box<BgPoint>;

// A region built without the boolean that would have made it, tidied as that boolean's result is
// (region.h: at the resolution of its operands' size, the largest side of their envelope), so that
// it is the region the boolean makes.
void tidyAsBooleanOf(BgRegion& region, const BgBox& operands) {
  tidy(region, std::max(operands.max_corner().x() - operands.min_corner().x(),
                        operands.max_corner().y() - operands.min_corner().y()));
}

// The stock between a graph over the cut axis (flattened: `points`) and a level it reaches between
// its ends (a collar up to the level), over [lo, hi] along the cut axis: one outline for each run of
// the points between two that reach the level (within kTidyDistance), closed along the level — the
// pieces the band below the level minus the part falls into (its operands: the band and the part,
// both down to `bottom`). Nothing when a point stands above the level (the boolean decides).
std::optional<BgRegion> stockPiecesUpToLevel(const std::vector<Point>& points, const DepthFrame& frame, double level,
                                             double lo, double hi, double bottom) {
  BgBox operands = boost::geometry::make_inverse<BgBox>();
  for (Point corner : {frame.point(lo, level), frame.point(hi, level), frame.point(lo, bottom), frame.point(hi, bottom),
                       frame.atDepth(points.back(), bottom), frame.atDepth(points.front(), bottom)}) {
    boost::geometry::expand(operands, toBg(corner));
  }
  BgRegion pieces;
  std::vector<Point> outline;
  const auto closePiece = [&] {
    if (outline.size() >= 2) {
      outline.push_back(frame.atDepth(outline.back(), level));
      outline.push_back(frame.atDepth(outline.front(), level));
      const BgRegion piece = regionFromSimpleOutline(outline);
      pieces.insert(pieces.end(), piece.begin(), piece.end());
    }
    outline.clear();
  };
  for (Point p : points) {
    if (frame.depth(p) > level + kTidyDistance) return std::nullopt;
    boost::geometry::expand(operands, toBg(p));
    outline.push_back(p);
    if (frame.depth(p) >= level - kTidyDistance && outline.size() > 1) {
      closePiece();
      outline.push_back(p);
    }
  }
  closePiece();
  tidyAsBooleanOf(pieces, operands);
  return pieces;
}

// The stock between a shape and a level above it, over the shape's span along the cut axis: the
// band below the level minus the part. A shape that is a graph over the cut axis and stands below
// the level between its ends (an end may stand on it) bounds the stock itself: the shape, up to the
// level at its end and back along it — the same region, without a boolean; one that reaches the
// level between its ends bounds its pieces (stockPiecesUpToLevel).
BgRegion stockUpToLevel(const std::vector<Segment>& shape, Point away, double level, double reach, double chordTolerance) {
  const DepthFrame frame(away);
  const auto [lo, hi] = cutSpanOf(shape, frame);
  if (!(hi > lo)) return {};
  if (isGraphOverCutAxis(shape, frame)) {
    std::vector<Point> outline;
    for (const Segment& s : shape) appendFlattened(outline, s, chordTolerance);
    if (highestBetweenEnds(shape, frame) < level - kTidyDistance) {
      outline.push_back(frame.atDepth(shape.back().to, level));
      outline.push_back(frame.atDepth(shape.front().from, level));
      return regionFromSimpleOutline(outline);
    }
    double deepest = INFINITY;  // as the part's outline takes it (partOutlineOf): the segments' ends
    for (const Segment& s : shape) deepest = std::min({deepest, frame.depth(s.from), frame.depth(s.to)});
    if (std::optional<BgRegion> pieces = stockPiecesUpToLevel(outline, frame, level, lo, hi, deepest - reach)) {
      return *std::move(pieces);
    }
  }
  const BgRegion band = regionFromSimpleOutline({frame.point(lo, level), frame.point(hi, level),
                                                 frame.point(hi, level - reach), frame.point(lo, level - reach)});
  return without(band, partRegionOf(shape, away, reach, chordTolerance));
}

}  // namespace

std::vector<Segment> nearNetBlankProfile(const CycleSpec& c) {
  std::vector<Segment> blank;
  if (c.shape.size() < 2) return blank;
  const Point grown = c.relief + c.allowance;
  for (auto s = c.shape.begin() + 1; s != c.shape.end(); ++s) blank.push_back(s->shifted(grown));
  return blank;
}

namespace {

// The band of the cut coordinates [lo, hi] of a frame, `width` deep on either side of its cut axis.
BgRegion cutBand(const DepthFrame& frame, double lo, double hi, double width) {
  return regionFromSimpleOutline(
      {frame.point(lo, width), frame.point(hi, width), frame.point(hi, -width), frame.point(lo, -width)});
}

// The part of `region` whose cut coordinates in `frame` lie within [lo, hi], intersected in the
// frame's own coordinates (cut, depth) — a rotation, so the rings keep their orientation. There
// the band's edges are axis-parallel: an edge of the region running along one, collinear only to
// rounding in the plane when the frame is slanted (a G73 shape segment parallel to the relief),
// becomes exactly collinear at the booleans' resolution (region.h), which Boost.Geometry resolves;
// a slanted band in the plane it may return whole.
BgRegion withinCutBand(const BgRegion& region, const DepthFrame& frame, double lo, double hi) {
  if (region.empty()) return {};
  const auto mapped = [&](const BgRegion& from, auto map) {
    BgRegion to = from;
    for (BgPolygon& polygon : to) {
      for (BgPoint& p : polygon.outer()) p = map(p);
      for (auto& inner : polygon.inners()) {
        for (BgPoint& p : inner) p = map(p);
      }
    }
    return to;
  };
  const BgRegion inFrame = mapped(region, [&](const BgPoint& p) {
    const Point q = fromBg(p);
    return BgPoint(frame.cut(q), frame.depth(q));
  });
  const auto box = boost::geometry::return_envelope<boost::geometry::model::box<BgPoint>>(inFrame);
  const double d0 = box.min_corner().y() - 1, d1 = box.max_corner().y() + 1;
  const BgRegion band = regionFromSimpleOutline({{lo, d1}, {hi, d1}, {hi, d0}, {lo, d0}});
  return mapped(checkedIntersection(inFrame, band),
                [&](const BgPoint& p) { return toBg(frame.point(p.x(), p.y())); });
}

}  // namespace

// G73: the near-net blank (a casting or forging), everything behind the shape after block ns grown
// by (Δk + Δw, Δi + Δu/2) — the first pass's path — where the program describes it: over the
// shape's span along the cut axis of the side the part stands on (partSideOf), and between the rays
// from B and C along the relief (awayFrom: the direction the passes stand apart in, which the
// completeness oracle's span also follows). Beyond either, a point may lie past the ends of the
// part the program draws, where a pass's or the finishing pass's shadow cannot reach
// (interpretation, G73.PASS.SHIFT).
BgRegion nearNetBlankOf(const CycleSpec& c, double reach, double chordTolerance) {
  const std::vector<Segment> blank = nearNetBlankProfile(c);
  if (blank.empty()) return {};
  const std::span<const Segment> shape = std::span(c.shape).subspan(1);
  const DepthFrame partSide(partSideOf(c));
  const DepthFrame relief(awayFrom(c));
  const auto [lo, hi] = cutSpanOf(shape, partSide);
  const auto [reliefLo, reliefHi] = cutSpanOf(shape, relief);
  if (!(hi > lo) || !(reliefHi > reliefLo)) return {};
  // A relief along the part side's axis gives the same band twice: no boolean needed.
  const bool sameBands = std::abs(partSide.away().z * relief.away().x - partSide.away().x * relief.away().z) < 1e-12;
  const BgRegion alongPartSide =
      checkedIntersection(cutBand(partSide, lo, hi, 4 * reach), partRegionOf(blank, partSide.away(), reach, chordTolerance));
  // Drawn in along the relief by far less than any tolerance, yet by ten times the booleans'
  // resolution (region.h): a blank edge on the band's (a shape segment parallel to the relief, the
  // passes running along it) then stays apart from the passes' paths, whose shadows the material
  // model's booleans would otherwise meet collinear only to rounding and may not remove.
  const double clear = 10 * kBooleanResolution * reach;
  return sameBands ? alongPartSide : withinCutBand(alongPartSide, relief, reliefLo + clear, reliefHi - clear);
}

BgRegion impliedStockOf(const CycleSpec& c, Point away, double reach, double chordTolerance) {
  if (c.patternRepeating()) return nearNetBlankOf(c, reach, chordTolerance);
  const DepthFrame frame(away);
  const double level = frame.depth(c.start);
  // A stands on the shape; C may.
  return stockUpToLevel(stockBoundingShape(c, frame, level), away, level, reach, chordTolerance);
}
namespace {

// The stock the case gives (a bar, a polygon), or nothing when the cycle implies it.
std::optional<BgRegion> givenStock(const JudgeInput& in) {
  switch (in.stock.kind) {
    case Stock::Bar: return barStock(in.stock.diameter, in.stock.length, in.stock.frontZ);
    case Stock::Polygon: return polygonStock(in.stock.outline);
    case Stock::Implied: break;
  }
  return std::nullopt;
}

// A length that takes a shadow out of everything in the picture: the shapes, the path, the stock,
// and how far a blank stands out beyond its shape (`standOut`: G73's relief).
double reachFor(const JudgeInput& in, std::initializer_list<const std::vector<Segment>*> shapes, double standOut) {
  double size = 10;
  const auto grow = [&](Point p) { size = std::max({size, std::abs(p.z), std::abs(p.x)}); };
  for (const std::vector<Segment>* shape : shapes) {
    for (const Segment& s : *shape) {
      grow(s.from);
      grow(s.to);
    }
  }
  size += standOut;
  for (const Move& m : in.path.moves) grow(m.to);
  for (Point p : in.stock.outline) grow(p);
  grow({in.stock.frontZ, 0});
  return 4 * (size + in.stock.diameter + in.stock.length) + 10;
}

// The tool point is a point: a feed into the material along the depth axis removes no area in the
// model, but the tool has been there. Crossing pieces that lie on an earlier feed's path are the
// slot the tool cut, not material.
Crossing withoutOwnSlot(Crossing c, const Toolpath& path, std::size_t rapid, double tolerance) {
  Crossing kept;
  for (const Segment& piece : c.pieces) {
    bool onFeed = false;
    for (std::size_t j = 0; j < rapid && !onFeed; ++j) {
      if (path.moves[j].kind != MoveKind::Feed) continue;
      const Segment feed = path.segment(j);
      onFeed = distanceToSegment(piece.from, feed) <= tolerance && distanceToSegment(piece.to, feed) <= tolerance;
    }
    if (!onFeed) {
      kept.pieces.push_back(piece);
      kept.length += piece.length();
    }
  }
  return kept;
}

// What the pocket-entry oracle's continuations of rapid `i` cross of the material standing now and
// of the part (grown by the allowances: an entry point on a pocket's wall lies on it).
Crossing pocketEntryCrossing(const MaterialReplay& r, const MaterialModel& model, const JudgeInput& in,
                             std::size_t i) {
  const double tolerance = in.settings.tolerance();
  Crossing all;
  const auto add = [&](const Crossing& x) {
    all.length += x.length;
    all.pieces.insert(all.pieces.end(), x.pieces.begin(), x.pieces.end());
  };
  for (const Segment& probe : pocketEntryProbes(in, *r.cycle, i)) {
    add(withoutOwnSlot(model.crossing(probe, tolerance), in.path, i, tolerance));
    add(r.partCrossing(probe, tolerance, in.settings.chordTolerance));
  }
  return all;
}

// The pieces of `region` within `tolerance` of the move.
BgRegion touching(const BgRegion& region, const Segment& move, double tolerance) {
  boost::geometry::model::linestring<BgPoint> line;
  for (Point p : flatten(move, tolerance)) line.push_back(toBg(p));
  BgRegion near;
  for (const BgPolygon& piece : region) {
    // Zero-area slivers along an edge are not material (they come from touching boundaries).
    if (boost::geometry::area(piece) > tolerance * tolerance && boost::geometry::distance(piece, line) <= tolerance) {
      near.push_back(piece);
    }
  }
  return near;
}

// The feeds replayed so far, found by where they stand along the cut axis. A feed that runs along
// an earlier one moved back by t·away, 0 ≤ t ≤ the layer limit (G73's passes: each is the one
// before it moved by the division step along the relief, G73.PASS.SHIFT), removes a layer no
// thicker than t: the earlier feed's shadow took everything beyond t over the same cut span, so the
// material above the feed stands between the two (the envelope, material_model.h). The match is
// exact to kSameCut; a feed that matches none is measured.
class EarlierFeeds {
 public:
  explicit EarlierFeeds(Point away) : frame_(away) {}

  void add(const Segment& feed) { byCut_[keyOf(feed)].push_back(feed); }

  bool runAbove(const Segment& feed, double limit) const {
    const auto found = byCut_.find(keyOf(feed));
    if (found == byCut_.end()) return false;
    return std::any_of(found->second.begin(), found->second.end(),
                       [&](const Segment& earlier) { return isTranslateWithin(earlier, feed, limit); });
  }

 private:
  static constexpr double kSameCut = 1e-9;  // mm: far below every tolerance, far above rounding
  using Key = std::pair<long long, long long>;
  struct KeyHash {
    std::size_t operator()(const Key& k) const { return std::hash<long long>()(k.first * 1000003 ^ k.second); }
  };

  Key keyOf(const Segment& s) const {
    return {std::llround(frame_.cut(s.from) / (16 * kSameCut)), std::llround(frame_.cut(s.to) / (16 * kSameCut))};
  }

  // `earlier` is `feed` moved by t·away, 0 ≤ t ≤ limit (its ends, and an arc's centre and sense).
  bool isTranslateWithin(const Segment& earlier, const Segment& feed, double limit) const {
    if (earlier.kind != feed.kind) return false;
    const Point by = earlier.from - feed.from;
    const auto sameShift = [&](Point other) { return distance(other, by) <= kSameCut; };
    if (!sameShift(earlier.to - feed.to) || (feed.isArc() && !sameShift(earlier.center - feed.center))) return false;
    const double t = frame_.depth(by);
    return std::abs(frame_.cut(by)) <= kSameCut && t >= 0 && t <= limit;
  }

  DepthFrame frame_;
  std::unordered_map<Key, std::vector<Segment>, KeyHash> byCut_;
};

// The layer a feed removes when it may be thicker than Δd (nothing when it provably is not, or
// when the feed touches no material). The layer is the material the move itself touches, measured
// above it (its shadow): material the shadow reaches beyond a part overhang (a shape turning back
// within 5145/5146) is not a layer of this pass. The pieces of material that touch the move are
// measured whole — thickestAbove counts only what stands above the move within its span — which
// spares a boolean per feed.
std::optional<Thickest> layerBeyondDepthOfCut(const MaterialModel& model, const EarlierFeeds& earlier, const Segment& move,
                                              const CycleSpec& c, const JudgeSettings& settings) {
  const Point away = model.away();
  const double tolerance = settings.tolerance();
  const double allowed = c.layerLimit() + tolerance;
  if (earlier.runAbove(move, allowed)) return std::nullopt;
  // Most passes provably remove no more than Δd: the material's top over the move, measured
  // against it as finely as the region below would be, bounds the layer (thickness.h,
  // standsThickerThan) and spares making the material left.
  const DepthFrame frame(away);
  if (isGraphOverCutAxis(std::span(&move, 1), frame)) {
    const double a = std::min(frame.cut(move.from), frame.cut(move.to));
    const double b = std::max(frame.cut(move.from), frame.cut(move.to));
    if (!standsThickerThan(model.topWithin(a, b), {move}, away, kMeasuringChord, allowed)) return std::nullopt;
    // A layer that stands thicker only as a skin is no finding either (below): where the stock's
    // top slopes (G73's near-net blank, in the relief's frame) or the chords of the pass before
    // stray along the depth axis next to a tangent parallel to it, the top without skins decides.
    if (!mayStandThickerWithoutSkins(model, a, b, {move}, tolerance, allowed)) return std::nullopt;
  }
  const BgRegion layer = touching(model.remaining(), move, tolerance);
  if (layer.empty()) return std::nullopt;
  auto thickest = thickestAbove(layer, {move}, away, kMeasuringChord);
  // A skin narrower than the tolerance along the cut axis is not a layer: measure without it.
  if (thickest && thickest->thickness > allowed) {
    thickest = thickestAbove(withoutSkins(layer, away, tolerance), {move}, away, kMeasuringChord);
  }
  return thickest;
}

}  // namespace

bool onFinishShape(const JudgeInput& in, const CycleSpec& c, const Segment& move) {
  if (!in.program.hasFinishingCycle) return false;
  const double tol = in.settings.tolerance();
  return nearPath(pointAt(move, 0.5), c.shape, tol) && nearPath(move.to, c.shape, tol) &&
         nearPath(move.from, c.shape, tol);
}

namespace {

// The part: everything below `profile` in `frame` (nothing for an empty profile), and no-gouge's
// crossing test for it — below a profile that is a graph over the cut axis the part's edges are
// found by their cut coordinates (nothing to build); any other part's rings are indexed. Returns
// whether the profile is such a graph (isGraphOverCutAxis), which its outline found.
bool setPartBelow(MaterialReplay& r, const std::vector<Segment>& profile, const DepthFrame& frame, double chordTolerance) {
  bool graph = true;
  if (!profile.empty()) {
    const PartOutline part = partOutlineOf(profile, frame, r.reach, chordTolerance);
    graph = part.graph;
    r.part = partRegionFrom(part, profile, frame, r.reach, chordTolerance);
    if (part.graph) {
      std::vector<std::pair<double, double>> top;
      top.reserve(part.profile.size());
      for (Point p : part.profile) top.push_back({frame.cut(p), frame.depth(p)});
      if (top.front().first > top.back().first) std::reverse(top.begin(), top.end());
      r.partBelowProfile.emplace(frame, std::move(top), part.bottom);
    }
  }
  if (!r.partBelowProfile) r.partForCrossing = CrossingRegion(r.part);
  return graph;
}

// The replay's frame, stock and part for a FANUC roughing cycle (no move replayed yet).
MaterialReplay fanucReplayOf(const JudgeInput& in, const CycleSpec& c) {
  MaterialReplay r;
  r.cycle = &c;
  r.judgedMoves = movesJudgedAgainstThePart(in);
  r.away = awayFrom(c);
  r.reach = reachFor(in, {&c.shape}, std::hypot(c.relief.z, c.relief.x));
  const std::optional<BgRegion> given = givenStock(in);
  r.stock = given ? *given : impliedStockOf(c, r.away, r.reach, in.settings.chordTolerance);
  r.target = in.program.hasFinishingCycle ? c.shape : c.roughProfile();
  // The part region starts after the head block for type I (its A'→B' is the side of the stock).
  const std::vector<Segment> profile(r.target.begin() + (c.typeII ? 0 : 1), r.target.end());
  setPartBelow(r, profile, DepthFrame(partSideOf(c)), in.settings.chordTolerance);
  r.targetIsGraph = isGraphOverCutAxis(r.target, DepthFrame(r.away));
  return r;
}

// SINUMERIK: the stock-removal frame's depth axis (+x, from the profile towards the stock,
// siemens_cycle_spec.h) in the plane.
Point siemensAway(const SiemensCycleSpec& s) { return s.frame.toPlane(Point{0, 1}); }

// The box [z0, z1] × [x0, x1] of a SINUMERIK call's frame, in the plane (a rectangle never
// crosses itself: no validity check).
BgRegion frameBoxInPlane(const SiemensFrame& frame, double z0, double z1, double x0, double x1) {
  return regionFromSimpleOutline({frame.toPlane(Point{z0, x1}), frame.toPlane(Point{z1, x1}), frame.toPlane(Point{z1, x0}),
                     frame.toPlane(Point{z0, x0})});
}

// The top of the part's face below the profile's first point: the lowest point of the walls the
// profile begins with at that point's z (the point itself without them).
double siemensFaceTop(const SiemensCycleSpec& s) {
  const double frontZ = s.profile.front().from.z;
  double faceTop = s.profile.front().from.x;
  for (const Segment& seg : s.profile) {
    if (seg.isArc() || std::abs(seg.to.z - frontZ) > kGeomEps) break;
    faceTop = std::min(faceTop, seg.to.x);
  }
  return faceTop;
}

// SINUMERIK (LCYC95.ROUGH note, interpretation): below the contour's first point the part's face
// stands at that point's z, up to siemensFaceTop; a level below that meets the part at the face.
// What lies behind the face and above the profile (a recess the contour draws beyond a raised
// start) is out of the levels' reach: no stock of theirs.
// The face's z (frame): the profile's first point's, or the contour's where the allowance moved the
// profile's start behind it.
double siemensFrontZ(const SiemensCycleSpec& s) {
  return std::max(s.profile.front().from.z, s.frame.toFrame(s.contour.front().from).z);
}

BgRegion siemensFrontFace(const SiemensCycleSpec& s, double reach) {
  if (s.profile.empty() || s.contour.empty()) return {};
  const double frontZ = siemensFrontZ(s);
  const double faceTop = siemensFaceTop(s);
  return frameBoxInPlane(s.frame, frontZ - reach, frontZ, faceTop - reach, faceTop);
}

// Whether two paths are one within `tolerance`: the same kinds of segment, their ends and centres
// that close.
bool samePathWithin(const std::vector<Segment>& a, const std::vector<Segment>& b, double tolerance) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const bool same = a[i].kind == b[i].kind && nearlyEqual(a[i].from, b[i].from, tolerance) &&
                      nearlyEqual(a[i].to, b[i].to, tolerance) &&
                      (!a[i].isArc() || nearlyEqual(a[i].center, b[i].center, tolerance));
    if (!same) {
      return false;
    }
  }
  return true;
}

// The allowance layer of a SINUMERIK call: between its roughing profile and the finishing path (both
// in the plane). Without allowances and nose radius the two are the contour, one to rounding: no
// layer (the boolean of their regions leaves dust, which it drops). Two graphs over the cut axis a
// contour-parallel allowance keeps apart bound the layer themselves: the profile, across to the
// finishing path's end and back along it. Either way no boolean.
BgRegion siemensAllowanceLayer(const SiemensCycleSpec& s, const std::vector<Segment>& profile,
                               const std::vector<Segment>& finish, Point away, double reach, double chordTolerance) {
  if (samePathWithin(profile, finish, kTidyDistance)) return {};
  const DepthFrame frame(away);
  if (std::abs(s.allowance) > kTidyDistance && isGraphOverCutAxis(profile, frame) && isGraphOverCutAxis(finish, frame)) {
    std::vector<Point> outline;
    for (const Segment& seg : profile) appendFlattened(outline, seg, chordTolerance);
    for (auto seg = finish.rbegin(); seg != finish.rend(); ++seg) appendFlattened(outline, seg->reversed(), chordTolerance);
    return regionFromSimpleOutline(outline);
  }
  return without(partRegionOf(profile, away, reach, chordTolerance), partRegionOf(finish, away, reach, chordTolerance));
}

// The stock below a profile that is a graph over the cut axis less the face box (siemensFrontFace),
// without a boolean, when the box spans the stock's whole cut range (the profile runs from its
// first point away from the face side: no point of the stock stands beyond the face's z): then the
// box takes what stands below the face's top, and each ring is clipped to the half-plane above it
// in the frame (Sutherland–Hodgman). Each piece of such a stock is what stands between the profile
// and the top level, so its part above a level stays one simple ring. Nothing when the box does not
// span the stock.
std::optional<BgRegion> stockAboveFaceTop(const BgRegion& stock, const BgRegion& face, const SiemensCycleSpec& s,
                                          double reach) {
  if (stock.empty() || face.empty()) return std::nullopt;
  const double frontZ = siemensFrontZ(s);
  const double faceTop = siemensFaceTop(s);
  BgRegion above;
  std::vector<Point> ring, clipped;
  for (const BgPolygon& polygon : stock) {
    if (!polygon.inners().empty()) return std::nullopt;
    ring.clear();
    for (const BgPoint& p : polygon.outer()) {
      ring.push_back(s.frame.toFrame(fromBg(p)));
      const Point q = ring.back();
      if (q.z > frontZ || q.z < frontZ - reach || q.x < faceTop - reach) return std::nullopt;
    }
    clipped.clear();
    for (std::size_t i = 0; i + 1 < ring.size(); ++i) {  // the ring is closed: its last point is its first
      const Point a = ring[i], b = ring[i + 1];
      if (a.x >= faceTop) clipped.push_back(s.frame.toPlane(a));
      if ((a.x >= faceTop) != (b.x >= faceTop)) {
        const double t = (faceTop - a.x) / (b.x - a.x);
        clipped.push_back(s.frame.toPlane(Point{a.z + t * (b.z - a.z), faceTop}));
      }
    }
    const BgRegion piece = regionFromSimpleOutline(clipped);
    above.insert(above.end(), piece.begin(), piece.end());
  }
  BgBox operands = boost::geometry::return_envelope<BgBox>(stock);
  boost::geometry::expand(operands, boost::geometry::return_envelope<BgBox>(face));
  tidyAsBooleanOf(above, operands);
  return above;
}

// The stock a SINUMERIK call implies (interpretation, LCYC95.ROUGH note): a call that roughs takes
// the bar its first level is cut from — everything between the roughing profile (contour +
// allowances) and the level of the profile's highest point (LCYC95.DEPTH), over the profile's span
// along the cut axis, less what stands behind the part's face (siemensFrontFace); a call that only
// finishes (types 5…8) takes the allowance left by an earlier roughing — between the roughing
// profile and the finishing path.
BgRegion siemensImpliedStock(const SiemensCycleSpec& s, const std::vector<Segment>& profile,
                             const std::vector<Segment>& finish, Point away, double reach, double chordTolerance) {
  if (!s.roughs()) return siemensAllowanceLayer(s, profile, finish, away, reach, chordTolerance);
  // The frame's x is the plane's depth along `away`: the top level is the profile's highest point.
  const BgRegion stock = stockUpToLevel(profile, away, s.levels.top, reach, chordTolerance);
  // Only a profile that comes down below the face's top has stock behind the face.
  if (!(s.levels.bottom < siemensFaceTop(s) - kTidyDistance)) return stock;
  const BgRegion face = siemensFrontFace(s, reach);
  if (isGraphOverCutAxis(profile, DepthFrame(away))) {
    if (std::optional<BgRegion> above = stockAboveFaceTop(stock, face, s, reach)) return *std::move(above);
  }
  return without(stock, face);
}

// What a SINUMERIK call leaves standing by its rules: LCYC95 roughs no undercut (CYCLE95.UNDERCUT
// note), so a roughing-only LCYC95 call leaves each pocket below the level that passed over it.
BgRegion siemensLeftAlone(const SiemensCycleSpec& s, double reach) {
  BgRegion pockets;
  if (s.isCycle95() || s.finishes()) return pockets;
  for (const SiemensUndercut& u : s.undercuts) {
    const BgRegion pocket = frameBoxInPlane(s.frame, u.endZ, u.rimZ, u.top - reach, u.top);
    pockets.insert(pockets.end(), pocket.begin(), pocket.end());
  }
  return pockets;
}

// The replay's frame, stock and part for a SINUMERIK call: its moves stand in the plane, the
// frame's geometry is mapped back. No move may go below the roughing profile where roughing runs,
// nor below the finishing path where finishing runs: the part is what lies below both
// (interpretation: a nose radius puts the finishing path's control point off the contour, above or
// below the profile). Completeness measures what is left above the finishing path when the call
// finishes, else above the roughing profile.
MaterialReplay siemensReplayOf(const JudgeInput& in, const std::vector<const SiemensCycleSpec*>& calls) {
  MaterialReplay r;
  const auto roughing = std::find_if(calls.begin(), calls.end(), [](const SiemensCycleSpec* c) { return c->roughs(); });
  const auto finishing = std::find_if(calls.rbegin(), calls.rend(), [](const SiemensCycleSpec* c) { return c->finishes(); });
  r.siemens = roughing != calls.end() ? *roughing : calls.front();
  r.siemensFinishing = finishing != calls.rend() ? *finishing : nullptr;
  const SiemensCycleSpec& s = *r.siemens;
  r.judgedMoves = in.path.moves.size();
  r.away = siemensAway(s);
  const std::vector<Segment> profile = s.frame.toPlane(s.profile);
  const std::vector<Segment> finish = s.frame.toPlane((r.siemensFinishing ? *r.siemensFinishing : s).finishPath);
  r.reach = reachFor(in, {&profile, &finish}, 0);
  const double chord = in.settings.chordTolerance;
  const std::optional<BgRegion> given = givenStock(in);
  r.stock = given ? *given : siemensImpliedStock(s, profile, finish, r.away, r.reach, chord);
  if (!given && !s.roughs()) r.siemensAllowanceLayer = r.stock;
  r.target = r.siemensFinishing ? finish : profile;
  const DepthFrame frame(r.away);
  if (!r.siemensFinishing) {
    r.targetIsGraph = setPartBelow(r, profile, frame, chord);
  } else if (r.siemensFinishing->tool.noseRadius <= 0) {
    r.targetIsGraph = setPartBelow(r, finish, frame, chord);  // the contour: the profile stands above it
  } else {
    r.part = checkedIntersection(partRegionOf(profile, r.away, r.reach, chord), partRegionOf(finish, r.away, r.reach, chord));
    r.partForCrossing = CrossingRegion(r.part);
    r.targetIsGraph = isGraphOverCutAxis(r.target, frame);
  }
  if (!r.siemensFinishing) r.leftAlone = siemensLeftAlone(s, r.reach);
  return r;
}

// SINUMERIK: the material its documented rapids meet, which rapids-in-air does not count
// (interpretation, LCYC95.ROUGH and LCYC95.FINISH notes): the chip an infeed at R109 > 0 leaves in
// front of its level — the triangle between the slanted infeed and its level, which the G0 back
// along the cut axis at the retract height crosses — and, for finishing's G0 to the contour start
// (the rapid that ends there), the allowance in front of that start.
class SiemensDocumentedCrossings {
 public:
  SiemensDocumentedCrossings(const MaterialReplay& r, const SiemensCycleSpec& s, double tol, double chordTolerance)
      : r_(r), s_(s), tol_(tol), chord_(chordTolerance) {}

  // A feed of the path: a slanted infeed ending on a main level leaves its chip.
  void noteFeed(const Segment& feed) {
    if (s_.infeedAngle <= 0 || feed.isArc()) return;
    const Point a = s_.frame.toFrame(feed.from), b = s_.frame.toFrame(feed.to);
    if (b.z - a.z >= -tol_ || b.x - a.x >= -tol_ || !s_.levels.isLevel(b.x, tol_)) return;
    const BgRegion chip =  // a triangle never crosses itself
        regionFromSimpleOutline({s_.frame.toPlane(a), s_.frame.toPlane(b), s_.frame.toPlane(Point{a.z, b.x})});
    chips_.insert(chips_.end(), chip.begin(), chip.end());
  }

  // The crossing of a rapid without its pieces inside the material the sequence meets.
  Crossing without(const Crossing& c, const Segment& rapid) const {
    if (c.pieces.empty()) return c;
    const SiemensCycleSpec* f = r_.siemensFinishing;
    const bool toContourStart =
        f && !f->finishPath.empty() && distance(rapid.to, f->frame.toPlane(f->finishPath.front().from)) <= tol_;
    Crossing kept;
    for (const Segment& piece : c.pieces) {
      if (inside(chips_, piece) || (toContourStart && inside(allowanceLayer(), piece))) continue;
      kept.pieces.push_back(piece);
      kept.length += piece.length();
    }
    return kept;
  }

 private:
  bool inside(const BgRegion& region, const Segment& piece) const {
    if (region.empty()) return false;
    for (Point p : {piece.from, pointAt(piece, 0.5), piece.to}) {
      if (boost::geometry::distance(toBg(p), region) > tol_) return false;
    }
    return true;
  }

  // Between the roughing profile and the finishing path: made when a rapid to the contour start
  // first crosses material.
  const BgRegion& allowanceLayer() const {
    if (r_.siemensAllowanceLayer) return *r_.siemensAllowanceLayer;
    if (!layer_) {
      const SiemensCycleSpec& f = r_.siemensFinishing ? *r_.siemensFinishing : s_;
      layer_ = siemensAllowanceLayer(s_, s_.frame.toPlane(s_.profile), f.frame.toPlane(f.finishPath), r_.away, r_.reach,
                                     chord_);
    }
    return *layer_;
  }

  const MaterialReplay& r_;
  const SiemensCycleSpec& s_;
  double tol_;
  double chord_;
  BgRegion chips_;
  mutable std::optional<BgRegion> layer_;
};

// The replay before its moves, for the program's one roughing cycle or SINUMERIK call.
std::optional<MaterialReplay> replayOf(const JudgeInput& in) {
  if (in.path.alarm) return std::nullopt;
  if (const auto calls = in.program.siemensCallsOnOneContour(); !calls.empty()) return siemensReplayOf(in, calls);
  if (const CycleSpec* c = in.program.singleRoughingCycle()) return fanucReplayOf(in, *c);
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<std::vector<Point>>> materialAfter(const JudgeInput& in, std::size_t k) {
  const std::optional<MaterialReplay> r = replayOf(in);
  if (!r) return std::nullopt;
  MaterialModel model(r->stock, r->away, r->reach, in.settings.chordTolerance);
  for (std::size_t i = 0; i < r->judgedMoves && i <= k; ++i) model.apply(in.path.segment(i), in.path.moves[i].kind);
  return outlinesOf(model.remaining());
}

Crossing MaterialReplay::partCrossing(const Segment& move, double epsilon, double chordTolerance) const {
  return partBelowProfile ? crossingOf(*partBelowProfile, move, epsilon, chordTolerance)
                          : crossingOf(partForCrossing, move, epsilon, chordTolerance);
}

std::optional<MaterialReplay> replayMaterial(const JudgeInput& in) {
  std::optional<MaterialReplay> replay = replayOf(in);
  if (!replay) return std::nullopt;
  MaterialReplay& r = *replay;
  // A SINUMERIK call's layers are its infeed steps' business (siemens-infeed-steps), and it has no
  // pocket entries of type II: only its rapids are measured.
  const CycleSpec* c = r.cycle;
  MaterialModel model(r.stock, r.away, r.reach, in.settings.chordTolerance);
  const double tolerance = in.settings.tolerance();
  r.rapidCrossings.resize(in.path.moves.size());
  const bool judgesEntries = c && judgesPocketEntries(*c, in.settings);
  if (judgesEntries) r.pocketEntryCrossings.resize(in.path.moves.size());
  r.removedThickness.resize(in.path.moves.size());
  // The moves before the first cycle (PROG.WHOLE: the approach, a facing cut) remove material and
  // are judged for rapids, but they are no roughing pass: their layers are not Δd's business.
  const std::size_t firstPass = c ? firstMoveOfTheCycles(in) : r.judgedMoves;
  EarlierFeeds earlierFeeds(r.away);
  std::optional<SiemensDocumentedCrossings> documented;
  if (r.siemens) documented.emplace(r, *r.siemens, tolerance, in.settings.chordTolerance);
  for (std::size_t i = 0; i < r.judgedMoves; ++i) {
    const Segment move = in.path.segment(i);
    if (in.path.moves[i].kind == MoveKind::Rapid) {
      r.rapidCrossings[i] = withoutOwnSlot(model.crossing(move, tolerance), in.path, i, tolerance);
      if (documented) r.rapidCrossings[i] = documented->without(r.rapidCrossings[i], move);
      if (judgesEntries) r.pocketEntryCrossings[i] = pocketEntryCrossing(r, model, in, i);
    } else if (documented) {
      documented->noteFeed(move);
    } else {
      if (i >= firstPass && !onFinishShape(in, *c, move)) {
        r.removedThickness[i] = layerBeyondDepthOfCut(model, earlierFeeds, move, *c, in.settings);
      }
      earlierFeeds.add(move);
    }
    model.apply(move, in.path.moves[i].kind);
  }
  r.model = std::move(model);
  return replay;  // moved out (`r` would copy the whole replay into the returned optional)
}

}  // namespace cyclecert
