// The oracles' own reading of a G74.1 program (G74_1.FMT, G74_1.ADDR, G74_1.RANGE) and the groove's
// outline built from docs/g74_1.md §3–§5 — written apart from reference/cycles/g74_1*.cpp, so that
// an oracle does not agree with the planner by construction. The interpretations I1…I28 are the
// docs' (and specs/rules.json's).
#include "oracles/groove/groove_spec.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "reference/model/alarms.h"
#include "reference/model/offset.h"

namespace cyclecert {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLargestLength = 9999.9999;  // IS-C (I5)
constexpr double kLargestSmall = 99.9999;     // e and r1…r4
constexpr double kFitEps = 1e-9;

// A reason the reading stops: the alarm the controller raises.
struct GrooveAlarm {
  Alarm alarm;
};

[[noreturn]] void raise(std::string_view code, int line, std::string message) {
  throw GrooveAlarm{Alarm{std::string(code), std::move(message), line, "cycle block"}};
}

[[noreturn]] void outOfRange(const Word& w, const std::string& range) {
  raise(alarm::kOutOfRange, w.line, w.text + " is outside " + range + " (G74_1.RANGE)");
}

// The groove does not fit (I9, I11, §7): PS0062 at the second block.
struct Misfit {
  std::string why;
};

// G74_1.FMT: the words each block takes (F S T M and G on any block), else PS0009.
void requireWords(const Block& b, std::string_view letters, const char* format) {
  for (const Word& w : b.words) {
    if (std::string_view("GFSTMN").find(w.letter) != std::string_view::npos) continue;
    if (letters.find(w.letter) == std::string_view::npos) {
      raise(alarm::kImproperAddress, w.line, w.text + ": " + format + " (G74_1.FMT)");
    }
  }
}

const Word& requiredWord(const Block& b, char letter, std::string_view code) {
  if (const Word* w = b.find(letter)) return *w;
  raise(code, b.line, std::string("the first G74.1 block has no ") + letter + " (I2: no default)");
}

// H and D: signed, not zero (I3).
double signedLength(const Word& w) {
  if (std::abs(w.value) > kLargestLength || std::abs(w.value) <= kGeomEps) {
    outOfRange(w, "-9999.9999…9999.9999 without 0 (I3: its sign is the direction)");
  }
  return w.value;
}

double angleWord(const Block& b, char letter, double absent, bool flank) {
  const Word* w = b.find(letter);
  if (!w) return absent;
  const bool ok = flank ? (w->value > 0 && w->value <= 90) : (w->value >= 0 && w->value < 90);
  if (!ok) outOfRange(*w, flank ? "0 < angle ≤ 90" : "0 ≤ angle < 90");
  return w->value;
}

// P(Δi), Q(Δk): least increments of IS-C without a decimal point (182#7 = 0) or mm (1) (I5).
double stepWord(const Word& w, const ModalState& s, const MachineParams& params) {
  if (w.value <= 0) raise(alarm::kCuttingAmount, w.line, w.text + ": Δi and Δk of G74.1 must be positive (I6b)");
  if (params.bit("182#7")) {
    if (w.value > kLargestLength) outOfRange(w, "0 < value ≤ 9999.9999 (parameter 182#7 = 1)");
    return w.value * s.unitScale();
  }
  if (w.hasDecimalPoint) {
    raise(alarm::kIllegalDecimalPoint, w.line, w.text + ": P and Q are least input increments (182#7 = 0, I5)");
  }
  if (w.value > 99'999'999) outOfRange(w, "1…99999999 least input increments");
  return w.value * (s.inch ? 0.00001 : 0.0001) * s.unitScale();
}

double smallWord(const Block& b, char letter) {
  const Word* w = b.find(letter);
  if (!w) return 0;
  if (w->value < 0 || w->value > kLargestSmall) outOfRange(*w, "0…99.9999");
  return w->value;
}

// U, W, I: signed ranges read as magnitudes (I4).
double magnitudeWord(const Block& b, char letter) {
  const Word* w = b.find(letter);
  if (!w) return 0;
  if (std::abs(w->value) > kLargestLength) outOfRange(*w, "-9999.9999…9999.9999");
  return std::abs(w->value);
}

void readGrooveBlock(const Block& b, const ModalState& s, const MachineParams& params, GrooveSpec& g) {
  requireWords(b, "XZPQHDABL", "the first G74.1 block takes X Z P Q H D A B L");
  const double k = s.unitScale();
  const Word& x = requiredWord(b, 'X', alarm::kOutOfRange);
  const Word& z = requiredWord(b, 'Z', alarm::kOutOfRange);
  const Word& h = requiredWord(b, 'H', alarm::kOutOfRange);
  const Word& d = requiredWord(b, 'D', alarm::kOutOfRange);
  const Word& p = requiredWord(b, 'P', alarm::kPQMissing);
  const Word& q = requiredWord(b, 'Q', alarm::kPQMissing);
  const double depth = signedLength(h) * k, width = signedLength(d) * k;
  g.grooveLine = b.line;
  g.start = {z.value * k, x.value * k / 2};
  g.depthSign = depth > 0 ? 1 : -1;
  g.widthSign = width > 0 ? 1 : -1;
  g.depth = std::abs(depth);
  g.floorWidth = std::abs(width) / 2;
  g.angleA = angleWord(b, 'A', 90, true);
  g.angleB = angleWord(b, 'B', 90, true);
  g.slope = angleWord(b, 'L', 0, false);
  g.radialStep = stepWord(p, s, params) / 2;
  g.peck = stepWord(q, s, params);
}

void readCuttingBlock(const Block& b, const ModalState& s, GrooveSpec& g) {
  requireWords(b, "RVUWIJABDEP", "the second G74.1 block takes R V U W I J A B D E P");
  const double k = s.unitScale();
  g.retract = smallWord(b, 'R') * k;
  if (const Word* v = b.find('V')) {
    if (v->value <= 0) raise(alarm::kCuttingAmount, v->line, v->text + ": the layer depth Δv must be positive (I6b)");
    if (v->value > kLargestLength) outOfRange(*v, "0 < Δv ≤ 9999.9999");
    g.layerDepth = v->value * k;
  }
  g.flankAllowance = magnitudeWord(b, 'U') * k / 2;
  g.floorAllowance = magnitudeWord(b, 'W') * k;
  g.toolWidth = magnitudeWord(b, 'I') * k;
  if (const Word* j = b.find('J')) {
    if (j->value != 0 && j->value != 1 && j->value != 2) outOfRange(*j, "J0, J1 or J2");
    g.pathType = static_cast<int>(j->value);
  }
  // P(abde) (I6): up to four digits, each 0 or 1, padded with zeros on the left.
  if (const Word* p = b.find('P')) {
    const double v = p->value;
    if (p->hasDecimalPoint || v < 0 || v > 1111 || v != std::floor(v)) outOfRange(*p, "P0000…P1111");
    int digits = static_cast<int>(v);
    for (int c = 3; c >= 0; --c, digits /= 10) {
      if (digits % 10 > 1) outOfRange(*p, "P0000…P1111");
      g.corners[static_cast<std::size_t>(c)].shape = digits % 10 == 1 ? GrooveCornerShape::Round : GrooveCornerShape::Chamfer;
    }
  }
  const char letters[4] = {'A', 'B', 'D', 'E'};  // r1 r2 r3 r4
  for (std::size_t c = 0; c < 4; ++c) g.corners[c].size = smallWord(b, letters[c]) * k;
}

// ---- the outline (§3, §5) ----

Point unit(Point v) {
  const double n = std::hypot(v.z, v.x);
  return n > 0 ? (1 / n) * v : v;
}
double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }

