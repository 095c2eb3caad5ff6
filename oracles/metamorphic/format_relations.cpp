#include "oracles/metamorphic/format_relations.h"

#include <algorithm>
#include <cmath>

#include "oracles/metamorphic/g_code_writing.h"
#include "oracles/metamorphic/lathe_program.h"
#include "oracles/metamorphic/path_compare.h"
#include "oracles/metamorphic/pattern_repeating_format.h"
#include "oracles/metamorphic/word_edit.h"
#include "reference/gcode/writer.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

std::string lineOf(const Program& p, std::size_t block) { return "line " + std::to_string(p.blocks[block].line) + ": "; }

// Δd and e as the first blocks read so far set them (G71.DD.MODAL, G71.E.MODAL): the words as
// written.
struct FirstBlockValues {
  std::optional<Word> depthOfCutWord, retractWord;
  std::optional<double> depthOfCut, retract;

  void read(const Block& b, const BlockInfo& info) {
    for (const Word& w : b.words) {
      const WordRole role = roleOf(info, w);
      if (role == WordRole::DepthOfCut) depthOfCutWord = w;
      if (role == WordRole::Retract) retractWord = w;
    }
    if (depthOfCutWord) depthOfCut = depthOfCutWord->value;
    if (retractWord) retract = retractWord->value;
  }
};

// Blocks emptied by the rewriting go, last first (the indices of the others stay valid).
void eraseBlocks(Program& p, std::vector<std::size_t> indices) {
  std::sort(indices.rbegin(), indices.rend());
  for (std::size_t i : indices) p.blocks.erase(p.blocks.begin() + static_cast<std::ptrdiff_t>(i));
}

// The word inserted before the block's first F (or at its end): where a programmer writes it.
void insertBeforeFeed(Block& b, Word w) {
  const auto feed = std::find_if(b.words.begin(), b.words.end(), [](const Word& x) { return x.letter == 'F'; });
  b.words.insert(feed, std::move(w));
}

// The one-block dialects a relation writes (format_relations.h): how D carries Δd, whether R1 marks
// type II, the settings and profile the follow-up runs with.
enum class OneBlockDialect { Series10, Haas };

// G71.FS10.D: Δd in least input increments of metric IS-B (the reader refuses G20): 0.001 mm.
// HAAS.G71.D: Δd in the program's units, with its decimal point.
std::optional<Word> depthWord(OneBlockDialect dialect, double depthOfCut) {
  if (dialect == OneBlockDialect::Haas) return makeWord('D', depthOfCut, true);
  const double increments = depthOfCut * 1000;
  const double whole = std::round(increments);
  if (std::abs(increments - whole) > 1e-6 || whole > 999'999'999) return std::nullopt;
  return makeWord('D', whole, false);
}

// A roughing cycle whose block ns moves the cut axis too — Z for G71, X for G72: type II
// (G71.TYPE.SELECT, G72.TYPE.SELECT, HAAS.G71.R1).
bool headMovesTheCutAxis(const Program& p, const LatheProgram& lathe, const RoughingCycleInfo& cycle) {
  const bool g71 = cycle.code == 71;
  return std::any_of(p.blocks[cycle.ns].words.begin(), p.blocks[cycle.ns].words.end(), [&](const Word& w) {
    const WordRole role = roleOf(lathe.blocks[cycle.ns], w);
    return g71 ? role == WordRole::AbsFirst || role == WordRole::IncFirst
               : role == WordRole::AbsSecond || role == WordRole::IncSecond;
  });
}

const RoughingCycleInfo* cycleAt(const LatheProgram& lathe, std::size_t block) {
  for (const RoughingCycleInfo& c : lathe.cycles) {
    if (c.block == block) return &c;
  }
  return nullptr;
}

