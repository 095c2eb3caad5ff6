#include "oracles/metamorphic/siemens_relations.h"

#include <cmath>
#include <functional>
#include <map>
#include <numbers>

#include "reference/gcode/writer.h"

#include "reference/model/geometry.h"

namespace cyclecert {

namespace {

bool isSiemensLength(SiemensRole role) {
  switch (role) {
    case SiemensRole::AbsZ:
    case SiemensRole::AbsX:
    case SiemensRole::CentreZ:
    case SiemensRole::CentreX:
    case SiemensRole::ArcRadius:
    case SiemensRole::CornerLength:
    case SiemensRole::LengthParameter:
    case SiemensRole::CycleLength:
      return true;
    default:
      return false;
  }
}

// One block of a text as its words move the tool: the motion mode in force, where it starts and
// ends (x a radius: X is a diameter) when the text has set them, its words by address.
struct SiemensMotion {
  std::string where;  // "subprogram L18 line 3"
  int motion = 0;
  std::optional<Point> from, to;
  std::map<std::string, const SiemensNumber*> words;

  std::optional<double> value(const std::string& address) const {
    const auto it = words.find(address);
    return it == words.end() ? std::nullopt : std::optional<double>(it->second->value);
  }
  bool isArc() const { return motion == 2 || motion == 3; }
  bool byCentre() const { return isArc() && !words.count("CR") && (words.count("I") || words.count("K")); }
};

// The blocks of each text in order, each starting where the one before ended. A subprogram starts
// where the cycle puts the tool, unknown here, until its words have set both X and Z.
std::vector<SiemensMotion> walkMotions(const SiemensWords& words) {
  std::map<std::pair<std::size_t, int>, SiemensMotion> blocks;  // (text, line), in order
  for (const SiemensNumber& n : words.numbers) {
    SiemensMotion& b = blocks[{n.text, n.line}];
    const bool motionCode = n.value >= 0 && n.value <= 3 && n.value == std::floor(n.value);
    if (n.address == "G" && !motionCode) continue;  // G18, G90, …: no motion mode
    b.words[n.address] = &n;
    if (b.where.empty()) b.where = n.where.substr(0, n.where.find(','));
  }
  std::vector<SiemensMotion> out;
  std::size_t text = words.numbers.empty() ? 0 : words.numbers.front().text;
  Point at{0, 0};
  bool zSet = false, xSet = false;
  int motion = 0;
  for (auto& [key, b] : blocks) {
    if (key.first != text) {
      text = key.first;
      zSet = xSet = false;
      motion = 0;
    }
    if (const auto g = b.value("G")) motion = static_cast<int>(*g);
    b.motion = motion;
    if (zSet && xSet) b.from = at;
    if (const auto v = b.value("Z")) at.z = *v, zSet = true;
    if (const auto v = b.value("X")) at.x = *v / 2, xSet = true;
    if (zSet && xSet) b.to = at;
    out.push_back(std::move(b));
  }
  return out;
}

SegmentKind arcKind(const SiemensMotion& m) { return m.motion == 2 ? SegmentKind::ArcCW : SegmentKind::ArcCCW; }

// An arc given by I/K whose end is off its circle by more than 1e-6 mm (SIEMENS.ARC: the controller
// takes it within an absolute tolerance), or one whose start the text does not set: the reason.
std::optional<std::string> centreArcOffItsCircle(const SiemensMotion& m) {
  if (!m.from || !m.to) return m.where + ": an arc by I/K from a position the text does not set";
  const Point centre = *m.from + Point{m.value("K").value_or(0), m.value("I").value_or(0)};
  const double off = std::abs(distance(*m.to, centre) - distance(*m.from, centre));
  if (off <= 1e-6) return std::nullopt;
  return m.where + ": the arc's end is off its circle by " + std::to_string(off) +
         " mm; the controller takes that within an absolute tolerance";
}

// scale-k: an arc off its circle, scaled, is off by k times as much and may alarm where the source
// does not.
std::optional<std::string> arcOffItsCircle(const SiemensWords& words) {
  for (const SiemensMotion& m : walkMotions(words)) {
    if (!m.byCentre()) continue;
    if (const auto off = centreArcOffItsCircle(m)) return *off + ": scaled, it may alarm where the source does not";
  }
  return std::nullopt;
}

// A computed length as a word's number, rounded to 1e-9 mm: "0", not the 8.9e-16 of a centre worked
// out from the chord (the runner takes a centre within far more than that).
std::string tidy(double mm) { return formatNumber(std::round(mm * 1e9) / 1e9, false); }

// r-ik on one arc: CR= → I K, or I/K → CR= (negative above 180°).
std::optional<std::vector<SiemensTextEdit>> exchangeArcWords(const SiemensMotion& m, std::string& whyNot) {
  if (!m.from || !m.to) {
    whyNot = m.where + ": an arc from a position the text does not set";
    return std::nullopt;
  }
  if (const auto cr = m.words.find("CR"); cr != m.words.end()) {
    const auto centre = arcCenterFromRadius(*m.from, *m.to, cr->second->value, arcKind(m));
    if (!centre) {
      whyNot = m.where + ": CR= is shorter than half the chord (no such arc)";
      return std::nullopt;
    }
    const Point c = *centre - *m.from;
    return std::vector<SiemensTextEdit>{replaceWord(*cr->second, "I" + tidy(c.x) + " K" + tidy(c.z))};
  }
  if (const auto off = centreArcOffItsCircle(m)) {
    whyNot = *off + ": CR= would move the centre";
    return std::nullopt;
  }
  Segment arc;
  arc.kind = arcKind(m);
  arc.from = *m.from;
  arc.to = *m.to;
  arc.center = *m.from + Point{m.value("K").value_or(0), m.value("I").value_or(0)};
  const double radius = distance(arc.from, arc.center);
  const bool overHalf = std::abs(sweep(arc)) > std::numbers::pi + 1e-9;
  std::vector<SiemensTextEdit> edits;
  bool written = false;
  for (const char* address : {"I", "K"}) {
    const auto w = m.words.find(address);
    if (w == m.words.end()) continue;
    edits.push_back(replaceWord(*w->second, written ? "" : "CR=" + tidy(overHalf ? -radius : radius)));
    written = true;
  }
  return edits;
}

FollowUp siemensFollowUp(SiemensSource texts, const ParamSettings& params, std::function<Point(Point)> map) {
  FollowUp f;
  f.params = params;
  f.expectedPath = [map](const Toolpath& t) { return mapToolpath(t, map, false); };
  f.siemens = std::move(texts);
  return f;
}

}  // namespace

std::optional<FollowUp> translateSiemens(Point shift, const SiemensSource& source, const ParamSettings& params,
                                         std::string& whyNot) {
  const auto words = readSiemensWords(source, whyNot);
  if (!words) return std::nullopt;
  std::vector<std::pair<SiemensNumber, double>> changes;
  for (const SiemensNumber& n : words->numbers) {
    if (n.role == SiemensRole::AbsZ) changes.push_back({n, n.value + shift.z});
    if (n.role == SiemensRole::AbsX) changes.push_back({n, n.value + 2 * shift.x});
  }
  return siemensFollowUp(rewriteNumbers(source, changes), params, [shift](Point q) { return q + shift; });
}

std::optional<FollowUp> scaleSiemens(double k, const SiemensSource& source, const ParamSettings& params,
                                     std::string& whyNot) {
  const auto words = readSiemensWords(source, whyNot);
  if (!words) return std::nullopt;
  if (!words->defaultedLengths.empty()) {
    whyNot = words->defaultedLengths.front();
    return std::nullopt;
  }
  if (const auto off = arcOffItsCircle(*words)) {
    whyNot = *off;
    return std::nullopt;
  }
  std::vector<std::pair<SiemensNumber, double>> changes;
  for (const SiemensNumber& n : words->numbers) {
    if (isSiemensLength(n.role)) changes.push_back({n, k * n.value});
  }
  return siemensFollowUp(rewriteNumbers(source, changes), params, [k](Point q) { return k * q; });
}

std::optional<FollowUp> radiusCentreSiemens(const SiemensSource& source, const ParamSettings& params,
                                            std::string& whyNot) {
  const auto words = readSiemensWords(source, whyNot);
  if (!words) return std::nullopt;
  std::vector<SiemensTextEdit> edits;
  for (const SiemensMotion& m : walkMotions(*words)) {
    if (!m.isArc() || !(m.words.count("CR") || m.words.count("I") || m.words.count("K"))) continue;
    const auto arcEdits = exchangeArcWords(m, whyNot);
    if (!arcEdits) return std::nullopt;
    edits.insert(edits.end(), arcEdits->begin(), arcEdits->end());
  }
  if (edits.empty()) {
    whyNot = "no arc with CR= or I/K: nothing to exchange";
    return std::nullopt;
  }
  return siemensFollowUp(applyEdits(source, std::move(edits)), params, [](Point q) { return q; });
}

}  // namespace cyclecert
