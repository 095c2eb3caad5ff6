#pragma once
// A region prepared for many crossing tests (material_model.h, crossingOf): its edges as plain
// points, indexed by a grid over them so that a chord of a move meets only the edges near it, and
// containment by the even-odd rule over the same index. No Boost.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "oracles/material/depth_frame.h"
#include "oracles/material/region.h"

namespace cyclecert {

// The box a region's points span, grown point by point (empty at first): what both indexes below
// test a query against before visiting any edge.
struct PlaneBox {
  double zMin = INFINITY, zMax = -INFINITY, xMin = INFINITY, xMax = -INFINITY;
  void include(Point p) {
    zMin = std::min(zMin, p.z);
    zMax = std::max(zMax, p.z);
    xMin = std::min(xMin, p.x);
    xMax = std::max(xMax, p.x);
  }
  // Whether the box [z0, z1] × [x0, x1] meets this one.
  bool meets(double z0, double z1, double x0, double x1) const {
    return !(z1 < zMin || z0 > zMax || x1 < xMin || x0 > xMax);
  }
};

class CrossingRegion {
 public:
  // The grid is made on the first query that visits edges (a move the box alone shows clear of the
  // region never needs it): one region, one thread.
  CrossingRegion() = default;  // empty
  explicit CrossingRegion(const BgRegion& region);
  explicit CrossingRegion(const std::vector<std::vector<Point>>& rings);  // each closed implicitly

  // Whether the box [zMin, zMax] × [xMin, xMax] meets the region's box.
  bool mayMeet(double zMin, double zMax, double xMin, double xMax) const { return box_.meets(zMin, zMax, xMin, xMax); }
  // Whether p is inside: the even-odd rule over every ring (outer rings and holes alike). For
  // points away from the boundary, as the crossing test asks.
  bool contains(Point p) const;
  // Calls visit(a, b) once for every edge whose box meets [zMin, zMax] × [xMin, xMax] (and for a few
  // more nearby).
  template <typename Visit>
  void forEachEdgeNear(double zMin, double zMax, double xMin, double xMax, Visit visit) const;

 private:
  struct Edge {
    Point a, b;
    int col0, row0;  // the first grid cell its box meets
  };
  struct CellRange {
    int col0, col1, row0, row1;
  };
  void addEdge(Point a, Point b);  // an edge of a ring (none for a repeated point)
  CellRange cellsOf(double zMin, double zMax, double xMin, double xMax) const;
  void makeGrid() const;

  PlaneBox box_;
  std::vector<Edge> edges_;  // every edge, ring by ring
  // Edges spanning a good part of the region (a bottom line, the sides) are few and visited
  // always; the others sit in a grid over their own box, each listed in every cell its box meets.
  mutable bool gridMade_ = false;
  mutable std::vector<Edge> long_;
  mutable std::vector<Edge> grid_;
  mutable double gridZ_ = 0, gridX_ = 0, gridZEnd_ = 0, gridXEnd_ = 0, cellWidth_ = 1, cellHeight_ = 1;
  mutable int columns_ = 0, rows_ = 0;
  mutable std::vector<std::uint32_t> cellStart_;  // per cell (row-major), where its edges start in cellEdges_
  mutable std::vector<std::uint32_t> cellEdges_;  // indices into grid_
};

template <typename Visit>
void CrossingRegion::forEachEdgeNear(double zMin, double zMax, double xMin, double xMax, Visit visit) const {
  if (!gridMade_) makeGrid();
  for (const Edge& e : long_) visit(e.a, e.b);
  if (grid_.empty()) return;
  const CellRange q = cellsOf(zMin, zMax, xMin, xMax);
  if (q.col0 > q.col1 || q.row0 > q.row1) return;
  for (int row = q.row0; row <= q.row1; ++row) {
    for (int col = q.col0; col <= q.col1; ++col) {
      const std::size_t cell = static_cast<std::size_t>(row) * static_cast<std::size_t>(columns_) + static_cast<std::size_t>(col);
      for (std::uint32_t k = cellStart_[cell]; k < cellStart_[cell + 1]; ++k) {
        const Edge& e = grid_[cellEdges_[k]];
        // Listed in every cell its box meets: visited from the first of those the query meets.
        if (std::max(e.col0, q.col0) == col && std::max(e.row0, q.row0) == row) visit(e.a, e.b);
      }
    }
  }
}

// The same tests for a region below a graph over the frame's cut axis, down to a flat bottom (the
// region below the feeds' envelope, CutEnvelope::belowTop): its top's edges are found by their cut
// coordinates, a binary search — nothing to build.
class RegionBelowGraph {
 public:
  // `top`: (cut, depth) in frame coordinates, cut not decreasing, from the region's one side to the
  // other; at least two points.
  RegionBelowGraph(const DepthFrame& frame, std::vector<std::pair<double, double>> top, double dBottom);

