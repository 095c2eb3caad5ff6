#pragma once
// Reads an ISO-6983 lathe program (FANUC / GSK / HNC dialect) into blocks of address words.
#include <string>
#include <string_view>

#include "reference/model/program.h"

namespace cyclecert {

// Blocks end at ';' or a line end; blocks without words or sequence number (blank lines, comment
// lines, '%' lines) are dropped. N goes to Block::sequence (an unsigned whole number, at most
// 99999), O to Program::number (once per file); neither is kept in Block::words.
//
// Throws ParseError at the exact line and column of the first thing that is not in the dialect:
// a letter without a number, a number without a letter, a second decimal point, a number of more
// than 15 significant digits or spelled "nan"/"inf", a character such as '#', '[' or '=' (so
// SINUMERIK's R105=1 and CR=8 are rejected, not misread), an unclosed comment, a bad N or O.
// A number has no exponent, as on the controller: "X1e308" is read as X1 followed by the word
// E308, which the runner refuses where E means nothing (PS0009, PROG.ADDRESS); ranges are the
// runner's too (PS0003, PROG.RANGE).
Program parseProgram(std::string_view text, const std::string& file);

}  // namespace cyclecert
