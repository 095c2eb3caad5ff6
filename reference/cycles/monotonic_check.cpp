#include "reference/cycles/monotonic_check.h"

#include <algorithm>
#include <sstream>

#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// Tracks the furthest progress along one direction and reports a step back beyond the tolerance.
class ProgressTracker {
 public:
  ProgressTracker(double start, const AxisCheck& check) : best_(start), check_(check) {}

  void visit(double progress, int line) {
    if (progress < best_ - check_.tolerance - kGeomEps) {
      std::ostringstream msg;
      msg << check_.axisName << " moves back by " << (best_ - progress)
          << " mm against the shape's direction (allowed " << check_.tolerance << ")";
      throw CycleAlarm(check_.alarmCode, line, msg.str());
    }
    best_ = std::max(best_, progress);
  }

 private:
  double best_;
  const AxisCheck& check_;
};

}  // namespace

void checkType1Monotonic(const Type1Cycle& cycle, const AxisCheck& cutAxis, const AxisCheck& depthAxis) {
  const int cut = cycle.cutDirection();
  const int depth = cycle.depthDirection();
  // Progress along z is cut·z; progress along x is retreat from the infeed: −depth·x.
  ProgressTracker alongCut(cut * cycle.headEnd.z, cutAxis);
  ProgressTracker retreat(-depth * cycle.headEnd.x, depthAxis);
  for (const Segment& s : cycle.body) {
    std::vector<Point> points = apexesAlong(s);  // G71.T1.ALARM: "including the apex of an arc"
    points.push_back(s.to);
    for (Point p : points) {
      alongCut.visit(cut * p.z, s.sourceLine);
      retreat.visit(-depth * p.x, s.sourceLine);
    }
  }
}

void checkMonotonicAlongCut(const std::vector<Segment>& shape, int cutDirection, const AxisCheck& cutAxis) {
  if (shape.empty()) return;
  ProgressTracker alongCut(cutDirection * shape.front().from.z, cutAxis);
  for (const Segment& s : shape) {
    std::vector<Point> points = apexesAlong(s);
    points.push_back(s.to);
    for (Point p : points) alongCut.visit(cutDirection * p.z, s.sourceLine);
  }
}

}  // namespace cyclecert
