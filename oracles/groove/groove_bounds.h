#pragma once
// Bounds that spare the G74.1 replay its Boost booleans where they prove the exact answer
// (groove_replay.h), in the groove's frame (u = x, w = z: depth, down):
// - PartTop: where the part begins below each u — the target's chain where the groove is, the
//   mouth line beside it, nothing beyond the stock band. A move whose tool stays at or above it over
//   its whole span touches no part: no crossing, without intersecting regions.
// - ClearedStaircase: the union of the removals that reach up out of the material (a blade's sweep:
//   its shank runs back out of the stock; a point's peck that starts where the material is already
//   gone), which is {w ≤ C(u)} within the band for a step function C. The material still standing
//   lies below C, so a rapid whose tool stays at or above max(C, mouth) crosses none; and the
//   material after many pecks is the band without one staircase polygon, not hundreds of
//   differences. Removals of any other shape (a pass along a flank) stay exact regions.
// - ClearedOutline: the same union for a blade's every feed, {w ≤ D(u)} for a piecewise-linear D
//   (a blade's sweep reaches back out of the band over its whole span, down to its deepest
//   outline). A bound only, never a region: a blade's rapid at or above max(D, mouth) crosses
//   nothing still standing, and a target whose chain lies at or above D is emptied — the exact
//   removals are then never needed.
// - ShadowedRows: the same for a point's feeds over w: a shadow reaching the band's side clears
//   the rows behind its chord, {u ≤ L(w)} ∪ {u ≥ R(w)}.
// ClearedOutline and ShadowedRows prove "nothing thicker than a slack" (the replay's ε/2: what lies
// between two outlines that close is no thicker, 2·area/perimeter). All are conservative: where
// they cannot prove it, the exact computation runs.
#include <map>
#include <optional>
#include <vector>

#include "oracles/groove/groove_spec.h"
#include "oracles/material/region.h"

namespace cyclecert {

// The extent of a tool's move in the groove's frame: u from uFrom to uTo, at most wDeepest deep.
struct ToolExtent {
  double uFrom = 0, uTo = 0;
  double wShallowest = 0, wDeepest = 0;
};
// A move's extent with the tool spanning `width` towards −u from its programmed point (0: a point);
// arcs through their chords within chordTolerance.
ToolExtent toolExtent(const Segment& localMove, double width, double chordTolerance);

// The stock band's u range and its top (the mouth line w = u·tan∠p).
struct BandFrame {
  double uLo = 0, uHi = 0;
  double tanSlope = 0;
  double mouthAt(double u) const { return u * tanSlope; }
  double shallowestMouth(double u0, double u1) const { return std::min(mouthAt(u0), mouthAt(u1)); }
};

class PartTop {
 public:
  // Nothing when the target's chain is no graph over u (then no bound: every move is exact).
  static std::optional<PartTop> of(const GrooveOutline& target, const BandFrame& band, double chordTolerance);
  // The shallowest depth at which the part begins over [u0, u1] (+∞ where there is none). A span
  // of some width ignores walls at its ends (a blade beside a wall overlaps none of it); a point
  // (u0 = u1) is judged by the deeper of its two sides: on a wall or an edge, it touches the part
  // only when both sides do (the point crossings count what lies deeper than ε inside).
  double shallowestOver(double u0, double u1) const;
  // Whether the part begins at or below the polyline `outline` (local points, u strictly
  // increasing) within `slack` at every u of its span: a tool whose deepest outline that is
  // touches no part. Both are linear between their vertices, so they are compared there (at the
  // span's ends, the part's side within the span).
  bool liesBelow(const std::vector<Point>& outline, double slack) const;
  // The target's chain, flattened (u non-decreasing).
  const std::vector<Point>& chain() const { return chain_; }

