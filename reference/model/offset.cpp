#include "reference/model/offset.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace cyclecert {

namespace {
constexpr double kTwoPi = 2 * std::numbers::pi;

double dot(Point a, Point b) { return a.z * b.z + a.x * b.x; }
double cross(Point a, Point b) { return a.z * b.x - a.x * b.z; }  // > 0: b turns left of a
double norm(Point a) { return std::hypot(a.z, a.x); }
Point unit(Point a) { return (1.0 / norm(a)) * a; }
double angleOf(Point p, Point center) { return std::atan2(p.x - center.x, p.z - center.z); }

// Direction of travel on an arc at point p (p on the arc).
Point arcTangentAt(const Segment& s, Point p) {
  const Point radial = unit(p - s.center);
  const Point ccw{-radial.x, radial.z};  // radial turned +90°
  return s.kind == SegmentKind::ArcCCW ? ccw : -1.0 * ccw;
}

std::string describe(OffsetProblem problem, int segmentIndex, int sourceLine) {
  const std::string where =
      " at segment " + std::to_string(segmentIndex) + " (line " + std::to_string(sourceLine) + ")";
  if (problem == OffsetProblem::ArcVanishes) {
    return "tool-nose radius compensation: arc radius would become <= 0" + where;
  }
  return "tool-nose radius compensation: interference, offset pieces do not meet" + where;
}

// A piece of the offset path under construction. Arcs carry their signed sweep explicitly, so a
// piece trimmed down to nothing (from == to) is not mistaken for a full circle.
struct Piece {
  Segment seg;
  double sweep = 0;    // signed, arcs only
  int index = 0;       // input segment it comes from