  bool mayMeet(double zMin, double zMax, double xMin, double xMax) const { return box_.meets(zMin, zMax, xMin, xMax); }
  bool contains(Point p) const;
  template <typename Visit>
  void forEachEdgeNear(double zMin, double zMax, double xMin, double xMax, Visit visit) const;
  // Whether no point of the segment a→b is more than `slack` inside, found without measuring: it
  // comes no more than `slack` below the top wherever it passes over the region (their difference
  // is linear between the top's points, so those decide), or — a segment along the depth axis, as
  // a plunge or a move down a wall — it stands no lower than the top somewhere within `slack` of
  // it along the cut axis (beside a wall, or a side of the region).
  bool staysWithin(Point a, Point b, double slack) const;

 private:
  // The top's vertices by cut coordinate: the first at or after c (searched from `from` on), the
  // first after c.
  using Vertex = std::vector<std::pair<double, double>>::const_iterator;
  Vertex firstAtOrAfter(double c, Vertex from) const;
  Vertex firstAfter(double c) const;
  // The top's depth just before c and just after it along the cut axis — the two sides of a wall
  // standing at c — given the vertex found for c.
  double topBefore(double c, Vertex atOrAfter) const;
  double topAfter(double c, Vertex after) const;
  bool staysAbove(double ca, double da, double cb, double db, double slack) const;  // ca < cb, not along the depth axis
  double lowestTopWithin(double c0, double c1) const;  // -∞ where [c0, c1] reaches past a side

  static constexpr std::size_t kBlock = 16;  // top edges per block
  static constexpr std::ptrdiff_t kNearVertices = 4;  // firstAtOrAfter's look before it searches

  DepthFrame frame_;
  std::vector<std::pair<double, double>> top_;
  // Per block of kBlock top edges, the depths they span: a query skips the blocks it cannot meet.
  std::vector<std::pair<double, double>> blockDepths_;
  double dBottom_;
  PlaneBox box_;
};

template <typename Visit>
void RegionBelowGraph::forEachEdgeNear(double zMin, double zMax, double xMin, double xMax, Visit visit) const {
  const double cMin = top_.front().first, cMax = top_.back().first;
  // The sides and the bottom, always; then the top's edges over the query's cut coordinates.
  visit(frame_.point(cMin, dBottom_), frame_.point(cMin, top_.front().second));
  visit(frame_.point(cMax, top_.back().second), frame_.point(cMax, dBottom_));
  visit(frame_.point(cMax, dBottom_), frame_.point(cMin, dBottom_));
  const DepthFrame::Ranges q = frame_.rangesOf(zMin, zMax, xMin, xMax);
  const Vertex it = firstAtOrAfter(q.cMin, top_.begin());
  std::size_t i = it == top_.begin() ? 0 : static_cast<std::size_t>(it - top_.begin()) - 1;
  while (i + 1 < top_.size() && top_[i].first <= q.cMax) {
    const auto& [low, high] = blockDepths_[i / kBlock];
    if (high < q.dMin || low > q.dMax) {  // the rest of this block stands wholly above or below the query
      i = (i / kBlock + 1) * kBlock;
      continue;
    }
    visit(frame_.point(top_[i].first, top_[i].second), frame_.point(top_[i + 1].first, top_[i + 1].second));
    ++i;
  }
}

}  // namespace cyclecert
