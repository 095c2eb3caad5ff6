#pragma once
// PROG.CAP: cyclecert's own bounds on reading a program (not a controller's rule), so that a huge
// or hostile program is refused with a clear error before it exhausts the machine. The planners'
// bounds are in reference/cycles/roughing_cycle.h, the toolpath's in reference/model/toolpath.h;
// README "Limits" lists them all.
#include <cstddef>
#include <string>

namespace cyclecert {

// PROG.CAP.BLOCKS: blocks (with a word or a sequence number) in one program text (a SINUMERIK
// program with the subprograms printed after it). A lathe roughing program has tens to thousands;
// reading a million took 740 MB and 12 s (the 64 MiB input cap alone let through five million:
// 3.3 GB and a minute). Block 250,001 is a ParseError at its line, after some 3 s and 190 MB.
inline constexpr std::size_t kMostBlocksPerProgram = 250'000;

// PROG.CAP.BLOCKS: throws ParseError at `line` (column 1) when `blockNumber`, the count of blocks
// read so far with this one, is beyond kMostBlocksPerProgram.
void requireBlockWithinTheCap(std::size_t blockNumber, const std::string& file, int line);

// "1,000,000": a count for a message.
std::string groupedCount(unsigned long long n);
// A count computed in floating point (passes = depth / Δd…), rounded: "1,000,000"; beyond 10^15
// (or not finite) "more than 1,000,000,000,000,000", never an overflowing conversion.
std::string countText(double n);

}  // namespace cyclecert