// Two-block → one-block: every first block loses Δd, e and its code, every P/Q block gets D (and,
// on Haas, R1 for type II); e goes to 5133, which holds one value for all cycles.
std::optional<FollowUp> toOneBlock(const Program& p, const ParamSettings& params, OneBlockDialect dialect,
                                   std::string& whyNot) {
  const auto lathe = readLatheProgram(p, params, whyNot);
  if (!lathe) return std::nullopt;
  if (lathe->cycles.empty()) {
    whyNot = "no G71/G72 cycle: nothing to write in the one-block format";
    return std::nullopt;
  }
  Program out = p;
  FirstBlockValues inForce;
  std::optional<std::optional<double>> retractOfTheCycles;  // e at every cycle: it becomes one 5133
  std::vector<std::size_t> emptied;
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    const BlockInfo& info = lathe->blocks[i];
    if (info.kind == BlockKind::CycleFirst) {
      inForce.read(p.blocks[i], info);
      if (dropFirstBlockWords(out.blocks[i], info)) emptied.push_back(i);
    }
    if (info.kind != BlockKind::CycleSecond) continue;
    if (!inForce.depthOfCut) {
      whyNot = lineOf(p, i) + "no Δd is programmed before this cycle (parameter 5132 gives it): no D to write";
      return std::nullopt;
    }
    const auto d = depthWord(dialect, *inForce.depthOfCut);
    if (!d) {
      whyNot = lineOf(p, i) + "Δd " + std::to_string(*inForce.depthOfCut) +
               " mm is not a whole number of least input increments (0.001 mm): D cannot write it";
      return std::nullopt;
    }
    insertBeforeFeed(out.blocks[i], *d);
    const RoughingCycleInfo* cycle = cycleAt(*lathe, i);
    if (dialect == OneBlockDialect::Haas && cycle && headMovesTheCutAxis(p, *lathe, *cycle)) {
      insertBeforeFeed(out.blocks[i], makeWord('R', 1, false));  // HAAS.G71.R1: "R1 (with no decimal)"
    }
    if (retractOfTheCycles && *retractOfTheCycles != inForce.retract) {
      whyNot = lineOf(p, i) + "e differs from an earlier cycle's: the one-block format has no address for e, "
                              "and parameter 5133 holds one value";
      return std::nullopt;
    }
    retractOfTheCycles = inForce.retract;
  }
  eraseBlocks(out, emptied);
  ParamSettings settings = params;
  if (*retractOfTheCycles) {
    settings.push_back({"5133", **retractOfTheCycles});
  } else if (dialect == OneBlockDialect::Haas) {
    // e from the source's 5133 (Setting 73 has another default on the haas profile).
    settings.push_back({"5133", machineParamsOf(params).get("5133")});
  }
  if (dialect == OneBlockDialect::Series10) settings.push_back({"FCV", 1});
  return FollowUp{std::move(out), std::move(settings), [](const Toolpath& t) { return t; },
                  dialect == OneBlockDialect::Haas ? "haas" : ""};
}

// The one roughing cycle's G70: it must follow nf directly, run that cycle's shape from its start
// point, and be the program's last motion — in the Huazhong form the blocks after nf run from the
// shape's end, not from A.
std::optional<std::size_t> finishingBlock(const Program& p, const LatheProgram& lathe, std::string& whyNot) {
  const RoughingCycleInfo& cycle = lathe.cycles.front();
  const std::size_t g70 = cycle.nf + 1;
  if (g70 >= p.blocks.size() || lathe.blocks[g70].kind != BlockKind::Finish) {
    whyNot = lineOf(p, cycle.block) +
             "no G70 right after the shape's block nf: the Huazhong G71 runs ns…nf again after roughing, "
             "which stands for a G70 P Q there";
    return std::nullopt;
  }
  if (!lathe.blocks[g70].finishAtCycleStart) {
    whyNot = lineOf(p, g70) + "G70 does not run the cycle's shape from the cycle's start point";
    return std::nullopt;
  }
  for (std::size_t i = g70 + 1; i < p.blocks.size(); ++i) {
    if (lathe.blocks[i].segment || lathe.blocks[i].kind != BlockKind::Plain) {
      whyNot = lineOf(p, i) + "motion after G70: FANUC starts it from the start point, the Huazhong form from "
                              "the shape's end";
      return std::nullopt;
    }
  }
  return g70;
}

