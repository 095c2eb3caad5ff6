#include "oracles/material/thickness.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/depth_frame.h"

namespace cyclecert {

namespace {

// A piece of the profile that advances along the cut axis, in frame coordinates (c0 < c1): a line,
// or an arc that is a graph over the cut axis (its upper or lower half, `side` +1 or −1, around
// the centre (cc, dc)) — measured exactly, not flattened.
struct ProfileStep {
  double c0, d0, c1, d1;
  bool arc = false;
  double cc = 0, dc = 0, radius = 0, side = 0;

  double depthAt(double c) const {
    c = std::clamp(c, c0, c1);
    if (arc) return dc + side * std::sqrt(std::max(0.0, radius * radius - (c - cc) * (c - cc)));
    return c1 > c0 ? d0 + (c - c0) / (c1 - c0) * (d1 - d0) : d0;
  }
  // Its lowest depth over [a, b] (clamped to its own span): at an end, or at the bottom of a lower
  // half-circle.
  double lowestWithin(double a, double b) const {
    a = std::max(a, c0);
    b = std::min(b, c1);
    const double ends = std::min(depthAt(a), depthAt(b));
    return arc && side < 0 && cc > a && cc < b ? std::min(ends, dc - radius) : ends;
  }
  // Where an edge of slope `slope` stands highest above an arc (its tangent there has the same
  // slope); nothing for a line, whose distance to an edge is largest at the overlap's ends.
  std::optional<double> tangentTo(double slope) const {
    if (!arc) return std::nullopt;
    const double c = cc - side * slope * radius / std::sqrt(1 + slope * slope);
    if (c <= c0 || c >= c1) return std::nullopt;
    return c;
  }
};

// A region edge that advances along the cut axis, in frame coordinates (c0 < c1).
struct RegionEdge {
  double c0, d0, c1, d1;
  double depthAt(double c) const { return d0 + (c - c0) / (c1 - c0) * (d1 - d0); }
};

// The profile's pieces that advance along the cut axis, sorted by c0, with the widest one's length,
// to find those overlapping an interval quickly. Walls along the depth axis are left out.
class ProfileSteps {
 public:
  // A profile that is a graph over the cut axis is measured exactly: under any point one piece
  // (two at a junction, which the window's measurements cover), so the thickness above it is
  // largest at the points measureEdge takes. Where the profile turns back, pieces overlap and the
  // one beneath switches where they cross, which those points miss: such a profile is measured
  // against fine chords (within `chordTolerance`) instead, which sample it densely.
  ProfileSteps(const std::vector<Segment>& profile, const DepthFrame& frame, double chordTolerance) {
    // The graph's pieces, found as isGraphOverCutAxis finds whether it is one.
    std::vector<Segment> pieces;
    bool graph = true;
    OneWayAlongCut way;
    for (const Segment& segment : profile) {
      for (const Segment& piece : splitWhereTangentIsAlong(segment, frame)) {
        graph = graph && way.keeps(piece, frame);
        pieces.push_back(piece);
      }
    }
    if (graph) {
      for (const Segment& piece : pieces) add(piece, frame);
    } else {
      for (const Segment& segment : profile) {
        if (!segment.isArc()) {
          add(segment, frame);
          continue;
        }
        const std::vector<Point> chords = flatten(segment, chordTolerance);
        for (std::size_t i = 1; i < chords.size(); ++i) add({SegmentKind::Line, chords[i - 1], chords[i], {}, 0}, frame);
      }
    }
    std::sort(steps_.begin(), steps_.end(),
              [](const ProfileStep& a, const ProfileStep& b) { return a.c0 < b.c0; });
  }

  // The steps sharing more than `least` with [c0, c1].
  void overlapping(double c0, double c1, double least,
                   std::vector<const ProfileStep*>& out) const {
    out.clear();
    auto it = std::lower_bound(steps_.begin(), steps_.end(), c0 - widest_,
                               [](const ProfileStep& s, double c) { return s.c0 < c; });
    for (; it != steps_.end() && it->c0 < c1 - least; ++it) {
      if (std::min(c1, it->c1) - std::max(c0, it->c0) > least) out.push_back(&*it);
    }
  }

 private:
  void add(const Segment& piece, const DepthFrame& frame) {
    ProfileStep step{frame.cut(piece.from), frame.depth(piece.from), frame.cut(piece.to), frame.depth(piece.to)};
    if (std::abs(step.c1 - step.c0) <= kTidyDistance) return;  // a wall along the depth axis
    if (step.c0 > step.c1) {
      std::swap(step.c0, step.c1);
      std::swap(step.d0, step.d1);
    }
    if (piece.isArc() && piece.radius() > kGeomEps) {
      step.arc = true;
      step.cc = frame.cut(piece.center);
      step.dc = frame.depth(piece.center);
      step.radius = piece.radius();
      step.side = frame.depth(pointAt(piece, 0.5)) >= step.dc ? 1.0 : -1.0;
    }
    steps_.push_back(step);
    widest_ = std::max(widest_, step.c1 - step.c0);
  }

