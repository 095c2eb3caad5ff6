#include "reference/siemens/siemens_roughing_steps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>

#include "reference/cycles/roughing_cycle.h"
#include "reference/gcode/program_limits.h"
#include "reference/model/alarms.h"
#include "reference/model/number_text.h"
#include "reference/model/offset.h"
#include "reference/siemens/siemens_roughing_undercut.h"

namespace cyclecert {

void stampPhase(Move& m, MovePhase phase, int pass) {
  m.phase = phase;
  m.pass = phase == MovePhase::Pass ? pass : 0;
}

namespace {

// Smallest and largest z and x anywhere on the path (an arc's apexes included): worked out once per
// cycle, for its start (computedStart) and its lowest level.
Extent extentOf(const std::vector<Segment>& path) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Extent all{kInf, -kInf, kInf, -kInf};
  for (const Segment& s : path) {
    const Extent e = extent(s);
    all.zMin = std::min(all.zMin, e.zMin);
    all.zMax = std::max(all.zMax, e.zMax);
    all.xMin = std::min(all.xMin, e.xMin);
    all.xMax = std::max(all.xMax, e.xMax);
  }
  return all;
}

// computedStart of a profile whose extent is known.
Point startBeyond(const Extent& profile, Point clearance) {
  return {profile.zMax + clearance.z, profile.xMax + clearance.x};
}

}  // namespace

Point computedStart(const std::vector<Segment>& profile, Point clearance) {
  return startBeyond(extentOf(profile), clearance);
}

InfeedSteps equalInfeedSteps(double totalDepth, double maxInfeed, int line) {
  if (totalDepth <= kGeomEps) return {};
  const double count = std::max(1.0, std::ceil(totalDepth / maxInfeed - 1e-9));
  if (!(count <= kMostRoughingPasses)) {  // PROG.CAP.PASSES, checked before the count is made an int
    throw NotSupported(line, "the stock-removal cycle would make " + countText(count) +
                                 " passes (depth " + shortDecimalText(totalDepth) + " mm in steps of at most " +
                                 shortDecimalText(maxInfeed) + " mm); cyclecert plans at most " +
                                 countText(kMostRoughingPasses));
  }
  return {static_cast<int>(count), totalDepth / count};
}

std::vector<double> equalInfeedLevels(double top, double bottom, double maxInfeed, int line) {
  const InfeedSteps steps = equalInfeedSteps(top - bottom, maxInfeed, line);
  std::vector<double> levels{top};
  for (int k = 1; k <= steps.count; ++k) levels.push_back(k == steps.count ? bottom : top - k * steps.depth);
  return levels;
}

