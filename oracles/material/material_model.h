#pragma once
// The material model: the stock minus what the tool has removed so far, replayed move by move.
// A feed removes its shadow — the region the ray from the tool point along `away` (towards the
// cycle start side, away from the part) sweeps over `reach` mm as the tool point moves; a rapid
// removes nothing (a rapid through material is a crash, which `crossing` measures, not a cut).
#include <cmath>
#include <optional>
#include <vector>

#include <boost/geometry/geometries/box.hpp>

#include "oracles/material/crossing_region.h"
#include "oracles/material/cut_envelope.h"
#include "oracles/material/depth_frame.h"
#include "oracles/material/region.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// The shadow of a move: {p + t·away : p on the move (arcs flattened within chordTolerance),
// t ∈ [0, reach]} — a parallelogram for a line (a rectangle when the line runs along the cut axis),
// empty for a move along the depth axis or of zero length. Arcs are split where their tangent is
// parallel to `away`, so that every piece is a graph over the cut axis.
BgRegion shadowOf(const Segment& move, Point away, double reach, double chordTolerance);

// The parts of a move that run through the interior of a region.
struct Crossing {
  double length = 0;            // mm, the sum of the pieces' lengths
  std::vector<Segment> pieces;  // lines, in move order (pieces of chords for an arc)
};

// The pieces of `move` (arcs flattened within chordTolerance) that lie in `region` at a distance of
// more than `epsilon` from its boundary — i.e. in the region eroded by a disk of radius epsilon,
// computed exactly rather than through a buffer — so that touching or grazing the region within
// epsilon does not count. epsilon below kTidyDistance counts as kTidyDistance. Serves both the
// rapids-in-air oracle (region = the material left) and no-gouge (region = partRegion).
// Distances here are Euclidean, so flattening errs by at most chordTolerance per flattened figure
// (region.h): pass ε + chordTolerance when only one of region and move has arcs (a rapid, a line,
// against the material), ε + 2·chordTolerance when both may. Cost: O(flattened chords × region
// edges) plain arithmetic, no Boost boolean.
Crossing crossingOf(const BgRegion& region, const Segment& move, double epsilon,
                    double chordTolerance);
// The same for a region prepared once for many moves.
Crossing crossingOf(const CrossingRegion& region, const Segment& move, double epsilon, double chordTolerance);
Crossing crossingOf(const RegionBelowGraph& region, const Segment& move, double epsilon, double chordTolerance);

// The model keeps the stock as it is and, for what the feeds removed, the envelope of their paths
// (cut_envelope.h): every shadow removes all beyond its move, so the feeds together remove all
// beyond one piecewise-linear function of the cut coordinate. Applying a feed merges it into that
// function; the material left (stock below the envelope) is made — one boolean — only when asked.
class MaterialModel {
 public:
  // `stock` is taken as it is (a region from stock.h); `away` as in DepthFrame; `reach` is used by
  // removedBy's shadows (the envelope needs none). Throws std::invalid_argument for a zero `away`,
  // or a reach or chord tolerance that is not positive.
  MaterialModel(BgRegion stock, Point away, double reach, double chordTolerance);

  // Feeds remove their shadow; rapids remove nothing.
  void apply(const Segment& move, MoveKind kind);

  // The material still there: the stock below the envelope of the feeds so far.
  const BgRegion& remaining() const;
  double area() const;

  // crossingOf(remaining(), move, epsilon, chordTolerance), without making remaining(): a point is
  // ε inside the material exactly when it is ε inside the stock and ε below the envelope.
  Crossing crossing(const Segment& move, double epsilon) const;

  // A top of the material over the cut coordinates [c0, c1], in frame coordinates: the envelope
  // where feeds have been, capped by the stock's deepest point over each of its pieces, and that
  // point over the gaps (nothing where no stock stands). Every point of remaining() there stands at
  // or below it (exactly the material's top for a stock with a flat top: a bar, or the stock a
  // cycle implies). No Boost.
  std::vector<CutEnvelope::Piece> topWithin(double c0, double c1) const;

  // A tighter top over [c0, c1] that leaves out skins narrower than 2·`skin` along the cut axis:
  // at each cut coordinate c the lowest of the material's top at c and at c ± skin, the top being
  // the lower of the envelope and the stock's own top there (not its highest point over a piece,
  // as topWithin takes). A point of the material without such skins — withoutSkins in
  // material_replay.h: what is left where the material and its copies moved by ± skin along the
  // cut axis meet — stands at or below it (up to the booleans' rounding). Nothing where no stock
  // stands; nothing at all where the envelope's pieces overlap there (a feed split into pieces
  // that are no graph over the cut axis): no bound. No Boost.
  std::optional<std::vector<CutEnvelope::Piece>> topWithoutSkinsWithin(double c0, double c1, double skin) const;

  // The material's top at each cut coordinate over [c0, c1]: the stock's top, lowered to the
  // envelope where feeds have been; nothing where no stock stands. Nothing at all where the
  // envelope's pieces overlap. What topWithoutSkinsWithin reads from.
  std::optional<CutEnvelope> pointwiseTopWithin(double c0, double c1) const;

  // topWithoutSkinsWithin(c0, c1, skin) read from `top`, a pointwiseTopWithin over at least
  // [c0 − skin, c1 + skin]: one top serves several skin widths.
  static std::vector<CutEnvelope::Piece> withoutSkinsOf(const CutEnvelope& top, double c0, double c1, double skin);

  // The material a feed along `move` would remove now (remaining ∩ shadow), without removing it.
  BgRegion removedBy(const Segment& move) const;

  Point away() const { return frame_.away(); }
  double reach() const { return reach_; }
  double chordTolerance() const { return chordTolerance_; }

 private:
  using Box = boost::geometry::model::box<BgPoint>;
  struct FrameBox {
    double cMin, cMax, dBottom, dTop;
  };

  FrameBox inFrame(const Box& box) const;  // the box's ranges along the cut and depth axes
  FrameBox frameBox() const;
  // The deepest the stock comes over the cut coordinates [c0, c1]; nothing when it has no point
  // there. Where the range has some width, a wall standing at one of its ends does not count.
  std::optional<double> stockDeepestWithin(double c0, double c1) const;
  // The region below the envelope as the crossing tests see it, made when first asked for after
  // the feeds lowered the envelope.
  const RegionBelowGraph& belowForCrossing() const;

  BgRegion stock_;
  CrossingRegion stockForCrossing_;
  CutEnvelope stockTop_;  // the stock's top, seen from the other side (stockDeepestWithin)
  Box stockEnvelope_;
  DepthFrame frame_;
  double reach_;
  double chordTolerance_;
  CutEnvelope cut_;
  std::vector<Point> flattened_;  // apply's buffer for a move's chords
  mutable std::optional<RegionBelowGraph> belowForCrossing_;  // belowForCrossing's
  mutable std::optional<BgRegion> remaining_;  // likewise
};

}  // namespace cyclecert
