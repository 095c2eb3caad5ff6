// The oracles' own derivation of what a SINUMERIK stock-removal call asks, from the values the front
// end read: written apart from the reference planners (reference/siemens/siemens_roughing_*), so
// that the two readings catch each other's mistakes.
#include "oracles/siemens/siemens_cycle_spec.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "oracles/siemens/siemens_allowance_rectangle.h"
#include "reference/model/alarms.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

constexpr const char* kContourAlarm = "10931";  // LCYC95.ALARMS (interpretation)

int reflections(const SiemensFrame& f) { return (f.transposed ? 1 : 0) + (f.mirrored ? 1 : 0); }

// LCYC95.ROUGH note: the allowance R106 / FAL is contour-parallel on the stock side (offset.h); then
// FALZ / FALX on each element's stock side: the profile grown by the rectangle ±FALZ × ±FALX
// (CYCLE95.ROUGH note; siemens_allowance_rectangle.h).
std::vector<Segment> roughingProfileOf(const SiemensCycleSpec& c, const std::vector<Segment>& frameContour) {
  std::vector<Segment> profile;
  try {
    profile = offsetPath(frameContour, std::abs(c.allowance), CompensationSide::Right);
  } catch (const OffsetError& e) {
    throw CycleAlarm(kContourAlarm, c.line,
                     "the finishing allowance does not fit contour " + c.contourName + " at its line " +
                         std::to_string(e.sourceLine));
  }
  const Point plane{std::abs(c.allowanceZ), std::abs(c.allowanceX)};
  const Point rectangle = c.frame.transposed ? transposed(plane) : plane;
  try {
    return grownByAllowanceRectangle(profile, rectangle);
  } catch (const OffsetError& e) {
    throw CycleAlarm(kContourAlarm, c.line,
                     "the axis allowances FALZ/FALX do not fit contour " + c.contourName + " at its line " +
                         std::to_string(e.sourceLine));
  }
}

// LCYC95.FINISH note: the contour itself, or with a nose radius the control point's path on the
// stock side (G42 longitudinal external; each reflection of the frame swaps the side).
std::vector<Segment> finishPathOf(const SiemensCycleSpec& c) {
  if (c.tool.noseRadius <= 0) return c.frame.toFrame(c.contour);
  const CompensationSide side = reflections(c.frame) % 2 == 0 ? CompensationSide::Right : CompensationSide::Left;
  try {
    return c.frame.toFrame(compensatedPath(c.contour, c.tool, side));
  } catch (const OffsetError& e) {
    throw CycleAlarm(kContourAlarm, c.line,
                     "the nose radius does not fit contour " + c.contourName + " at its line " + std::to_string(e.sourceLine));
  }
}

Extent extentOf(const std::vector<Segment>& path) {
  Extent all{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
             std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (const Segment& s : path) {
    const Extent e = extent(s);
    all = {std::min(all.zMin, e.zMin), std::max(all.zMax, e.zMax), std::min(all.xMin, e.xMin), std::max(all.xMax, e.xMax)};
  }
  return all;
}

// The profile's points in order where its height can turn: each segment's ends and an arc's apexes.
struct ProfileVertex {
  Point at;
  std::size_t segment = 0;
};
std::vector<ProfileVertex> verticesOf(const std::vector<Segment>& profile) {
  std::vector<ProfileVertex> out;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    if (i == 0) out.push_back({profile[i].from, i});
    for (Point p : apexesAlong(profile[i])) out.push_back({p, i});
    out.push_back({profile[i].to, i});
  }
  return out;
}

// Where the profile, rising from vertex `m − 1` to `m`, reaches the height `top`.
double zWhereRisingTo(const std::vector<Segment>& profile, const std::vector<ProfileVertex>& v, std::size_t m, double top) {
  const Point a = v[m - 1].at, b = v[m].at;
  for (Point p : intersectWithLevelX(profile[v[m].segment], top)) {
    if (p.z <= std::max(a.z, b.z) + kGeomEps && p.z >= std::min(a.z, b.z) - kGeomEps) return p.z;
  }
  return b.z;
}

// CYCLE95.UNDERCUT note: a pocket begins where the profile turns back towards the depth axis (its
// height falls) and ends where it is back at the lowest main level strictly above that rim; a descent
// on the profile's front (from its first point, down a wall at its z) turns back from nothing and is
// none.
std::vector<SiemensUndercut> undercutsOf(const std::vector<Segment>& profile, const SiemensLevels& levels) {
  std::vector<SiemensUndercut> out;
  const std::vector<ProfileVertex> v = verticesOf(profile);
  std::size_t k = 0;
  while (k + 1 < v.size()) {
    if (v[k + 1].at.x >= v[k].at.x - kGeomEps) {
      ++k;
      continue;
    }
    // A wall falling down the face after walls rising at the first point's z is no undercut and
    // only that wall (stock on both sides): a pocket behind a later rim is one (interpretation).
    const double frontZ = v.front().at.z;
    const bool fromTheStart = distance(v[k].at, v.front().at) <= kGeomEps;
    if (!fromTheStart && v[k].at.z >= frontZ - kGeomEps && v[k + 1].at.z >= frontZ - kGeomEps) {
      ++k;
      continue;
    }
    SiemensUndercut u;
    u.rimZ = v[k].at.z;
    u.top = levels.levelAbove(v[k].at.x, kGeomEps);
    u.bottom = v[k + 1].at.x;
    std::size_t m = k + 1;
    while (m < v.size() && v[m].at.x < u.top - kGeomEps) u.bottom = std::min(u.bottom, v[m++].at.x);
    u.endZ = m < v.size() ? zWhereRisingTo(profile, v, m, u.top) : v.back().at.z;
    // A descent from the contour's first point is no undercut: nothing stands before it, and the
    // main passes reach it along their levels from the start side (interpretation). One leaving the
    // front from the top of a wall the contour begins with, rising at the first point's z, is: the
    // wall stands before it.
    if (!fromTheStart) out.push_back(u);
    k = m;
  }
  return out;
}

}  // namespace