std::optional<FollowUp> toHuazhong(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto lathe = readLatheProgram(p, params, whyNot);
  if (!lathe) return std::nullopt;
  if (lathe->cycles.size() != 1) {
    whyNot = "the relation handles one roughing cycle; the program has " + std::to_string(lathe->cycles.size());
    return std::nullopt;
  }
  const RoughingCycleInfo& cycle = lathe->cycles.front();
  if (cycle.code != 71) {
    whyNot = lineOf(p, cycle.block) + "G72: seed 003 describes the Huazhong G71 only";
    return std::nullopt;
  }
  if (headMovesTheCutAxis(p, *lathe, cycle)) {  // seed 003 gives the Huazhong G71 without pockets
    whyNot = lineOf(p, cycle.ns) + "block ns moves Z too (type II): seed 003 gives the Huazhong G71 without pockets";
    return std::nullopt;
  }
  const auto g70 = finishingBlock(p, *lathe, whyNot);
  if (!g70) return std::nullopt;

  Program out = p;
  FirstBlockValues inForce;
  std::vector<std::size_t> emptied;
  for (std::size_t i = 0; i < cycle.block; ++i) {
    if (lathe->blocks[i].kind != BlockKind::CycleFirst) continue;
    inForce.read(p.blocks[i], lathe->blocks[i]);
    if (dropFirstBlockWords(out.blocks[i], lathe->blocks[i])) emptied.push_back(i);
  }
  // HNC.G71.FMT: G71 U(Δd) R(r) P Q X(Δx, diameter) Z(Δz) F.
  Block& g71 = out.blocks[cycle.block];
  for (Word& w : g71.words) {
    const WordRole role = roleOf(lathe->blocks[cycle.block], w);
    if (role == WordRole::AllowanceSecond) rename(w, 'X', w.value);
    if (role == WordRole::AllowanceFirst) rename(w, 'Z', w.value);
  }
  const auto afterCode = std::find_if(g71.words.begin(), g71.words.end(), [](const Word& w) { return w.letter == 'G'; });
  std::vector<Word> depthWords;
  if (inForce.depthOfCutWord) depthWords.push_back(*inForce.depthOfCutWord);  // G71's U: the letter stays
  if (inForce.retractWord) depthWords.push_back(*inForce.retractWord);
  g71.words.insert(afterCode == g71.words.end() ? g71.words.begin() : afterCode + 1, depthWords.begin(), depthWords.end());
  // The G70 goes (its S, T, M stay as a plain block): the finishing is the run of ns…nf.
  if (dropFinishWords(out.blocks[*g70], lathe->blocks[*g70])) emptied.push_back(*g70);
  eraseBlocks(out, emptied);

  const Point a = cycle.start;
  return FollowUp{std::move(out), params,
                  [a](const Toolpath& t) {
                    Toolpath e = t;
                    // G70.EX's return to A in one rapid; the Huazhong run ends at the shape's end.
                    if (!e.moves.empty() && e.moves.back().kind == MoveKind::Rapid && distance(e.moves.back().to, a) < 1e-9) {
                      e.moves.pop_back();
                    }
                    return e;
                  },
                  "hnc"};
}

// ---- G code systems B and C ------------------------------------------------------------------

// Each G word renamed to the code `system` writes its function with (system C: G71 → G73, G21 →
// G71; B and C: G98 → G94, G99 → G95), through the G code table.
void renameGCodes(Block& b, GCodeSystem system) {
  for (Word& w : b.words) {
    if (w.letter != 'G') continue;
    const GCode* code = findGCode(GCodeSystem::A, gCode10(w.value));
    const auto number = code ? gCodeNumberIn(system, code->function) : std::nullopt;
    if (number) setValue(w, *number / 10.0);  // the reader let only system A codes with a B/C twin through
  }
}

// PROG.GSYS.INCREMENTAL: a block's axis words in system B/C, where X/Z are absolute under G90 and
// increments under G91 and U/W are no axis words. A block of increments only keeps them (U → X, W →
// Z, under G91) where `mayStayIncremental`; otherwise (a block mixing both, a shape block) the
// increments become absolute words, from where the block starts. Returns the programming mode the
// block needs, or 0 for a block without axis words.
int writeAxisWordsInSystemBC(Block& out, const Block& source, const BlockInfo& info, bool mayStayIncremental) {
  bool absolute = false, incremental = false;
  for (const Word& w : source.words) {
    const WordRole role = roleOf(info, w);
    absolute = absolute || role == WordRole::AbsFirst || role == WordRole::AbsSecond;
    incremental = incremental || role == WordRole::IncFirst || role == WordRole::IncSecond;
  }
  if (!absolute && !incremental) return 0;
  const bool toAbsolute = absolute || !mayStayIncremental;
  const Point from = info.before.planePoint();
  for (std::size_t k = 0; k < source.words.size(); ++k) {
    const WordRole role = roleOf(info, source.words[k]);
    Word& w = out.words[k];
    if (role == WordRole::IncFirst) rename(w, 'Z', toAbsolute ? from.z + w.value : w.value);
    if (role == WordRole::IncSecond) rename(w, 'X', toAbsolute ? 2 * from.x + w.value : w.value);
  }
  return toAbsolute ? kAbsoluteProgramming : kIncrementalProgramming;
}