namespace {

// A point on the profile and the segment it lies on.
struct ProfilePoint {
  std::size_t segment = 0;
  Point at;
};

// Whether `p` on profile element `i` lies on the walls the contour begins with at its first point's z
// (before `foot`, the element where the profile leaves the part's face) above the face's top (the
// foot's height): such a wall has no part in front of it (nothing of the part stands beyond the
// contour's start) nor behind it: stock on both sides (LCYC95.ROUGH note) — a wall falling down the
// face, or one rising and falling back along itself (a spike of no width, issue 16).
bool isFrontWallAboveTheFace(std::size_t i, Point p, std::size_t foot, double faceTop) {
  return i < foot && p.x > faceTop + kGeomEps;
}

// The roughing intersection (LCYC95.ROUGH): the first point where the level, run towards −z from
// `fromZ`, meets the profile — not counting the front walls above the face's top
// (isFrontWallAboveTheFace: a level between the face's top and the walls' top runs through them
// into the stock behind).
std::optional<ProfilePoint> roughingIntersection(const std::vector<Segment>& profile, double level, double fromZ,
                                                 std::size_t foot = 0,
                                                 double faceTop = std::numeric_limits<double>::infinity()) {
  std::optional<ProfilePoint> best;
  for (std::size_t i = 0; i < profile.size(); ++i) {
    // An element standing nowhere in front of the best point yet (by a box round it, an arc's whole
    // circle: enclosingExtent) has no point further forward: its crossings are not worked out (each
    // pass asks for the whole profile's, most of it behind the first crossing).
    if (best && enclosingExtent(profile[i]).zMax <= best->at.z) continue;
    for (const Point& p : intersectWithLevelX(profile[i], level)) {
      if (p.z > fromZ + kGeomEps || isFrontWallAboveTheFace(i, p, foot, faceTop)) continue;
      if (!best || p.z > best->at.z + kGeomEps) best = ProfilePoint{i, p};
    }
  }
  return best;
}

double angleAround(const Segment& arc, Point p) { return std::atan2(p.x - arc.center.x, p.z - arc.center.z); }

// How far along `s` (0 at `from`) the point `p` on it lies.
double positionAlong(const Segment& s, Point p) {
  if (!s.isArc()) return distance(s.from, p);
  return offsetAlongArc(s, angleAround(s, p)).value_or(std::abs(sweep(s)));
}

// Where the contour-parallel cleanup stops on `s`: where the profile reaches the previous level
// `upper` (after its start), or where it starts to turn back down (an undercut begins) unless
// `throughDescents` (in the front stretch, frontStretchEnd, and on a pocket's own profile).
std::optional<Point> cleanupStopOn(const Segment& s, double upper, bool throughDescents) {
  std::optional<Point> first;  // the stop first along `s` (of equally far ones, the first found)
  const auto stop = [&](Point p) {
    if (!first || positionAlong(s, p) < positionAlong(s, *first)) first = p;
  };
  for (const Point& p : intersectWithLevelX(s, upper)) {
    if (distance(p, s.from) > kGeomEps) stop(p);
  }
  if (const auto descent = throughDescents ? std::nullopt : descentStartOn(s)) stop(*descent);
  return first;
}

// The parts of `s` (the piece of profile element `i` a cleanup runs along, its end the element's), each
// with whether the cleanup goes through the profile's descents on it: up to `end` it does, beyond it
// not — within the element where `end` lies too (an allowance rounding rising to the front stretch's
// level and falling on from there: before, the main pass went on down its far side, fuzz seed
// 15261219683670512766).
// At most two parts, kept in place: the cleanup asks for them on every element it runs along.
struct PartsThroughDescents {
  std::array<std::pair<Segment, bool>, 2> parts;
  std::size_t count = 1;
  auto begin() const { return parts.begin(); }
  auto end() const { return parts.begin() + count; }
};

PartsThroughDescents partsThroughDescents(const Segment& element, const Segment& s, std::size_t i,
                                          const std::optional<ProfilePoint>& end) {
  if (!end || i > end->segment) return {{{{s, false}}}};
  if (i < end->segment) return {{{{s, true}}}};
  const double at = positionAlong(element, end->at), from = positionAlong(element, s.from);
  if (at <= from + kGeomEps) return {{{{s, false}}}};
  if (at >= positionAlong(element, s.to) - kGeomEps) return {{{{s, true}}}};
  return {{{{portionOf(s, s.from, end->at), true}, {portionOf(s, end->at, s.to), false}}}, 2};
}

// The contour-parallel cleanup (LCYC95.ROUGH "G1/G2/G3 along contour + allowance to its last
// point"; CYCLE95.ROUGH "up to the last point of intersection"), interpretation: from the roughing
// intersection forwards along the profile until it reaches the previous level (the last point the
// previous pass cut), turns back towards the depth axis (an undercut), or ends. A level that meets
// the profile at an element's end goes on along the next element; a stop at an element's start
// leaves nothing on it (no piece without length: an arc's would read as a full circle).
// Up to the point `throughDescentsUpTo`, when given (the front stretch's end; a pocket's end), the
// cleanup goes on through the profile's descents.
std::vector<Segment> cleanupAlongProfile(const std::vector<Segment>& profile, const ProfilePoint& hit, double upper,
                                         std::optional<ProfilePoint> throughDescentsUpTo = std::nullopt) {
  std::vector<Segment> pieces;
  pieces.reserve(profile.size() - hit.segment + 1);  // a piece per element, two on the stretch's end
  for (std::size_t i = hit.segment; i < profile.size(); ++i) {
    const Segment s = i == hit.segment ? portionOf(profile[i], hit.at, profile[i].to) : profile[i];
    if (hasNoLength(s)) continue;  // the hit is this element's end
    for (const auto& [part, throughDescents] : partsThroughDescents(profile[i], s, i, throughDescentsUpTo)) {
      if (hasNoLength(part)) continue;
      if (const auto stop = cleanupStopOn(part, upper, throughDescents)) {
        const Segment piece = portionOf(part, part.from, *stop);
        if (!hasNoLength(piece)) pieces.push_back(piece);
        return pieces;
      }
      pieces.push_back(part);
      if (part.to.x >= upper - kGeomEps) return pieces;
    }
  }
  return pieces;
}

// The first point of `path` (in its direction) at or below `level`: its start when that stands no
// higher, else where it first comes down to the level; nothing when it never does.
std::optional<ProfilePoint> firstAtOrBelow(const std::vector<Segment>& path, double level) {
  if (path.empty()) return std::nullopt;
  if (path.front().from.x <= level + kGeomEps) return ProfilePoint{0, path.front().from};
  for (std::size_t i = 0; i < path.size(); ++i) {
    std::optional<Point> first;
    for (const Point& p : intersectWithLevelX(path[i], level)) {
      if (!first || positionAlong(path[i], p) < positionAlong(path[i], *first)) first = p;
    }
    if (first) return ProfilePoint{i, *first};
  }
  return std::nullopt;
}

// The part of `path` from `a` to `b` (points on it, in its order), without pieces of no length.
std::vector<Segment> pathBetween(const std::vector<Segment>& path, const ProfilePoint& a, const ProfilePoint& b) {
  std::vector<Segment> pieces;
  for (std::size_t i = a.segment; i <= b.segment && i < path.size(); ++i) {
    const Segment piece = portionOf(path[i], i == a.segment ? a.at : path[i].from, i == b.segment ? b.at : path[i].to);
    if (!hasNoLength(piece)) pieces.push_back(piece);
  }
  return pieces;
}

// The front stretch (CYCLE95.UNDERCUT note, interpretation): where the profile falls from its
// first point — a wall falling down the part's face, a slope, an arc leaving it downwards — the
// stretch from there to where the profile first rises back to the lowest level strictly above that
// point is no undercut (findUndercuts passes over it): nothing stands before it, and the main
// passes reach it along their levels from the start side. Their cleanup goes through the stretch's
// descents up to the previous level. Where the stretch ends (its element and point), or nothing when the
// profile does not fall from its first point (or never rises back).
std::optional<ProfilePoint> frontStretchEnd(const std::vector<Segment>& profile, const std::vector<double>& levels) {
  const Point first = profile.front().from;
  const auto descent = descentStartOn(profile.front());
  if (!descent || distance(*descent, first) > kGeomEps) return std::nullopt;
  const double top = lowestLevelAbove(levels, first.x);
  for (std::size_t i = 0; i < profile.size(); ++i) {
    for (const Point& p : intersectWithLevelX(profile[i], top)) {
      if (distance(p, first) > kGeomEps) return ProfilePoint{i, p};
    }
  }
  return ProfilePoint{profile.size() - 1, profile.back().to};
}

// Where a pocket pass standing at `at` at its level next meets the pocket's profile along the level
// (towards −z): where the profile rises from `at` itself — a bump inside the pocket beginning where
// the falling side reaches the level —, at `at` (before, the pass crossed at the level under that
// bump: no-gouge, fuzz seed 15931212366711559875); else the first point strictly beyond it (on the
// falling side the pass came down: no crossing of its own).
std::optional<ProfilePoint> nextMeetingAlongTheLevel(const std::vector<Segment>& pocket, double level, Point at) {
  for (std::size_t i = 0; i < pocket.size(); ++i) {
    if (distance(pocket[i].from, at) <= kGeomEps && unitTangentAtStart(pocket[i]).x > 1e-9) return ProfilePoint{i, at};
  }
  constexpr double kBeyond = 1e-7;
  return roughingIntersection(pocket, level, at.z - kBeyond);
}

// Whether the pieces run straight along the depth axis (a wall): a plunge down them is one G1.
bool isWall(const std::vector<Segment>& pieces) {
  return std::all_of(pieces.begin(), pieces.end(),
                     [](const Segment& s) { return !s.isArc() && std::abs(s.to.z - s.from.z) <= kGeomEps; });
}

// Whether the profile stands above the retract from `p` by `v` in each axis (the diagonal towards +z
// and +x): the part lies in its way — a pocket's falling side closer than `v` in front of the pass's
// end, standing higher than the diagonal there (CYCLE95.UNDERCUT note, interpretation). The
// highest the profile stands above the diagonal within z ∈ (p.z, p.z + v] is at an element's end,
// where it crosses z = p.z + v, or where an arc runs parallel to the diagonal.
bool diagonalRetractRunsIntoThePart(const std::vector<Segment>& profile, Point p, double v) {
  const auto above = [&](Point q) {
    return q.z > p.z + kGeomEps && q.z <= p.z + v + kGeomEps && q.x > p.x + (q.z - p.z) + kGeomEps;
  };
  constexpr double h = 1 / std::numbers::sqrt2;
  // The directions from an arc's centre to where it runs parallel to the diagonal, and their angles.
  static const Point kNormals[] = {Point{h, -h}, Point{-h, h}};
  static const double kNormalAngles[] = {std::atan2(kNormals[0].x, kNormals[0].z),
                                         std::atan2(kNormals[1].x, kNormals[1].z)};
  for (const Segment& s : profile) {
    // Most elements lie outside the window or below p (the pass has just cut there): a box around
    // the element (an arc's whole circle: enclosingExtent) rules them out before anything is computed.
    const Extent box = enclosingExtent(s);
    if (box.zMax <= p.z + kGeomEps || box.zMin > p.z + v + kGeomEps || box.xMax <= p.x + kGeomEps) continue;
    if (above(s.from) || above(s.to)) return true;
    for (const Point& t : intersectWithLevelX(transposed(s), p.z + v)) {
      if (above(transposed(t))) return true;
    }
    if (s.isArc()) {
      const ArcAngles angles(s);
      const double r = s.radius();
      for (int k = 0; k < 2; ++k) {
        if (offsetAlongArc(angles, kNormalAngles[k]) && above(s.center + r * kNormals[k])) return true;
      }
    }
  }
  return false;
}

// The computed start (LCYC95.START, interpretation) lies the clearance beyond the part's face too:
// where the allowance moves the profile's start behind the contour's first point (a first element
// falling away from the front, offset contour-parallel), the face still stands at that point's z,
// and a start the clearance beyond the profile alone stood over the part: the straight infeed from it
// ran into the allowance (before, the infeed ran back along the cut axis to the face; fuzz seed
// 17617655989876150606).
Point startBeyondTheFace(const StockRemoval& c, const Extent& profile) {
  Point start = startBeyond(profile, c.clearance);
  start.z = std::max(start.z, c.contourFront.z + c.clearance.z);
  return start;
}

class StockRemovalPlanner {
 public:
  StockRemovalPlanner(const StockRemoval& c, Point position)
      : c_(c), position_(position), profileExtent_(extentOf(c.profile)), start_(startBeyondTheFace(c, profileExtent_)) {}

