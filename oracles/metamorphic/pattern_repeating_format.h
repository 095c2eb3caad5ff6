#pragma once
// fs10-one-block on G73 programs (format_relations.h): FANUC's two-block G73 written as the Series
// 10/11 block (G73.FS10.FMT, FCV = 1): `G73 U(Δi) W(Δk) R(d); G73 P Q U(Δu) W(Δw) F;` becomes
// `G73 P Q U(Δu) W(Δw) I(Δi) K(Δk) D(d) F;` — I, K and D write parameters 5135/5136/5137 as the
// first block's U, W and R did. Expected: the same toolpath.
#include <optional>
#include <string>

#include "oracles/metamorphic/relations.h"

namespace cyclecert {

// True when a block of the program commands G73.
bool hasPatternRepeating(const Program& program);

// The program in the Series 10/11 format, with FCV = 1 among the settings; nothing, with the
// reason, for a program outside lathe_program.h's vocabulary (G73 included), one that mixes G73 with
// G71/G72, or a d that D (a whole number without a decimal point) cannot write.
std::optional<FollowUp> patternRepeatingToSeries10(const Program& p, const ParamSettings& params, std::string& whyNot);

}  // namespace cyclecert
