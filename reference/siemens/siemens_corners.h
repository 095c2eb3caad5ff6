#pragma once
// Chamfers and roundings a SINUMERIK contour inserts at the corner after a block (rule
// SIEMENS.CORNER): CHF= the chamfer's length, CHR= its leg (the width in the direction of motion),
// RND= the radius of a rounding tangent to both elements — between lines and arcs in any combination
// (next to an arc, interpretations in the rule's notes).
#include <string>

#include "reference/model/geometry.h"

namespace cyclecert {

enum class CornerKind { ChamferLength, ChamferLeg, Rounding };

struct CornerRequest {
  CornerKind kind = CornerKind::ChamferLength;
  double value = 0;  // mm
  std::string text;  // "CHF=1.5"
  int line = 0;
};

// The corner at a.to == b.from: trims `a` and `b` and returns the element between them (a line, or
// an arc for a rounding); nothing for elements tangent at the corner (no corner). Throws NotSupported
// when the chamfer or rounding does not fit its elements (the controller would shorten it).
std::optional<Segment> insertCorner(Segment& a, Segment& b, const CornerRequest& corner);

}  // namespace cyclecert