  std::vector<Move> plan() {
    if (c_.technology != SiemensTechnology::Finishing) rough();
    if (c_.technology != SiemensTechnology::Roughing) finish();
    return std::move(moves_);
  }

 private:
  Point current() const { return moves_.empty() ? position_ : moves_.back().to; }

  // `rules`: the rule IDs the move cites, each copied once into it (a braced list of strings would
  // be copied twice: into the list, then into the move).
  void emit(MoveKind kind, Point to, double feed, MovePhase phase, int pass, std::initializer_list<std::string_view> rules) {
    if (distance(current(), to) <= kGeomEps) return;  // zero-length moves are never emitted
    Move& m = push();
    m.kind = kind;
    m.to = to;
    if (kind == MoveKind::Feed) m.feed = feed;
    stampPhase(m, phase, pass);
    m.rules.assign(rules.begin(), rules.end());
  }

  // A piece of the profile or of the finishing path; one without length is never emitted (an arc
  // whose ends coincide would be read as a full circle by a controller).
  void emitAlong(const Segment& s, double feed, MovePhase phase, int pass, const std::string& rule) {
    if (hasNoLength(s)) return;
    if (!s.isArc()) return emit(MoveKind::Feed, s.to, feed, phase, pass, {rule});
    Move& m = push();
    m.kind = MoveKind::Feed;
    m.shape = s.kind;
    m.to = s.to;
    m.center = s.center;
    m.feed = feed;
    stampPhase(m, phase, pass);
    m.rules.assign(1, rule);
  }

