#include "oracles/material/crossing_region.h"

namespace cyclecert {

namespace {

constexpr int kMostCells = 64;  // per axis

}  // namespace

CrossingRegion::CrossingRegion(const BgRegion& region) {
  // The rings' edges as outlinesOf gives them (a ring's closing point is its first), read in place.
  std::size_t points = 0;
  for (const BgPolygon& polygon : region) {
    points += polygon.outer().size();
    for (const auto& hole : polygon.inners()) points += hole.size();
  }
  edges_.reserve(points);
  const auto addRing = [this](const BgPolygon::ring_type& ring) {
    std::size_t n = ring.size();
    if (n >= 2 && fromBg(ring.front()) == fromBg(ring.back())) --n;
    for (std::size_t i = 0; i < n; ++i) addEdge(fromBg(ring[i]), fromBg(ring[(i + 1) % n]));
  };
  for (const BgPolygon& polygon : region) {
    addRing(polygon.outer());
    for (const auto& hole : polygon.inners()) addRing(hole);
  }
}

CrossingRegion::CrossingRegion(const std::vector<std::vector<Point>>& rings) {
  for (const auto& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) addEdge(ring[i], ring[(i + 1) % ring.size()]);
  }
}

void CrossingRegion::addEdge(Point a, Point b) {
  if (a == b) return;
  edges_.push_back({a, b, 0, 0});
  box_.include(a);
  box_.include(b);
}

void CrossingRegion::makeGrid() const {
  gridMade_ = true;
  // Long: more than a quarter of the region's width or height.
  const double longZ = 0.25 * (box_.zMax - box_.zMin), longX = 0.25 * (box_.xMax - box_.xMin);
  grid_.reserve(edges_.size());
  double gz0 = INFINITY, gz1 = -INFINITY, gx0 = INFINITY, gx1 = -INFINITY;
  for (const Edge& e : edges_) {
    if (std::abs(e.b.z - e.a.z) > longZ || std::abs(e.b.x - e.a.x) > longX) {
      long_.push_back(e);
      continue;
    }
    grid_.push_back(e);
    gz0 = std::min({gz0, e.a.z, e.b.z});
    gz1 = std::max({gz1, e.a.z, e.b.z});
    gx0 = std::min({gx0, e.a.x, e.b.x});
    gx1 = std::max({gx1, e.a.x, e.b.x});
  }
  if (grid_.empty()) return;
  const int side = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(grid_.size()))), 1, kMostCells);
  columns_ = rows_ = side;
  gridZ_ = gz0;
  gridX_ = gx0;
  gridZEnd_ = gz1;
  gridXEnd_ = gx1;
  cellWidth_ = std::max((gz1 - gz0) / side, 1e-9);
  cellHeight_ = std::max((gx1 - gx0) / side, 1e-9);
  // Two passes: count each cell's edges, then list them.
  std::vector<CellRange> ranges;
  ranges.reserve(grid_.size());
  cellStart_.assign(static_cast<std::size_t>(columns_ * rows_) + 1, 0);
  for (Edge& e : grid_) {
    const CellRange r = cellsOf(std::min(e.a.z, e.b.z), std::max(e.a.z, e.b.z), std::min(e.a.x, e.b.x), std::max(e.a.x, e.b.x));
    e.col0 = r.col0;
    e.row0 = r.row0;
    ranges.push_back(r);
    for (int row = r.row0; row <= r.row1; ++row) {
      for (int col = r.col0; col <= r.col1; ++col) ++cellStart_[static_cast<std::size_t>(row * columns_ + col) + 1];
    }
  }
  for (std::size_t c = 1; c < cellStart_.size(); ++c) cellStart_[c] += cellStart_[c - 1];
  cellEdges_.resize(cellStart_.back());
  std::vector<std::uint32_t> filled(cellStart_.begin(), cellStart_.end() - 1);
  for (std::size_t k = 0; k < grid_.size(); ++k) {
    const CellRange& r = ranges[k];
    for (int row = r.row0; row <= r.row1; ++row) {
      for (int col = r.col0; col <= r.col1; ++col) cellEdges_[filled[static_cast<std::size_t>(row * columns_ + col)]++] = static_cast<std::uint32_t>(k);
    }
  }
}

CrossingRegion::CellRange CrossingRegion::cellsOf(double zMin, double zMax, double xMin, double xMax) const {
  // Beyond the grid's box on one side: no cell; across it: the cells it covers there.
  if (zMax < gridZ_ || zMin > gridZEnd_ || xMax < gridX_ || xMin > gridXEnd_) return {0, -1, 0, -1};
  const auto cell = [](double v, double origin, double size, int count) {
    return static_cast<int>(std::clamp(std::floor((v - origin) / size), 0.0, static_cast<double>(count - 1)));
  };
  return {cell(zMin, gridZ_, cellWidth_, columns_), cell(zMax, gridZ_, cellWidth_, columns_),
          cell(xMin, gridX_, cellHeight_, rows_), cell(xMax, gridX_, cellHeight_, rows_)};
}

bool CrossingRegion::contains(Point p) const {
  if (!mayMeet(p.z, p.z, p.x, p.x)) return false;
  bool inside = false;
  // Even-odd: count the edges a ray from p towards +z crosses.
  forEachEdgeNear(p.z, box_.zMax, p.x, p.x, [&](Point a, Point b) {
    if ((a.x > p.x) != (b.x > p.x) && p.z < a.z + (p.x - a.x) / (b.x - a.x) * (b.z - a.z)) inside = !inside;
  });
  return inside;
}

