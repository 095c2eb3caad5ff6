#include "oracles/metamorphic/siemens_relations.h"

#include <cmath>
#include <functional>
#include <map>

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

// An arc given by I/K whose end is off its circle by more than 1e-6 mm: the controller accepts it
// within an absolute tolerance (SIEMENS.ARC), so a scaled copy — off by k times as much — may alarm
// where the source does not. Walks each text's blocks with the position and motion mode they set
// (X a diameter); an arc before a text has set both X and Z cannot be checked and counts as off.
std::optional<std::string> arcOffItsCircle(const SiemensWords& words) {
  struct Block {
    std::map<std::string, double> values;
    std::string where;
  };
  std::map<std::pair<std::size_t, int>, Block> blocks;  // (text, line) in order
  for (const SiemensNumber& n : words.numbers) {
    Block& b = blocks[{n.text, n.line}];
    b.values[n.address] = n.value;
    if (b.where.empty()) b.where = n.where.substr(0, n.where.find(':'));
  }
  std::size_t text = 0;
  std::optional<double> z, x;
  int motion = 0;
  for (const auto& [at, b] : blocks) {
    if (at.first != text) {  // each subprogram starts where the cycle puts the tool: unknown here
      text = at.first;
      z.reset();
      x.reset();
      motion = 0;
    }
    const auto value = [&](const char* a) -> std::optional<double> {
      const auto it = b.values.find(a);
      return it == b.values.end() ? std::nullopt : std::optional<double>(it->second);
    };
    if (const auto g = value("G"); g && *g >= 0 && *g <= 3) motion = static_cast<int>(*g);
    const std::optional<double> endZ = value("Z") ? value("Z") : z;
    const std::optional<double> endX = value("X") ? std::optional<double>(*value("X") / 2) : x;
    const bool byCentre = (motion == 2 || motion == 3) && !value("CR") && (value("I") || value("K"));
    if (byCentre) {
      if (!z || !x || !endZ || !endX) return b.where + ": an arc by I/K from a position the text does not set";
      const Point from{*z, *x}, centre{*z + value("K").value_or(0), *x + value("I").value_or(0)}, to{*endZ, *endX};
      const double off = std::abs(distance(to, centre) - distance(from, centre));
      if (off > 1e-6) {
        return b.where + ": the arc's end is off its circle by " + std::to_string(off) +
               " mm; the controller's tolerance for that is absolute, so the scaled program may alarm where the "
               "source does not";
      }
    }
    z = endZ;
    x = endX;
  }
  return std::nullopt;
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

}  // namespace cyclecert
