#pragma once
// The material model: the stock minus what the tool has removed so far, replayed move by move.
// A feed removes its shadow — the region the ray from the tool point along `away` (towards the
// cycle start side, away from the part) sweeps over `reach` mm as the tool point moves; a rapid
// removes nothing (a rapid through material is a crash, which `crossing` measures, not a cut).
#include <vector>

#include <boost/geometry/geometries/box.hpp>

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

// What a feed removes sinks kShadowSink below the move: material left by earlier passes often
// ends on the very line a later feed follows (a pass ending on the profile, then the semi-finish
// along it), and Boost's difference mishandles such nearly collinear edges — it can leave the whole
// piece standing. A sunk edge crosses them cleanly. Areas and thicknesses the model reports may
// differ from the exact ones by this much per mm of move.
inline constexpr double kShadowSink = 1e-7;  // mm: far below every tolerance, far above rounding

class MaterialModel {
 public:
  // `stock` is taken as it is (a region from stock.h); `away` as in DepthFrame; `reach` should
  // exceed the stock's size along the depth axis so that a shadow leaves the stock (the model cuts
  // its shadows 1 mm past the material's far side anyway). Throws std::invalid_argument for a zero
  // `away`, or a reach or chord tolerance that is not positive.
  MaterialModel(BgRegion stock, Point away, double reach, double chordTolerance);

  // Feeds remove their shadow; rapids remove nothing. A line whose shadow misses the material's
  // interior (retracts, moves over ground already cut) costs no Boost boolean.
  void apply(const Segment& move, MoveKind kind);

  // The material still there.
  const BgRegion& remaining() const { return remaining_; }
  double area() const;

  // crossingOf(remaining(), move, epsilon, chordTolerance).
  Crossing crossing(const Segment& move, double epsilon) const;

  // The material a feed along `move` would remove now (remaining ∩ shadow), without removing it.
  BgRegion removedBy(const Segment& move) const;

  Point away() const { return frame_.away(); }
  double reach() const { return reach_; }
  double chordTolerance() const { return chordTolerance_; }

 private:
  using Box = boost::geometry::model::box<BgPoint>;

  void updateEnvelope();
  double farDepth() const;  // depth of the far side of the material's envelope

  BgRegion remaining_;
  DepthFrame frame_;
  double reach_;
  double chordTolerance_;
  Box envelope_;  // of remaining_: moves whose shadow misses it are skipped
};

}  // namespace cyclecert
