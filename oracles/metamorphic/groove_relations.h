#pragma once
// The geometric relations on G74.1 programs (groove_program.h; docs/g74_1.md; README "G74.1"):
// the relation of the same id (relations.h) hands a program with a G74.1 block to these. The whole
// cycle is planned in the groove's own coordinates u = sd·(x − X/2), w = sh·(z − Z) (sh = sign h,
// sd = sign d), so a mirror that flips h's (or d's) sign along with the start's Z (or X) leaves
// (u, w), and with them the flanks ∠a/∠b and the corners r1…r4, where they were.
#include <optional>
#include <string>

#include "oracles/metamorphic/relations.h"

namespace cyclecert {

// z → −z: Z and W words and h negated. Expected: z → −z, arcs reversed.
std::optional<FollowUp> mirrorGrooveZ(const Program& p, const ParamSettings& params, std::string& whyNot);
// x → 2·x0 − x about x0 = groove_program.h's largestRadius rounded up: X → 4·x0 − X, U and d
// negated. Expected: x → 2·x0 − x, arcs reversed.
std::optional<FollowUp> mirrorGrooveX(const Program& p, const ParamSettings& params, std::string& whyNot);
// Z + shift.z, X + 2·shift.x (every absolute word, the groove's start with them). Expected: + shift.
std::optional<FollowUp> translateGroove(Point shift, const Program& p, const ParamSettings& params,
                                        std::string& whyNot);
// Every length × k: positions, h, d, e, Δv, Δu, Δw, r, r1…r4, and Δi/Δk (P/Q, which must stay
// whole numbers when read in increments, 182#7 = 0); angles, J, P(abde) and F unchanged; refused
// when a scaled word would leave or enter its range (G74_1.RANGE): the alarm would change.
std::optional<FollowUp> scaleGroove(double k, const Program& p, const ParamSettings& params, std::string& whyNot);
// G21 → G20, every length and F ÷ 25.4; P/Q ÷ 25.4 in mm (182#7 = 1), and in increments
// (0.0001 mm → 0.00001 in: ÷ 2.54) only when that is a whole number; refused, as scale-k, when a
// word would leave or enter its range (the ranges are numbers in the program's units). Expected:
// the same toolpath.
std::optional<FollowUp> metricInchGroove(const Program& p, const ParamSettings& params, std::string& whyNot);

}  // namespace cyclecert
