// The fuzzer's SINUMERIK cases (siemens_case_generator.h says what is drawn).
//
// A contour is drawn as a list of pieces in the stock-removal frame of reference/siemens (cut along
// z towards −z, the stock above, towards +x): every machining type is drawn as longitudinal
// external and then placed in the plane as the type's frame maps it back (face exchanges z and x,
// internal mirrors the depth axis), so that the contour is programmed in the finishing direction
// for its type. Offsets keep every radius ≥ 0 (longitudinal: ≥ 1 mm) and, for internal work, the
// cycle's start and the program's start inside the bore.
#include "harness/fuzz/siemens_case_generator.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "harness/fuzz/generator_parts.h"
#include "harness/fuzz/named_choices.h"
#include "reference/siemens/siemens_cycles.h"

namespace cyclecert {

namespace {


// --- what is drawn ---

// The thirteen choices 0…9 a SINUMERIK case draws first (field by field in the order drawn), by the
// decision each makes.
struct SiemensChoices {
  int cycle;           // CYCLE95 when odd (when the run asks for both cycles)
  int fault;           // one invalid parameter when 9 (one case in ten)
  int whichFault;      // which (mod 4: kFaults)
  int noAllowance;     // no R106 / FAL when < 4
  int axisAllowances;  // CYCLE95: FALZ when 6 or 7, FALX when 8, both when 9
  int sameFeeds;       // FF2 = FF1 when 0 (the boundary where an undercut's feed does not show)
  int infeedAngle;     // LCYC95: R109 kAngles[choice − 6] when ≥ 6, else 0
  int interrupt;       // CYCLE95: DAM when ≥ 7
  int dwell;           // CYCLE95: DT when ≥ 7
  int compact;         // the contour written without spaces when < 3
  int badType;         // the fault MachiningType: 0 when even, 13 when odd
  int reversedStart;   // the contour's first block in G0 (else G1) when 9 (either starts it)
  int centreWords;     // quarter arcs with I/K rather than CR= when odd
};

SiemensChoices siemensChoicesFrom(const std::vector<int>& drawn) {
  const auto at = [&](std::size_t i) { return choiceAt(drawn, i); };
  return {at(0), at(1), at(2), at(3), at(4), at(5), at(6), at(7), at(8), at(9), at(10), at(11), at(12)};
}
constexpr std::size_t kSiemensChoices = 13;

// A piece of contour as drawn, before it is expanded into SiemensSegments: the shapes of
// SiemensSegment, and a groove (down, along the bottom, up: CYCLE95's relief cut).
struct DrawnPiece {
  int shape = 0;  // 0 line, 1 chamfer 45°, 2 convex quarter, 3 concave quarter, 4 flat, 5 step, 6/7 shallow arcs, 8 groove
  int along = 0, up = 0;
  int corner = 0;  // CHF= when 6, CHR= when 7, RND= when 8 or 9 (where a corner can be inserted)
  int cornerSize = 0;
};

rc::Gen<DrawnPiece> genDrawnPiece() {
  return rc::gen::apply(
      [](int shape, int along, int up, int corner, int cornerSize) { return DrawnPiece{shape, along, up, corner, cornerSize}; },
      rc::gen::weightedElement<int>({{6, 0}, {3, 1}, {3, 2}, {3, 3}, {3, 4}, {3, 5}, {2, 6}, {2, 7}, {2, 8}}),
      rc::gen::inRange(10, 600), rc::gen::inRange(10, 300), wholeRange(0, 10), rc::gen::inRange(10, 200));
}

struct SiemensDraws {
  SiemensChoices choice;
  std::vector<DrawnPiece> pieces;
  std::vector<int> downs;  // CYCLE95: which lines turn back towards the axis (mod 4 = 0)
  int type, base, allowance, allowanceZ, allowanceX, maxInfeed, retract, ff1, ff2, ff3, dwell, dam, startClear, halfCircle;
  int onlyCycle;  // 1 LCYC95, 2 CYCLE95 when the run asks for one only (not drawn: chosen); 0 both
};

// The smallest radius a concave arc (and a groove's width or depth) keeps, so that the finishing
// allowance offsets it without the arc vanishing (10931, an allowance the contour cannot take).
int roomForTheAllowance(const SiemensFuzzCase& s) { return s.allowance + std::max(s.allowanceZ, s.allowanceX) + 50; }

// CYCLE95: lines turned back towards the axis (undercuts), one line in four.
void turnLinesBack(std::vector<DrawnPiece>& pieces, const std::vector<int>& downs) {
  for (std::size_t i = 0; i < pieces.size() && i < downs.size(); ++i) {
    DrawnPiece& p = pieces[i];
    if (downs[i] % 4 == 0 && (p.shape == 0 || p.shape == 1)) p.up = -(p.shape == 1 ? p.along : p.up), p.shape = 0;
  }
}

// The drawn pieces as segments: a groove becomes three lines (CYCLE95; LCYC95 leaves undercuts to
// finishing, so its grooves are drawn flat); concave arcs and grooves keep room for the allowance.
std::vector<SiemensSegment> expandPieces(const std::vector<DrawnPiece>& pieces, const SiemensFuzzCase& s) {
  using S = SiemensSegment;
  const int room = roomForTheAllowance(s);
  std::vector<SiemensSegment> segments;
  for (const DrawnPiece& p : pieces) {
    const int a = p.along;
    switch (p.shape) {
      case 0: segments.push_back({S::Line, a, p.up}); break;
      case 1: segments.push_back({S::Line, a, a}); break;
      case 2: segments.push_back({S::ConvexQuarter, a, a}); break;
      case 3: segments.push_back({S::ConcaveQuarter, std::max(a, room), std::max(a, room)}); break;
      case 4: segments.push_back({S::Line, a, 0}); break;
      case 5: segments.push_back({S::Line, 0, p.up}); break;
      case 6: segments.push_back({S::ConvexShallow, a, a}); break;
      case 7: segments.push_back({S::ConcaveShallow, std::max(a, room), std::max(a, room)}); break;
      default:
        if (!s.cycle95) {
          segments.push_back({S::Line, a, 0});
          break;
        }
        segments.push_back({S::Line, 0, -std::max(p.up, room)});
        segments.push_back({S::Line, std::max(a, 2 * room), 0});
        segments.push_back({S::Line, 0, std::max(p.up, room)});
    }
    segments.back().corner = static_cast<S::Corner>(p.corner < 6 ? 0 : p.corner == 6 ? 1 : p.corner == 7 ? 2 : 3);
    segments.back().cornerSize = p.cornerSize;
  }
  return segments;
}

double lengthOf(const SiemensSegment& s) { return std::hypot(double(s.along), double(s.up)); }

// With a finishing allowance the offset of a line shrinks at a concave corner by up to
// allowance·tan(turn/2) at each end — 2.4 times the allowance where a line turning back meets a
// step up (135°) —, and the reference alarms (10931) where an offset piece vanishes: every line is
// drawn at least six allowances long (lengthened along the axes it moves on).
void longEnoughForTheAllowance(SiemensFuzzCase& s) {
  if (s.allowance == 0) return;
  const int least = 6 * s.allowance + 20;
  for (SiemensSegment& g : s.segments) {
    if (g.kind != SiemensSegment::Line || lengthOf(g) >= least) continue;
    if (g.along > 0) g.along = std::max(g.along, least);
    if (g.up != 0) g.up = g.up < 0 ? std::min(g.up, -least) : std::max(g.up, least);
  }
}

// The direction (radians from +z towards +x, in the frame) in which element `g` leaves its start
// (`atEnd` false) or arrives at its end. A line runs along (−along, up); a convex quarter leaves
// upwards and arrives along −z, a concave one the other way round; a shallow arc (radius 2·along
// over the chord (−along, along): a sweep of 2·asin(√2/4)) turns by half its sweep either side of
// the chord's 135°, convex (G3 in the frame) to the left, concave to the right.
double directionOf(const SiemensSegment& g, bool atEnd) {
  const double half = std::asin(std::sqrt(2.0) / 4);
  constexpr double pi = std::numbers::pi;
  const double chord = 0.75 * pi;
  switch (g.kind) {
    case SiemensSegment::Line: return std::atan2(double(g.up), -double(g.along));
    case SiemensSegment::ConvexQuarter: return atEnd ? pi : pi / 2;
    case SiemensSegment::ConcaveQuarter: return atEnd ? pi / 2 : pi;
    case SiemensSegment::ConvexShallow: return atEnd ? chord + half : chord - half;
    case SiemensSegment::ConcaveShallow: return atEnd ? chord - half : chord + half;
    case SiemensSegment::HalfCircle: break;
  }
  return 0;
}

// The largest corner element `g` takes: a third of a line's length or of an arc's chord (a√2 for
// both arcs drawn over (−a, a)), and at most half an arc's radius (a rounding next to a concave arc
// stays well inside its circle).
double largestCornerOn(const SiemensSegment& g) {
  if (g.kind == SiemensSegment::Line) return lengthOf(g) / 3;
  const bool shallow = g.kind == SiemensSegment::ConvexShallow || g.kind == SiemensSegment::ConcaveShallow;
  const double radius = shallow ? 2.0 * g.along : g.along;
  return std::min(g.along * std::sqrt(2.0) / 3, radius / 2);
}

// Whether element `g` may carry a corner or be the element after one: a line going up (not turned
// back towards the axis) or an arc (SIEMENS.CORNER: between lines and arcs in any combination).
bool takesACorner(const SiemensSegment& g) {
  return g.kind == SiemensSegment::Line ? g.up >= 0 : g.kind != SiemensSegment::HalfCircle;
}

// A corner the controller can insert (CHF=, CHR=, RND=) between two elements — lines or arcs — that
// meet at an angle, both going up (a turn of at most 90°), each at least three times the corner's
// size (an arc: its chord, and the corner at most half its radius) and the corner large enough for
// the allowance to offset it. Elsewhere the drawn corner is dropped.
void keepInsertableCorners(SiemensFuzzCase& s) {
  for (std::size_t i = 0; i < s.segments.size(); ++i) {
    SiemensSegment& a = s.segments[i];
    if (a.corner == SiemensSegment::NoCorner) continue;
    const SiemensSegment* b = i + 1 < s.segments.size() ? &s.segments[i + 1] : nullptr;
    const bool both = b && takesACorner(a) && takesACorner(*b);
    const bool turn = both && std::abs(directionOf(a, true) - directionOf(*b, false)) > 1e-6;
    const int room = turn ? static_cast<int>(std::min(largestCornerOn(a), largestCornerOn(*b))) : 0;
    a.cornerSize = std::min(a.cornerSize, room);
    if (a.cornerSize < 2 * s.allowance + 20) a.corner = SiemensSegment::NoCorner, a.cornerSize = 0;
  }
}

// The contour: the drawn pieces (five hundredths along at least: a contour with no length towards
// −z has nothing to machine), undercuts for CYCLE95, corners where they fit.
void drawContour(SiemensFuzzCase& s, const SiemensDraws& d) {
  std::vector<DrawnPiece> pieces = d.pieces;
  if (pieces.size() > 8) pieces.resize(8);
  if (pieces.empty()) pieces.push_back({0, 500, 300, 0, 0});
  if (s.cycle95) turnLinesBack(pieces, d.downs);
  s.segments = expandPieces(pieces, s);
  if (std::all_of(s.segments.begin(), s.segments.end(), [](const SiemensSegment& g) { return g.along == 0; })) {
    s.segments.front().along = 100;
  }
  for (SiemensSegment& g : s.segments) g.centreWords = d.choice.centreWords % 2 == 1;
  longEnoughForTheAllowance(s);
  keepInsertableCorners(s);
}

void drawParameters(SiemensFuzzCase& s, const SiemensDraws& d) {
  s.base = d.base;
  s.allowance = d.choice.noAllowance < 4 ? 0 : d.allowance;
  if (s.cycle95) {
    s.allowanceZ = d.choice.axisAllowances == 6 || d.choice.axisAllowances == 7 || d.choice.axisAllowances == 9 ? d.allowanceZ : 0;
    s.allowanceX = d.choice.axisAllowances >= 8 ? d.allowanceX : 0;
  }
  s.maxInfeed = d.maxInfeed;
  static constexpr int kAngles[] = {5, 10, 30, 45};
  s.infeedAngle = !s.cycle95 && d.choice.infeedAngle >= 6 ? kAngles[d.choice.infeedAngle - 6] : 0;
  s.retract = d.retract;
  s.roughingFeed = d.ff1;
  s.undercutFeed = d.choice.sameFeeds == 0 ? d.ff1 : d.ff2;
  s.finishingFeed = d.ff3;
  s.dwell = s.cycle95 && d.choice.dwell >= 7 ? d.dwell : 0;
  s.interruptLength = s.cycle95 && d.choice.interrupt >= 7 ? d.dam : 0;
  s.startClear = d.startClear;
  s.compact = d.choice.compact < 3;
}

// One invalid parameter one case in ten (LCYC95.ALARMS).
void drawFault(SiemensFuzzCase& s, const SiemensDraws& d) {
  if (d.choice.fault != 9) return;
  static constexpr SiemensFault kFaults[] = {SiemensFault::MachiningType, SiemensFault::NoInfeedDepth,
                                             SiemensFault::AgainstDirection, SiemensFault::ArcOverQuarter};
  s.fault = kFaults[d.choice.whichFault % 4];
  switch (s.fault) {
    case SiemensFault::MachiningType: s.type = d.choice.badType % 2 == 0 ? 0 : 13; break;
    case SiemensFault::NoInfeedDepth:
      s.maxInfeed = 0;
      if (s.type >= 5 && s.type <= 8) s.type -= 4;  // finishing needs no infeed: the roughing type
      break;
    case SiemensFault::ArcOverQuarter:
      s.segments.push_back({SiemensSegment::HalfCircle, d.halfCircle, 0});
      s.segments.back().centreWords = true;
      break;
    case SiemensFault::AgainstDirection:
    case SiemensFault::None: break;
  }
}

FuzzCase siemensCaseFrom(const SiemensDraws& d) {
  FuzzCase c;
  c.cycle = 95;
  SiemensFuzzCase& s = c.siemens;
  s.cycle95 = d.onlyCycle ? d.onlyCycle == 2 : d.choice.cycle % 2 == 1;
  c.profile = s.cycle95 ? "sinumerik-802d" : "sinumerik-802s";
  s.type = d.type;
  drawParameters(s, d);
  drawContour(s, d);
  drawFault(s, d);
  return c;
}

bool asks(const FuzzCycles& cycles, FuzzCycle c) { return std::find(cycles.begin(), cycles.end(), c) != cycles.end(); }

}  // namespace

rc::Gen<FuzzCase> genSiemensCase(const FuzzCycles& cycles) {
  const bool lcyc95 = asks(cycles, FuzzCycle::Lcyc95), cycle95 = asks(cycles, FuzzCycle::Cycle95);
  const int onlyCycle = lcyc95 && cycle95 ? 0 : lcyc95 ? 1 : 2;
  return rc::gen::apply(
      [onlyCycle](const std::vector<int>& choice, std::vector<DrawnPiece> pieces, std::vector<int> downs, int type,
                  int base, int allowance, int allowanceZ, int allowanceX, int maxInfeed, int retract, int ff1, int ff2,
                  int ff3, int dwell, int dam, int startClear, int halfCircle) {
        return siemensCaseFrom({siemensChoicesFrom(choice), std::move(pieces), std::move(downs), type, base, allowance,
                                allowanceZ, allowanceX, maxInfeed, retract, ff1, ff2, ff3, dwell, dam, startClear,
                                halfCircle, onlyCycle});
      },
      rc::gen::container<std::vector<int>>(kSiemensChoices, wholeRange(0, 10)),  // SiemensChoices
      firstOf(8, genDrawnPiece()),          // the contour: 8 pieces at most
      firstOf(8, rc::gen::inRange(0, 99)),  // CYCLE95: which lines turn back
      wholeRange(1, 13),                    // R105 / VARI (shrinks to 1: longitudinal external roughing)
      rc::gen::inRange(100, 2000),          // the part's distance from the axis
      rc::gen::inRange(1, 50),              // R106 / FAL
      rc::gen::inRange(1, 50),              // FALZ
      rc::gen::inRange(1, 50),              // FALX
      rc::gen::inRange(50, 300),            // R108 / MID
      rc::gen::inRange(10, 200),            // R110 / _VRT
      rc::gen::inRange(10, 50),             // R111 / FF1
      rc::gen::inRange(5, 30),              // FF2
      rc::gen::inRange(5, 20),              // R112 / FF3
      rc::gen::inRange(1, 20),              // DT, tenths of a second
      rc::gen::inRange(100, 1500),          // DAM
      rc::gen::inRange(50, 500),            // the program's start beyond the cycle's
      rc::gen::inRange(50, 300));           // the fault's half circle: its radius
}

namespace {

// --- how it is written ---

// A piece of the contour in the frame, absolute (hundredths): a line or an arc with its centre.
struct ContourPiece {
  enum Kind { Line, Ccw, Cw } kind = Line;
  long fromZ = 0, fromX = 0, toZ = 0, toX = 0;
  long centreZ = 0, centreX = 0, radius = 0;
  bool centreWords = false;
  SiemensSegment::Corner corner = SiemensSegment::NoCorner;  // at its end, before the next piece
  int cornerSize = 0;
};

// The pieces from (0, 0), relative; then shifted by the placement.
std::vector<ContourPiece> piecesOf(const SiemensFuzzCase& s) {
  std::vector<ContourPiece> pieces;
  long z = 0, x = 0;
  for (const SiemensSegment& g : s.segments) {
    ContourPiece p;
    p.fromZ = z;
    p.fromX = x;
    const long a = g.along;
    p.toZ = z - (g.kind == SiemensSegment::HalfCircle ? 2 * a : a);
    p.toX = x + g.up;
    p.centreWords = g.centreWords;
    p.corner = g.corner;
    p.cornerSize = g.cornerSize;
    switch (g.kind) {
      case SiemensSegment::Line: break;
      case SiemensSegment::ConvexQuarter:
      case SiemensSegment::HalfCircle: p = {ContourPiece::Ccw, z, x, p.toZ, p.toX, z - a, x, a, p.centreWords, p.corner, p.cornerSize}; break;
      case SiemensSegment::ConcaveQuarter: p = {ContourPiece::Cw, z, x, p.toZ, p.toX, z, x + a, a, p.centreWords, p.corner, p.cornerSize}; break;
      case SiemensSegment::ConvexShallow: p = {ContourPiece::Ccw, z, x, p.toZ, p.toX, 0, 0, 2 * a, false, p.corner, p.cornerSize}; break;
      case SiemensSegment::ConcaveShallow: p = {ContourPiece::Cw, z, x, p.toZ, p.toX, 0, 0, 2 * a, false, p.corner, p.cornerSize}; break;
    }
    pieces.push_back(p);
    z = p.toZ;
    x = p.toX;
  }
  return pieces;
}

// The contour against the finishing direction (SiemensFault::AgainstDirection): its pieces in the
// reverse order, each run backwards, a corner kept between the same two lines.
std::vector<ContourPiece> reversed(std::vector<ContourPiece> pieces) {
  std::reverse(pieces.begin(), pieces.end());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    ContourPiece& p = pieces[i];
    std::swap(p.fromZ, p.toZ);
    std::swap(p.fromX, p.toX);
    if (p.kind != ContourPiece::Line) p.kind = p.kind == ContourPiece::Ccw ? ContourPiece::Cw : ContourPiece::Ccw;
  }
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    pieces[i].corner = pieces[i + 1].corner;
    pieces[i].cornerSize = pieces[i + 1].cornerSize;
  }
  if (!pieces.empty()) pieces.back().corner = SiemensSegment::NoCorner;
  return pieces;
}