// A corner of the chain at `v` between the edges towards `prev` and `next`, cut by a chamfer of
// equal legs (I10) or a round tangent to both edges.
struct CornerCut {
  Point entry, exit;
  double leg = 0;  // distance of entry/exit from v
  std::optional<Segment> piece;
};

CornerCut cutCorner(Point prev, Point v, Point next, const GrooveCornerSpec& c) {
  CornerCut cut{v, v, 0, std::nullopt};
  if (c.size <= 0) return cut;
  const Point e1 = unit(prev - v), e2 = unit(next - v);
  const double theta = std::acos(std::clamp(dot(e1, e2), -1.0, 1.0));  // the interior angle
  cut.leg = c.shape == GrooveCornerShape::Chamfer ? c.size : c.size / std::tan(theta / 2);
  cut.entry = v + cut.leg * e1;
  cut.exit = v + cut.leg * e2;
  Segment s{SegmentKind::Line, cut.entry, cut.exit, {}, 0};
  if (c.shape == GrooveCornerShape::Round) {
    s.center = v + (c.size / std::sin(theta / 2)) * unit(e1 + e2);
    s.kind = cross(cut.entry - s.center, cut.exit - s.center) > 0 ? SegmentKind::ArcCCW : SegmentKind::ArcCW;
  }
  cut.piece = s;
  return cut;
}

