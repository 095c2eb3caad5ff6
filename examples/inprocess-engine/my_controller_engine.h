#pragma once
// A controller's planner as a cyclecert engine (harness/engines/engine.h): one spec case in — the
// program text, its profile, machine parameters, tool — and the toolpath it would run out, or the
// alarm it raises, or "not applicable" for what the controller does not do.
#include <memory>

#include "harness/engines/engine.h"

namespace my_controller {

std::unique_ptr<cyclecert::Engine> makeEngine();

}  // namespace my_controller
