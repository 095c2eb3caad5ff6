#pragma once
// `fuzz --metamorphic`: a generated case judged by the oracles (judgeFuzzResult) and then, when
// nothing failed yet, by the metamorphic relations (harness/judge/metamorphic_run.h) — the engine against
// itself. A violation fails the case with kind "metamorphic:<relation>", which the shrinker keeps
// like any other kind; a follow-up the engine fails on makes the case an engine failure.
#include "harness/fuzz/fuzz_run.h"
#include "harness/judge/metamorphic_run.h"

namespace cyclecert {

// The relations run only on a case whose source the engine planned or alarmed on and that neither
// the oracles nor the comparison with `vs` failed (its failure is known; the first kind is the one
// shrunk). The case's counts go into `tally` when it is given.
FuzzVerdict judgeFuzzResultWithRelations(EngineResult r, Engine& engine, Engine* vs, const SpecCase& c, double tolerance,
                                         MetamorphicTally* tally);

}  // namespace cyclecert