  // PROG.CAP.MOVES for one cycle (roughing_cycle.h): a tiny DAM or MID over a long contour could
  // otherwise make millions of moves. The new move, at the plan's end, is filled in place.
  Move& push() {
    if (moves_.size() >= kMostCycleMoves) {
      throw NotSupported(c_.line, "the stock-removal cycle would make more than " +
                                      countText(kMostCycleMoves) +
                                      " moves (DAM or the infeed depth too small for the contour)");
    }
    return moves_.emplace_back();
  }

  // --- roughing (LCYC95.ROUGH, CYCLE95.ROUGH) ---

  void rough() {
    const double top = start_.x - c_.clearance.x;
    const std::vector<double> levels = c_.mainLevels(top, profileExtent_.xMin, c_.maxInfeed, c_.line);
    // PROG.CAP.WORK: each level meets the profile.
    requireWorkWithinTheCap(
        "the stock-removal cycle", static_cast<double>(levels.size() - 1), c_.profile.size(),
        [&] { return " (infeed of at most " + shortDecimalText(c_.maxInfeed) + " mm)"; }, c_.line);
    frontStretchEnd_ = frontStretchEnd(c_.profile, levels);
    approachStart();
    const int count = static_cast<int>(levels.size()) - 1;
    for (int k = 1; k <= count; ++k) {
      roughingPass(k, levels[k], levels[k - 1]);
      if (k < count) backAlongCutAxis(k);
    }
    if (c_.roughUndercuts) {
      int pass = count;
      for (const Undercut& u : findUndercuts(c_.profile, levels)) roughUndercut(u, pass);
    }
    if (c_.technology == SiemensTechnology::Roughing) returnToStart();
  }

