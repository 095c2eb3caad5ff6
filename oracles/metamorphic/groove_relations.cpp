#include "oracles/metamorphic/groove_relations.h"

#include <cmath>
#include <functional>

#include "oracles/metamorphic/groove_program.h"
#include "oracles/metamorphic/word_edit.h"
#include "reference/gcode/writer.h"

namespace cyclecert {

namespace {

using GrooveChange = std::function<void(GrooveBlockKind, GrooveRole, Word&)>;

Program mapGrooveWords(const Program& source, const GrooveProgram& groove, const GrooveChange& change) {
  Program out = source;
  for (std::size_t i = 0; i < out.blocks.size(); ++i) {
    for (Word& w : out.blocks[i].words) change(groove.blocks[i], grooveRoleOf(groove.blocks[i], w), w);
  }
  return out;
}

// I5: P and Q are least input increments unless parameter 182#7 says mm.
bool stepsInIncrements(const ParamSettings& params) { return !machineParamsOf(params).bit("182#7"); }

// G74_1.RANGE: the largest magnitude a word may have (IS-C): e and r1…r4 99.9999, P/Q in increments
// 99999999, every other length 9999.9999.
double largestValue(GrooveRole role, char letter, bool increments) {
  if (role == GrooveRole::Step) return increments ? 99'999'999 : 9999.9999;
  if (role == GrooveRole::Length && (letter == 'R' || letter == 'A' || letter == 'B' || letter == 'D' || letter == 'E')) {
    return 99.9999;
  }
  return 9999.9999;
}

bool isGrooveLength(GrooveRole role) {
  switch (role) {
    case GrooveRole::AbsFirst:
    case GrooveRole::AbsSecond:
    case GrooveRole::IncFirst:
    case GrooveRole::IncSecond:
    case GrooveRole::Step:
    case GrooveRole::Depth:
    case GrooveRole::FloorWidth:
    case GrooveRole::Length:
      return true;
    default:
      return false;
  }
}

bool isWhole(double v) { return std::abs(v - std::round(v)) <= 1e-9 * std::max(1.0, std::abs(v)); }

// The factors a unit change or a scaling applies: to lengths, to P/Q (which may count increments),
// to F.
struct Factors {
  double length = 1, steps = 1, feed = 1;
};

// Every length word, P/Q and F multiplied by its factor, or nothing with the first word that cannot
// take its new value: a P/Q in increments that is no longer whole, a value leaving or entering its
// range.
std::optional<Program> convertLengths(const Program& p, const GrooveProgram& groove, const ParamSettings& params,
                                      Factors factors, std::string& whyNot) {
  const bool increments = stepsInIncrements(params);
  Program out = mapGrooveWords(p, groove, [&](GrooveBlockKind, GrooveRole role, Word& w) {
    if (role == GrooveRole::Feed) setValue(w, w.value * factors.feed);
    if (!isGrooveLength(role) || !whyNot.empty()) return;
    const double value = w.value * (role == GrooveRole::Step ? factors.steps : factors.length);
    const std::string where = "line " + std::to_string(w.line) + ": " + w.text + ": ";
    if (role == GrooveRole::Step && increments && !isWhole(value)) {
      whyNot = where + "P and Q are least input increments (182#7 = 0) and would become " + std::to_string(value) +
               ", not a whole number";
      return;
    }
    // The ranges are numbers in the program's units: a word that left (or entered) its range would
    // make the follow-up alarm where the source does not (or not where it does).
    const double largest = largestValue(role, w.letter, increments);
    const bool inRange = std::abs(w.value) <= largest;
    if (inRange != (std::abs(value) <= largest)) {
      whyNot = where + "would become " + std::to_string(value) + ", " + (inRange ? "outside" : "inside") +
               " its range (G74_1.RANGE): the follow-up would alarm where the source does not, or not where it does";
      return;
    }
    setValue(w, role == GrooveRole::Step && increments ? std::round(value) : value);
  });
  if (!whyNot.empty()) return std::nullopt;
  return out;
}

std::optional<FollowUp> groovePathMap(Program program, const ParamSettings& params,
                                      std::function<Point(Point)> map, bool mirrors) {
  return FollowUp{std::move(program), params,
                  [map, mirrors](const Toolpath& t) { return mapToolpath(t, map, mirrors); }, ""};
}

}  // namespace

std::optional<FollowUp> mirrorGrooveZ(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto groove = readGrooveProgram(p, whyNot);
  if (!groove) return std::nullopt;
  Program out = mapGrooveWords(p, *groove, [](GrooveBlockKind, GrooveRole role, Word& w) {
    if (role == GrooveRole::AbsFirst || role == GrooveRole::IncFirst || role == GrooveRole::Depth) setValue(w, -w.value);
  });
  return groovePathMap(std::move(out), params, [](Point q) { return Point{-q.z, q.x}; }, true);
}

std::optional<FollowUp> mirrorGrooveX(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto groove = readGrooveProgram(p, whyNot);
  if (!groove) return std::nullopt;
  const double x0 = std::max(1.0, std::ceil(groove->largestRadius));
  Program out = mapGrooveWords(p, *groove, [x0](GrooveBlockKind, GrooveRole role, Word& w) {
    if (role == GrooveRole::AbsSecond) setValue(w, 4 * x0 - w.value);
    if (role == GrooveRole::IncSecond || role == GrooveRole::FloorWidth) setValue(w, -w.value);
  });
  return groovePathMap(std::move(out), params, [x0](Point q) { return Point{q.z, 2 * x0 - q.x}; }, true);
}

std::optional<FollowUp> translateGroove(Point shift, const Program& p, const ParamSettings& params,
                                        std::string& whyNot) {
  const auto groove = readGrooveProgram(p, whyNot);
  if (!groove) return std::nullopt;
  Program out = mapGrooveWords(p, *groove, [shift](GrooveBlockKind, GrooveRole role, Word& w) {
    if (role == GrooveRole::AbsFirst) setValue(w, w.value + shift.z);
    if (role == GrooveRole::AbsSecond) setValue(w, w.value + 2 * shift.x);
  });
  return groovePathMap(std::move(out), params, [shift](Point q) { return q + shift; }, false);
}

std::optional<FollowUp> scaleGroove(double k, const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto groove = readGrooveProgram(p, whyNot);
  if (!groove) return std::nullopt;
  auto out = convertLengths(p, *groove, params, {k, k, 1}, whyNot);
  if (!out) return std::nullopt;
  return groovePathMap(std::move(*out), params, [k](Point q) { return k * q; }, false);
}

std::optional<FollowUp> metricInchGroove(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto groove = readGrooveProgram(p, whyNot);
  if (!groove) return std::nullopt;
  // I5: in increments a P/Q of n · 0.0001 mm is n / 2.54 increments of 0.00001 in.
  const double inch = 1 / kMmPerInch;
  auto out = convertLengths(p, *groove, params, {inch, stepsInIncrements(params) ? 10 * inch : inch, inch}, whyNot);
  if (!out) return std::nullopt;
  commandFromTheStart(*out, 210, 20);
  return FollowUp{std::move(*out), params, [](const Toolpath& t) { return t; }, ""};
}

}  // namespace cyclecert
