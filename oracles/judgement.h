#pragma once
// Engine-independent judgement of a toolpath (DESIGN.md "Oracles"): each oracle has an ID, serves
// rule IDs and reports findings that name the move index and carry a witness to draw.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "oracles/cycle_spec.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// The stock the cycle works on: a bar (diameter, length from a front face), an explicit polygon in
// plane coordinates (z, x radius), or implied by the cycle (the region between the start point's
// level and the shape over the shape's span).
struct Stock {
  enum Kind { Implied, Bar, Polygon } kind = Implied;
  double diameter = 0, length = 0, frontZ = 0;  // Bar: x ∈ [0, diameter/2], z ∈ [frontZ − length, frontZ]
  std::vector<Point> outline;                   // Polygon: closed, counter-clockwise or not
};

// Geometry a finding points at, for the plots: regions (the gouged part, the material a rapid
// crossed, what remains), a segment, or a point.
struct Witness {
  std::vector<std::vector<Point>> regions;
  std::optional<Segment> segment;
  std::optional<Point> point;
};

struct Finding {
  std::string oracle;               // "no-gouge", "rapids-in-air", …
  std::vector<std::string> rules;   // the rule IDs the oracle serves
  std::optional<std::size_t> move;  // index into the toolpath's moves
  std::string message;
  Witness witness;
};

struct JudgeSettings {
  double epsilon = 1e-3;         // mm: what the oracles tolerate (the spec cases' tolerance)
  double chordTolerance = 1e-3;  // mm: arcs are flattened within this
  // What every verdict tolerates: epsilon plus twice the chord tolerance, since a measure between
  // two flattened boundaries (a move and the material) can be off by the chord error of each.
  double tolerance() const { return epsilon + 2 * chordTolerance; }
};

struct JudgeInput {
  ProgramSpec program;
  Stock stock;
  Toolpath path;
  JudgeSettings settings;
};

struct MaterialReplay;  // oracles/material_replay.h
struct GrooveReplay;    // oracles/groove/groove_replay.h
struct SiemensCycleMoves;  // oracles/siemens/siemens_moves.h

// What the oracles see: the input, and the material replay computed once for all of them (null
// when the program is not one the geometric oracles judge) — for a G74.1 program the groove's
// replay with the tool's shape instead.
struct JudgeContext {
  const JudgeInput& in;
  const MaterialReplay* replay = nullptr;
  const GrooveReplay* groove = nullptr;
  // A SINUMERIK program's calls and their moves (oracles/siemens/siemens_moves.h), found once for
  // all the Siemens oracles.
  const std::vector<SiemensCycleMoves>* siemensCalls = nullptr;
};

class Oracle {
 public:
  virtual ~Oracle() = default;
  virtual std::string id() const = 0;
  virtual std::vector<std::string> rules() const = 0;
  // Whether the oracle judges a roughing cycle of this family (its rules apply to it); judge() skips
  // it for a program whose one roughing cycle (or SINUMERIK program) it does not judge. How it
  // judges each family is in its comment and oracles/README.md (depth-per-pass: Δd for G71/G72, the
  // division step for G73). By default the FANUC families; the SINUMERIK oracles (oracles/siemens/,
  // siemens-alarm) judge LCYC95 and CYCLE95; the groove oracles (oracles/groove/) and alarm, feeds,
  // no-gouge, rapids-in-air and complete judge G74.1.
  virtual bool judges(CycleFamily family) const { return !isSiemensFamily(family) && family != CycleFamily::G74_1; }
  virtual void judge(const JudgeContext& ctx, std::vector<Finding>& findings) const = 0;
};

// Every oracle, in a stable order.
const std::vector<std::unique_ptr<Oracle>>& allOracles();

// Runs every oracle and returns the findings, oracle by oracle, at most kMostFindingsPerOracle of
// each (the last one says how many more). A path the oracles cannot measure — its arcs would take
// more than kMostChordsPerPath chords in all (or one arc more than kMostChordsPerArc), or geometry
// the material model refuses — gives the one finding `measurable` (PROG.CAP) instead of a verdict.
std::vector<Finding> judge(const JudgeInput& in);

// README "Limits".
inline constexpr std::size_t kMostFindingsPerOracle = 100;
inline constexpr double kMostChordsPerPath = 10'000'000;
inline constexpr const char* kMeasurableOracle = "measurable";

}  // namespace cyclecert
