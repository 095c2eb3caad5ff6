// RapidCheck properties of the type I planner on random monotone contours (lines and quarter arcs),
// written as G71 or G72 programs: every pass is at most Δd deeper than the previous level, every
// cut ends on the rough contour (or at C' where the level is beyond it), the semi-finish pass runs
// on the rough contour, all feeds are the cycle's F, and the path ends at the start point.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <optional>
#include <cmath>
#include <sstream>

#include "harness/engines/reference_plan.h"
#include "reference/model/offset.h"

namespace cyclecert {
namespace {

// A type I contour in the cycle frame (cut along z towards −z, depth along x towards −x): B at
// (0, b), then segments moving −z and +x. Lengths are on a 0.01 mm grid so the program text is exact.
struct FrameSegment {
  int kind;  // 0 line, 1 convex quarter arc (G03 in G71), 2 concave quarter arc (G02 in G71)
  int dz, dx;  // hundredths of a mm; arcs use dz == dx
};

struct RandomCycle {
  bool g72 = false;
  bool headRapid = true;
  int b = 0;            // B's depth coordinate, hundredths
  int startAbove = 0;   // A.x − C.x, hundredths (≥ 0: LIMIT.HEIGHT holds)
  int startAhead = 0;   // A.z − B.z, hundredths (≥ 0)
  std::vector<FrameSegment> segments;
  int dd = 100, e = 50, du = 0, dw = 0;  // hundredths (du as a radius)
  bool rf1 = false, dtp = false;
  bool typeII = false;  // block ns moves both axes (W0 / U0); segments may go down again (pockets)
  bool r16 = false, nsp = false, rf2 = false;  // type II parameters
};

double mm(int hundredths) { return hundredths / 100.0; }

rc::Gen<FrameSegment> genSegment() {
  return rc::gen::apply(
      [](int kind, int a, int b) {
        if (kind == 0) return FrameSegment{0, a, b};
        return FrameSegment{kind, a, a};
      },
      rc::gen::inRange(0, 3), rc::gen::inRange(0, 800), rc::gen::inRange(0, 800));
}

rc::Gen<RandomCycle> genCycle() {
  return rc::gen::apply(
      [](bool g72, bool headRapid, int b, int above, int ahead, std::vector<FrameSegment> segs, int dd, int e,
         int du, int dw, bool rf1, bool dtp) {
        RandomCycle c;
        c.g72 = g72;
        c.headRapid = headRapid;
        c.b = b;
        // A stands outside the shape grown by the allowances: further above B than the depth-axis
        // allowance (else the start point itself lies inside it and every move from A "enters" it).
        c.startAbove = std::max(above, du + 1);
        c.startAhead = ahead;
        // Zero-length lines are dropped by the interpreter; keep at least one real segment.
        segs.erase(std::remove_if(segs.begin(), segs.end(), [](const FrameSegment& s) { return s.dz == 0 && s.dx == 0; }),
                   segs.end());
        if (segs.size() > 12) segs.resize(12);
        if (segs.empty()) segs.push_back({0, 500, 300});
        c.segments = segs;
        c.dd = dd;
        c.e = e;
        c.du = du;
        c.dw = dw;
        c.rf1 = rf1;
        c.dtp = dtp;
        return c;
      },
      rc::gen::arbitrary<bool>(), rc::gen::arbitrary<bool>(), rc::gen::inRange(0, 2000), rc::gen::inRange(1, 1500),
      rc::gen::inRange(0, 300), rc::gen::container<std::vector<FrameSegment>>(genSegment()),
      rc::gen::inRange(20, 400), rc::gen::inRange(0, 100), rc::gen::inRange(0, 60), rc::gen::inRange(0, 30),
      rc::gen::arbitrary<bool>(), rc::gen::arbitrary<bool>());
}

// Frame → physical program coordinates. G71: z = frame z, x = frame x (diameter in the program).
// G72: physical x = frame z (shifted positive), physical z = frame x.
struct Emitter {
  const RandomCycle& c;
  int zOffset;  // keeps physical x positive for G72