  std::vector<ProfileStep> steps_;
  double widest_ = 0;
};

// The thickness of a region edge above a line of the profile is linear over their overlap, so it
// is largest at one of the overlap's ends; above an arc, at an end or where the arc's tangent is
// parallel to the edge. Only overlaps longer
// than `resolution` count: a region touching the profile's span at a single cut coordinate
// (material beside a shoulder, or beyond the profile's end) stands above nothing there.
// Where the profile is steep, a point off by δ along the cut axis seems slope·δ thicker, and both
// flattening (region.h) and the booleans' rounding move points that way; so the profile beneath a
// point at c is the highest that the steps under its edge come within c ± window (not above the
// point by more than the window), and each overlap is also measured `window` inside its ends, where
// that window no longer reaches past them. Only steps under the edge: a step across a shoulder is
// not beneath.
class ThicknessSearch {
 public:
  // Only thicknesses above `floor` are sought: an edge that cannot stand thicker is not measured.
  // With `firstOnly`, the search ends at the first one found (whether any is: standsThickerThan).
  ThicknessSearch(const ProfileSteps& profile, const DepthFrame& frame, double resolution, double window,
                  double floor = -INFINITY, bool firstOnly = false)
      : profile_(profile), frame_(frame), resolution_(resolution), window_(window), floor_(floor),
        firstOnly_(firstOnly) {}
  // Whether the search has what it was asked for: a thickness above the floor, when the first will do.
  bool done() const { return firstOnly_ && best_.has_value(); }

  void measureEdge(Point p, Point q) { measureEdge(frame_.cut(p), frame_.depth(p), frame_.cut(q), frame_.depth(q)); }

  // The same in frame coordinates.
  void measureEdge(double c0, double d0, double c1, double d1) {
    if (std::abs(c1 - c0) <= kTidyDistance) return;  // along the depth axis: its ends are measured
    if (c0 > c1) {                                   // with the neighbouring edges
      std::swap(c0, c1);
      std::swap(d0, d1);
    }
    const RegionEdge edge{c0, d0, c1, d1};
    profile_.overlapping(c0, c1, resolution_, under_);
    underWidest_ = 0;
    // The lowest the steps come within the window of the edge: every depth measureAt takes beneath
    // a point of the edge is at least that.
    double lowestStep = INFINITY;
    for (const ProfileStep* s : under_) {
      underWidest_ = std::max(underWidest_, s->c1 - s->c0);
      lowestStep = std::min(lowestStep, s->lowestWithin(c0 - window_, c1 + window_));
    }
    // Bounds that decide without measuring (exactly: a point's thickness is its depth less the
    // depth of a step beneath it): an edge wholly beneath every step stands above none, and one
    // that cannot beat the thickest found so far (or the floor) need not be measured.
    const double highestPoint = std::max(d0, d1);
    if (highestPoint + window_ < lowestStep) return;
    if (highestPoint - lowestStep <= sought()) return;
    for (const ProfileStep* s : under_) {
      if (done()) return;
      const double lo = std::max(c0, s->c0), hi = std::min(c1, s->c1);
      measureOver(edge, *s, lo);
      measureOver(edge, *s, hi);
      if (hi - lo > 2 * window_) {
        measureOver(edge, *s, lo + window_);
        measureOver(edge, *s, hi - window_);
      }
      if (const auto tangent = s->tangentTo((d1 - d0) / (c1 - c0)); tangent && *tangent > lo && *tangent < hi) {
        measureOver(edge, *s, *tangent);
      }
    }
  }

  const std::optional<Thickest>& best() const { return best_; }

 private:
  // What a thickness must beat to count: the floor, and the thickest found so far.
  double sought() const { return best_ ? std::max(best_->thickness, floor_) : floor_; }

  // Whether the edge's point at c (over step s, which measureEdge measures it for) cannot measure
  // thicker than what is sought — above the floor and the thickest so far — found from s alone, so
  // that measureAt need not look at every step near c. Where s neither rises nor falls back within
  // the window around c (a line; an arc away from its apex, the centre's cut coordinate), the
  // higher of its depths at c ± window, which measureAt takes, is no lower than its depth at c: if
  // that stands less than the window above the point, s is among the steps beneath it (not wholly
  // above) and the thickness is at most the point's height above s there. Exact: each rounded
  // operation keeps that order.
  bool cannotBeatAt(const RegionEdge& edge, const ProfileStep& s, double c) const {
    if (s.arc && s.cc > c - window_ && s.cc < c + window_) return false;
    const double d = edge.depthAt(c), onStep = s.depthAt(c);
    return onStep <= d + window_ && std::max(0.0, d - onStep) <= sought();
  }