MachiningType placedType(const SiemensFuzzCase& s) { return machiningTypeOf(s.type).value_or(MachiningType{}); }

// How far beyond the contour the cycle's start and then the program's start lie, in each axis.
long startClearance(const SiemensFuzzCase& s) {
  return s.retract + s.allowance + s.allowanceZ + s.allowanceX + s.startClear;
}

// The frame placed in the plane for the case's type (siemens_roughing_frame.h), hundredths.
struct SiemensPlacement {
  bool transposed = false, mirrored = false;
  long z0 = 0, x0 = 0;

  // A frame vector in the plane (z, x): I/K.
  std::pair<long, long> planeVector(long fz, long fx) const {
    if (mirrored) fx = -fx;
    return transposed ? std::pair{fx, fz} : std::pair{fz, fx};
  }
  std::pair<long, long> planePoint(long fz, long fx) const { return planeVector(fz + z0, fx + x0); }
  // G2/G3: a counter-clockwise arc in the frame is G3 in the plane unless one reflection turns it.
  bool turnsArcs() const { return transposed != mirrored; }
};

SiemensPlacement placementFor(const SiemensFuzzCase& s, const std::vector<ContourPiece>& pieces) {
  long zMin = 0, xMin = 0, xMax = 0;
  for (const ContourPiece& p : pieces) {
    zMin = std::min(zMin, p.toZ);
    xMin = std::min(xMin, p.toX);
    xMax = std::max(xMax, p.toX);
  }
  const MachiningType type = placedType(s);
  SiemensPlacement place{type.cut == SiemensCut::Face, type.side == SiemensSide::Internal};
  const long clear = startClearance(s);
  if (!place.transposed) {
    // Longitudinal: the radius ≥ base (external); internal: the bore's smallest radius leaves room
    // for both starts inside it, base from the axis.
    place.x0 = place.mirrored ? -xMax - s.base - clear : s.base - xMin;
  } else {
    // Face: the radius (frame z) down to base − 1 mm at the contour's end; the face at Z0.
    place.z0 = -zMin + s.base - 100;
    place.x0 = place.mirrored ? -xMin : -xMax;
  }
  return place;
}

