#pragma once
// The rough profile of a type II cycle seen as pockets: in the cycle frame (cut along z, steps
// along x), the profile A'→B'→…→C' cut into pieces that are monotonic on both axes (arcs split at
// their apexes), with the questions the type II motion asks of it: where is it deeper than a level
// (intervals), where are its valley bottoms, and where does walking up a wall end.
#include <optional>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

// A point on the profile and the piece it lies on.
struct ProfilePos {
  std::size_t piece = 0;
  Point p;
};

// A maximal run of the cut axis where the profile is strictly deeper than a level.
struct ProfileInterval {
  ProfilePos start, end;  // the level's crossings of the near and far walls (or C' when openEnd)
  bool openEnd = false;   // the profile ends (at C') still deeper than the level
};

// A valley bottom (G71.T2.VALLEY): a piece parallel to the cut axis, or a point where the profile
// turns from going deeper to coming back.
struct ValleyBottom {
  ProfilePos start, end;  // equal for a point
  double depth = 0;
};

class PocketProfile {
 public:
  // `segments`: the rough profile in the frame, head segment(s) first (`headCount` of them).
  // depth(x) = depthSign·(x − origin.x) grows into the part; progress(z) = cutSign·z grows along the cut.
  PocketProfile(const std::vector<Segment>& segments, std::size_t headCount, Point origin, int depthSign, int cutSign);

  double depth(Point p) const { return d_ * (p.x - origin_.x); }
  double progress(Point p) const { return c_ * p.z; }
  double xAtDepth(double depth) const { return origin_.x + d_ * depth; }

  const std::vector<Segment>& pieces() const { return pieces_; }
  bool isHeadPiece(std::size_t i) const { return i < headPieces_; }
  bool isAlongCut(std::size_t i) const;  // parallel to the cut axis

  double deepest() const;         // largest depth on the profile
  double shallowestAfterHead() const;  // least depth after B' (G71.T2.RETURN)
  bool hasPocketWall() const;     // the profile goes deeper again after coming back (G71.T2.DW0)

  std::vector<ProfileInterval> intervalsAt(double level) const;
  const std::vector<ValleyBottom>& valleyBottoms() const { return bottoms_; }

  // Walking back from `from` up the near wall: the first point at depth `level`, or the top of the
  // wall when the profile turns before, or A'. Returns the path from that point to `from`.
  std::vector<Segment> wallAbove(const ProfilePos& from, double level) const;
  // Walking forward from `from` up the far wall: until depth `level`, a peak, C', or — unless
  // `followAlongCut` — the start of a piece parallel to the cut axis.
  std::vector<Segment> wallAfter(const ProfilePos& from, double level, bool followAlongCut) const;

 private:
  std::optional<Point> crossing(std::size_t piece, double level) const;
  void findValleyBottoms();

  std::vector<Segment> pieces_;
  std::size_t headPieces_ = 0;
  Point origin_;
  int d_, c_;
  std::vector<ValleyBottom> bottoms_;
};

}  // namespace cyclecert
