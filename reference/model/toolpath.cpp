#include "reference/model/toolpath.h"

#include <array>
#include <utility>

namespace cyclecert {

namespace {

constexpr std::array<std::pair<MovePhase, std::string_view>, 6> kPhaseNames{{
    {MovePhase::Approach, "approach"},
    {MovePhase::Pass, "pass"},
    {MovePhase::SemiFinish, "semi-finish"},
    {MovePhase::Finish, "finish"},
    {MovePhase::Return, "return"},
    {MovePhase::Program, "program"},
}};

}  // namespace

std::string_view phaseName(MovePhase p) {
  for (const auto& [phase, name] : kPhaseNames) {
    if (phase == p) return name;
  }
  return "";
}

std::optional<MovePhase> phaseNamed(std::string_view name) {
  for (const auto& [phase, spelling] : kPhaseNames) {
    if (spelling == name) return phase;
  }
  return std::nullopt;
}

std::string phaseNamesText() {
  std::string text;
  for (std::size_t i = 0; i < kPhaseNames.size(); ++i) {
    if (i > 0) text += i + 1 == kPhaseNames.size() ? " or " : ", ";
    text += "\"" + std::string(kPhaseNames[i].second) + "\"";
  }
  return text;
}

std::vector<Segment> CycleRecord::roughProfile() const {
  if (!roughShape.empty()) return roughShape;
  std::vector<Segment> rough;
  rough.reserve(shape.size());
  for (const Segment& s : shape) rough.push_back(s.shifted(allowance));
  return rough;
}

Segment Toolpath::segment(std::size_t i) const {
  const Move& m = moves[i];
  Segment s;
  s.kind = m.shape;
  s.from = from(i);
  s.to = m.to;
  if (m.center) s.center = *m.center;
  return s;
}

}  // namespace cyclecert