// text += each piece in turn (the programs and the title are written for every fuzz case: no
// stream, no temporary strings joined).
void appendPieces(std::string& text, std::initializer_list<std::string_view> pieces) {
  for (std::string_view piece : pieces) text += piece;
}

// Writes blocks word by word into one text (no list of words per block: the writing is part of
// every fuzz case's cost): words apart by a space, or run together when compact.
class BlockWriter {
 public:
  explicit BlockWriter(bool compact) : compact_(compact) {}
  // A word: its address ("G", "X", "CR=") and its value as written.
  BlockWriter& word(std::string_view address, std::string_view value = {}) {
    if (!atBlockStart_ && !compact_) text_ += ' ';
    text_.append(address).append(value);
    atBlockStart_ = false;
    return *this;
  }
  void endBlock() {
    text_ += '\n';
    atBlockStart_ = true;
  }
  std::string text() && { return std::move(text_); }

 private:
  bool compact_;
  bool atBlockStart_ = true;
  std::string text_;
};

std::string diameter(long radius) { return mm(2 * radius); }  // X is a diameter (G23 / DIAMON)

const char* cornerAddress(SiemensSegment::Corner c) {
  switch (c) {
    case SiemensSegment::Chamfer: return "CHF=";
    case SiemensSegment::ChamferLeg: return "CHR=";
    case SiemensSegment::Rounding: return "RND=";
    case SiemensSegment::NoCorner: break;
  }
  return "";
}

