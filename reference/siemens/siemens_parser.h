#pragma once
// Reads a SINUMERIK 802S/802D program (seed 004; rules SIEMENS.*) into blocks: one block per line,
// `;` comments, words without spaces (`G3X20.8Z-25.8K-15I0`), the named addresses CR=, CHF=,
// CHR=, RND=, R parameter assignments (`R105=1 R106=0.3`), the string variable _CNAME="L42", cycle
// calls (`LCYC95`, `CYCLE95("L18", 1.5, , …)`), subprogram calls by name (`L42`), N numbers, the
// keywords RET, DIAMON and DIAMOF.
//
// Throws ParseError at the line and column of the first thing that is not in the dialect, naming
// what was expected there.
#include <string>
#include <string_view>

#include "reference/siemens/siemens_program.h"

namespace cyclecert {

// A main program, followed (SIEMENS.SUB.PRINTED) by any subprograms printed after its M02/M30 as
// seed 004 prints them: a line `L42.spf` of its own, then the subprogram's blocks up to M02/M17/RET.
SiemensProgram parseSiemensProgram(std::string_view text, const std::string& file);

// A subprogram given on its own (a sibling file L42.spf, or a spec case's "subprograms" entry).
SiemensBlocks parseSiemensSubprogram(std::string_view text, const std::string& file);

}  // namespace cyclecert
