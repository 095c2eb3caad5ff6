#pragma once
// The built-in engines (engine.cpp's factory builds them by name).
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness/engines/engine.h"

namespace cyclecert {

std::unique_ptr<Engine> makeReferenceEngine();
std::unique_ptr<Engine> makeProcessEngine(const std::string& command, const EngineOptions& options);
// nullptr for an unknown fault name.
std::unique_ptr<Engine> makeMutantEngine(const std::string& fault);
// Every seeded fault: name and what it gets wrong.
const std::vector<std::pair<std::string, std::string>>& mutantFaults();

}  // namespace cyclecert