  std::string axisWords(int fz, int fx) const {
    std::ostringstream s;
    s.precision(12);
    if (!c.g72) s << "X" << 2 * mm(fx) << " Z" << mm(fz);
    else s << "X" << 2 * mm(fz + zOffset) << " Z" << mm(fx);
    return s.str();
  }
  // Exchanging the axes mirrors the plane: G72 swaps G02 and G03.
  std::string arcCode(int kind) const {
    const bool convexCcw = kind == 1;
    return (convexCcw != c.g72) ? "G03" : "G02";
  }
};

std::string programFor(const RandomCycle& c, int zOffset) {
  const Emitter em{c, zOffset};
  int z = c.startAhead, x = c.b;  // B: block ns moves the depth axis only
  std::vector<std::pair<int, int>> points;
  for (const auto& s : c.segments) {
    z -= s.dz;
    x += s.dx;
    points.push_back({z, x});
  }
  // A stands above the whole shape (G71.LIMIT.HEIGHT): above its highest point (C for type I).
  int cX = c.b;
  for (const auto& pt : points) cX = std::max(cX, pt.second);
  std::ostringstream p;
  p.precision(12);
  p << "G00 " << em.axisWords(c.startAhead, cX + c.startAbove) << ";\n";
  if (!c.g72) p << "G71 U" << mm(c.dd) << " R" << mm(c.e) << ";\nG71 P10 Q20 U" << 2 * mm(c.du) << " W" << mm(c.dw);
  else p << "G72 W" << mm(c.dd) << " R" << mm(c.e) << ";\nG72 P10 Q20 U" << 2 * mm(c.dw) << " W" << mm(c.du);
  p << " F0.2;\n";
  // Head block: the depth axis only (type I), or both axes with W0 / U0 (type II).
  if (!c.g72) p << "N10 " << (c.headRapid ? "G00" : "G01") << " X" << 2 * mm(c.b) << (c.typeII ? " W0" : "") << ";\n";
  else p << "N10 " << (c.headRapid ? "G00" : "G01") << (c.typeII ? " U0" : "") << " Z" << mm(c.b) << ";\n";
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const auto& s = c.segments[i];
    p << (i + 1 == c.segments.size() ? "N20 " : "");
    if (s.kind == 0) p << "G01 " << em.axisWords(points[i].first, points[i].second);
    else p << em.arcCode(s.kind) << " " << em.axisWords(points[i].first, points[i].second) << " R" << mm(s.dz);
    p << ";\n";
  }
  return p.str();
}

// Type II contours: lines and quarter arcs going −z, up or down (pockets), never below the axis.
rc::Gen<RandomCycle> genType2Cycle() {
  return rc::gen::apply(
      [](RandomCycle c, std::vector<int> downs, int flags) {
        c.typeII = true;
        c.rf1 = false;
        c.r16 = flags & 1;
        c.nsp = flags & 2;
        c.rf2 = flags & 4;
        for (std::size_t i = 0; i < c.segments.size() && i < downs.size(); ++i) {
          if (downs[i] % 3 == 0) c.segments[i].dx = -c.segments[i].dx;  // a third of them go down
        }
        // Keep the contour off the spindle axis: raise B by the deepest dip.
        int x = c.b, lowest = c.b;
        for (const auto& s : c.segments) lowest = std::min(lowest, x += s.dx);
        if (lowest < 100) c.b += 100 - lowest;
        return c;
      },
      genCycle(), rc::gen::container<std::vector<int>>(rc::gen::inRange(0, 99)), rc::gen::inRange(0, 8));
}

// The toolpath back in the cycle frame.
Point toFrame(Point p, const RandomCycle& c, int zOffset) {
  return c.g72 ? Point{p.x - mm(zOffset), p.z} : p;
}

// True when p lies on one of the segments (exactly at its level: cut ends are computed at the level).
bool onContour(Point p, const std::vector<Segment>& segments) {
  for (const Segment& s : segments) {
    for (Point hit : intersectWithLevelX(s, p.x)) {
      if (std::abs(hit.z - p.z) < 1e-6) return true;
    }
  }
  return false;
}

RC_GTEST_PROP(PlannerProperties, TypeIPassesAreBoundedAndEndOnTheRoughContour, ()) {
  const RandomCycle c = *genCycle();
  const int zOffset = 10000;  // 100 mm
  std::vector<std::pair<std::string, double>> params = {{"RF1", c.rf1 ? 1.0 : 0.0}, {"DTP", c.dtp ? 1.0 : 0.0}};
  const std::string program = programFor(c, zOffset);
  RC_LOG() << program;
  const Toolpath t = planWithReference({program, "prop.nc", "fanuc-0i-f", params, {}});
  RC_ASSERT(!t.alarm.has_value());
  RC_ASSERT(t.cycles.size() == 1u);

  // The rough contour in the frame, from the recorded finish shape and allowance.
  std::vector<Segment> rough;
  for (Segment s : t.cycles[0].shape) {
    s = s.shifted(t.cycles[0].allowance);
    if (c.g72) {
      s = transposed(s);
      s = s.shifted({-mm(zOffset), 0});
    }
    rough.push_back(s);
  }
  const Point aPrime = rough.front().from;
  const Point bPrime = rough.front().to;
  const Point cPrime = rough.back().to;
  const double dd = mm(c.dd);
  const std::vector<Segment> body(rough.begin() + 1, rough.end());  // B' → C', without the head

  double lastLevel = aPrime.x;
  Point at = toFrame(t.start, c, zOffset);
  for (const Move& m : t.moves) {
    const Point to = toFrame(m.to, c, zOffset);
    if (m.kind == MoveKind::Feed) RC_ASSERT(std::abs(*m.feed - 0.2) < 1e-12);
    const bool cut = m.phase == MovePhase::Pass && m.kind == MoveKind::Feed && std::abs(to.x - at.x) < 1e-9 && to.z < at.z - 1e-9;
    // An infeed to a new pass level (at A'.z): at most Δd deeper than the level before it.
    if (m.phase == MovePhase::Pass && std::abs(to.z - aPrime.z) < 1e-9 && to.x < lastLevel - 1e-9) {
      RC_ASSERT(lastLevel - to.x <= dd + 1e-9);
      lastLevel = to.x;
    }
    if (cut) {
      RC_ASSERT(std::abs(to.x - lastLevel) < 1e-9);  // cuts run at the current level
      if (to.x > cPrime.x + 1e-9) {
        RC_ASSERT(std::abs(to.z - cPrime.z) < 1e-6);  // level beyond C': the cut ends at C'.z
      } else {
        RC_ASSERT(onContour(to, body));
      }
    }
    if (m.phase == MovePhase::SemiFinish && m.kind == MoveKind::Feed) RC_ASSERT(onContour(to, body));
    at = to;
  }
  // The material left between the deepest pass and B' is at most Δd.
  RC_ASSERT(lastLevel - bPrime.x <= dd + 1e-9);
  // Path ends at the start point.
  RC_ASSERT(nearlyEqual(t.from(t.moves.size()), t.start, 1e-9));
  RC_ASSERT(std::none_of(t.moves.begin(), t.moves.end(), [&](const Move& m) { return m.phase == MovePhase::SemiFinish; }) == c.rf1);
}

// The least radius of the rough profile at z (its lower envelope), or nothing outside its span.
std::optional<double> profileFloor(const std::vector<Segment>& rough, double z) {
  std::optional<double> floor;
  for (const Segment& s : rough) {
    for (Point hit : intersectWithLevelX(transposed(s), z)) {
      floor = floor ? std::min(*floor, hit.z) : hit.z;  // in the transposed frame, hit.z is the radius
    }
  }
  return floor;
}

RC_GTEST_PROP(PlannerProperties, TypeIIStaysOutOfThePartReachesEveryValleyBottomAndReturns, ()) {
  const RandomCycle c = *genType2Cycle();
  const int zOffset = 20000;
  const std::string program = programFor(c, zOffset);
  RC_LOG() << program;
  const Toolpath t = planWithReference(
      {program, "prop2.nc", "fanuc-0i-f",
       {{"5134", 0.3}, {"R16", c.r16 ? 1.0 : 0.0}, {"NSP", c.nsp ? 1.0 : 0.0}, {"RF2", c.rf2 ? 1.0 : 0.0}}, {}});
  RC_ASSERT(!t.alarm.has_value());
  std::vector<Segment> rough;
  for (Segment s : t.cycles[0].shape) {
    s = s.shifted(t.cycles[0].allowance);
    if (c.g72) s = transposed(s).shifted({-mm(zOffset), 0});
    rough.push_back(s);
  }
  // No move enters the part: every sampled point lies on or above the rough profile's floor.
  Point at = toFrame(t.start, c, zOffset);
  for (std::size_t i = 0; i < t.moves.size(); ++i) {
    Segment seg = t.segment(i);
    seg.from = at;
    seg.to = toFrame(seg.to, c, zOffset);
    if (seg.isArc()) seg.center = toFrame(seg.center, c, zOffset);
    if (c.g72 && seg.isArc()) seg.kind = reversedKind(seg.kind);
    for (int k = 0; k <= 16; ++k) {
      const Point p = pointAt(seg, k / 16.0);
      if (const auto floor = profileFloor(rough, p.z)) RC_ASSERT(p.x >= *floor - 1e-6);
    }
    at = seg.to;
  }
  // Every valley bottom below A' (a block along z, or a V) is reached by a roughing move: a move
  // ends there or runs through it (a bottom made of collinear blocks is cut in one move).
  const double top = rough.front().from.x;
  const auto reached = [&](Point b) {
    for (std::size_t i = 0; i < t.moves.size(); ++i) {
      if (t.moves[i].phase != MovePhase::Pass) continue;
      Segment seg = t.segment(i);
      if (seg.isArc()) {
        if (distance(toFrame(seg.to, c, zOffset), b) < 1e-6) return true;
        continue;
      }
      seg.from = toFrame(seg.from, c, zOffset);
      seg.to = toFrame(seg.to, c, zOffset);
      if (distanceToSegment(b, seg) < 1e-6) return true;
    }
    return false;
  };
  for (std::size_t i = 1; i < rough.size(); ++i) {
    const Segment& s = rough[i];
    const bool flat = !s.isArc() && std::abs(s.to.x - s.from.x) < 1e-9 && s.from.x < top - 1e-9;
    const bool vee = i + 1 < rough.size() && !s.isArc() && !rough[i + 1].isArc() && s.to.x < s.from.x - 1e-9 &&
                     rough[i + 1].to.x > rough[i + 1].from.x + 1e-9;
    if (flat) RC_ASSERT(reached(s.to));
    if (vee) RC_ASSERT(reached(s.to));
  }
  RC_ASSERT(nearlyEqual(t.from(t.moves.size()), t.start, 1e-9));
}

}  // namespace
}  // namespace cyclecert
