#include "oracles/metamorphic/pattern_repeating_format.h"

#include <algorithm>
#include <cmath>

#include "oracles/metamorphic/lathe_program.h"
#include "oracles/metamorphic/word_edit.h"
#include "reference/gcode/writer.h"

namespace cyclecert {

namespace {

std::string lineOf(const Program& p, std::size_t block) { return "line " + std::to_string(p.blocks[block].line) + ": "; }

// Δi, Δk and d as the first G73 blocks read so far set them (G73.FMT: modal): I, K and D of the
// one block, with the words' values.
struct ReliefWords {
  std::optional<double> di, dk, d;

  void read(const Block& b, const BlockInfo& info) {
    for (const Word& w : b.words) {
      switch (roleOf(info, w)) {
        case WordRole::ReliefSecond: di = w.value; break;
        case WordRole::ReliefFirst: dk = w.value; break;
        case WordRole::Divisions: d = w.value; break;
        default: break;
      }
    }
  }
};

void insertBeforeFeed(Block& b, Word w) {
  const auto feed = std::find_if(b.words.begin(), b.words.end(), [](const Word& x) { return x.letter == 'F'; });
  b.words.insert(feed, std::move(w));
}

}  // namespace

bool hasPatternRepeating(const Program& program) {
  return std::any_of(program.blocks.begin(), program.blocks.end(), [](const Block& b) { return b.hasG(730); });
}

std::optional<FollowUp> patternRepeatingToSeries10(const Program& p, const ParamSettings& params, std::string& whyNot) {
  const auto lathe = readLatheProgram(p, params, whyNot, LatheFamilies::WithPatternRepeating);
  if (!lathe) return std::nullopt;
  for (const RoughingCycleInfo& c : lathe->cycles) {
    if (c.code != 73) {
      whyNot = lineOf(p, c.block) + "G" + std::to_string(c.code) +
               " with G73 in one program: the relation writes either family, not both";
      return std::nullopt;
    }
  }
  Program out = p;
  ReliefWords inForce;
  std::vector<std::size_t> emptied;
  for (std::size_t i = 0; i < p.blocks.size(); ++i) {
    const BlockInfo& info = lathe->blocks[i];
    if (info.kind == BlockKind::CycleFirst) {
      inForce.read(p.blocks[i], info);
      if (dropFirstBlockWords(out.blocks[i], info)) emptied.push_back(i);
    }
    if (info.kind != BlockKind::CycleSecond) continue;
    if (inForce.d && (*inForce.d != std::floor(*inForce.d) || *inForce.d < 0)) {
      whyNot = lineOf(p, i) + "d = " + std::to_string(*inForce.d) +
               " is not a whole number: D (without a decimal point) cannot write it";
      return std::nullopt;
    }
    // G73.FS10.FMT: I = Δi (radius), K = Δk, D = d; what no first block wrote stays in 5135–5137.
    if (inForce.di) insertBeforeFeed(out.blocks[i], makeWord('I', *inForce.di, true));
    if (inForce.dk) insertBeforeFeed(out.blocks[i], makeWord('K', *inForce.dk, true));
    if (inForce.d) insertBeforeFeed(out.blocks[i], makeWord('D', *inForce.d, false));
  }
  std::sort(emptied.rbegin(), emptied.rend());
  for (std::size_t i : emptied) out.blocks.erase(out.blocks.begin() + static_cast<std::ptrdiff_t>(i));
  ParamSettings settings = params;
  settings.push_back({"FCV", 1});
  return FollowUp{std::move(out), std::move(settings), [](const Toolpath& t) { return t; }, ""};
}

}  // namespace cyclecert