  double length() const {
    return seg.isArc() ? std::abs(sweep) * seg.radius() : distance(seg.from, seg.to);
  }
};

// The offset of one input segment (index i), before corners are resolved.
Piece offsetPiece(const Segment& s, int i, double r, CompensationSide side) {
  Piece piece{s, s.isArc() ? cyclecert::sweep(s) : 0.0, i};
  if (!s.isArc()) {
    const Point shift = r * sideNormal(unitTangentAtStart(s), side);
    piece.seg = s.shifted(shift);
    return piece;
  }
  // The left normal of a CCW arc points to its centre, of a CW arc away from it.
  const bool centreOnLeft = s.kind == SegmentKind::ArcCCW;
  const bool shrinks = centreOnLeft == (side == CompensationSide::Left);
  const double newRadius = s.radius() + (shrinks ? -r : r);
  if (newRadius <= kGeomEps) throw OffsetError(OffsetProblem::ArcVanishes, i, s.sourceLine);
  piece.seg.from = s.center + newRadius * unit(s.from - s.center);
  piece.seg.to = s.center + newRadius * unit(s.to - s.center);
  return piece;
}

// fractionAlong on an arc `s` of signed sweep `sweep` whose start lies at the angle `start` around
// its centre (angleOf(s.from, s.center), given: distanceToSegment knows it already).
std::optional<double> fractionAlongArc(const Segment& s, double sweep, double start, Point p) {
  const double span = std::abs(sweep);
  const double angularTol = kGeomEps / s.radius();
  const double dir = sweep >= 0 ? 1.0 : -1.0;
  double off = normalizedAngle(dir * (angleOf(p, s.center) - start));
  if (off > kTwoPi - angularTol) off -= kTwoPi;  // just before the start counts as the start
  if (off < -angularTol || off > span + angularTol) return std::nullopt;
  return span > 0 ? std::clamp(off / span, 0.0, 1.0) : 0.0;
}

// Where p lies on the piece as a fraction of its length in [0, 1], or nothing when p is off the
// piece by more than the tolerance. p is known to lie on the piece's line or circle.
std::optional<double> fractionAlong(const Piece& piece, Point p) {
  const Segment& s = piece.seg;
  if (!s.isArc()) {
    const double len = distance(s.from, s.to);
    if (len <= kGeomEps) {
      return distance(p, s.from) <= kGeomEps ? std::optional<double>(0.0) : std::nullopt;
    }
    const double along = dot(p - s.from, s.to - s.from) / len;
    if (along < -kGeomEps || along > len + kGeomEps) return std::nullopt;
    return std::clamp(along / len, 0.0, 1.0);
  }
  return fractionAlongArc(s, piece.sweep, angleOf(s.from, s.center), p);
}

// Intersections of the full lines/circles carrying two pieces.
std::vector<Point> lineLine(const Segment& a, const Segment& b) {
  const Point d = a.to - a.from, e = b.to - b.from;
  const double den = cross(d, e);
  if (std::abs(den) <= 1e-15 * norm(d) * norm(e)) return {};  // parallel
  const double t = cross(b.from - a.from, e) / den;
  return {a.from + t * d};
}

std::vector<Point> lineCircle(const Segment& line, Point center, double radius) {
  const Point d = unit(line.to - line.from);
  const Point foot = line.from + dot(center - line.from, d) * d;
  const double off = distance(foot, center);
  if (off > radius + kGeomEps) return {};
  const double h = std::sqrt(std::max(0.0, radius * radius - off * off));
  return {foot - h * d, foot + h * d};
}

std::vector<Point> circleCircle(Point c1, double r1, Point c2, double r2) {
  const double d = distance(c1, c2);
  if (d <= kGeomEps || d > r1 + r2 + kGeomEps || d < std::abs(r1 - r2) - kGeomEps) return {};
  const double a = (r1 * r1 - r2 * r2 + d * d) / (2 * d);
  const double h = std::sqrt(std::max(0.0, r1 * r1 - a * a));
  const Point u = (1.0 / d) * (c2 - c1);
  const Point mid = c1 + a * u;
  const Point perp{-u.x, u.z};
  return {mid - h * perp, mid + h * perp};
}

std::vector<Point> curveIntersections(const Segment& a, const Segment& b) {
  if (!a.isArc() && !b.isArc()) return lineLine(a, b);
  if (!a.isArc()) return lineCircle(a, b.center, b.radius());
  if (!b.isArc()) return lineCircle(b, a.center, a.radius());
  return circleCircle(a.center, a.radius(), b.center, b.radius());
}

void trimEnd(Piece& piece, Point p, double fraction) {
  piece.seg.to = p;
  piece.sweep *= fraction;
}

void trimStart(Piece& piece, Point p, double fraction) {
  piece.seg.from = p;
  piece.sweep *= 1 - fraction;
}

// Concave corner: cut `in` and `out` back to their common point nearest to the corner.
void trimToIntersection(Piece& in, Piece& out, Point corner) {
  struct Hit { Point p; double fin, fout; };
  std::optional<Hit> best;
  for (Point p : curveIntersections(in.seg, out.seg)) {
    const auto fin = fractionAlong(in, p);
    const auto fout = fractionAlong(out, p);
    if (!fin || !fout) continue;
    if (!best || distance(p, corner) < distance(best->p, corner)) best = Hit{p, *fin, *fout};
  }
  if (!best) throw OffsetError(OffsetProblem::Interference, out.index, out.seg.sourceLine);
  trimEnd(in, best->p, best->fin);
  trimStart(out, best->p, best->fout);
}

enum class Corner { Smooth, Convex, Concave };

// A corner is convex when the path turns away from the tool's side (left turn with the tool on
// the right): the offset pieces leave a gap there. A reversal (U-turn) is convex on either side.
Corner classify(const Segment& in, const Segment& out, const Piece& inPiece, const Piece& outPiece,
                CompensationSide side) {
  const Point t1 = unitTangentAtEnd(in), t2 = unitTangentAtStart(out);
  const double turn = cross(t1, t2);
  const bool gap = distance(inPiece.seg.to, outPiece.seg.from) > kGeomEps;
  if (!gap || (dot(t1, t2) > 0 && std::abs(turn) <= kGeomEps)) return Corner::Smooth;
  if (std::abs(turn) <= kGeomEps) return Corner::Convex;  // reversal
  const bool turnsLeft = turn > 0;
  return turnsLeft == (side == CompensationSide::Right) ? Corner::Convex : Corner::Concave;
}

Piece cornerArc(Point from, Point to, Point corner, CompensationSide side, const Piece& next) {
  Segment s{side == CompensationSide::Right ? SegmentKind::ArcCCW : SegmentKind::ArcCW, from, to,
            corner, next.seg.sourceLine};
  return Piece{s, cyclecert::sweep(s), next.index};
}

// The input without zero-length segments, each with its index in the input.
std::vector<std::pair<int, Segment>> nonEmptySegments(const std::vector<Segment>& path) {
  std::vector<std::pair<int, Segment>> kept;
  kept.reserve(path.size());
  for (int i = 0; i < static_cast<int>(path.size()); ++i) {
    if (path[i].length() <= kGeomEps) continue;
    if (!kept.empty() && distance(kept.back().second.to, path[i].from) > 1e-6) {
      throw std::invalid_argument("offsetPath: the path has a gap before segment " +
                                  std::to_string(i));
    }
    kept.push_back({i, path[i]});
  }
  return kept;
}

// Pieces to segments: drops zero-length pieces and makes every join exact.
std::vector<Segment> assemble(const std::vector<Piece>& pieces) {
  std::vector<Segment> result;
  result.reserve(pieces.size());
  for (const Piece& piece : pieces) {
    if (piece.length() <= kGeomEps) continue;
    Segment s = piece.seg;
    if (!result.empty()) s.from = result.back().to;
    result.push_back(s);
  }
  return result;
}
}  // namespace

