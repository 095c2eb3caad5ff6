#include "reference/interpreter/block_words.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "reference/interpreter/block_motion.h"
#include "reference/model/alarms.h"

namespace cyclecert {

namespace {

// IS-B (least input increment 0.001 mm, 0.0001 inch): nine digits, ±999999.999 mm and
// ±99999.9999 inch (seed 001's table gives the same bounds for the cycle addresses).
constexpr double kLargestMetric = 999999.999;
constexpr double kLargestInch = 99999.9999;

bool isDimensionOrFeed(char letter) {
  switch (letter) {
    case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W':
    case 'I': case 'J': case 'K': case 'R': case 'F':
      return true;
    default:
      return false;
  }
}

std::string at(const Word& w) { return w.text + " at column " + std::to_string(w.column); }

// PROG.SIGN: a feed, a spindle speed and a tool number have no direction.
bool takesNoMinusSign(char letter) { return letter == 'F' || letter == 'S' || letter == 'T'; }

[[noreturn]] void improperAddress(const Word& w, const std::string& why) {
  throw CycleAlarm(alarm::kImproperAddress, w.line, at(w) + ": " + why);
}

// The word stands right after another word's number, with nothing between ("X1e308", "D1e3").
bool gluedToPreviousNumber(const Block& b, const Word& w) {
  const Word* previous = nullptr;
  for (const Word& x : b.words) {
    if (&x == &w) break;
    previous = &x;
  }
  return previous && previous->line == w.line &&
         previous->column + static_cast<int>(previous->text.size()) == w.column;
}

bool hasM(const Block& b, double code) {
  for (const Word* m : b.all('M')) {
    if (m->value == code) return true;
  }
  return false;
}

}  // namespace

// PROG.ADDRESS (interpretation): one word of an address per block, G and M apart (codes of
// different groups share a block); a second X or U is PS0009 naming both, rather than one of them
// read silently.
void checkOneWordPerAddress(const Block& b) {
  for (std::size_t i = 0; i < b.words.size(); ++i) {
    const Word& w = b.words[i];
    if (w.letter == 'G' || w.letter == 'M') continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (b.words[j].letter != w.letter) continue;
      improperAddress(w, std::string("a second ") + w.letter + " word in the block (" + at(b.words[j]) +
                             "): one word of an address per block");
    }
  }
}

void checkWordRanges(const Block& b, bool inch) {
  checkOneWordPerAddress(b);
  const double largest = inch ? kLargestInch : kLargestMetric;
  for (const Word& w : b.words) {
    if (takesNoMinusSign(w.letter) && std::signbit(w.value)) {
      throw CycleAlarm(alarm::kNegativeSign, w.line,
                       at(w) + ": " + w.letter + " takes no minus sign (a feed, a spindle speed or a tool number)");
    }
    if (!isDimensionOrFeed(w.letter) || std::abs(w.value) <= largest) continue;
    std::ostringstream why;
    why << std::setprecision(12) << at(w) << " is outside -" << largest << "…" << largest
        << (inch ? " inch" : " mm") << " (IS-B: at most 9 digits, 3 of them decimals in mm)";
    throw CycleAlarm(alarm::kOutOfRange, w.line, why.str());
  }
}

std::string exponentHint(const Block& b, const Word& w) {
  if (w.letter != 'E' || !gluedToPreviousNumber(b, w)) return "";
  return "; a number with an exponent (\"1e308\") is not a G-code number: write the value in full";
}

void checkNoThreadLead(const Block& b) {
  for (const Word* e : b.all('E')) {
    improperAddress(*e, "E (thread lead) has a meaning only in a threading block (G32, G76, G92)" + exponentHint(b, *e));
  }
}

void checkMotionBlockAddresses(const Block& b, int motion, const ModalState& s) {
  const PlaneAxes axes = s.axes();
  const bool arc = motion == 2 || motion == 3;
  for (const Word& w : b.words) {
    switch (w.letter) {
      case 'G': case 'M': case 'S': case 'T': case 'F':
      case 'X': case 'Y': case 'Z': case 'U': case 'V': case 'W':
        continue;
      case 'E':
        checkNoThreadLead(b);
        continue;
      default:
        break;
    }
    if (w.letter == 'P' && (hasM(b, 98) || hasM(b, 99))) continue;  // subprogram call or return target
    const bool centreOrRadius = w.letter == 'R' || w.letter == axes.firstArc || w.letter == axes.secondArc;
    if (arc && centreOrRadius) continue;
    if (motion == 1 && (w.letter == 'I' || w.letter == 'K' || w.letter == 'C' || w.letter == 'R')) {
      throw NotSupported(w.line, at(w) + ": chamfering and corner rounding in G01 (I, K, C, R) are not planned by "
                                         "the reference yet");
    }
    improperAddress(w, std::string("a G0") + std::to_string(motion) + " block does not use address " + w.letter +
                           (arc ? std::string(" (an arc takes R or ") + axes.firstArc + "/" + axes.secondArc + ")" : ""));
  }
}

void checkShapeBlockWords(const Block& b, const ModalState& s) {
  checkWordRanges(b, s.inch);
  checkNoThreadLead(b);
  if (hasAxisWord(b)) checkMotionBlockAddresses(b, s.motion, s);
}

}  // namespace cyclecert
