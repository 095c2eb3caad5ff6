// G74.1's groove in its own frame (docs/g74_1.md §3, §5, §7; rules G74_1.ADDR, G74_1.STEP9/10).
#include "reference/cycles/g74_1_groove.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// tan and cot of an angle in degrees, exact at 0° and 90° (the defaults) so that straight grooves
// are computed without rounding.
double tanDeg(double a) { return a == 0 ? 0.0 : std::tan(radians(a)); }
double cotDeg(double a) { return a == 90 ? 0.0 : 1.0 / std::tan(radians(a)); }

double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }
Point unit(Point v) { return (1.0 / std::hypot(v.z, v.x)) * v; }

std::string mm(double v) { return shortDecimalText(v); }

// The four vertices of the (rough or finish) trapezoid: S on the mouth, N and F on the floor, M2 on
// the mouth (docs/g74_1.md §3, §5).
struct Trapezoid {
  Point s, n, f, m2;
  Point mouthDir;  // along the mouth towards +u
};

Trapezoid trapezoid(const GrooveShape& g, double flank, double floorAllowance) {
  const double tanP = tanDeg(g.slope), cotA = cotDeg(g.angleA), cotB = cotDeg(g.angleB);
  const double floorW = g.depth - floorAllowance;
  if (floorW <= kGeomEps) {
    throw GrooveDoesNotFit("the floor allowance Δw " + mm(floorAllowance) + " is not less than the depth |h| " +
                           mm(g.depth) + ": no groove is left to rough");
  }
  // I9: the near flank must go below the mouth (∠p < ∠a).
  if (tanP * cotA >= 1.0 - kGeomEps) {
    throw GrooveDoesNotFit("the slope ∠p " + mm(g.slope) + "° is not smaller than the flank angle ∠a " +
                           mm(g.angleA) + "°: the near flank never goes below the slope");
  }
  Trapezoid t;
  const double sU = flank / (1.0 - tanP * cotA);
  t.s = grooveLocal(sU, sU * tanP);
  t.n = grooveLocal(flank + floorW * cotA, floorW);
  const double farFloorU = g.depth * cotA + g.floorWidth;  // F of the finish groove
  t.f = grooveLocal(farFloorU - flank + (g.depth - floorW) * cotB, floorW);
  if (t.f.x - t.n.x <= kGeomEps) {
    throw GrooveDoesNotFit("the floor has no width left (" + mm(t.f.x - t.n.x) +
                           " mm) once the flanks are moved in by the allowance Δu/2 " + mm(flank));
  }
  // I9: the mouth must not reach the floor before the far flank.
  if (t.f.x * tanP >= floorW - kGeomEps) {
    throw GrooveDoesNotFit("the slope ∠p " + mm(g.slope) + "° reaches the floor before the far flank: no groove");
  }
  const double m2U = (farFloorU - flank + g.depth * cotB) / (1.0 + tanP * cotB);
  t.m2 = grooveLocal(m2U, m2U * tanP);
  t.mouthDir = grooveLocal(std::cos(radians(g.slope)), tanP * std::cos(radians(g.slope)));
  if (g.slope == 0) t.mouthDir = grooveLocal(1, 0);
  return t;
}

// A corner cut between the edge arriving along `in` and the edge leaving along `out` (unit
// directions): a chamfer from `size` before the corner to `size` after it (I10), or the arc of
// radius `size` tangent to both edges.
struct CornerCut {
  Point before, after;  // where the cut leaves the arriving edge and meets the leaving one
  Segment cut;
  double setBack = 0;   // distance of `before` and `after` from the corner along the edges
};

CornerCut cutCorner(Point corner, Point in, Point out, const GrooveCorner& c) {
  CornerCut k;
  k.before = k.after = corner;
  if (c.size <= kGeomEps) return k;
  const double interior = std::acos(std::clamp(-dot(in, out), -1.0, 1.0));
  k.setBack = c.kind == GrooveCornerKind::Chamfer ? c.size : c.size / std::tan(interior / 2);
  k.before = corner + (-k.setBack) * in;
  k.after = corner + k.setBack * out;
  k.cut.from = k.before;
  k.cut.to = k.after;
  if (c.kind == GrooveCornerKind::Round) {
    k.cut.kind = cross(in, out) > 0 ? SegmentKind::ArcCCW : SegmentKind::ArcCW;
    k.cut.center = corner + (c.size / std::sin(interior / 2)) * unit(out - in);
  }
  return k;
}