  // G0 to the computed start with both axes together.
  void approachStart() {
    emit(MoveKind::Rapid, start_, 0, MovePhase::Approach, 0, {c_.rules.rough, c_.rules.start});
  }

  // The part's front (LCYC95.ROUGH, interpretation): below the contour's first point the part's face
  // stands at that point's z. The profile leaves that z at the end of the walls the contour begins
  // with there (the first point itself without them): `foot`, with the element that starts there.
  // Where one of those walls falls, the face stands up to the foot (its `top`), and the walls above
  // it stand in stock on both sides: falling down the face, or rising and falling back along
  // themselves (before issue 16 the top was the walls' lowest point, and a level between it and the
  // foot met a rising wall the profile then falls back along: the pocket behind it stayed, fuzz seed
  // 12927597250111814412). Walls that only rise are the part's own front, which a level meets as it
  // meets the profile: the face stands up to the first point. A level below the top meets the part
  // at the face: the pass stops there (what lies behind the face, below the contour's start, is an
  // undercut, CYCLE95.UNDERCUT).
  struct FrontFace {
    double top = 0;
    ProfilePoint foot;
    double wallsInStockAbove = std::numeric_limits<double>::infinity();  // the top where a wall falls
  };
  FrontFace frontFace() const {
    const double frontZ = c_.profile.front().from.z;
    FrontFace face{c_.profile.front().from.x, {0, c_.profile.front().from}};
    bool falls = false;
    while (face.foot.segment < c_.profile.size()) {
      const Segment& s = c_.profile[face.foot.segment];
      if (s.isArc() || std::abs(s.to.z - frontZ) > kGeomEps) break;
      falls = falls || s.to.x < s.from.x - kGeomEps;
      face.foot = {face.foot.segment + 1, s.to};
    }
    if (falls) face.top = face.wallsInStockAbove = face.foot.at.x;
    return face;
  }

  // The z the part's face stands at: the profile's first point's, or the contour's own where the
  // allowance moved the profile's start behind it (a first element falling away from the front: its
  // offset's start lies at −z of the contour's).
  double faceZ() const { return std::max(c_.profile.front().from.z, c_.contourFront.z); }

  void roughingPass(int k, double level, double previous) {
    const FrontFace face = frontFace();
    const bool meetsTheFace = level < face.top - kGeomEps;
    const auto hit = meetsTheFace ? std::nullopt : roughingIntersection(c_.profile, level, start_.z, face.foot.segment, face.wallsInStockAbove);
    const double hitZ = meetsTheFace ? faceZ() : hit ? hit->at.z : c_.profile.back().to.z;
    infeed(k, level, hitZ);
    cutToIntersection(k, {hitZ, level});
    if (hit) cleanUpAlongProfile(k, *hit, previous);
    if (meetsTheFace) cleanUpFromTheFace(k, face.foot, previous);
    climbOffASteepEnd(k, previous, c_.roughingFeed, c_.rules.rough);
    retract(k);
  }

