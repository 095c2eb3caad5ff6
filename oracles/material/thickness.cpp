#include "oracles/material/thickness.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "oracles/material/boost_geometry.h"
#include "oracles/material/depth_frame.h"

namespace cyclecert {

namespace {

// A chord of the profile that advances along the cut axis, in frame coordinates (c0 < c1).
struct ProfileStep {
  double c0, d0, c1, d1;
  double depthAt(double c) const {
    const double t = std::clamp((c - c0) / (c1 - c0), 0.0, 1.0);
    return d0 + t * (d1 - d0);
  }
};

// A region edge that advances along the cut axis, in frame coordinates (c0 < c1).
struct RegionEdge {
  double c0, d0, c1, d1;
  double depthAt(double c) const { return d0 + (c - c0) / (c1 - c0) * (d1 - d0); }
};

// The flattened profile's chords that advance along the cut axis, sorted by c0, with the widest
// one's length, to find those overlapping an interval quickly.
class FlatProfile {
 public:
  FlatProfile(const std::vector<Point>& points, const DepthFrame& frame) {
    for (std::size_t i = 1; i < points.size(); ++i) {
      double c0 = frame.cut(points[i - 1]), d0 = frame.depth(points[i - 1]);
      double c1 = frame.cut(points[i]), d1 = frame.depth(points[i]);
      if (std::abs(c1 - c0) <= kTidyDistance) continue;  // a wall along the depth axis
      if (c0 > c1) {
        std::swap(c0, c1);
        std::swap(d0, d1);
      }
      steps_.push_back({c0, d0, c1, d1});
      widest_ = std::max(widest_, c1 - c0);
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
  std::vector<ProfileStep> steps_;
  double widest_ = 0;
};

// The thickness of a region edge above the profile is piecewise linear between the ends of its
// overlaps with the profile's steps, so it is largest at one of those ends. Only overlaps longer
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
  ThicknessSearch(const FlatProfile& profile, const DepthFrame& frame, double resolution,
                  double window)
      : profile_(profile), frame_(frame), resolution_(resolution), window_(window) {}

  void measureEdge(Point p, Point q) {
    double c0 = frame_.cut(p), d0 = frame_.depth(p), c1 = frame_.cut(q), d1 = frame_.depth(q);
    if (std::abs(c1 - c0) <= kTidyDistance) return;  // along the depth axis: its ends are measured
    if (c0 > c1) {                                   // with the neighbouring edges
      std::swap(c0, c1);
      std::swap(d0, d1);
    }
    const RegionEdge edge{c0, d0, c1, d1};
    profile_.overlapping(c0, c1, resolution_, under_);
    underWidest_ = 0;
    double lowestStep = INFINITY;
    for (const ProfileStep* s : under_) {
      underWidest_ = std::max(underWidest_, s->c1 - s->c0);
      lowestStep = std::min({lowestStep, s->d0, s->d1});
    }
    // Bounds that decide without measuring (exactly: a point's thickness is its depth less the
    // depth of a step beneath it): an edge wholly beneath every step stands above none, and one
    // that cannot beat the thickest found so far need not be measured.
    const double highestPoint = std::max(d0, d1);
    if (highestPoint + window_ < lowestStep) return;
    if (best_ && highestPoint - lowestStep <= best_->thickness) return;
    for (const ProfileStep* s : under_) {
      const double lo = std::max(c0, s->c0), hi = std::min(c1, s->c1);
      measureAt(edge, lo);
      measureAt(edge, hi);
      if (hi - lo > 2 * window_) {
        measureAt(edge, lo + window_);
        measureAt(edge, hi - window_);
      }
    }
  }

  const std::optional<Thickest>& best() const { return best_; }

 private:
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
    if (!best_ || thickness > best_->thickness) {
      const Point where = frame_.atDepth(c * frame_.along(), d);
      best_ = Thickest{thickness, where, frame_.atDepth(where, *beneath)};
    }
  }

  const FlatProfile& profile_;
  const DepthFrame& frame_;
  double resolution_;
  double window_;
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
  std::vector<Point> points;
  for (const Segment& s : profile) appendFlattened(points, s, chordTolerance);
  const FlatProfile flat(points, frame);
  const double resolution = std::max(kTidyDistance, 4 * kBooleanResolution * sizeOf(region));
  ThicknessSearch search(flat, frame, resolution, 2 * chordTolerance + resolution);
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

std::optional<double> deepestWithin(const BgRegion& region, const DepthFrame& frame, double c0, double c1) {
  std::optional<double> deepest;
  // The deepest point of an edge within [c0, c1] is one of its ends clipped to that range.
  const auto clipEdge = [&](Point p, Point q) {
    double a = frame.cut(p), da = frame.depth(p), b = frame.cut(q), db = frame.depth(q);
    if (a > b) {
      std::swap(a, b);
      std::swap(da, db);
    }
    if (b < c0 || a > c1) return;
    const auto depthAt = [&](double c) { return b - a > 0 ? da + (c - a) / (b - a) * (db - da) : std::max(da, db); };
    const double top = std::max(depthAt(std::max(a, c0)), depthAt(std::min(b, c1)));
    if (!deepest || top > *deepest) deepest = top;
  };
  const auto visitRing = [&](const BgPolygon::ring_type& ring) {
    for (std::size_t i = 1; i < ring.size(); ++i) clipEdge(fromBg(ring[i - 1]), fromBg(ring[i]));
  };
  for (const BgPolygon& polygon : region) {
    visitRing(polygon.outer());
    for (const auto& hole : polygon.inners()) visitRing(hole);
  }
  return deepest;
}

}  // namespace cyclecert