// I11: the corners at both ends of an edge must fit on it.
void requireCornersFit(const char* edge, Point from, Point to, const CornerCut& a, const CornerCut& b) {
  const double length = distance(from, to);
  if (a.setBack + b.setBack <= length + kGeomEps) return;
  throw GrooveDoesNotFit(std::string("the corners at the ends of the ") + edge + " need " +
                         mm(a.setBack + b.setBack) + " mm of it; it is " + mm(length) + " mm long");
}

void append(GrooveProfile& p, const Segment& s, GroovePart part) {
  if (distance(s.from, s.to) <= kGeomEps) return;
  p.chain.push_back(s);
  p.parts.push_back(part);
}

Segment line(Point from, Point to) {
  Segment s;
  s.from = from;
  s.to = to;
  return s;
}

bool isNear(GroovePart p) { return p == GroovePart::NearFlank || p == GroovePart::CornerR3; }
bool isFar(GroovePart p) { return p == GroovePart::CornerR4 || p == GroovePart::FarFlank; }

// u where the segment crosses depth w, if it does.
std::vector<double> crossingsAtDepth(const Segment& s, double w) {
  std::vector<double> us;
  for (const Point& hit : intersectWithLevelX(transposed(s), w)) us.push_back(hit.z);
  return us;
}

}  // namespace

GrooveProfile buildGrooveProfile(const GrooveShape& g, double flankAllowance, double floorAllowance) {
  const Trapezoid t = trapezoid(g, flankAllowance, floorAllowance);
  const Point nearDir = unit(t.n - t.s), floorDir = grooveLocal(1, 0), farDir = unit(t.m2 - t.f);
  const CornerCut r1 = cutCorner(t.s, t.mouthDir, nearDir, g.corners[kCornerR1]);
  const CornerCut r3 = cutCorner(t.n, nearDir, floorDir, g.corners[kCornerR3]);
  const CornerCut r4 = cutCorner(t.f, floorDir, farDir, g.corners[kCornerR4]);
  const CornerCut r2 = cutCorner(t.m2, farDir, t.mouthDir, g.corners[kCornerR2]);
  requireCornersFit("near flank", t.s, t.n, r1, r3);
  requireCornersFit("floor", t.n, t.f, r3, r4);
  requireCornersFit("far flank", t.f, t.m2, r4, r2);
  GrooveProfile p;
  p.start = t.s;
  p.floorDepth = t.n.z;
  p.floorFrom = r3.after.x;
  p.floorTo = r4.before.x;
  p.nearDirection = nearDir;
  p.farDirection = farDir;
  append(p, r1.cut, GroovePart::CornerR1);
  append(p, line(r1.after, r3.before), GroovePart::NearFlank);
  append(p, r3.cut, GroovePart::CornerR3);
  p.chain.push_back(line(r3.after, r4.before));  // the floor, kept even when it is a point
  p.parts.push_back(GroovePart::Floor);
  append(p, r4.cut, GroovePart::CornerR4);
  append(p, line(r4.after, r2.before), GroovePart::FarFlank);
  append(p, r2.cut, GroovePart::CornerR2);
  return p;
}

GrooveSlice sliceAt(const GrooveProfile& p, double w) {
  if (w >= p.floorDepth - kGeomEps) return {p.floorFrom, p.floorTo};
  GrooveSlice slice{p.floorFrom, p.floorTo};
  bool nearFound = false, farFound = false;
  const Point* nearTop = nullptr;
  const Point* farTop = nullptr;
  for (std::size_t i = 0; i < p.chain.size(); ++i) {
    const Segment& s = p.chain[i];
    if (isNear(p.parts[i])) {
      if (!nearTop) nearTop = &s.from;
      for (double u : crossingsAtDepth(s, w)) {
        slice.nearU = nearFound ? std::max(slice.nearU, u) : u;
        nearFound = true;
      }
    } else if (isFar(p.parts[i])) {
      farTop = &s.to;
      for (double u : crossingsAtDepth(s, w)) {
        slice.farU = farFound ? std::min(slice.farU, u) : u;
        farFound = true;
      }
    }
  }
  // Above a flank's top (a depth the slope or the mouth corner leaves): that top.
  if (!nearFound && nearTop) slice.nearU = nearTop->x;
  if (!farFound && farTop) slice.farU = farTop->x;
  return slice;
}

