#pragma once
// What the controller remembers between blocks: position, modal G codes, feed.
#include "reference/interpreter/g_code_system.h"
#include "reference/interpreter/plane.h"
#include "reference/model/geometry.h"

namespace cyclecert {

// Physical position of the three linear axes (X as a radius), in mm.
struct AxisPosition {
  double x = 0, y = 0, z = 0;
  double& operator[](char axis) { return axis == 'X' ? x : axis == 'Y' ? y : z; }
  double operator[](char axis) const { return axis == 'X' ? x : axis == 'Y' ? y : z; }
};

struct ModalState {
  AxisPosition position;
  int motion = 0;        // group 01: 0, 1, 2, 3 (G00 at power-on)
  int plane = 18;        // G18 at power-on on a lathe
  bool inch = false;     // G20
  int tnrc = 40;         // G40/G41/G42
  int workCoordinates = 54;  // group 14: G54…G59 (their offsets are modelled as zero: PROG.WCS)
  double feed = 0;       // modal F, in mm/min or mm/rev
  GCodeSystem gCodeSystem = GCodeSystem::A;  // the list the block's G numbers are read in (PROG.GSYS.*)
  bool gCodeSystemByParameters = false;  // the profile lets parameter 3401 choose it (the FANUC profiles)
  bool incremental = false;  // group 03 G91 (systems B/C, Huazhong): X/Y/Z are incremental

  PlaneAxes axes() const { return planeAxes(plane); }
  double unitScale() const { return inch ? 25.4 : 1.0; }
  // The position in the plane's canonical frame (z = 1st axis, x = 2nd axis).
  Point planePoint() const {
    const PlaneAxes a = axes();
    return {position[a.first], position[a.second]};
  }
};

}  // namespace cyclecert
