#pragma once
// The relations on SINUMERIK programs (siemens_words.h; seed 004, LCYC95.* and CYCLE95.*): the
// relation of the same id (relations.h) carries them as its transformSiemens. They rewrite numbers
// of the text in place: the main program's and the contour subprograms' alike.
#include <optional>
#include <string>

#include "oracles/metamorphic/relations.h"
#include "oracles/metamorphic/siemens_words.h"

namespace cyclecert {

// Z + shift.z, X + 2·shift.x (diameters) in the program and its subprograms; I, K, CR=, the corners
// and the cycle's parameters are relative and stay. Expected: + shift.
std::optional<FollowUp> translateSiemens(Point shift, const SiemensSource& source, const ParamSettings& params,
                                         std::string& whyNot);

// Every length × k: X Z I K, CR= CHF= CHR= RND=, LCYC95's R106 R108 R110, CYCLE95's MID FALZ FALX
// FAL DAM _VRT; feeds (R111 R112 FF1–FF3 F), angles (R109), VARI/R105 and DT kept. Refused when a
// length argument of CYCLE95 is empty (its default would not scale) and for an I/K arc whose end is
// off its circle by more than 1e-6 mm (the controller's tolerance is absolute: scaled, the same
// error may alarm). The tool's nose radius is not
// a word of the program: a case with a nose radius must scale it too (the caller's business).
// Expected: every point × k.
std::optional<FollowUp> scaleSiemens(double k, const SiemensSource& source, const ParamSettings& params,
                                     std::string& whyNot);

// r-ik: every arc block with CR= gets I K (the centre from the arc's start; I along X as a radius,
// K along Z), every one with I/K gets CR= (negative above 180°), in the program and the
// subprograms. Refused: an I/K arc whose end is off its circle by more than 1e-6 mm (CR= would move
// the centre), an arc whose start the text does not set (a subprogram's first block), a text without
// arcs. Expected: the same toolpath.
std::optional<FollowUp> radiusCentreSiemens(const SiemensSource& source, const ParamSettings& params,
                                            std::string& whyNot);

}  // namespace cyclecert