  void cleanUpAlongProfile(int k, const ProfilePoint& from, double previous) {
    for (const Segment& s : cleanupAlongProfile(c_.profile, from, previous, frontStretchEnd_)) {
      emitAlong(s, c_.roughingFeed, MovePhase::Pass, k, c_.rules.rough);
    }
  }

  // A level that met the part's face (interpretation, LCYC95.ROUGH): where the profile leaves the
  // face below the previous level, the pass goes on up the face (G1) to that foot and along the
  // profile up to the previous level, as a level that meets the profile does — else the band
  // between the two levels above the profile beyond the face stays standing. Through the front
  // stretch's descents too: where the profile falls from its first point, the band between the
  // face's top and the previous level over the stretch is reached by no other pass.
  void cleanUpFromTheFace(int k, const ProfilePoint& foot, double previous) {
    if (foot.segment >= c_.profile.size() || foot.at.x >= previous - kGeomEps) return;
    // Where the profile's start lies behind the face: up the face to the contour's first point,
    // then across the allowance to the profile's start.
    if (foot.at.z < faceZ() - kGeomEps) {
      emit(MoveKind::Feed, {faceZ(), c_.contourFront.x}, c_.roughingFeed, MovePhase::Pass, k, {c_.rules.rough});
    }
    emit(MoveKind::Feed, foot.at, c_.roughingFeed, MovePhase::Pass, k, {c_.rules.rough});
    cleanUpAlongProfile(k, foot, previous);
  }

  // --- undercuts (CYCLE95.UNDERCUT), interpretation: after the axis-parallel passes, each pocket in
  // its own equal steps from the lowest level above its rim down to its lowest point, at FF2: G0 up
  // to the start's height (the first pocket pass) or along the cut axis at the retract height to
  // above where the previous level meets the pocket's falling side (the rim, for the first pass),
  // G1 straight down to it, along the falling side down to the level ("a cut parallel to the
  // contour to remove the remaining ridges": a plunge beside a sloping side would leave a ridge
  // above it), G1 across to the rising side, along the profile up to the previous level, retract in
  // each axis.

  void roughUndercut(const Undercut& u, int& pass) {
    emit(MoveKind::Rapid, {current().z, start_.x}, 0, MovePhase::Pass, pass + 1, {c_.rules.undercut});
    const std::vector<double> levels = equalInfeedLevels(u.top, u.bottom(), c_.maxInfeed, c_.line);
    for (std::size_t m = 1; m < levels.size(); ++m) undercutPass(u, ++pass, levels[m], levels[m - 1], m + 1 == levels.size());
  }

  // The pocket's falling side between the previous level and this one (empty without one).
  static std::vector<Segment> fallingSideBetween(const Undercut& u, double previous, double level, bool lowest) {
    if (u.down.empty()) return {};
    const auto upper = firstAtOrBelow(u.down, previous);
    const auto lower = lowest ? std::optional<ProfilePoint>{ProfilePoint{u.down.size() - 1, u.down.back().to}}
                              : firstAtOrBelow(u.down, level);
    if (!upper || !lower) return {};
    return pathBetween(u.down, *upper, *lower);
  }

  // The pocket's profile from its rim to its end: the falling side, then the rising side.
  static std::vector<Segment> piecesOf(const Undercut& u) {
    std::vector<Segment> pieces = u.down;
    pieces.insert(pieces.end(), u.up.begin(), u.up.end());
    return pieces;
  }

