#pragma once
// G71.T1.MONO / G72.T1.MONO with G71.T1.ALARM: a type I shape must progress monotonically along
// both plane axes, arc apexes included. Parameters 5145 (1st axis) and 5146 (2nd axis) allow a
// small backward motion without alarm.
#include <string>
#include <string_view>
#include <vector>

#include "reference/cycles/type1_roughing.h"

namespace cyclecert {

struct AxisCheck {
  std::string_view alarmCode;  // PS0064 for the plane's 1st axis, PS0329 for the 2nd
  double tolerance;            // parameter 5145 or 5146
  std::string axisName;        // for the message: "Z", "X", …
};

// Checks the finish shape B → C of a cycle given in the cycle frame: z must move in the cut
// direction, x must retreat from the infeed (back towards A). Throws CycleAlarm naming the block.
void checkType1Monotonic(const Type1Cycle& cycle, const AxisCheck& cutAxis, const AxisCheck& depthAxis);

// G71.T2.MONO / G72.T2.MONO: a type II shape (head block included) must progress monotonically
// along the cut axis only, in direction `cutDirection`.
void checkMonotonicAlongCut(const std::vector<Segment>& shape, int cutDirection, const AxisCheck& cutAxis);

}  // namespace cyclecert
