#pragma once
// The working plane (G17/G18/G19) decides which address letters are the plane's 1st and 2nd axes.
// cyclecert maps every plane onto (z = 1st axis, x = 2nd axis) so one planner serves all three
// (G71.FMT.ZX, G71.FMT.YZ, G71.FMT.XY). On a lathe X is programmed as a diameter in every plane.
#include <string>

namespace cyclecert {

struct PlaneAxes {
  int gCode;             // 17, 18, 19
  char first, second;    // absolute addresses of the 1st and 2nd axis
  char firstInc, secondInc;  // incremental addresses
  char firstArc, secondArc;  // arc centre offsets (I, J, K), always radius values
  bool firstDiameter, secondDiameter;

  std::string name() const { return "G" + std::to_string(gCode); }
};

inline PlaneAxes planeAxes(int gCode) {
  switch (gCode) {
    case 17: return {17, 'X', 'Y', 'U', 'V', 'I', 'J', true, false};
    case 19: return {19, 'Y', 'Z', 'V', 'W', 'J', 'K', false, false};
    default: return {18, 'Z', 'X', 'W', 'U', 'K', 'I', false, true};
  }
}

}  // namespace cyclecert