  void undercutPass(const Undercut& u, int k, double level, double previous, bool lowest) {
    const Point lowPoint = u.up.empty() ? u.down.back().to : u.up.front().from;
    const auto in = lowest ? std::nullopt : roughingIntersection(u.down, level, std::numeric_limits<double>::infinity());
    const std::string& rule = c_.rules.undercut;
    const std::vector<Segment> side = fallingSideBetween(u, previous, level, lowest);
    if (side.empty() || isWall(side)) {
      // A level at or above the rim (the pocket's top stands above it) crosses over from the rim —
      // where the level first meets the pocket's profile is then no falling side's point, but may
      // be a bump's rising side further on (before, the pass went down there and crossed at the
      // level under the bump: no-gouge, fuzz seed 5698905055672233322).
      const Point rim = u.down.empty() ? lowPoint : u.down.front().from;
      const double inZ = level >= rim.x - kGeomEps ? rim.z : in ? in->at.z : lowPoint.z;
      rapidAlongTheCutAxis(inZ, k, rule);
      emit(MoveKind::Feed, {inZ, level}, c_.undercutFeed, MovePhase::Pass, k, {rule});
    } else {
      rapidAlongTheCutAxis(side.front().from.z, k, rule);
      emit(MoveKind::Feed, side.front().from, c_.undercutFeed, MovePhase::Pass, k, {rule});
      for (const Segment& s : side) emitAlong(s, c_.undercutFeed, MovePhase::Pass, k, rule);
    }
    // Across at the level to where it next meets the pocket's profile — the rising side, or a bump
    // inside the pocket standing above the level —, then along the profile through its descents (the
    // bump's far side, a groove inside the pocket, a wall returning along itself) up to the previous
    // level. The lowest pass is at the lowest point already.
    const std::vector<Segment> pocket = piecesOf(u);
    const auto across = lowest ? std::optional<ProfilePoint>{ProfilePoint{u.down.size(), lowPoint}}
                               : nextMeetingAlongTheLevel(pocket, level, current());
    // (A pocket open to the profile's end has no rising side, but may hold a bump the level meets.)
    if (across) {
      cutAlongLevel(k, across->at, c_.undercutFeed, rule);
      for (const Segment& s : cleanupAlongProfile(pocket, *across, previous, ProfilePoint{pocket.size() - 1, pocket.back().to})) {
        emitAlong(s, c_.undercutFeed, MovePhase::Pass, k, rule);
      }
    } else {  // the pocket stays open to the profile's end
      const Point end = u.up.empty() ? lowPoint : u.up.back().to;
      cutAlongLevel(k, {end.z, level}, c_.undercutFeed, rule);
    }
    climbOffASteepEnd(k, u.top, c_.undercutFeed, rule);  // the pocket's profile stands below its top
    emit(MoveKind::Rapid, retractPoint(), 0, MovePhase::Pass, k, {rule});
  }

  // G0 along the cut axis to `z` at the current height, between a pocket's passes: where the profile
  // stands above that height in between (a bump inside the pocket the last pass went over, at a
  // retract height below its top), G0 up to the start's height first (interpretation,
  // CYCLE95.UNDERCUT note; before, the rapid ran through the bump: no-gouge, fuzz seed
  // 14727398570297873640).
  void rapidAlongTheCutAxis(double z, int k, const std::string& rule) {
    const double low = std::min(z, current().z) + kGeomEps, high = std::max(z, current().z) - kGeomEps;
    const double height = current().x;
    const auto between = [&](Point p) { return p.z > low && p.z < high; };
    const bool crosses = std::any_of(c_.profile.begin(), c_.profile.end(), [&](const Segment& s) {
      const auto hits = intersectWithLevelX(s, height);
      const bool endAbove = (between(s.from) && s.from.x > height + kGeomEps) || (between(s.to) && s.to.x > height + kGeomEps);
      return endAbove || std::any_of(hits.begin(), hits.end(), between);
    });
    if (crosses) emit(MoveKind::Rapid, {current().z, start_.x}, 0, MovePhase::Pass, k, {rule});
    emit(MoveKind::Rapid, {z, current().x}, 0, MovePhase::Pass, k, {rule});
  }

  // A pass that ends at the profile's last z, below `height`, where the profile arrives falling more
  // steeply than 45° (towards −z): the retract by the clearance in each axis would run back into the
  // part across that last element. The pass first climbs with G1 along the depth axis at the end's
  // z — beyond the profile, where no part stands — to `height` (the previous level for a main pass,
  // the pocket's top for a pocket pass), above the profile there (interpretation, LCYC95.ROUGH and
  // CYCLE95.UNDERCUT notes).
  void climbOffASteepEnd(int k, double height, double feed, const std::string& rule) {
    const Point end = c_.profile.back().to;
    if (std::abs(current().z - end.z) > kGeomEps || current().x >= height - kGeomEps) return;
    const Point t = unitTangentAtEnd(c_.profile.back());
    if (!(t.x < 0 && -t.x > std::abs(t.z) + 1e-9)) return;
    emit(MoveKind::Feed, {end.z, height}, feed, MovePhase::Pass, k, {rule});
  }

