#include "harness/fuzz/fuzz_relations.h"

#include <utility>

namespace cyclecert {

FuzzVerdict judgeFuzzResultWithRelations(EngineResult r, Engine& engine, Engine* vs, const SpecCase& c, double tolerance,
                                         MetamorphicTally* tally) {
  std::optional<Toolpath> source;
  if (hasOutcome(r)) source = r.path;
  FuzzVerdict v = judgeFuzzResult(std::move(r), engine, vs, c, tolerance);
  if (!source || v.verdict == "fail" || v.verdict == "engine-failure") return v;
  RelationsVerdict relations = checkRelations(engine, c, *source, tolerance);
  if (tally) tally->add(relations.tally);
  if (!relations.findings.empty()) {
    v.verdict = "fail";
    v.kind = relations.findings.front().oracle;
    v.detail = v.kind + ": " + relations.findings.front().message;
    v.findings = std::move(relations.findings);
    v.violation = std::move(relations.violations.front());
  } else if (relations.engineFailure) {
    v.verdict = v.kind = "engine-failure";
    v.detail = *relations.engineFailure;
  }
  return v;
}

}  // namespace cyclecert