namespace {

// The depth of the profile's floor side (flanks, floor and floor corners) at u; 0 outside it.
double depthAt(const GrooveProfile& p, double u) {
  double deepest = 0;
  for (std::size_t i = 0; i < p.chain.size(); ++i) {
    if (p.parts[i] == GroovePart::CornerR1 || p.parts[i] == GroovePart::CornerR2) continue;
    for (const Point& hit : intersectWithLevelX(p.chain[i], u)) deepest = std::max(deepest, hit.z);
  }
  return deepest;
}

}  // namespace

double deepestUnderTheBlade(const GrooveProfile& p, double u, double toolWidth) {
  return std::min(depthAt(p, u - toolWidth), depthAt(p, u));
}

namespace {

// The piece of element `s` from `a` to `b` (points on it, in its direction).
Segment trimmedTo(Segment s, Point a, Point b) {
  s.from = a;
  s.to = b;
  return s;
}

// The highest point (least w) of a far-side element of the chain, where the chain starts to fall
// again towards the mouth beyond it (a round r2 or chamfer r2 meeting a mouth that slopes deeper,
// ∠p > 0): for a line its start when it falls; for an arc the point below its centre when the arc
// passes it. Nothing when the element rises (w falling) all the way.
std::optional<Point> whereItStartsToFall(const Segment& s) {
  if (!s.isArc()) {
    if (s.to.z > s.from.z + kGeomEps) return s.from;
    return std::nullopt;
  }
  const Point top{s.center.z - s.radius(), s.center.x};
  // The point below the centre (least w) lies at the angle atan2(0, −1) = π around it.
  const bool between = distance(top, s.from) > kGeomEps && distance(top, s.to) > kGeomEps &&
                       offsetAlongArc(s, std::numbers::pi).has_value();
  if (between) return top;
  if (s.to.z > s.from.z + kGeomEps) return s.from;
  return std::nullopt;
}

}  // namespace

std::vector<Segment> bladePath(const GrooveProfile& p, double toolWidth) {
  if (p.floorTo - p.floorFrom < toolWidth - kGeomEps) {
    throw GrooveDoesNotFit("the tool width I " + mm(toolWidth) + " is wider than the groove's floor (" +
                           mm(p.floorTo - p.floorFrom) + " mm between its corners)");
  }
  const Point shift = grooveLocal(toolWidth, 0);
  std::vector<Segment> path;
  for (std::size_t i = 0; i < p.chain.size(); ++i) {
    const Segment& s = p.chain[i];
    if (p.parts[i] < GroovePart::Floor) {
      path.push_back(s.shifted(shift));
    } else if (p.parts[i] == GroovePart::Floor) {
      if (distance(s.from + shift, s.to) > kGeomEps) path.push_back(line(s.from + shift, s.to));
    } else if (const auto top = p.parts[i] == GroovePart::CornerR2 && toolWidth > 0 ? whereItStartsToFall(s) : std::nullopt) {
      // I23: where the far mouth corner falls again towards a sloping mouth, the blade's start-side
      // corner takes over: level across the blade's width at the top, then the rest shifted by r.
      if (distance(s.from, *top) > kGeomEps) path.push_back(trimmedTo(s, s.from, *top));
      path.push_back(line(*top, *top + shift));
      if (distance(*top, s.to) > kGeomEps) path.push_back(trimmedTo(s, *top, s.to).shifted(shift));
    } else {
      path.push_back(s);
    }
  }
  return path;
}

Segment GrooveFrame::toPlane(const Segment& local) const {
  Segment s = local;
  s.from = toPlane(local.from);
  s.to = toPlane(local.to);
  s.center = toPlane(local.center);
  if (local.isArc() && depthSign * widthSign < 0) s.kind = reversedKind(local.kind);
  return s;
}

}  // namespace cyclecert