double cotDeg(double deg) { return deg >= 90 ? 0 : 1 / std::tan(deg * kPi / 180); }

// §3 with the allowances of §5 (I15): each flank moved into the groove by `side` along u, the floor
// by `bottom` towards the mouth; the mouth line stays; the corners keep their sizes.
GrooveOutline buildOutline(const GrooveSpec& g, double side, double bottom) {
  const double tp = std::tan(g.slope * kPi / 180), ca = cotDeg(g.angleA), cb = cotDeg(g.angleB);
  if (1 - tp * ca <= kFitEps) throw Misfit{"the slope ∠p is not below the near flank ∠a (I9)"};
  const double floorW = g.depth - bottom;
  if (floorW <= kFitEps) throw Misfit{"the Z allowance Δw leaves no groove (I15)"};
  const double uS = side / (1 - tp * ca);
  const Point s = grooveUW(uS, uS * tp);
  const Point n = grooveUW(side + floorW * ca, floorW);
  const double uFarFinish = g.depth * ca + g.floorWidth;
  const Point f = grooveUW(uFarFinish - side + bottom * cb, floorW);
  const double uM = (uFarFinish - side + g.depth * cb) / (1 + tp * cb);
  const Point m = grooveUW(uM, uM * tp);
  if (f.x - n.x <= kFitEps) throw Misfit{"the allowances leave no floor (I15)"};
  if (s.z >= floorW - kFitEps || m.z >= floorW - kFitEps) {
    throw Misfit{"the slope reaches the floor before a flank (I9)"};
  }
  const Point mouth = grooveUW(std::cos(g.slope * kPi / 180), std::sin(g.slope * kPi / 180));
  const CornerCut r1 = cutCorner(s - mouth, s, n, g.corners[0]);
  const CornerCut r3 = cutCorner(s, n, f, g.corners[2]);
  const CornerCut r4 = cutCorner(n, f, m, g.corners[3]);
  const CornerCut r2 = cutCorner(f, m, m + mouth, g.corners[1]);
  // I11: each edge holds both its corners' legs.
  if (r1.leg + r3.leg > distance(s, n) + kFitEps || r3.leg + r4.leg > distance(n, f) + kFitEps ||
      r4.leg + r2.leg > distance(f, m) + kFitEps) {
    throw Misfit{"the corners r1…r4 do not fit the groove's edges (I11)"};
  }
  GrooveOutline o;
  o.nearMouth = s;
  o.floorNear = n;
  o.floorFar = f;
  o.floorDepth = floorW;
  o.floorFrom = r3.exit.x;
  o.floorTo = r4.entry.x;
  const auto line = [&o](Point a, Point b) {
    if (distance(a, b) > kGeomEps) o.chain.push_back(Segment{SegmentKind::Line, a, b, {}, 0});
  };
  const auto corner = [&o](const CornerCut& c) {
    if (c.piece) o.chain.push_back(*c.piece);
  };
  corner(r1);
  line(r1.exit, r3.entry);
  corner(r3);
  line(r3.exit, r4.entry);
  corner(r4);
  line(r4.exit, r2.entry);
  corner(r2);
  return o;
}

// §7: the blade needs a floor at least as wide as itself.
void requireFloorForTheBlade(const GrooveOutline& o, double toolWidth) {
  if (o.floorTo - o.floorFrom < toolWidth - kFitEps) throw Misfit{"the floor is narrower than the tool width I (§7)"};
}

// I26: a pointed tool (no I) under G41/G42 with a nose radius: the groove's inside lies left of its
// profile passes when h and d have the same sign (G41), else right (G42); the other code is PS0041.
void readNose(const Block& cutting, const ModalState& s, const ToolOffset& tool, GrooveSpec& g) {
  if (s.tnrc == 40 || cutting.has('I') || tool.noseRadius <= 0) return;
  const int inside = g.depthSign * g.widthSign > 0 ? 41 : 42;
  if (s.tnrc != inside) {
    raise(alarm::kInterference, cutting.line,
          "a pointed tool under G" + std::to_string(s.tnrc) + " with h·d of this sign has the groove on its other side: G" +
              std::to_string(inside) + " (I26)");
  }
  g.noseRadius = tool.noseRadius;
  if (tool.tip >= 0 && tool.tip <= 9) g.tipShift = tool.noseRadius * imaginaryTipDirection(tool.tip);
}

