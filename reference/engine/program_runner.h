#pragma once
// Runs a program through the reference controller model: tracks modal state and position block by
// block and plans every canned cycle. The toolpath starts at the first cycle's start point A and
// holds every move from there on (positioning blocks between cycles included, phase "program").
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/model/program.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// How the program is run: from memory or in MDI mode (G72.MDI), and with which tool offset
// (nose radius and imaginary tip direction, for G41/G42).
struct RunOptions {
  bool mdi = false;
  ToolOffset tool;
};

// A controller alarm ends the run: the toolpath keeps the moves made before it and names the alarm.
// Throws NotSupported for cycles the reference cannot plan yet (G75, G76, …).
Toolpath planProgram(const Program& program, const Profile& profile, const MachineParams& params,
                     const RunOptions& options = {});

}  // namespace cyclecert