std::vector<ContourPiece> writtenPieces(const SiemensFuzzCase& s) {
  std::vector<ContourPiece> pieces = piecesOf(s);
  return s.fault == SiemensFault::AgainstDirection ? reversed(std::move(pieces)) : pieces;
}

}  // namespace

std::string siemensContourProgram(const FuzzCase& c) {
  const SiemensFuzzCase& s = c.siemens;
  const std::vector<ContourPiece> pieces = writtenPieces(s);
  const SiemensPlacement place = placementFor(s, piecesOf(s));
  BlockWriter w(s.compact);
  const auto [z0, x0] = place.planePoint(pieces.front().fromZ, pieces.front().fromX);
  w.word("G1").word("X", diameter(x0)).word("Z", mm(z0)).endBlock();
  for (const ContourPiece& p : pieces) {
    const auto [z, x] = place.planePoint(p.toZ, p.toX);
    if (p.kind == ContourPiece::Line) {
      w.word("G1").word("X", diameter(x)).word("Z", mm(z));
    } else {
      const bool ccw = (p.kind == ContourPiece::Ccw) != place.turnsArcs();
      w.word(ccw ? "G3" : "G2").word("X", diameter(x)).word("Z", mm(z));
      if (p.centreWords) {
        const auto [k, i] = place.planeVector(p.centreZ - p.fromZ, p.centreX - p.fromX);
        w.word("I", mm(i)).word("K", mm(k));  // SIEMENS.ARC: the centre from the start, I a radius
      } else {
        w.word("CR=", mm(p.radius));
      }
    }
    if (p.corner != SiemensSegment::NoCorner) w.word(cornerAddress(p.corner), mm(p.cornerSize));
    w.endBlock();
  }
  w.word("RET").endBlock();
  return std::move(w).text();
}

