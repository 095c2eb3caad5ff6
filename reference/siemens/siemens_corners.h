#pragma once
// Chamfers and roundings a SINUMERIK contour inserts at the corner after a block (rule
// SIEMENS.CORNER): CHF= the chamfer's length, CHR= its leg (the width in the direction of motion),
// RND= the radius of a rounding tangent to both elements. cyclecert inserts them between two lines;
// next to an arc they are not read yet (NotSupported).
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
// an arc for a rounding); nothing for elements in line (no corner). Throws NotSupported next to an
// arc or when the chamfer or rounding is longer than an element.
std::optional<Segment> insertCorner(Segment& a, Segment& b, const CornerRequest& corner);

}  // namespace cyclecert
