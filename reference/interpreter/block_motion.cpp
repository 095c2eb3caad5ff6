#include "reference/interpreter/block_motion.h"

#include <cmath>

#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {
constexpr double kArcRadiusTolerance = 0.01;  // mm; FANUC's parameter 3410 plays this role

struct AxisLetters {
  char axis, absolute, incremental;
  bool diameter;
};
constexpr AxisLetters kAxes[] = {{'X', 'X', 'U', true}, {'Y', 'Y', 'V', false}, {'Z', 'Z', 'W', false}};
}  // namespace

double physicalLength(double programmed, bool diameterAxis, const ModalState& s) {
  return programmed * s.unitScale() / (diameterAxis ? 2.0 : 1.0);
}

bool hasAxisWord(const Block& b) {
  for (const AxisLetters& a : kAxes) {
    if (b.has(a.absolute) || b.has(a.incremental)) return true;
  }
  return false;
}

AxisPosition targetPosition(const Block& b, const ModalState& s) {
  AxisPosition p = s.position;
  for (const AxisLetters& a : kAxes) {
    if (const Word* w = b.find(a.absolute)) {
      const double length = physicalLength(w->value, a.diameter, s);
      p[a.axis] = s.incremental ? p[a.axis] + length : length;  // PROG.GSYS.INCREMENTAL: G91
    }
    if (const Word* w = b.find(a.incremental)) p[a.axis] += physicalLength(w->value, a.diameter, s);
  }
  return p;
}

char incrementalAddressOf(char axis) {
  for (const AxisLetters& a : kAxes) {
    if (a.axis == axis) return a.incremental;
  }
  return 0;
}

bool setsAxisAbsolutely(const Block& b, char axis, const ModalState& s) { return !s.incremental && b.has(axis); }

bool movesAxisIncrementally(const Block& b, char axis, const ModalState& s) {
  for (const AxisLetters& a : kAxes) {
    if (a.axis == axis) return b.has(a.incremental) || (s.incremental && b.has(a.absolute));
  }
  return false;
}

const Word* incrementalAddressOutsideItsSystem(const Block& b, const ModalState& s) {
  if (s.gCodeSystem != GCodeSystem::B && s.gCodeSystem != GCodeSystem::C) return nullptr;
  for (const AxisLetters& a : kAxes) {
    if (const Word* w = b.find(a.incremental)) return w;
  }
  return nullptr;
}

AxisWordsMean axisWordsMeaning(const Block& b, GCodeSystem system) {
  // PROG.GROUP.LAST: of several group 00 codes in one block, the last one is in effect.
  switch (oneShotFunction(b, system)) {
    case 40: return AxisWordsMean::Dwell;
    case 270: return AxisWordsMean::ReferenceCheck;
    case 280: case 300: return AxisWordsMean::ReferenceReturn;
    case 530: return AxisWordsMean::MachineCoordinates;
    case 500: return AxisWordsMean::CoordinateSetting;
    case 100: case 650: return AxisWordsMean::Data;
    default: return AxisWordsMean::Motion;
  }
}

bool axisWordsMoveTheTool(AxisWordsMean meaning) {
  return meaning == AxisWordsMean::Motion || meaning == AxisWordsMean::ReferenceCheck ||
         meaning == AxisWordsMean::ReferenceReturn;
}

AxisPosition positionAfterBlock(const Block& b, const ModalState& s) {
  const AxisWordsMean meaning = axisWordsMeaning(b, s.gCodeSystem);
  if (axisWordsMoveTheTool(meaning) || meaning == AxisWordsMean::CoordinateSetting) return targetPosition(b, s);
  return s.position;  // a dwell, G53's machine coordinates, G10/G65 data
}

void followKnownAxes(KnownPosition& known, const Block& b, AxisWordsMean meaning, const ModalState& s) {
  const bool toReference = meaning == AxisWordsMean::ReferenceReturn;
  if (toReference || meaning == AxisWordsMean::MachineCoordinates) {
    const std::string command = !toReference ? "G53" : b.hasG(300) ? "G30" : "G28";
    for (const AxisLetters& a : kAxes) {
      if (b.has(a.absolute) || b.has(a.incremental)) known.forget(a.axis, {b.line, command, toReference});
    }
    return;
  }
  if (!axisWordsMoveTheTool(meaning) && meaning != AxisWordsMean::CoordinateSetting) return;
  for (const AxisLetters& a : kAxes) {
    if (setsAxisAbsolutely(b, a.axis, s)) known.learn(a.axis);
  }
}

std::optional<Segment> motionSegment(const Block& b, int motion, const ModalState& s) {
  const PlaneAxes axes = s.axes();
  const AxisPosition target = targetPosition(b, s);
  Segment seg;
  seg.sourceLine = b.line;
  seg.from = s.planePoint();
  seg.to = {target[axes.first], target[axes.second]};
  if (motion != 2 && motion != 3) {
    if (distance(seg.from, seg.to) <= kGeomEps) return std::nullopt;
    return seg;
  }
  seg.kind = motion == 2 ? SegmentKind::ArcCW : SegmentKind::ArcCCW;
  if (const Word* r = b.find('R')) {
    const auto center = arcCenterFromRadius(seg.from, seg.to, r->value * s.unitScale(), seg.kind);
    if (!center) {
      throw CycleAlarm(alarm::kIllegalRadius, b.line,
                       "R" + r->text.substr(1) + " is shorter than half the chord, or the end point equals the start");
    }
    seg.center = *center;
    return seg;
  }
  const Word* i1 = b.find(axes.firstArc);
  const Word* i2 = b.find(axes.secondArc);
  if (!i1 && !i2) {
    throw CycleAlarm(alarm::kIllegalRadius, b.line, std::string("arc without R or ") + axes.firstArc +
                                                        "/" + axes.secondArc + " centre words");
  }
  // I, J, K are radius values whatever the axis's diameter programming.
  seg.center = seg.from + Point{i1 ? i1->value * s.unitScale() : 0.0, i2 ? i2->value * s.unitScale() : 0.0};
  const double r0 = distance(seg.from, seg.center);
  const double r1 = distance(seg.to, seg.center);
  if (std::abs(r0 - r1) > kArcRadiusTolerance || r0 <= kGeomEps) {
    throw CycleAlarm(alarm::kRadiusTolerance, b.line,
                     "the end point is not on the circle (radius at start " + std::to_string(r0) +
                         " mm, at end " + std::to_string(r1) + " mm)");
  }
  return seg;
}

}  // namespace cyclecert