std::string siemensMainProgram(const FuzzCase& c) {
  const SiemensFuzzCase& s = c.siemens;
  const std::vector<ContourPiece> pieces = piecesOf(s);
  const SiemensPlacement place = placementFor(s, pieces);
  long xMax = 0;
  for (const ContourPiece& p : pieces) xMax = std::max(xMax, p.toX);
  const long clear = startClearance(s);
  // The start beyond the contour on the entry side (+z of the frame) and above it (+x): clear of
  // the part and of the cycle's own start.
  const auto [z, x] = place.planePoint(clear, xMax + clear);
  // Appended piece by piece into room for the whole program (no temporaries, no regrowth: the
  // writing is part of every fuzz case's cost).
  std::string p;
  p.reserve(160);
  appendPieces(p, {"T1 D1\nG0 X", diameter(x), " Z", mm(z), "\n"});
  if (!s.cycle95) {
    appendPieces(p, {"_CNAME=\"", kSiemensContourName, "\"\n"});
    appendPieces(p, {"R105=", std::to_string(s.type), " R106=", mm(s.allowance), " R108=", mm(s.maxInfeed), " R109=",
            std::to_string(s.infeedAngle), "\n"});
    appendPieces(p, {"R110=", mm(s.retract), " R111=", mm(s.roughingFeed), " R112=", mm(s.finishingFeed), "\n"});
    appendPieces(p, {"LCYC95\nM02\n"});
    return p;
  }
  appendPieces(p, {"CYCLE95(\"", kSiemensContourName, "\", ", mm(s.maxInfeed), ", ", mm(s.allowanceZ), ", ",
                   mm(s.allowanceX), ", ", mm(s.allowance), ", ", mm(s.roughingFeed), ", ", mm(s.undercutFeed), ", ",
                   mm(s.finishingFeed), ", ", std::to_string(s.type), ", ", mm(10L * s.dwell), ", ",
                   mm(s.interruptLength), ", ", mm(s.retract), ")\nM02\n"});
  return p;
}

