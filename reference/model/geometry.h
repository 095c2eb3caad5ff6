#pragma once
// Plane geometry of lathe contours, in physical coordinates of the cycle plane:
// z along the spindle axis (the plane's 1st axis), x the distance from the axis (radius, the 2nd axis).
// Arc direction convention (used everywhere in cyclecert): G02/G03 as seen from +Y with Z to the
// right and X up, i.e. G02 = clockwise and G03 = counter-clockwise in a plot with Z right, X up.
// The same holds for G17/G19 once mapped to (1st axis right, 2nd axis up).
#include <optional>
#include <vector>

namespace cyclecert {

inline constexpr double kGeomEps = 1e-9;  // lengths below this are zero (mm)

// The sign of a length or a difference of coordinates: +1, −1, or 0 within kGeomEps of zero.
inline int signOf(double v) { return v > kGeomEps ? 1 : (v < -kGeomEps ? -1 : 0); }

struct Point {
  double z = 0;
  double x = 0;
  friend bool operator==(const Point&, const Point&) = default;
};
inline Point operator+(Point a, Point b) { return {a.z + b.z, a.x + b.x}; }
inline Point operator-(Point a, Point b) { return {a.z - b.z, a.x - b.x}; }
inline Point operator*(double k, Point a) { return {k * a.z, k * a.x}; }
double distance(Point a, Point b);
bool nearlyEqual(Point a, Point b, double tol = kGeomEps);

enum class SegmentKind { Line, ArcCW, ArcCCW };

// A line or a circular arc from `from` to `to`; `center` is meaningful for arcs only.
// `sourceLine` is the program line of the block that produced it (0 when synthetic).
struct Segment {
  SegmentKind kind = SegmentKind::Line;
  Point from, to, center;
  int sourceLine = 0;

  bool isArc() const { return kind != SegmentKind::Line; }
  double radius() const;
  double length() const;
  Segment shifted(Point by) const;   // translation (the allowance shift of type I cycles)
  Segment reversed() const;
};

// Point on the segment at parameter t in [0,1] (by arc angle for arcs).
Point pointAt(const Segment& s, double t);

// The angle `a` (radians) in [0, 2π): std::fmod(a, 2π), plus 2π when negative.
double normalizedAngle(double a);

// Signed sweep angle of an arc in radians (negative for CW), in (-2π, 2π]; 0 for lines.
double sweep(const Segment& s);

// An arc's angles, worked out once (two atan2) for many questions about one arc: the angle of
// `from` around the centre (atan2(x, z) of the direction from it) and the signed sweep.
struct ArcAngles {
  explicit ArcAngles(const Segment& arc);
  double start, sweep;
};

// How far along the arc (0 at `from`, |sweep| at `to`) the angle `a` around its centre lies
// (measured as atan2(x, z) of the direction from the centre), or nothing when the angle is outside
// the arc's span (with an angular tolerance of 1e-9).
std::optional<double> offsetAlongArc(const Segment& s, double a);
std::optional<double> offsetAlongArc(const ArcAngles& arc, double a);
// pointAt of an arc whose angles are known.
Point pointAt(const Segment& arc, const ArcAngles& angles, double t);

// Exchanges the roles of z and x (transposes the plane); arcs change direction.
inline Point transposed(Point p) { return {p.x, p.z}; }
Segment transposed(const Segment& s);

// Intersections of a segment with the line `x == level` (axis-parallel), ordered along the
// segment from `from` to `to`. A segment lying on the line returns its two end points.
std::vector<Point> intersectWithLevelX(const Segment& s, double level);

// Smallest and largest x and z reached anywhere on the segment (arcs include their apexes).
struct Extent { double zMin, zMax, xMin, xMax; };
Extent extent(const Segment& s);
// A box holding the segment, found without its angles: its ends' box, grown to its whole circle's
// for an arc. Looser than extent(s) for an arc, and cheap: a quick test that rules segments out.
Extent enclosingExtent(const Segment& s);

// Points of an arc where it turns back on the z or x axis (its apexes), in order along the arc.
std::vector<Point> apexesAlong(const Segment& s);
SegmentKind reversedKind(SegmentKind k);

// Arc centre from end points and a signed radius R (FANUC: R>0 arc ≤ 180°, R<0 arc > 180°).
// Returns nothing when |R| is shorter than half the chord (no such arc).
std::optional<Point> arcCenterFromRadius(Point from, Point to, double r, SegmentKind dir);

}  // namespace cyclecert