Block modeBlock(GCodeSystem system, int mode, int line) {
  Block b;
  b.line = line;
  b.words.push_back(makeWord('G', *gCodeNumberIn(system, mode) / 10.0));
  return b;
}

// System A → B or C: the codes renamed; G90/G91 where the programming mode changes between blocks
// outside the shapes. The reference refuses G90/G91 between P and Q (G72.NSNF.GCODES lists the codes
// a shape may hold), so a shape's words are all absolute and G90 is in force at every cycle and G70
// that runs it (a block `G90;` of its own before them when G91 was). 3401#6 or #7 set.
std::optional<FollowUp> toGCodeSystem(const Program& p, const ParamSettings& params, GCodeSystem system,
                                      std::string& whyNot) {
  const auto lathe = readLatheProgram(p, params, whyNot);
  if (!lathe || !finishesAtCycleStarts(p, *lathe, whyNot)) return std::nullopt;
  Program out = p;
  out.blocks.clear();
  int inForce = 0;  // the programming mode in force; 0 until a block commands one (power-on: absolute)
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    const BlockInfo& info = lathe->blocks[i];
    Block b = p.blocks[i];
    const bool shape = info.shapeOf.has_value();
    const int mode = info.kind == BlockKind::Plain ? writeAxisWordsInSystemBC(b, p.blocks[i], info, !shape) : 0;
    renameGCodes(b, system);
    if (info.kind != BlockKind::Plain && inForce == kIncrementalProgramming) {
      out.blocks.push_back(modeBlock(system, kAbsoluteProgramming, b.line));
      inForce = kAbsoluteProgramming;
    }
    if (mode && !shape && mode != inForce) {
      b.words.insert(b.words.begin(), makeWord('G', *gCodeNumberIn(system, mode) / 10.0));
      inForce = mode;
    }
    out.blocks.push_back(std::move(b));
  }
  ParamSettings settings = params;
  settings.push_back({system == GCodeSystem::B ? "3401#6" : "3401#7", 1});
  return FollowUp{std::move(out), std::move(settings), [](const Toolpath& t) { return t; }, ""};
}

std::string gCodeSystemDescription(GCodeSystem system) {
  const std::string letter = system == GCodeSystem::B ? "B" : "C";
  return "G code system A → " + letter + " (--param " + (system == GCodeSystem::B ? "3401#6" : "3401#7") +
         "=1): every G code renamed to the code system " + letter + " writes its function with (the G code table "
         "of reference/interpreter/g_codes.h: G98/G99 → G94/G95" +
         (system == GCodeSystem::C ? ", G20/G21 → G70/G71, G70/G71/G72 → G72/G73/G74" : "") +
         "); outside the shapes, G90 (absolute words) or G91 (a block of U/W increments only: U → X, W → Z) "
         "where the mode changes, and a block mixing X/Z with U/W gets absolute words from where it starts; "
         "inside ns…nf every increment becomes an absolute word (the reference refuses G90/G91 between P and "
         "Q), and a block G90 goes before a cycle or G70 that G91 would precede. Refuses a G70 that does not "
         "start at its cycle's start point. For the FANUC profiles (the others do not read 3401: the "
         "follow-up fails there by design). Expected: the same toolpath. Handles the vocabulary of "
         "lathe_program.h.";
}

