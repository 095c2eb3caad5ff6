#pragma once
// The cycle's frame as the material model sees it: a depth axis (along `away`, which points from
// the part towards the cycle start side) and a cut axis perpendicular to it. G71 outer turning:
// away = (0, +1); boring: (0, −1); G72 facing: (±1, 0).
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

class DepthFrame {
 public:
  // `away` need not be unit length; it is normalised. Throws std::invalid_argument when it is zero
  // or not finite.
  explicit DepthFrame(Point away) {
    const double length = std::hypot(away.z, away.x);
    if (!std::isfinite(length) || length <= kGeomEps) {
      throw std::invalid_argument("the away direction must be a finite, non-zero vector");
    }
    away_ = (1.0 / length) * away;
    along_ = {away_.x, -away_.z};  // `away` turned by −90°
  }

  Point away() const { return away_; }
  Point along() const { return along_; }  // unit vector of the cut axis
  // Coordinate along the depth axis, growing away from the part.
  double depth(Point p) const { return p.z * away_.z + p.x * away_.x; }
  // Coordinate along the cut axis.
  double cut(Point p) const { return p.z * along_.z + p.x * along_.x; }
  // The point with p's cut coordinate at the given depth.
  Point atDepth(Point p, double depthCoordinate) const {
    return p + (depthCoordinate - depth(p)) * away_;
  }
  // The point of the plane at the given frame coordinates.
  Point point(double cutCoordinate, double depthCoordinate) const {
    return cutCoordinate * along_ + depthCoordinate * away_;
  }

  // The ranges of cut and depth coordinates a box of the plane, [zMin, zMax] × [xMin, xMax], spans.
  struct Ranges {
    double cMin, cMax, dMin, dMax;
  };
  Ranges rangesOf(double zMin, double zMax, double xMin, double xMax) const {
    Ranges r{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const Point corner : {Point{zMin, xMin}, Point{zMin, xMax}, Point{zMax, xMin}, Point{zMax, xMax}}) {
      r.cMin = std::min(r.cMin, cut(corner));
      r.cMax = std::max(r.cMax, cut(corner));
      r.dMin = std::min(r.dMin, depth(corner));
      r.dMax = std::max(r.dMax, depth(corner));
    }
    return r;
  }

 private:
  Point away_;
  Point along_;
};

// The span of segments' end points along a frame's cut axis; lo > hi when there are none.
struct CutSpan {
  double lo = INFINITY, hi = -INFINITY;
};
inline CutSpan cutSpanOf(std::span<const Segment> segments, const DepthFrame& frame) {
  CutSpan span;
  for (const Segment& s : segments) {
    for (Point p : {s.from, s.to}) {
      span.lo = std::min(span.lo, frame.cut(p));
      span.hi = std::max(span.hi, frame.cut(p));
    }
  }
  return span;
}

// The pieces of a segment, held in place (no allocation: callers split every move): an arc turns
// back along the cut axis at most twice, so three pieces at most.
class SegmentPieces {
 public:
  void push(const Segment& piece) { pieces_[count_++] = piece; }
  const Segment* begin() const { return pieces_.data(); }
  const Segment* end() const { return pieces_.data() + count_; }

 private:
  std::array<Segment, 3> pieces_;
  std::size_t count_ = 0;
};

// The segment cut into pieces that are each a graph over the frame's cut axis: an arc is cut at
// the points where its tangent is parallel to `away` (where it turns back along the cut axis);
// lines come back unchanged.
SegmentPieces splitWhereTangentIsAlong(const Segment& s, const DepthFrame& frame);

// Whether the path is a graph over the cut axis: it never turns back along it (walls along the
// depth axis allowed).
bool isGraphOverCutAxis(std::span<const Segment> path, const DepthFrame& frame);

// isGraphOverCutAxis piece by piece, for a caller that splits the path itself: whether each piece
// (of splitWhereTangentIsAlong) goes the way the ones before went along the cut axis.
class OneWayAlongCut {
 public:
  bool keeps(const Segment& piece, const DepthFrame& frame);

 private:
  int direction_ = 0;  // +1 or −1 once a piece advanced
};

}  // namespace cyclecert
