#pragma once
// Word rewriting shared by the relations (relations.cpp, format_relations.cpp, groove_relations.cpp): a word keeps its
// place in the block, and its text is the writer's for the new letter and value.
#include <string>

#include "oracles/metamorphic/lathe_program.h"
#include "reference/gcode/writer.h"
#include "reference/model/program.h"

namespace cyclecert {

inline void setValue(Word& w, double value) {
  w.value = value;
  w.text = formatWord(w);
}

inline void rename(Word& w, char letter, double value) {
  w.letter = letter;
  setValue(w, value);
}

constexpr double kMmPerInch = 25.4;

// Replaces every G code `from` (×10) by `to`, and makes sure the first block commands `to`, so
// that the whole program runs in it (metric-inch: G21 → G20).
inline void commandFromTheStart(Program& program, int from10, int to) {
  for (Block& b : program.blocks) {
    for (Word& w : b.words) {
      if (w.letter == 'G' && gCode10(w.value) == from10) setValue(w, to);
    }
  }
  if (!program.blocks.empty() && program.blocks.front().hasG(to * 10)) return;
  Block b;
  b.words.push_back(makeWord('G', to));
  program.blocks.insert(program.blocks.begin(), b);
}

// A first cycle block (G71 U(Δd) R(e), G72 W(Δd) R(e), G73 U(Δi) W(Δk) R(d)) without those words and
// its cycle code: its other words (F S T M) stay as a plain block. True when nothing is left of it
// (no word, no N).
inline bool dropFirstBlockWords(Block& b, const BlockInfo& info) {
  std::erase_if(b.words, [&](const Word& w) {
    switch (roleOf(info, w)) {
      case WordRole::DepthOfCut:
      case WordRole::Retract:
      case WordRole::ReliefFirst:
      case WordRole::ReliefSecond:
      case WordRole::Divisions:
      case WordRole::CycleCode:
        return true;
      default:
        return false;
    }
  });
  return b.words.empty() && !b.sequence;
}

// A G70 P Q block without its code and P, Q: its other words (S T M) stay as a plain block. True
// when nothing is left of it.
inline bool dropFinishWords(Block& b, const BlockInfo& info) {
  std::erase_if(b.words, [&](const Word& w) {
    const WordRole role = roleOf(info, w);
    return role == WordRole::CycleCode || role == WordRole::Sequence;
  });
  return b.words.empty() && !b.sequence;
}

}  // namespace cyclecert
