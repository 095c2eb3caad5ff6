#pragma once
// What the feeds have removed, as a height field: a feed's shadow takes everything beyond the move
// along `away` (material_model.h), so what all the feeds so far have removed is everything beyond
// one piecewise-linear function of the cut coordinate — at each cut coordinate, the depth of the
// deepest feed over it (the lower envelope of the feeds' paths), and nothing where no feed has
// been. Applying a feed is a merge of two piecewise-linear functions: no polygon boolean.
#include <algorithm>
#include <vector>

#include "oracles/material/depth_frame.h"
#include "oracles/material/region.h"

namespace cyclecert {

class CutEnvelope {
 public:
  // A linear piece over [c0, c1] (c0 < c1), from depth d0 to d1, in frame coordinates.
  struct Piece {
    double c0, d0, c1, d1;
    double depthAt(double c) const;
  };

  // Lowers the envelope to a path (points of the plane) that is a graph over the frame's cut axis,
  // walked in either direction; chords no longer than kTidyDistance along the cut axis (moves
  // along the depth axis) remove nothing. True when the envelope came lower somewhere.
  bool lower(const std::vector<Point>& path, const DepthFrame& frame);
  // The same for pieces already in frame coordinates, sorted and disjoint (not empty).
  bool lower(const std::vector<Piece>& pieces) { return !pieces.empty() && lowerTo(pieces); }

  bool empty() const { return pieces_.empty(); }
  const std::vector<Piece>& pieces() const { return pieces_; }  // sorted, disjoint

  // Walks [c0, c1] from left to right: each piece's part over it (onPiece(Piece), a single point
  // where a piece only touches it) and each stretch between that no piece covers (onGap(g0, g1):
  // no feed there, the material may stand at its full height).
  template <typename OnPiece, typename OnGap>
  void walk(double c0, double c1, OnPiece onPiece, OnGap onGap) const;

  // The region below the envelope (where material may stand) within the box [cMin, cMax] ×
  // [dBottom, dTop] of the frame, as a region of the plane: the box itself where no feed has been.
  // The box must hold the stock; depths beyond it are clipped to it.
  BgRegion below(const DepthFrame& frame, double cMin, double cMax, double dBottom, double dTop) const;
  // That region's top, as (cut, depth) in frame coordinates from cMin to cMax: a graph over the cut
  // axis (the region is below it, down to dBottom).
  std::vector<std::pair<double, double>> belowTop(double cMin, double cMax, double dBottom, double dTop) const;

 private:
  bool lowerTo(const std::vector<Piece>& fresh);  // sorted, disjoint
  std::vector<Piece> pieces_;
  std::vector<Piece> fresh_, spare_;  // lower()'s working space, kept to spare allocations
};

template <typename OnPiece, typename OnGap>
void CutEnvelope::walk(double c0, double c1, OnPiece onPiece, OnGap onGap) const {
  double covered = c0;
  auto it = std::lower_bound(pieces_.begin(), pieces_.end(), c0, [](const Piece& p, double c) { return p.c1 < c; });
  for (; it != pieces_.end() && it->c0 <= c1; ++it) {
    const double x0 = std::max(c0, it->c0), x1 = std::min(c1, it->c1);
    if (x0 > covered) onGap(covered, x0);
    onPiece(Piece{x0, it->depthAt(x0), x1, it->depthAt(x1)});
    covered = std::max(covered, x1);
  }
  if (covered < c1) onGap(covered, c1);
}

}  // namespace cyclecert