std::optional<FuzzExpectedAlarm> siemensExpectedAlarm(const FuzzCase& c) {
  const SiemensFuzzCase& s = c.siemens;
  const int callLine = s.cycle95 ? 3 : 6;  // after T1 D1, G0 (and _CNAME, the two R lines)
  switch (s.fault) {
    case SiemensFault::MachiningType: return FuzzExpectedAlarm{"61002", callLine};
    case SiemensFault::NoInfeedDepth: return FuzzExpectedAlarm{"61610", callLine};
    case SiemensFault::AgainstDirection:
    case SiemensFault::ArcOverQuarter: return FuzzExpectedAlarm{"10931", callLine};
    case SiemensFault::None: break;
  }
  return std::nullopt;
}

namespace {

const char* technologyName(SiemensTechnology t) {
  return t == SiemensTechnology::Roughing ? "roughing" : t == SiemensTechnology::Finishing ? "finishing" : "complete";
}

std::string typeText(const SiemensFuzzCase& s) {
  const auto type = machiningTypeOf(s.type);
  std::string text = std::string(s.cycle95 ? "VARI=" : "R105=") + std::to_string(s.type);
  if (!type) return text + " (out of range)";
  return text + " (" + (type->cut == SiemensCut::Face ? "face " : "longitudinal ") +
         (type->side == SiemensSide::Internal ? "internal " : "external ") + technologyName(type->technology) + ")";
}

const char* faultText(SiemensFault f) {
  switch (f) {
    case SiemensFault::MachiningType: return ", machining type out of range (61002)";
    case SiemensFault::NoInfeedDepth: return ", no infeed depth (61610)";
    case SiemensFault::AgainstDirection: return ", contour against the finishing direction (10931)";
    case SiemensFault::ArcOverQuarter: return ", a half circle in the contour (10931)";
    case SiemensFault::None: break;
  }
  return "";
}

int undercutsOf(const SiemensFuzzCase& s) {
  return static_cast<int>(std::count_if(s.segments.begin(), s.segments.end(), [](const SiemensSegment& g) { return g.up < 0; }));
}

std::vector<std::string> siemensRules(const SiemensFuzzCase& s) {
  const std::string cycle = s.cycle95 ? "CYCLE95." : "LCYC95.";
  std::vector<std::string> rules{cycle + "PARAMS"};
  if (s.fault != SiemensFault::None) {
    rules.push_back("LCYC95.ALARMS");
    if (s.fault == SiemensFault::AgainstDirection || s.fault == SiemensFault::ArcOverQuarter) rules.push_back("LCYC95.CONTOUR");
    return rules;
  }
  const SiemensTechnology t = placedType(s).technology;
  if (t != SiemensTechnology::Finishing) rules.push_back(cycle + "ROUGH");
  if (t != SiemensTechnology::Roughing) rules.push_back(cycle + (t == SiemensTechnology::Complete ? "COMPLETE" : "FINISH"));
  if (s.cycle95 && undercutsOf(s) > 0 && t != SiemensTechnology::Finishing) rules.push_back("CYCLE95.UNDERCUT");
  if (s.cycle95 && s.interruptLength > 0 && t != SiemensTechnology::Finishing) rules.push_back("CYCLE95.DAM");
  return rules;
}

}  // namespace