// I27: the nose centre must find a floor R above the rough floor between the flanks moved in by R:
// at that depth the near flank's line moved in lies R·tan(∠a/2) beyond N, the far one R·tan(∠b/2)
// before F; and the groove must be deeper than R.
void requireTheNoseFits(const GrooveSpec& g) {
  if (g.noseRadius <= 0) return;
  const GrooveOutline& o = g.rough;
  const double halfA = g.angleA * kPi / 360, halfB = g.angleB * kPi / 360;
  const double room = o.floorFar.x - o.floorNear.x - g.noseRadius * (std::tan(halfA) + std::tan(halfB));
  if (room <= kFitEps || o.floorDepth <= g.noseRadius + kFitEps) {
    throw Misfit{"the nose radius R does not fit the rough groove (I27)"};
  }
}

}  // namespace

bool givesTheGroove(const Block& b) { return b.has('X') || b.has('Z'); }

Segment GrooveSpec::toPlane(const Segment& local) const {
  Segment s = local;
  s.from = toPlane(local.from);
  s.to = toPlane(local.to);
  if (local.isArc()) {
    s.center = toPlane(local.center);
    if (depthSign * widthSign < 0) s.kind = reversedKind(local.kind);  // the frame mirrors
  }
  return s;
}

Point GrooveSpec::roughStart() const {
  if (noseRadius <= 0) return grooveUW(rough.nearMouth.x + toolWidth, 0);
  const double a = angleA * kPi / 180;
  // The flank's line moved in by R, at the centre's depth −R (its lowest point on the start level).
  return grooveUW(rough.nearMouth.x - (rough.nearMouth.z + noseRadius) * cotDeg(angleA) + noseRadius / std::sin(a), 0);
}

std::vector<double> GrooveSpec::layerTops() const {
  const double bottom = roughDepth();
  if (!layerDepth) return {0};
  std::vector<double> tops;
  for (int m = 0; m * *layerDepth < bottom - kFitEps; ++m) tops.push_back(m * *layerDepth);
  return tops;
}

std::optional<Alarm> grooveBlockAlarm(const Block& groove, const ModalState& state, const MachineParams& params) {
  GrooveSpec unused;
  try {
    readGrooveBlock(groove, state, params, unused);
  } catch (const GrooveAlarm& a) {
    return a.alarm;
  }
  return std::nullopt;
}

GrooveSpec readGrooveSpec(const Block* groove, const Block& cutting, const ModalState& state,
                          const MachineParams& params, const ToolOffset& tool) {
  GrooveSpec g;
  g.line = cutting.line;
  g.before = state.planePoint();
  g.feed = state.feed;
  try {
    if (!groove) {
      raise(alarm::kPQMissing, cutting.line, "no first G74.1 block (X Z P Q H D …) before this one (I1)");
    }
    readGrooveBlock(*groove, state, params, g);
    readCuttingBlock(cutting, state, g);
    readNose(cutting, state, tool, g);
  } catch (const GrooveAlarm& a) {
    g.forbiddenBy = a.alarm;
    return g;
  }
  try {
    g.finish = buildOutline(g, 0, 0);
    g.rough = buildOutline(g, g.flankAllowance, g.floorAllowance);
    if (g.roughs()) requireFloorForTheBlade(g.rough, g.toolWidth);
    if (g.finishes()) requireFloorForTheBlade(g.finish, g.toolWidth);
  } catch (const Misfit& m) {
    g.forbiddenBy = Alarm{std::string(alarm::kCuttingAmount), "G74.1: " + m.why, cutting.line, "cycle block"};
    return g;
  }
  try {
    requireTheNoseFits(g);
  } catch (const Misfit& m) {
    g.forbiddenBy = Alarm{std::string(alarm::kInterference), "G74.1: " + m.why, cutting.line, "cycle block"};
  }
  return g;
}

}  // namespace cyclecert