OffsetError::OffsetError(OffsetProblem problem, int segmentIndex, int sourceLine)
    : std::runtime_error(describe(problem, segmentIndex, sourceLine)),
      problem(problem),
      segmentIndex(segmentIndex),
      sourceLine(sourceLine) {}

Point imaginaryTipDirection(int tip) {
  static constexpr std::array<Point, 10> kChart{{
      {0, 0},    // 0: nose centre
      {1, 1},    // 1: +z +x
      {-1, 1},   // 2: −z +x
      {-1, -1},  // 3: −z −x
      {1, -1},   // 4: +z −x
      {1, 0},    // 5: +z
      {0, 1},    // 6: +x
      {-1, 0},   // 7: −z
      {0, -1},   // 8: −x
      {0, 0},    // 9: nose centre
  }};
  if (tip < 0 || tip > 9) throw std::out_of_range("imaginary tip direction must be 0..9");
  return kChart[tip];
}

Point unitTangentAtStart(const Segment& s) {
  return s.isArc() ? arcTangentAt(s, s.from) : unit(s.to - s.from);
}

Point unitTangentAtEnd(const Segment& s) {
  return s.isArc() ? arcTangentAt(s, s.to) : unit(s.to - s.from);
}

Point sideNormal(Point t, CompensationSide side) {
  return side == CompensationSide::Left ? Point{-t.x, t.z} : Point{t.x, -t.z};
}

double distanceToSegment(Point p, const Segment& s) {
  if (!s.isArc()) {
    const Point d = s.to - s.from;
    const double len2 = dot(d, d);
    const double t = len2 > 0 ? std::clamp(dot(p - s.from, d) / len2, 0.0, 1.0) : 0.0;
    return distance(p, s.from + t * d);
  }
  return distanceToSegment(p, s, ArcAngles(s));
}

double distanceToSegment(Point p, const Segment& arc, const ArcAngles& angles) {
  const double toEnds = std::min(distance(p, arc.from), distance(p, arc.to));
  if (distance(p, arc.center) <= kGeomEps) return arc.radius();
  // The nearest point of the full circle counts when it lies on the arc.
  const Point nearest = arc.center + arc.radius() * unit(p - arc.center);
  if (fractionAlongArc(arc, angles.sweep, angles.start, nearest)) return std::min(toEnds, distance(p, nearest));
  return toEnds;
}

double distanceToPath(Point p, const std::vector<Segment>& path) {
  double best = std::numeric_limits<double>::infinity();
  for (const Segment& s : path) best = std::min(best, distanceToSegment(p, s));
  return best;
}

bool nearPath(Point p, const std::vector<Segment>& path, double tolerance) {
  for (const Segment& s : path) {
    // A box around the segment (an arc's whole circle) decides most segments without measuring.
    const Extent box = enclosingExtent(s);
    if (p.z < box.zMin - tolerance || p.z > box.zMax + tolerance || p.x < box.xMin - tolerance ||
        p.x > box.xMax + tolerance) {
      continue;
    }
    if (distanceToSegment(p, s) <= tolerance) return true;
  }
  return false;
}

std::vector<Segment> offsetPath(const std::vector<Segment>& path, double r, CompensationSide side) {
  if (!(r >= 0)) throw std::invalid_argument("offsetPath: the nose radius must be >= 0");
  const auto kept = nonEmptySegments(path);
  std::vector<Piece> pieces;
  pieces.reserve(2 * kept.size());  // a piece per segment and one per corner at most
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const auto& [index, segment] = kept[k];
    Piece next = offsetPiece(segment, index, r, side);
    if (k > 0) {
      Piece& prev = pieces.back();
      switch (classify(kept[k - 1].second, segment, prev, next, side)) {
        case Corner::Smooth:
          break;  // the joins are made exact in assemble()
        case Corner::Convex:
          pieces.push_back(cornerArc(prev.seg.to, next.seg.from, segment.from, side, next));
          break;
        case Corner::Concave:
          trimToIntersection(prev, next, segment.from);
          break;
      }
    }
    pieces.push_back(next);
  }
  return assemble(pieces);
}

std::vector<Segment> compensatedPath(const std::vector<Segment>& path, const ToolOffset& tool,
                                     CompensationSide side) {
  const Point tipShift = tool.noseRadius * imaginaryTipDirection(tool.tip);
  std::vector<Segment> result = offsetPath(path, tool.noseRadius, side);
  for (Segment& s : result) s = s.shifted(tipShift);
  return result;
}

Point startUpPoint(Point p, const Segment& next, const ToolOffset& tool, CompensationSide side) {
  const double r = tool.noseRadius;
  return p + r * sideNormal(unitTangentAtStart(next), side) + r * imaginaryTipDirection(tool.tip);
}

}  // namespace cyclecert
