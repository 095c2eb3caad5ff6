#pragma once
// Metamorphic relations (DESIGN.md "Oracles"): a program is transformed in a way whose effect on a
// correct toolpath is known, so an engine is judged against itself — no expected toolpath needed.
// A relation turns a *source* program (and its parameter settings) into a *follow-up* program, and
// says what the follow-up's toolpath must be, given the source's: mirror it, translate it, scale
// it, or leave it as it is.
//
// The relations read and write words only (oracles/metamorphic/lathe_program.h lists the
// vocabulary); they never plan. Running both programs through an engine is the caller's business
// (the tests and the harness). See oracles/metamorphic/README.md for each relation.
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "oracles/metamorphic/lathe_program.h"
#include "oracles/metamorphic/siemens_words.h"
#include "reference/model/program.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

// What a relation makes of one source case.
struct FollowUp {
  Program program;
  ParamSettings params;  // the complete settings for the follow-up (the source's, changed or added to)
  // The source's toolpath → what the follow-up's must be. It belongs to the follow-up, not to the
  // relation, because some relations choose a constant from the program (the mirror line of
  // mirror-x, the shift that keeps radii positive in transpose).
  std::function<Toolpath(const Toolpath&)> expectedPath;
  std::string profile;  // the profile the follow-up runs under; empty: the source's (hnc-one-block: "hnc")
  // SINUMERIK follow-ups (Relation::transformSiemens): the main program and the subprograms as text,
  // run with the source's profile; `program` is then empty.
  std::optional<SiemensSource> siemens = std::nullopt;
};

using PathComparison =
    std::function<std::optional<std::string>(const Toolpath& expected, const Toolpath& actual, double tol)>;

// What the harness knows of a source's run that a relation cannot read from the program.
struct SourceRun {
  std::string profile;      // the profile the source ran under
  bool noseRadius = false;  // its tool has a nose radius: a compensated path
  std::string alarm;        // the alarm code the engine raised on it; empty when it planned
};

struct Relation {
  std::string id;           // "mirror-z", …
  std::string description;  // what it does, the words it handles and what it refuses
  std::vector<std::string> rules;  // the rule IDs it serves (specs/rules.json)
  // The follow-up, or nothing with the reason in whyNot when the program is outside what the
  // relation handles (a word it does not know, a G72 cycle for a G71-only relation, …).
  std::function<std::optional<FollowUp>(const Program& source, const ParamSettings& params, std::string& whyNot)>
      transform;
  // The same for a SINUMERIK source (siemens_words.h: a main program and its contour subprograms as
  // text, which the FANUC reader cannot read); empty for a relation that does not handle them
  // (translate-z, translate-x and scale-k do). The follow-up carries its texts in FollowUp::siemens.
  std::function<std::optional<FollowUp>(const SiemensSource& source, const ParamSettings& params, std::string& whyNot)>
      transformSiemens = nullptr;
  // compareToolpaths, or compareGeometry for split-segment.
  PathComparison compare;
  // The sources the relation cannot judge although it transforms their program — a limit its
  // description states —, from how they ran; empty: none beyond relationJudges' common one.
  std::function<bool(const SourceRun&)> outside = nullptr;
};

// Whether the relation judges a follow-up of a source that ran so: never when the source alarmed
// PS0003 (a word out of its range: every relation rewrites words — ÷ 25.4, into a parameter, into
// another format — and the alarm goes with the word), nor where the relation's `outside` says so.
bool relationJudges(const Relation& r, const SourceRun& run);

// Every relation, in a stable order: mirror-z, mirror-x, translate-z, translate-x, scale-k,
// split-segment, abs-inc, r-ik, plane-g17, plane-g19, metric-inch, param-default, transpose,
// fs10-one-block, hnc-one-block, haas-one-block, gsys-b, gsys-c (format_relations.h).
const std::vector<Relation>& allRelations();
const Relation* findRelation(std::string_view id);

// The verdict on one pair of runs: relation.compare(followUp.expectedPath(source), actual, tol).
std::optional<std::string> checkRelation(const Relation& relation, const FollowUp& followUp, const Toolpath& source,
                                         const Toolpath& actual, double tol);

// The relations with another constant than the registered one (scale-k uses k = 2.5, translate-z
// dz = 12.5 mm, translate-x dx = 5 mm on the radius).
Relation scaleRelation(double k);
Relation translateZRelation(double dz);
Relation translateXRelation(double dxRadius);  // dxRadius ≥ 0: outwards, radii stay positive

// split-segment's work on one block: the shape block (a roughing cycle's ns+1…nf) at blockIndex
// becomes two blocks meeting at its midpoint (lines) or mid-angle point (arcs, same centre and
// direction). Nothing, with the reason, for a block that is not such a block or does not move.
std::optional<Program> splitBlock(const Program& source, std::size_t blockIndex, std::string& whyNot);

// The expected-path building block of the geometric relations: every point (start, end points,
// centres) through `map`; arcs change direction when `mirrors` (the map reverses orientation).
Toolpath mapToolpath(const Toolpath& path, const std::function<Point(Point)>& map, bool mirrors);

}  // namespace cyclecert