RegionBelowGraph::RegionBelowGraph(const DepthFrame& frame, std::vector<std::pair<double, double>> top, double dBottom)
    : frame_(frame), top_(std::move(top)), dBottom_(dBottom) {
  blockDepths_.reserve(top_.size() / kBlock + 1);
  // Block b holds the edges from vertex b·kBlock on: its depths are those of its vertices, up to the
  // one ending its last edge.
  for (std::size_t first = 0; first + 1 < top_.size(); first += kBlock) {
    const std::size_t last = std::min(first + kBlock, top_.size() - 1);
    double low = top_[first].second, high = low;
    for (std::size_t v = first + 1; v <= last; ++v) {
      low = std::min(low, top_[v].second);
      high = std::max(high, top_[v].second);
    }
    blockDepths_.push_back({low, high});
  }
  // The box of the frame's rectangle the region fills: for a frame along the axes, as every
  // cycle's is, the region's own box.
  double highest = dBottom_;
  for (const auto& [low, high] : blockDepths_) highest = std::max(highest, high);
  const double cMin = top_.front().first, cMax = top_.back().first;
  for (const Point p : {frame_.point(cMin, dBottom_), frame_.point(cMin, highest), frame_.point(cMax, dBottom_),
                        frame_.point(cMax, highest)}) {
    box_.include(p);
  }
}

bool RegionBelowGraph::staysWithin(Point a, Point b, double slack) const {
  double ca = frame_.cut(a), da = frame_.depth(a), cb = frame_.cut(b), db = frame_.depth(b);
  if (ca > cb) {
    std::swap(ca, cb);
    std::swap(da, db);
  }
  if (cb < top_.front().first || ca > top_.back().first) return true;  // beside the region
  // Along the depth axis: each point has one at or above the top within `slack` beside it.
  if (cb - ca <= kGeomEps) return std::min(da, db) >= lowestTopWithin(ca - slack, cb + slack);
  return staysAbove(ca, da, cb, db, slack);
}

RegionBelowGraph::Vertex RegionBelowGraph::firstAtOrAfter(double c, Vertex from) const {
  // Searched from a vertex already found for a chord's other end, the one sought is mostly among
  // the next few (a chord spans few of the top's vertices): those are looked at first.
  const Vertex near = from + std::min<std::ptrdiff_t>(kNearVertices, top_.end() - from);
  for (Vertex it = from; it != near; ++it) {
    if (!(it->first < c)) return it;
  }
  return std::lower_bound(near, top_.end(), c, [](const auto& q, double v) { return q.first < v; });
}

RegionBelowGraph::Vertex RegionBelowGraph::firstAfter(double c) const {
  return std::upper_bound(top_.begin(), top_.end(), c, [](double v, const auto& q) { return v < q.first; });
}

double RegionBelowGraph::topBefore(double c, Vertex atOrAfter) const {
  if (atOrAfter == top_.end()) return top_.back().second;
  if (atOrAfter == top_.begin() || atOrAfter->first == c) return atOrAfter->second;
  const auto& [c0, d0] = *(atOrAfter - 1);
  return d0 + (c - c0) / (atOrAfter->first - c0) * (atOrAfter->second - d0);
}

double RegionBelowGraph::topAfter(double c, Vertex after) const {
  if (after == top_.begin()) return top_.front().second;
  const auto& [c0, d0] = *(after - 1);
  if (after == top_.end() || c0 == c) return d0;
  return d0 + (c - c0) / (after->first - c0) * (after->second - d0);
}

double RegionBelowGraph::lowestTopWithin(double c0, double c1) const {
  if (c0 <= top_.front().first || c1 >= top_.back().first) return -INFINITY;
  auto it = firstAtOrAfter(c0, top_.begin());
  double lowest = std::min(topBefore(c0, it), topAfter(c1, firstAfter(c1)));
  for (; it != top_.end() && it->first <= c1; ++it) lowest = std::min(lowest, it->second);
  return lowest;
}

bool RegionBelowGraph::staysAbove(double ca, double da, double cb, double db, double slack) const {
  const double cMin = top_.front().first, cMax = top_.back().first;
  // Over the region only: clip the segment to its cut coordinates.
  const auto depthAt = [&](double c) { return da + (c - ca) / (cb - ca) * (db - da); };
  const double c0 = std::max(ca, cMin), c1 = std::min(cb, cMax);
  // At its ends, the top on the segment's side of a wall standing there (one search finds both).
  const Vertex after = firstAfter(c0);
  if (depthAt(c0) < topAfter(c0, after) - slack) return false;
  if (depthAt(c1) < topBefore(c1, firstAtOrAfter(c1, c1 > c0 ? after : top_.begin())) - slack) return false;
  const double lowest = std::min(depthAt(c0), depthAt(c1)) + slack;
  for (std::size_t i = static_cast<std::size_t>(after - top_.begin()); i < top_.size() && top_[i].first < c1;) {
    if (blockDepths_[std::min(i, top_.size() - 2) / kBlock].second <= lowest) {  // the block stands no higher
      i = (i / kBlock + 1) * kBlock;
      continue;
    }
    if (depthAt(top_[i].first) < top_[i].second - slack) return false;
    ++i;
  }
  return true;
}

bool RegionBelowGraph::contains(Point p) const {
  const double c = frame_.cut(p), d = frame_.depth(p);
  if (!(c > top_.front().first && c < top_.back().first && d > dBottom_)) return false;
  // The first edge of the top reaching past c (a wall standing at c is as good as its neighbour:
  // the points asked about are away from the boundary).
  const Vertex it = firstAfter(c);
  const auto& [c1, d1] = *it;
  const auto& [c0, d0] = *(it - 1);
  return d < d0 + (c - c0) / (c1 - c0) * (d1 - d0);
}

}  // namespace cyclecert
