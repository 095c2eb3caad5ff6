#include "oracles/metamorphic/format_relations.h"

#include <algorithm>
#include <cmath>

#include "oracles/metamorphic/lathe_program.h"
#include "oracles/metamorphic/path_compare.h"
#include "oracles/metamorphic/word_edit.h"
#include "reference/gcode/writer.h"

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

// G71.FS10.D: Δd in least input increments of metric IS-B (the reader refuses G20): 0.001 mm.
std::optional<Word> depthInLeastIncrements(double depthOfCut) {
  const double increments = depthOfCut * 1000;
  const double whole = std::round(increments);
  if (std::abs(increments - whole) > 1e-6 || whole > 999'999'999) return std::nullopt;
  return makeWord('D', whole, false);
}

std::optional<FollowUp> toSeries10(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto lathe = readLatheProgram(p, whyNot);
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
    const auto d = depthInLeastIncrements(*inForce.depthOfCut);
    if (!d) {
      whyNot = lineOf(p, i) + "Δd " + std::to_string(*inForce.depthOfCut) +
               " mm is not a whole number of least input increments (0.001 mm): D cannot write it";
      return std::nullopt;
    }
    insertBeforeFeed(out.blocks[i], *d);
    if (retractOfTheCycles && *retractOfTheCycles != inForce.retract) {
      whyNot = lineOf(p, i) + "e differs from an earlier cycle's: the one-block format has no address for e, "
                              "and parameter 5133 holds one value";
      return std::nullopt;
    }
    retractOfTheCycles = inForce.retract;
  }
  eraseBlocks(out, emptied);
  ParamSettings settings = params;
  if (*retractOfTheCycles) settings.push_back({"5133", **retractOfTheCycles});
  settings.push_back({"FCV", 1});
  return FollowUp{std::move(out), std::move(settings), [](const Toolpath& t) { return t; }, ""};
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

// Seed 003 gives the Huazhong G71 without pockets: a head moving along Z too is type II.
bool headMovesTheCutAxis(const Program& p, const LatheProgram& lathe) {
  const std::size_t ns = lathe.cycles.front().ns;
  return std::any_of(p.blocks[ns].words.begin(), p.blocks[ns].words.end(), [&](const Word& w) {
    const WordRole role = roleOf(lathe.blocks[ns], w);
    return role == WordRole::AbsFirst || role == WordRole::IncFirst;
  });
}

std::optional<FollowUp> toHuazhong(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto lathe = readLatheProgram(p, whyNot);
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
  if (headMovesTheCutAxis(p, *lathe)) {
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

}  // namespace

Relation series10OneBlockRelation() {
  Relation r;
  r.id = "fs10-one-block";
  r.description =
      "Two-block → Series 10/11 one-block format (FCV = 1): every first block G71 U(Δd) R(e) / G72 W(Δd) R(e) "
      "loses Δd, e and its code (its F S T M stay as a plain block), and every P/Q block gets D = the Δd in "
      "force in least input increments (D1500 = 1.5 mm; Δd finer than 0.001 mm is refused); the settings gain "
      "5133 = e (the format has no address for e: refused when the cycles' e differ) and FCV = 1. Refuses a "
      "cycle without a programmed Δd before it (D would have nothing to say). Expected: the same toolpath. "
      "Handles the vocabulary of lathe_program.h.";
  r.rules = {"G71.FS10.FMT", "G71.FS10.D", "G71.DD.MODAL", "G71.E.MODAL"};
  r.transform = toSeries10;
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
  r.transform = toHuazhong;
  r.compare = compareToolpaths;
  return r;
}

}  // namespace cyclecert