Point SiemensFrame::toFrame(Point p) const {
  if (transposed) p = cyclecert::transposed(p);
  if (mirrored) p.x = -p.x;
  return p;
}

Point SiemensFrame::toPlane(Point p) const {
  if (mirrored) p.x = -p.x;
  if (transposed) p = cyclecert::transposed(p);
  return p;
}

namespace {

// A path mapped point by point; an odd number of reflections turns an arc's sense.
template <typename Map>
std::vector<Segment> mappedPath(const SiemensFrame& f, const std::vector<Segment>& path, Map map) {
  std::vector<Segment> out;
  out.reserve(path.size());
  const bool turned = reflections(f) % 2 == 1;
  for (Segment s : path) {
    s.from = map(s.from);
    s.to = map(s.to);
    s.center = map(s.center);
    if (turned) s.kind = reversedKind(s.kind);
    out.push_back(s);
  }
  return out;
}

}  // namespace

std::vector<Segment> SiemensFrame::toFrame(const std::vector<Segment>& plane) const {
  return mappedPath(*this, plane, [&](Point p) { return toFrame(p); });
}

std::vector<Segment> SiemensFrame::toPlane(const std::vector<Segment>& frame) const {
  return mappedPath(*this, frame, [&](Point p) { return toPlane(p); });
}

SiemensLevels equalLevels(double top, double bottom, double maxInfeed) {
  SiemensLevels l{top, bottom, 0, 0};
  const double depth = top - bottom;
  if (depth <= kGeomEps || !(maxInfeed > 0)) return l;
  l.count = std::max(1.0, std::ceil(depth / maxInfeed - 1e-9));
  l.step = depth / l.count;
  return l;
}

double SiemensLevels::levelAbove(double x, double tol) const {
  if (count <= 0 || x >= top - tol) return top;
  // level(k) = top − k·step > x + tol for k < (top − x − tol) / step.
  const double k = std::ceil((top - x - tol) / step) - 1;
  return level(std::max(0.0, k));
}

bool SiemensLevels::isLevel(double x, double tol) const {
  if (count <= 0 || x > top - step + tol || x < bottom - tol) return false;
  const double k = std::round((top - x) / step);
  return std::abs(level(k) - x) <= tol;
}

void describeSiemensCycle(SiemensCycleSpec& c) {
  c.frame = {c.type.cut == SiemensCut::Face, c.type.side == SiemensSide::Internal};
  const std::vector<Segment> frameContour = c.frame.toFrame(c.contour);
  c.profile = roughingProfileOf(c, frameContour);
  c.finishPath = finishPathOf(c);
  const Extent e = extentOf(c.profile);
  const double clearance = std::abs(c.retract);
  // The clearance beyond the part's face too, which stands at the contour's first point's z where
  // the allowance moves the profile's start behind it (LCYC95.START note).
  const double faceZ = frameContour.empty() ? e.zMax : std::max(e.zMax, frameContour.front().from.z);
  c.start = {faceZ + clearance, e.xMax + clearance};
  c.levels = equalLevels(e.xMax, e.xMin, c.maxInfeed);
  c.undercuts = undercutsOf(c.profile, c.levels);
}

bool inUndercut(const SiemensCycleSpec& c, Point from, Point to, double tol) {
  const double zLow = std::min(from.z, to.z), zHigh = std::max(from.z, to.z), xLow = std::min(from.x, to.x);
  // The plunge along the depth axis down to the falling side's top starts the pocket's pass, and
  // the pass goes on down the falling side: a move descending in the pocket belongs to it even
  // where it stays within the tolerance of its top level (a rim at the profile's top; a small
  // rounding of the allowance at the rim, falling a fraction of the tolerance).
  const bool plunge = from.x > to.x;
  // A climb along the depth axis at the rim's own z is the wall that rises to the rim (a zero-width
  // spike whose far side falls into the pocket along the same line): the main pass's, not the
  // pocket's.
  const bool climb = zHigh - zLow <= tol && to.x > from.x;
  // A move that does not descend and ends no higher than the pocket's top is the pocket pass's however
  // little below the top it lies (by more than 1e-6): the last sliver of a rising side, an allowance
  // rounding where the pocket ends, a flat a rounding error below the top (a spike's top inside the
  // pocket). A main pass's cut along the top level (in pieces with DAM) lies at the top.
  const auto justBelowTheTop = [&](const SiemensUndercut& u) {
    return to.x >= from.x && to.x <= u.top + tol && xLow < u.top - 1e-6;
  };
  return std::any_of(c.undercuts.begin(), c.undercuts.end(), [&](const SiemensUndercut& u) {
    if (climb && std::abs(zHigh - u.rimZ) <= tol) return false;
    return zHigh <= u.rimZ + tol && zLow >= u.endZ - tol && (xLow < u.top + (plunge ? tol : -tol) || justBelowTheTop(u));
  });
}

}  // namespace cyclecert
