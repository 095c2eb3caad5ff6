#pragma once
// Telling a SINUMERIK program by what only SINUMERIK writes (SIEMENS.DIALECT): a cycle call
// LCYC95 / CYCLE95(…), _CNAME=, an R parameter assignment R105=, a subprogram heading L42.spf.
// Used to explain a FANUC reader's parse error on such a program.
#include <optional>
#include <string>
#include <string_view>

namespace cyclecert {

// "LCYC95 at line 7": the first such construct, or nothing.
std::optional<std::string> siemensSignature(std::string_view text);

}  // namespace cyclecert