Relation gCodeSystemRelation(GCodeSystem system) {
  Relation r;
  r.id = system == GCodeSystem::B ? "gsys-b" : "gsys-c";
  r.description = gCodeSystemDescription(system);
  r.rules = {"PROG.GSYS.SELECT", system == GCodeSystem::B ? "PROG.GSYS.B" : "PROG.GSYS.C", "PROG.GSYS.INCREMENTAL"};
  r.transform = [system](const Program& p, const ParamSettings& params, std::string& whyNot) {
    return toGCodeSystem(p, params, system, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

// The one-block relations move a case into another dialect; their expected path is the FANUC 0i-F
// reading of the source (README: GSK's direct return, DTP = 1, and 0i-C's pocket order differ), or
// the source already in that dialect.
bool writtenFromFanucOrIn(const SourceRun& run, std::string_view profile) {
  return run.profile == "fanuc-0i-f" || run.profile == profile;
}

}  // namespace

Relation haasOneBlockRelation() {
  Relation r;
  r.id = "haas-one-block";
  r.description =
      "FANUC two-block → the Haas one block, profile haas: every first block G71 U(Δd) R(e) / G72 W(Δd) R(e) "
      "loses Δd, e and its code (its F S T M stay as a plain block), every P/Q block gets D = the Δd in force "
      "in mm with its decimal point (D1.5) and, when its block ns moves the cut axis too (type II), R1; the "
      "settings gain 5133 = e (Setting 73: the block has no address for e; refused when the cycles' e differ; "
      "without a programmed e the source's 5133). Refuses a cycle without a programmed Δd before it. "
      "Expected: the same toolpath. Handles the vocabulary of lathe_program.h (no G41/G42, so Haas's "
      "compensation inside P…Q is not exercised).";
  r.rules = {"HAAS.G71.FMT", "HAAS.G71.D", "HAAS.G71.R1", "HAAS.G71.SETTINGS"};
  r.outside = [](const SourceRun& run) { return !writtenFromFanucOrIn(run, "haas"); };
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) {
    return toOneBlock(p, params, OneBlockDialect::Haas, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation gCodeSystemBRelation() { return gCodeSystemRelation(GCodeSystem::B); }
Relation gCodeSystemCRelation() { return gCodeSystemRelation(GCodeSystem::C); }

Relation series10OneBlockRelation() {
  Relation r;
  r.id = "fs10-one-block";
  r.description =
      "Two-block → Series 10/11 one-block format (FCV = 1): every first block G71 U(Δd) R(e) / G72 W(Δd) R(e) "
      "loses Δd, e and its code (its F S T M stay as a plain block), and every P/Q block gets D = the Δd in "
      "force in least input increments (D1500 = 1.5 mm; Δd finer than 0.001 mm is refused); the settings gain "
      "5133 = e (the format has no address for e: refused when the cycles' e differ) and FCV = 1. Refuses a "
      "cycle without a programmed Δd before it (D would have nothing to say). G73 programs: `G73 U(Δi) W(Δk) "
      "R(d); G73 P Q U W F` becomes `G73 P Q U W I(Δi) K(Δk) D(d) F` (pattern_repeating_format.h), FCV = 1. "
      "Expected: the same toolpath. Handles the vocabulary of lathe_program.h.";
  r.rules = {"G71.FS10.FMT", "G71.FS10.D", "G71.DD.MODAL", "G71.E.MODAL", "G73.FS10.FMT"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) {
    if (hasPatternRepeating(p)) return patternRepeatingToSeries10(p, params, whyNot);
    return toOneBlock(p, params, OneBlockDialect::Series10, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation huazhongOneBlockRelation() {
  Relation r;
  r.id = "hnc-one-block";
  r.description =
      "FANUC two-block G71 + G70 → the Huazhong single block of seed 003, profile hnc: `G71 U(Δd) R(e) P Q "
      "X(Δu) Z(Δw) F`, the first block's Δd and e moved into it (its other words stay as a plain block), "
      "U → X and W → Z for the allowances, and the G70 P Q right after nf removed: after the Huazhong G71 "
      "the program runs ns…nf again as the finishing (HNC.G71.FST), as G70 did from the start point. "
      "Only one G71 type I cycle (seed 003 has no G72 and no pockets), with that G70 right after nf and "
      "no motion after it. Expected: the source's toolpath without G70's last rapid back to the start "
      "point (the Huazhong run ends at the shape's end). A source alarming PS0322 (G71.LIMIT.HEIGHT, "
      "which seed 003 does not state) fails the relation by design. Handles the vocabulary of "
      "lathe_program.h.";
  r.rules = {"HNC.G71.FMT", "HNC.G71.FST", "HNC.G71.RETURN", "G70.EX"};
  // PS0322 (G71.LIMIT.HEIGHT) is not stated by seed 003 for the Huazhong G71.
  r.outside = [](const SourceRun& run) {
    return !writtenFromFanucOrIn(run, "hnc") || run.alarm == alarm::kOverStartPoint;
  };
  r.transform = toHuazhong;
  r.compare = compareToolpaths;
  return r;
}

}  // namespace cyclecert
