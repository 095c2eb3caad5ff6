#pragma once
// A spec case (specs/README.md): a program, its profile and parameters, and the hand-derived
// expectation — a whole toolpath or an alarm.
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct ExpectedAlarm {
  std::string code;
  std::optional<int> line;
  std::optional<std::string> when;  // "cycle block", "before the cycle", "during the cycle"
};

// The stock a case names: a bar (diameter, length, front face at frontZ) or a polygon (z, x radius).
struct CaseStock {
  bool bar = true;
  double diameter = 0, length = 0, frontZ = 0;
  std::vector<Point> outline;
};

struct SpecCase {
  std::string file;
  std::string id;
  std::string title;
  std::vector<std::string> rules;
  std::string profile;
  std::vector<std::pair<std::string, double>> params;  // in file order
  std::string program;
  std::optional<std::vector<Move>> expectedMoves;
  double tolerance = 0.001;
  std::vector<std::string> expectedWarnings;  // substrings, each in one of the warnings
  std::optional<ExpectedAlarm> expectedAlarm;
  // {"oracles": "pass"}: no expected toolpath or alarm — the oracles judge whatever the engine does
  // (a shrunk fuzz case in corpus/regressions). With "agrees_with": ENGINE, the engine's result
  // must also agree with that built-in engine's, run at the same time (never a recorded copy).
  bool oraclesOnly = false;
  std::optional<std::string> agreesWith;
  std::optional<ToolOffset> tool;             // the active tool's nose radius and tip direction
  bool mdi = false;                           // the program runs in MDI mode
  std::optional<CaseStock> stock;             // explicit stock (else implied by the cycle)
  // SINUMERIK profiles (SIEMENS.SUB): the contour subprograms the program names, name → text
  // ("subprograms": {"L42": "G1X0Z0\n…\nM02\n"}), by name.
  std::vector<std::pair<std::string, std::string>> subprograms;
  nlohmann::json raw;                         // the case as written (what a process engine receives)
  std::string derivation;
};

// A case file that is not a valid spec case: names the file and the field (JSON pointer).
class SpecError : public std::runtime_error {
 public:
  SpecError(const std::string& file, const std::string& field, const std::string& expected);
};

SpecCase parseSpecCase(const std::string& jsonText, const std::string& file);
// The same for a case already parsed as JSON (the fuzzer's cases); the JSON becomes the case's raw.
SpecCase specCaseFrom(nlohmann::json j, const std::string& file);
SpecCase loadSpecCase(const std::string& path);

// Every *.json file under a directory, sorted.
std::vector<std::string> findSpecCaseFiles(const std::string& dir);

}  // namespace cyclecert