 private:
  double sideOf(double u, int side) const;  // where the part begins just left (−1) or right (+1) of u
  // The chain's segments k (from chain_[k − 1] to chain_[k]) that may reach into [lo, hi]: [first, end).
  std::pair<std::size_t, std::size_t> segmentsWithin(double lo, double hi) const;
  std::vector<Point> chain_;  // flattened, u non-decreasing (within a nanometre)
  std::vector<double> maxUpTo_;  // the greatest u of chain_[0..k]
  std::vector<double> minFrom_;  // the least u of chain_[k..]
  BandFrame band_;
};

class ClearedStaircase {
 public:
  explicit ClearedStaircase(BandFrame band) : band_(band) {}
  // C := max(C, w) on [u0, u1].
  void clearDownTo(double u0, double u1, double w);
  // Whether everything in the band above depth w over [u0, u1] is gone (cleared, or air above the
  // mouth): then a removal from w down unites with the staircase exactly.
  bool goneAbove(double u0, double u1, double w) const;
  // Whether a tool over [u0, u1] no deeper than w crosses nothing of the band still standing. A
  // point (u0 = u1) on a step's edge stands on the boundary: nothing when either side is gone.
  bool clearOver(double u0, double u1, double w) const;
  bool empty() const { return steps_.empty(); }
  // The cleared region within the band's u range, from `top` (above the band) down to C: one ring
  // per run of steps.
  std::vector<std::vector<Point>> outlines(double top) const;

 private:
  // For a step starting at u (key): its depth up to the next key; −∞ marks "not cleared" from there.
  std::map<double, double> steps_;
  BandFrame band_;
  double depthAt(std::map<double, double>::const_iterator it) const;
  double snapped(double u) const;  // an existing step's edge within a nanometre, else u
};

// The upper envelope M(x) of lines raised over their spans (a point's z is the value at its x):
// piecewise linear, −∞ where no line reaches.
class PiecewiseMax {
 public:
  // M := max(M, the line p → q) over [p.x, q.x]; nothing when p.x ≥ q.x.
  void raise(Point p, Point q);
  // M's values at x0 and x1 on the piece spanning [x0, x1] (no breakpoint inside it); nothing
  // where no line reaches.
  std::optional<std::pair<double, double>> over(double x0, double x1) const;
  // The greatest value at x of the pieces reaching within `near` of x (at a breakpoint, the
  // greater side); nothing where none does.
  std::optional<double> greatestNear(double x, double near) const;
  // M's breakpoints strictly between a and b, appended to `out`.
  void breakpoints(double a, double b, std::vector<double>& out) const;

 private:
  // M from (x0, m0) to (x1, m1), linear, x0 < x1; the pieces sorted along x, their interiors
  // disjoint.
  struct Piece {
    double x0, m0, x1, m1;
    double at(double x) const { return m0 + (m1 - m0) * (x - x0) / (x1 - x0); }
  };
  static void append(std::vector<Piece>& out, Piece piece);
  std::vector<Piece> pieces_, scratch_;
};

// A blade's feeds: the union of their sweeps is {w ≤ D(u)} within the band, D = the upper envelope
// (in w: depth) of their deepest outlines over u.
class ClearedOutline {
 public:
  explicit ClearedOutline(BandFrame band) : band_(band) {}
  // D := max(D, outline) over the outline's span (local points, u strictly increasing).
  void clearDownTo(const std::vector<Point>& outline);
  // Whether the polyline `outline` (u non-decreasing; a wall, a piece along w, is skipped: the
  // pieces beside it hold its ends) lies at or above max(D, mouth) within `slack` over its span
  // within the band: nothing that stands lies above it.
  bool covers(const std::vector<Point>& outline, double slack) const;

 private:
  bool coversLine(Point p, Point q, double slack) const;
  PiecewiseMax deepest_;  // over u: D
  BandFrame band_;
};

// A point's feeds: a chord p → q not along u, its shadow reaching the band's side, clears the rows
// it spans behind it: {u ≤ u(w)} for a shadow towards −u, {u ≥ u(w)} towards +u. Their union
// holds {u ≤ L(w)} ∪ {u ≥ R(w)} for L, R piecewise linear over w — a bound only, as ClearedOutline.
class ShadowedRows {
 public:
  explicit ShadowedRows(BandFrame band) : band_(band) {}
  // The chord's rows behind it, for a shadow of `shadow` towards `side` (±1 along u).
  void clearBehind(Point p, Point q, int side, double shadow);
  // Whether the target — the interior above its chain (local, u non-decreasing; down to its deepest
  // point, then up) and straight up from its ends — lies within the cleared rows within `slack`,
  // from the band's shallowest top down to the chain's deepest point.
  bool coversTarget(const std::vector<Point>& chain, double slack) const;
  // Whether the point's chord p → q runs within `slack` of the cleared rows, above the band's
  // shallowest top or beside the band all along: nothing that stands lies farther than that
  // inside of it.
  bool clears(Point p, Point q, double slack) const;

 private:
  PiecewiseMax left_;   // over w: L
  PiecewiseMax right_;  // over w: −R
  BandFrame band_;
};

}  // namespace cyclecert
