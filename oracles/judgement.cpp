#include "oracles/judgement.h"

#include <algorithm>
#include <map>
#include <stdexcept>

#include "oracles/groove/groove_replay.h"
#include "oracles/material/region.h"
#include "oracles/material_replay.h"
#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/gcode/program_limits.h"

namespace cyclecert {

const std::vector<std::unique_ptr<Oracle>>& allOracles() {
  static const std::vector<std::unique_ptr<Oracle>> oracles = makeOracles();
  return oracles;
}

namespace {

Finding unmeasurable(std::optional<std::size_t> move, std::string message) {
  return Finding{kMeasurableOracle, {"PROG.CAP"}, move, std::move(message) + "; the path is not judged", {}};
}

// Whether the path's arcs surely stay within PROG.CAP's limits, found without their angles: each
// arc bounded by the chords of a full circle of its radius (mostChordsToFlatten). Nearly every path
// is; only the others are counted exactly.
bool surelyMeasurable(const Toolpath& path, double finest) {
  double total = 0;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    if (path.moves[i].shape == SegmentKind::Line) continue;
    const double most = mostChordsToFlatten(path.segment(i), finest);
    if (!(most <= kMostChordsPerArc)) return false;  // also for a radius that is no number
    total += most;
  }
  return total <= kMostChordsPerPath;
}

// PROG.CAP (README "Limits"): the oracles flatten the path's arcs — the material model at the
// chord tolerance, the depth of a layer at kMeasuringChord — so a path whose arcs would take more
// than kMostChordsPerArc chords each or kMostChordsPerPath in all is reported rather than measured
// for minutes: arcs of hundreds of metres, which no lathe cycle's shape makes.
std::optional<Finding> pathTooLargeToMeasure(const Toolpath& path, const JudgeSettings& settings) {
  const double finest = std::min(settings.chordTolerance, kMeasuringChord);
  if (surelyMeasurable(path, finest)) return std::nullopt;
  double total = 0;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    if (path.moves[i].shape == SegmentKind::Line) continue;
    const Segment arc = path.segment(i);
    const double chords = chordsToFlatten(arc, finest);
    total += chords;
    if (chords > kMostChordsPerArc) {
      return unmeasurable(i, "an arc of radius " + std::to_string(arc.radius()) + " mm would take " +
                                 countText(chords) + " chords of " + std::to_string(finest) +
                                 " mm to measure; the oracles measure arcs of at most " +
                                 countText(kMostChordsPerArc) + " chords");
    }
    if (total > kMostChordsPerPath) {
      return unmeasurable(i, "the path's arcs up to this move would take " + countText(total) + " chords of " +
                                 std::to_string(finest) + " mm to measure; the oracles measure at most " +
                                 countText(kMostChordsPerPath) + " in a path");
    }
  }
  return std::nullopt;
}

// README "Limits": at most kMostFindingsPerOracle findings of one oracle are listed (a path failing
// every pass repeats one finding per pass); the last one says how many more there were.
void boundFindingsPerOracle(std::vector<Finding>& findings) {
  std::map<std::string, std::size_t> count;
  for (const Finding& f : findings) ++count[f.oracle];
  std::map<std::string, std::size_t> kept;
  std::vector<Finding> out;
  for (Finding& f : findings) {
    const std::size_t k = ++kept[f.oracle];
    if (k > kMostFindingsPerOracle) continue;
    if (k == kMostFindingsPerOracle && count[f.oracle] > k) {
      f.message += " (and " + groupedCount(count[f.oracle] - k) + " more " + f.oracle +
                   " findings, not listed: cyclecert lists " + std::to_string(kMostFindingsPerOracle) +
                   " per oracle)";
    }
    out.push_back(std::move(f));
  }
  findings = std::move(out);
}

}  // namespace

std::vector<Finding> judge(const JudgeInput& in) {
  if (auto tooLarge = pathTooLargeToMeasure(in.path, in.settings)) return {std::move(*tooLarge)};
  const std::optional<CycleFamily> family = in.program.judgedFamily();
  const bool groove = family == CycleFamily::G74_1;
  std::vector<Finding> findings;
  try {
    const std::optional<MaterialReplay> replay = groove ? std::nullopt : replayMaterial(in);
    const std::optional<GrooveReplay> grooveReplay = groove ? replayGroove(in) : std::nullopt;
    const std::vector<SiemensCycleMoves> siemensCalls = siemensCallsMoves(in);
    const JudgeContext ctx{in, replay ? &*replay : nullptr, grooveReplay ? &*grooveReplay : nullptr, &siemensCalls};
    for (const auto& oracle : allOracles()) {
      if (!family || oracle->judges(*family)) oracle->judge(ctx, findings);
    }
  } catch (const std::invalid_argument& e) {
    // Geometry the material model cannot take (Boost refusing a region, say): said, never a pass.
    return {unmeasurable(std::nullopt, std::string("the oracles cannot measure this path: ") + e.what())};
  }
  boundFindingsPerOracle(findings);
  return findings;
}

}  // namespace cyclecert