  // measureAt(edge, c) for a point measureEdge takes over step s, unless cannotBeatAt shows it
  // changes nothing.
  void measureOver(const RegionEdge& edge, const ProfileStep& s, double c) {
    if (!cannotBeatAt(edge, s, c)) measureAt(edge, c);
  }

  // The edge's point at c against the highest depth beneath it of the steps under the edge, within
  // c ± window.
  void measureAt(const RegionEdge& edge, double c) {
    const double d = edge.depthAt(c);
    std::optional<double> beneath;
    // under_ is sorted by c0: only the steps from c − window − the widest step on can reach c.
    const auto first = std::lower_bound(under_.begin(), under_.end(), c - window_ - underWidest_,
                                        [](const ProfileStep* s, double v) { return s->c0 < v; });
    for (auto it = first; it != under_.end() && (*it)->c0 <= c + window_; ++it) {
      const ProfileStep* s = *it;
      if (s->c1 < c - window_) continue;
      const double v0 = s->depthAt(c - window_), v1 = s->depthAt(c + window_);
      if (std::min(v0, v1) > d + window_) continue;  // wholly above the point
      const double highest = std::min(std::max(v0, v1), d);
      if (!beneath || highest > *beneath) beneath = highest;
    }
    if (!beneath) return;
    const double thickness = d - *beneath;
    if (thickness <= floor_) return;
    if (!best_ || thickness > best_->thickness) {
      const Point where = frame_.point(c, d);
      best_ = Thickest{thickness, where, frame_.atDepth(where, *beneath)};
    }
  }

  const ProfileSteps& profile_;
  const DepthFrame& frame_;
  double resolution_;
  double window_;
  double floor_;
  bool firstOnly_;
  std::vector<const ProfileStep*> under_;  // the steps under the edge being measured, by c0
  double underWidest_ = 0;
  std::optional<Thickest> best_;
};

double sizeOf(const BgRegion& region) {
  const auto box = boost::geometry::return_envelope<boost::geometry::model::box<BgPoint>>(region);
  return std::max(box.max_corner().x() - box.min_corner().x(),
                  box.max_corner().y() - box.min_corner().y());
}

}  // namespace

std::optional<Thickest> thickestAbove(const BgRegion& region, const std::vector<Segment>& profile,
                                      Point away, double chordTolerance) {
  if (region.empty() || profile.empty()) return std::nullopt;
  const DepthFrame frame(away);
  const ProfileSteps steps(profile, frame, chordTolerance);
  const double resolution = std::max(kTidyDistance, 4 * kBooleanResolution * sizeOf(region));
  ThicknessSearch search(steps, frame, resolution, 2 * chordTolerance + resolution);
  auto visitRing = [&search](const BgPolygon::ring_type& ring) {
    for (std::size_t i = 1; i < ring.size(); ++i) {
      search.measureEdge(fromBg(ring[i - 1]), fromBg(ring[i]));
    }
  };
  for (const BgPolygon& polygon : region) {
    visitRing(polygon.outer());
    for (const auto& hole : polygon.inners()) visitRing(hole);
  }
  return search.best();
}

namespace {

std::optional<Thickest> thickestBeneathAbove(const std::vector<CutEnvelope::Piece>& top,
                                             const std::vector<Segment>& profile, Point away, double chordTolerance,
                                             double floor, bool firstOnly) {
  if (top.empty() || profile.empty()) return std::nullopt;
  const DepthFrame frame(away);
  const ProfileSteps steps(profile, frame, chordTolerance);
  double cMin = INFINITY, cMax = -INFINITY, dMin = INFINITY, dMax = -INFINITY;
  for (const CutEnvelope::Piece& p : top) {
    cMin = std::min(cMin, p.c0);
    cMax = std::max(cMax, p.c1);
    dMin = std::min({dMin, p.d0, p.d1});
    dMax = std::max({dMax, p.d0, p.d1});
  }
  const double resolution = std::max(kTidyDistance, 4 * kBooleanResolution * std::max(cMax - cMin, dMax - dMin));
  ThicknessSearch search(steps, frame, resolution, 2 * chordTolerance + resolution, floor, firstOnly);
  for (const CutEnvelope::Piece& p : top) {
    if (search.done()) break;
    search.measureEdge(p.c0, p.d0, p.c1, p.d1);
  }
  return search.best();
}

}  // namespace

std::optional<Thickest> thickestBeneath(const std::vector<CutEnvelope::Piece>& top, const std::vector<Segment>& profile,
                                        Point away, double chordTolerance) {
  return thickestBeneathAbove(top, profile, away, chordTolerance, -INFINITY, false);
}

bool standsThickerThan(const std::vector<CutEnvelope::Piece>& top, const std::vector<Segment>& profile, Point away,
                       double chordTolerance, double limit) {
  // Any thickness above the limit answers: the search stops at the first.
  return thickestBeneathAbove(top, profile, away, chordTolerance, limit, true).has_value();
}

}  // namespace cyclecert