  // Infeed to the level at the infeed angle (R109, from the infeed axis), never beyond the
  // roughing intersection.
  void infeed(int k, double level, double hitZ) {
    const Point from = current();
    const double run = (from.x - level) * std::tan(c_.infeedAngle * std::numbers::pi / 180);
    const Point to{std::max(from.z - run, hitZ), level};
    emit(c_.infeedKind, to, c_.roughingFeed, MovePhase::Pass, k, {c_.rules.rough, c_.rules.depth});
  }

  // G1 parallel to the cut axis to the roughing intersection.
  void cutToIntersection(int k, Point to) { cutAlongLevel(k, to, c_.roughingFeed, c_.rules.rough); }

  // G1 along the level to `to`; with DAM, in pieces of that length, the tool dwelling DT at each
  // interruption (CYCLE95.DAM: every roughing step, a pocket's too).
  void cutAlongLevel(int k, Point to, double feed, const std::string& rule) {
    if (c_.interruptLength > 0 && std::abs(current().x - to.x) <= kGeomEps) {
      while (current().z - to.z > c_.interruptLength + kGeomEps) {
        emit(MoveKind::Feed, {current().z - c_.interruptLength, to.x}, feed, MovePhase::Pass, k, {rule, c_.rules.interrupt});
        if (c_.dwell > 0) moves_.back().dwell = c_.dwell;
      }
    }
    emit(MoveKind::Feed, to, feed, MovePhase::Pass, k, {rule});
  }

  // Retract by the clearance in each axis (R110 / _VRT), with G0.
  void retract(int k) { emit(MoveKind::Rapid, retractPoint(), 0, MovePhase::Pass, k, {c_.rules.rough}); }

  // Where the retract goes: the clearance in each axis; where the part stands in the way of that
  // diagonal (a pocket narrower than the clearance in front of the pass's end), the clearance along
  // the depth axis only — the profile lies below the tool there, so nothing stands above it
  // (interpretation, CYCLE95.UNDERCUT note; before, the retract ran into the pocket's falling side:
  // no-gouge, fuzz seed 7566792160692496541).
  Point retractPoint() const {
    if (diagonalRetractRunsIntoThePart(c_.profile, current(), c_.clearance.z)) return current() + Point{0, c_.clearance.x};
    return current() + c_.clearance;
  }

  // G0 back along the cut axis to the start's z, at the retract height.
  void backAlongCutAxis(int k) {
    emit(MoveKind::Rapid, {start_.z, current().x}, 0, MovePhase::Pass, k, {c_.rules.rough});
  }

  // After the last roughing pass (roughing only; complete machining goes on to finishing without it,
  // LCYC95.COMPLETE): LCYC95 both axes together, CYCLE95 one after the other, the infeed axis first.
  void returnToStart() {
    if (c_.axesReturnOneAfterTheOther) {
      emit(MoveKind::Rapid, {current().z, start_.x}, 0, MovePhase::Return, 0, {c_.rules.rough});
    }
    emit(MoveKind::Rapid, start_, 0, MovePhase::Return, 0, {c_.rules.rough});
  }

  // --- finishing (LCYC95.FINISH) ---

  void finish() {
    // G0 to the cycle start axis by axis, the infeed axis first (citing complete machining's rule too).
    const auto approach = [this](Point to) {
      if (c_.technology != SiemensTechnology::Complete) return emit(MoveKind::Rapid, to, 0, MovePhase::Approach, 0, {c_.rules.finish});
      emit(MoveKind::Rapid, to, 0, MovePhase::Approach, 0, {c_.rules.finish, c_.rules.complete});
    };
    approach({current().z, start_.x});
    approach(start_);
    // G0 both axes to the contour start; along the contour at the finishing feed; G0 back.
    emit(MoveKind::Rapid, c_.finishPath.front().from, 0, MovePhase::Finish, 0, {c_.rules.finish});
    for (const Segment& s : c_.finishPath) emitAlong(s, c_.finishingFeed, MovePhase::Finish, 0, c_.rules.finish);
    emit(MoveKind::Rapid, start_, 0, MovePhase::Return, 0, {c_.rules.finish});
  }

  const StockRemoval& c_;
  Point position_;
  const Extent profileExtent_;  // of c_.profile
  Point start_;
  std::optional<ProfilePoint> frontStretchEnd_;  // set by rough()
  std::vector<Move> moves_;
};

}  // namespace

std::vector<Move> planStockRemoval(const StockRemoval& cycle, Point position) {
  return StockRemovalPlanner(cycle, position).plan();
}

}  // namespace cyclecert
