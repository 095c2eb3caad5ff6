#pragma once
// The metamorphic relations (oracles/metamorphic) run against an engine: `check`, `fuzz` and `diff`
// with --metamorphic. For one case whose source toolpath the engine already gave, every relation
// transforms the case's program; each follow-up runs through the SAME engine, and its toolpath must
// be the relation's expected transformation of the source's. No reference and no expected toolpath
// are needed: the engine is judged against itself.
//
// Per case and relation exactly one of:
//   skipped        the relation does not apply to the program (it says why: a word it does not
//                  handle, a G72 cycle for a G71-only relation, …), or the engine answered "not
//                  applicable" on the follow-up (a format or dialect it does not support);
//   held           the follow-up's toolpath is the expected one;
//   violated       it is not: a finding `metamorphic:<relation>` with the relation's rule IDs;
//   engine failure the engine crashed, hung or garbled its reply on the follow-up — reported as
//                  an engine failure, never as a violation.
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "harness/engines/engine.h"
#include "harness/results/results_file.h"
#include "harness/spec/spec_case.h"
#include "oracles/judgement.h"
#include "oracles/metamorphic/relations.h"
#include "reports/svg/toolpath_svg.h"

namespace cyclecert {

// The finding kind (Finding::oracle) of a relation's violation: "metamorphic:<relation id>".
std::string metamorphicKind(const std::string& relationId);
bool isMetamorphicKind(const std::string& kind);

// What happened to one relation over the cases of a run.
struct RelationCount {
  long held = 0, violated = 0, engineFailure = 0;
  long doesNotApply = 0;  // the relation refused the program
  long notSupported = 0;  // the engine answered "not applicable" on the follow-up
  long run() const { return held + violated + engineFailure; }  // follow-ups the engine planned or failed on
  long skipped() const { return doesNotApply + notSupported; }
};

struct MetamorphicTally {
  std::map<std::string, RelationCount> byRelation;  // relation id → its counts
  RelationCount total() const;
  void add(const MetamorphicTally& other);
};

// {"relations": {"mirror-z": {"run", "held", "violated", "engine_failure", "skipped",
// "does_not_apply", "not_supported"}, …}, "total": {…}}
nlohmann::json tallyJson(const MetamorphicTally& tally);
MetamorphicTally tallyFromJson(const nlohmann::json& j);  // the inverse; throws on another shape
// One line: "metamorphic relations: R follow-ups run (V violated, F engine failures), S skipped
// (A not applicable to the program, N not supported by the engine)".
std::string tallyText(const MetamorphicTally& tally);
// OUT/metamorphic.json: the tally of the run (with `resume`, added to the tally already there).
void writeTallyFile(const std::string& outDir, const MetamorphicTally& tally, bool resume);

// The way back from a follow-up's coordinates to the source's, when the relation's expected path is
// an affine map of points (mirror, translate, scale, transpose; the identity for the relations that
// rewrite words only): found by mapping probe points through the relation's expectedPath.
struct BackMap {
  std::function<Point(Point)> map;
  bool mirrors = false;   // the map reverses orientation: arcs change direction
  bool identity = false;  // the follow-up's path should be the source's as it is
};

// The relation's way back, or nothing when its expected path is no affine map of points.
std::optional<BackMap> backMapOf(const FollowUp& followUp);

// One relation the engine's follow-up violated: both programs, both paths, the first divergence.
struct MetamorphicViolation {
  std::string relation;              // its id
  std::vector<std::string> rules;    // the relation's rule IDs
  SpecCase followUp;                 // the follow-up case as run (program, profile, parameters)
  Toolpath source;                   // the engine's toolpath of the source case
  Toolpath expected;                 // the relation's transformation of `source`
  EngineResult actual;               // the engine's result on the follow-up
  std::string divergence;            // the first divergence, for a person
  std::optional<std::size_t> move;   // the first move of `actual` that parts from `expected`, if any
  SpecCase sourceCase;               // the source case, for drawing on its contours
  std::optional<BackMap> back;       // nothing when the expected path is no map of points
};

struct RelationsVerdict {
  std::vector<Finding> findings;                 // one per violated relation, in relation order
  std::vector<MetamorphicViolation> violations;  // the same, with the paths
  std::optional<std::string> engineFailure;      // the first follow-up the engine failed on, said
  MetamorphicTally tally;                        // this case's counts
};

// The follow-up case of a relation: the source case (its tool, mode, subprograms, rules) with the
// follow-up's program, profile and parameters, no stock (the relations move the part) and no
// expectation but the oracles' ({"oracles": "pass"}) — a whole valid case, since process engines
// receive it as JSON. A SINUMERIK follow-up brings its own contour subprograms.
SpecCase followUpCase(const SpecCase& source, const std::string& relationId, const std::string& programText,
                      const std::string& profile, const std::vector<std::pair<std::string, double>>& params,
                      const std::optional<std::vector<std::pair<std::string, std::string>>>& subprograms = std::nullopt);

// Every relation on case `source`, whose toolpath (or alarm) the engine gave as `sourcePath`; the
// follow-ups run through `engine` in one batch. Lengths agree within `tolerance` (mm).
RelationsVerdict checkRelations(Engine& engine, const SpecCase& source, const Toolpath& sourcePath, double tolerance);

// `diff`'s use: one engine's relations on a case, for a person — the counts, then each violation
// (relation, rules, divergence, follow-up program) and the engine failure if any — and as JSON:
// {"counts": tallyJson's "total", "violations": [{"relation", "rules", "divergence", "move",
// "follow_up": {"profile", "program"}}], "engine_failure": null | text}.
std::string relationsText(const std::string& engineName, const RelationsVerdict& v);
nlohmann::ordered_json relationsJson(const RelationsVerdict& v);
bool relationsClean(const RelationsVerdict& v);  // no violation and no engine failure

// `check`'s use: the relations' findings appended to `out` (verdict "fail", the detail the first
// finding's when it has none yet); a follow-up engine failure turns an otherwise passing result into
// an engine failure. The case's counts go into `tally`. Returns the first violation, for the plot.
std::optional<MetamorphicViolation> addRelationVerdicts(Engine& engine, const SpecCase& source, const EngineResult& r,
                                                        CaseResult& out, MetamorphicTally& tally);

// The command that shows a case's failure with its relations again: `cyclecert diff --engine E --vs B
// FILE --metamorphic`, B being the engine the case must agree with, else the reference (whose
// relations on the same case are shown alongside; E may be the reference itself).
std::string metamorphicReproduceCommand(const std::string& engine, const std::string& caseFile,
                                        const std::string& agreesWith);

// The picture of a violation, in the source's coordinates when the relation maps points (`back`):
// the source's contours, the engine's source path, and over it the follow-up's path mapped back
// onto the source, both labelled, the first divergence ringed. Otherwise (hnc-one-block drops a
// move) in the follow-up's: its contours, the engine's follow-up path and over it the path the
// relation expects.
std::optional<PlotInput> metamorphicPlot(const MetamorphicViolation& v, const std::string& engineName, double tolerance);

}  // namespace cyclecert
