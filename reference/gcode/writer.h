#pragma once
// Writes a parsed program back as G-code text, so that a program built or transformed in memory
// (the metamorphic relations) can be given to any engine as text.
//
// One block per line, ended by ";": an optional '/', the N number, then the words in order. The O
// number, when there is one, comes first on a line of its own. Comments are dropped. A word whose
// source text still says its value is written as the source spelled it ("T0202", "X54.0", "G1");
// any other is formatted: plain decimal notation (never an exponent), the shortest digits that read
// back as exactly the value, at most 15 significant digits (what the parser accepts: a computed
// value with more is rounded to 15), a decimal point when the word had one ("X54."), G and M codes
// below 10 with two digits ("G01"). Parsing the text back gives every word its value exactly.
#include <string>

#include "reference/model/program.h"

namespace cyclecert {

std::string writeProgram(const Program& program);

// One block, without the ";" that ends it: "N12 G01 X10 Z-2".
std::string writeBlock(const Block& block);

// A word as written (see the file comment): "T0202" as spelled, or formatted: "G01", "G74.1", "X-0.6".
std::string formatWord(const Word& word);

// The number as written for a word (see the file comment).
std::string formatNumber(double value, bool decimalPoint);

// A word made in memory: its text is formatWord's, no source position.
Word makeWord(char letter, double value, bool decimalPoint = false);

}  // namespace cyclecert