std::string describeSiemensCase(const FuzzCase& c) {
  const SiemensFuzzCase& s = c.siemens;
  const auto arcs = std::count_if(s.segments.begin(), s.segments.end(), [](const SiemensSegment& g) { return g.kind != SiemensSegment::Line; });
  const auto corners = std::count_if(s.segments.begin(), s.segments.end(), [](const SiemensSegment& g) { return g.corner != SiemensSegment::NoCorner; });
  // Appended piece by piece (no stream: the title is written for every fuzz case).
  std::string o;
  o.reserve(200);
  appendPieces(o, {s.cycle95 ? "CYCLE95" : "LCYC95", " ", typeText(s), ", ", std::to_string(s.segments.size()),
                   " segment(s) (", std::to_string(arcs), " arc(s), ", std::to_string(corners), " corner(s), ",
                   std::to_string(undercutsOf(s)), " turning back), ", c.profile, ", ", s.cycle95 ? "MID " : "R108 ",
                   mm(s.maxInfeed), ", ", s.cycle95 ? "_VRT " : "R110 ", mm(s.retract), ", ",
                   s.cycle95 ? "FAL " : "R106 ", mm(s.allowance)});
  if (s.cycle95) {
    appendPieces(o, {", FALZ ", mm(s.allowanceZ), " FALX ", mm(s.allowanceX), ", FF1 ", mm(s.roughingFeed), " FF2 ",
                     mm(s.undercutFeed)});
    if (s.interruptLength) appendPieces(o, {", DAM ", mm(s.interruptLength)});
    if (s.dwell) appendPieces(o, {", DT ", mm(10L * s.dwell)});
  } else if (s.infeedAngle) {
    appendPieces(o, {", R109 ", std::to_string(s.infeedAngle)});
  }
  o += faultText(s.fault);
  return o;
}

nlohmann::json siemensSpecJson(const FuzzCase& c, const std::string& tag) {
  nlohmann::json j = drawnCaseJson(c, tag, siemensRules(c.siemens), siemensMainProgram(c), siemensExpectedAlarm(c),
                                   "generated by cyclecert fuzz with one invalid parameter: the alarm LCYC95.ALARMS "
                                   "names, at the call");
  j["subprograms"] = {{kSiemensContourName, siemensContourProgram(c)}};
  return j;
}

}  // namespace cyclecert
