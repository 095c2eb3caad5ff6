#include "harness/judge/metamorphic_run.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "harness/judge/toolpath_compare.h"
#include "harness/results/failure_plot.h"
#include "harness/run/reproduce.h"
#include "harness/spec/program_case.h"
#include "oracles/metamorphic/relations.h"
#include "reference/gcode/parser.h"
#include "reference/gcode/writer.h"
#include "reference/model/alarms.h"
#include "reference/model/profile.h"
#include "reports/svg/plot_json.h"

namespace cyclecert {

namespace {

constexpr const char* kKindPrefix = "metamorphic:";

nlohmann::json countJson(const RelationCount& c) {
  return {{"run", c.run()},
          {"held", c.held},
          {"violated", c.violated},
          {"engine_failure", c.engineFailure},
          {"skipped", c.skipped()},
          {"does_not_apply", c.doesNotApply},
          {"not_supported", c.notSupported}};
}

RelationCount countFromJson(const nlohmann::json& j) {
  RelationCount c;
  c.held = j.at("held").get<long>();
  c.violated = j.at("violated").get<long>();
  c.engineFailure = j.at("engine_failure").get<long>();
  c.doesNotApply = j.at("does_not_apply").get<long>();
  c.notSupported = j.at("not_supported").get<long>();
  return c;
}

void addCount(RelationCount& into, const RelationCount& c) {
  into.held += c.held;
  into.violated += c.violated;
  into.engineFailure += c.engineFailure;
  into.doesNotApply += c.doesNotApply;
  into.notSupported += c.notSupported;
}

// A program as one line (its blocks end with ';'), for a finding's message.
std::string oneLine(const std::string& programText) {
  std::string s;
  for (char c : programText) s += c == '\n' ? ' ' : c;
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// How the source ran, for the relations' limits (relationJudges).
SourceRun sourceRun(const SpecCase& source, const Toolpath& sourcePath) {
  return {source.profile, source.tool && source.tool->noseRadius > 0, sourcePath.alarm ? sourcePath.alarm->code : ""};
}

// A relation's transformation of the source, or nothing (counted as not applying).
struct PlannedFollowUp {
  const Relation* relation;
  FollowUp followUp;
  SpecCase c;
};

// A SINUMERIK case: its main program and contour subprograms are read by the relations'
// transformSiemens (the FANUC reader cannot read them).
bool isSiemensCase(const SpecCase& c) {
  const Profile* p = findProfile(c.profile);
  return p && p->dialect == Dialect::Siemens;
}

// The relation's follow-up of the source, or nothing (whyNot says why when the relation refuses).
std::optional<FollowUp> transformed(const Relation& r, const SpecCase& source, const std::optional<Program>& program,
                                    std::string& whyNot) {
  try {
    if (isSiemensCase(source)) {
      if (!r.transformSiemens) return std::nullopt;
      return r.transformSiemens(SiemensSource{source.program, source.subprograms}, source.params, whyNot);
    }
    if (program) return r.transform(*program, source.params, whyNot);
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

std::vector<PlannedFollowUp> followUpsOf(const SpecCase& source, const Toolpath& sourcePath, MetamorphicTally& tally) {
  std::vector<PlannedFollowUp> out;
  std::optional<Program> program;
  if (!isSiemensCase(source)) {
    try {
      program = parseProgram(source.program, source.file);
    } catch (const std::exception&) {
      // A program the G code reader refuses: no relation reads it.
    }
  }
  const SourceRun run = sourceRun(source, sourcePath);
  for (const Relation& r : allRelations()) {
    RelationCount& count = tally.byRelation[r.id];
    std::string whyNot;
    std::optional<FollowUp> f = transformed(r, source, program, whyNot);
    if (!f || !relationJudges(r, run)) {
      ++count.doesNotApply;
      continue;
    }
    const std::string profile = f->profile.empty() ? source.profile : f->profile;
    try {
      SpecCase c = f->siemens ? followUpCase(source, r.id, f->siemens->program, profile, f->params, f->siemens->subprograms)
                              : followUpCase(source, r.id, writeProgram(f->program), profile, f->params);
      out.push_back({&r, std::move(*f), std::move(c)});
    } catch (const std::exception&) {
      ++count.doesNotApply;  // a follow-up that is no valid case (a parameter the profile refuses)
    }
  }
  return out;
}

// The probe: three feed lines from the origin, so that an affine map shows in where they end.
constexpr Point kProbeU{1, 0}, kProbeV{0, 1}, kProbeCheck{0.37, 0.61};

Toolpath probePath() {
  Toolpath t;
  for (Point p : {kProbeU, kProbeV, kProbeCheck}) {
    Move m;
    m.kind = MoveKind::Feed;
    m.to = p;
    m.feed = 1;
    t.moves.push_back(m);
  }
  return t;
}

Finding violationFinding(const MetamorphicViolation& v) {
  Finding f;
  f.oracle = metamorphicKind(v.relation);
  f.rules = v.rules;
  // No move or witness: they would index the source's path, and the divergence is in the
  // follow-up's (metamorphicPlot draws it there).
  f.message = "the follow-up's toolpath is not the relation's transformation of the source's: " + v.divergence +
              " | follow-up program (profile " + v.followUp.profile + "): " + oneLine(v.followUp.program);
  return f;
}

}  // namespace

std::optional<BackMap> backMapOf(const FollowUp& f) {
  Toolpath mapped;
  try {
    mapped = f.expectedPath(probePath());
  } catch (const std::exception&) {
    return std::nullopt;
  }
  if (mapped.moves.size() != 3) return std::nullopt;
  const Point o = mapped.start, u = mapped.moves[0].to - o, v = mapped.moves[1].to - o;
  const auto forward = [=](Point p) { return o + p.z * u + p.x * v; };
  if (!nearlyEqual(forward(kProbeCheck), mapped.moves[2].to, 1e-9)) return std::nullopt;
  const double det = u.z * v.x - v.z * u.x;
  if (std::abs(det) < 1e-12) return std::nullopt;
  BackMap back;
  back.mirrors = det < 0;
  back.identity = nearlyEqual(o, Point{}, 1e-12) && nearlyEqual(u, kProbeU, 1e-12) && nearlyEqual(v, kProbeV, 1e-12);
  back.map = [=](Point q) {
    const Point d = q - o;  // solve d = a·u + b·v
    return Point{(d.z * v.x - v.z * d.x) / det, (u.z * d.x - d.z * u.x) / det};
  };
  return back;
}

std::string metamorphicKind(const std::string& relationId) { return kKindPrefix + relationId; }

bool isMetamorphicKind(const std::string& kind) { return kind.rfind(kKindPrefix, 0) == 0; }

RelationCount MetamorphicTally::total() const {
  RelationCount t;
  for (const auto& [id, c] : byRelation) addCount(t, c);
  return t;
}

void MetamorphicTally::add(const MetamorphicTally& other) {
  for (const auto& [id, c] : other.byRelation) addCount(byRelation[id], c);
}

nlohmann::json tallyJson(const MetamorphicTally& tally) {
  nlohmann::json relations = nlohmann::json::object();
  for (const auto& [id, c] : tally.byRelation) relations[id] = countJson(c);
  return {{"relations", relations}, {"total", countJson(tally.total())}};
}

MetamorphicTally tallyFromJson(const nlohmann::json& j) {
  MetamorphicTally t;
  for (const auto& [id, c] : j.at("relations").items()) t.byRelation[id] = countFromJson(c);
  return t;
}

std::string tallyText(const MetamorphicTally& tally) {
  const RelationCount t = tally.total();
  std::ostringstream s;
  s << "metamorphic relations: " << t.run() << " follow-ups run (" << t.violated << " violated, " << t.engineFailure
    << " engine failure(s)), " << t.skipped() << " skipped (" << t.doesNotApply << " not applicable to the program, "
    << t.notSupported << " not supported by the engine)";
  return s.str();
}

void writeTallyFile(const std::string& outDir, const MetamorphicTally& tally, bool resume) {
  const std::string path = outDir + "/metamorphic.json";
  MetamorphicTally all = tally;
  if (resume && std::filesystem::is_regular_file(path)) {
    try {
      std::ifstream in(path);
      all.add(tallyFromJson(nlohmann::json::parse(in)));
    } catch (const std::exception&) {
      // A torn file from a killed run: this run's counts only.
    }
  }
  std::ofstream out(path, std::ios::trunc);
  out << tallyJson(all).dump(2) << "\n";
  if (!out) throw std::runtime_error(path + ": cannot write the metamorphic relations' counts");
}

SpecCase followUpCase(const SpecCase& source, const std::string& relationId, const std::string& programText,
                      const std::string& profile, const std::vector<std::pair<std::string, double>>& params,
                      const std::optional<std::vector<std::pair<std::string, std::string>>>& subprograms) {
  nlohmann::json j = source.raw.is_object() ? source.raw : nlohmann::json::object();
  if (subprograms) {
    nlohmann::json subs = nlohmann::json::object();
    for (const auto& [name, text] : *subprograms) subs[name] = text;
    j["subprograms"] = subs;
  }
  j["id"] = source.id + "/metamorphic-" + relationId;
  j["title"] = "follow-up of " + source.id + " by the metamorphic relation " + relationId;
  if (!j.contains("rules")) j["rules"] = source.rules;
  j["profile"] = profile;
  nlohmann::json p = nlohmann::json::object();
  for (const auto& [name, value] : params) p[name] = value;
  j["params"] = p;
  j["program"] = programText;
  j["expect"] = everyOracleExpectation();
  j.erase("stock");
  j["derivation"] = "written by the metamorphic relation " + relationId + " (oracles/metamorphic) from " + source.id +
                    "; its toolpath must be the relation's transformation of the source's";
  return specCaseFrom(std::move(j), source.file);
}

RelationsVerdict checkRelations(Engine& engine, const SpecCase& source, const Toolpath& sourcePath, double tolerance) {
  RelationsVerdict v;
  std::vector<PlannedFollowUp> followUps = followUpsOf(source, sourcePath, v.tally);
  if (followUps.empty()) return v;
  std::vector<SpecCase> cases;
  for (const PlannedFollowUp& f : followUps) cases.push_back(f.c);
  std::vector<EngineResult> results = engine.runBatch(cases);
  for (std::size_t i = 0; i < followUps.size(); ++i) {
    const Relation& r = *followUps[i].relation;
    RelationCount& count = v.tally.byRelation[r.id];
    EngineResult& actual = results[i];
    if (actual.kind == EngineResult::NotApplicable) {
      ++count.notSupported;
      continue;
    }
    if (actual.kind == EngineResult::Failed) {
      ++count.engineFailure;
      if (!v.engineFailure) {
        v.engineFailure = "engine failure on the follow-up of metamorphic relation " + r.id + ": " + actual.detail +
                          " | follow-up program (profile " + followUps[i].c.profile +
                          "): " + oneLine(followUps[i].c.program);
      }
      continue;
    }
    const FollowUp& f = followUps[i].followUp;
    const auto divergence = checkRelation(r, f, sourcePath, actual.path, tolerance);
    if (!divergence) {
      ++count.held;
      continue;
    }
    ++count.violated;
    MetamorphicViolation violation;
    violation.relation = r.id;
    violation.rules = r.rules;
    violation.followUp = followUps[i].c;
    violation.source = sourcePath;
    violation.expected = f.expectedPath(sourcePath);
    violation.actual = std::move(actual);
    violation.divergence = *divergence;
    if (const auto d = firstMoveDivergence(violation.expected.moves, violation.actual.path.moves, tolerance)) {
      violation.move = d->move;
    }
    violation.sourceCase = source;
    violation.back = backMapOf(f);
    v.findings.push_back(violationFinding(violation));
    v.violations.push_back(std::move(violation));
  }
  return v;
}

std::string relationsText(const std::string& engineName, const RelationsVerdict& v) {
  const RelationCount t = v.tally.total();
  std::ostringstream s;
  s << "metamorphic relations on " << engineName << ": " << t.run() << " run, " << t.held << " held, " << t.violated
    << " violated, " << t.engineFailure << " engine failure(s), " << t.skipped() << " skipped (" << t.doesNotApply
    << " not applicable to the program, " << t.notSupported << " not supported by the engine)\n";
  for (const MetamorphicViolation& m : v.violations) {
    s << "  " << metamorphicKind(m.relation) << " (";
    for (std::size_t i = 0; i < m.rules.size(); ++i) s << (i ? ", " : "") << m.rules[i];
    s << "): " << m.divergence << "\n    follow-up program (profile " << m.followUp.profile
      << "): " << oneLine(m.followUp.program) << "\n";
  }
  if (v.engineFailure) s << "  " << *v.engineFailure << "\n";
  return s.str();
}

nlohmann::ordered_json relationsJson(const RelationsVerdict& v) {
  using nlohmann::ordered_json;
  const RelationCount t = v.tally.total();
  ordered_json out = {{"counts",
                       {{"run", t.run()},
                        {"held", t.held},
                        {"violated", t.violated},
                        {"engine_failure", t.engineFailure},
                        {"skipped", t.skipped()},
                        {"does_not_apply", t.doesNotApply},
                        {"not_supported", t.notSupported}}},
                      {"violations", ordered_json::array()},
                      {"engine_failure", v.engineFailure ? ordered_json(*v.engineFailure) : ordered_json(nullptr)}};
  for (const MetamorphicViolation& m : v.violations) {
    out["violations"].push_back({{"relation", m.relation},
                                 {"rules", m.rules},
                                 {"divergence", m.divergence},
                                 {"move", m.move ? ordered_json(*m.move) : ordered_json(nullptr)},
                                 {"follow_up", {{"profile", m.followUp.profile}, {"program", m.followUp.program}}}});
  }
  return out;
}

bool relationsClean(const RelationsVerdict& v) { return v.violations.empty() && !v.engineFailure; }

std::optional<MetamorphicViolation> addRelationVerdicts(Engine& engine, const SpecCase& source, const EngineResult& r,
                                                        CaseResult& out, MetamorphicTally& tally) {
  if (r.kind != EngineResult::Planned && r.kind != EngineResult::Alarmed) return std::nullopt;
  RelationsVerdict v = checkRelations(engine, source, r.path, source.tolerance);
  tally.add(v.tally);
  if (!v.findings.empty()) {
    if (out.detail.empty()) out.detail = v.findings.front().oracle + ": " + v.findings.front().message;
    out.verdict = "fail";
    for (Finding& f : v.findings) out.findings.push_back(std::move(f));
    return std::move(v.violations.front());
  }
  if (v.engineFailure && out.verdict.empty()) {
    out.verdict = "engine-failure";
    out.detail = *v.engineFailure;
  }
  return std::nullopt;
}

std::string metamorphicReproduceCommand(const std::string& engine, const std::string& caseFile,
                                        const std::string& agreesWith) {
  const std::string vs = agreesWith.empty() ? "reference" : agreesWith;
  return "cyclecert diff --engine " + shellQuote(engine) + " --vs " + shellQuote(vs) + " " + shellQuote(caseFile) +
         " --metamorphic";
}

std::optional<PlotInput> metamorphicPlot(const MetamorphicViolation& v, const std::string& engineName, double tolerance) {
  std::optional<PlotInput> plot;
  if (v.back) {
    Toolpath mappedBack = v.back->identity ? v.actual.path : mapToolpath(v.actual.path, v.back->map, v.back->mirrors);
    mappedBack.alarm = v.actual.path.alarm;
    std::optional<std::size_t> move;
    if (const auto d = firstMoveDivergence(v.source.moves, mappedBack.moves, tolerance)) move = d->move;
    const std::string label = "follow-up (" + v.relation + ")" + (v.back->identity ? "" : ", mapped back");
    plot = failurePlot(v.sourceCase, EngineResult::planned(v.source), "source", {}, tolerance, PlotComparison{label, std::move(mappedBack), move});
  } else {
    const PlotComparison expected{"expected (" + v.relation + " of the source's path)", v.expected, v.move};
    plot = failurePlot(v.followUp, v.actual, "follow-up (" + v.relation + ")", {}, tolerance, expected);
  }
  if (plot) plot->title = engineName + " \u2014 " + v.sourceCase.id + " (" + metamorphicKind(v.relation) + ")";
  return plot;
}

}  // namespace cyclecert
