#include "reference/siemens/siemens_contour.h"

#include <optional>
#include <vector>

#include "reference/model/alarms.h"
#include "reference/model/program.h"
#include "reference/siemens/siemens_corners.h"

namespace cyclecert {

namespace {

std::optional<CornerRequest> cornerOf(const SiemensBlock& b, const std::string& file) {
  std::optional<CornerRequest> found;
  for (const auto& [address, kind] : {std::pair{"CHF", CornerKind::ChamferLength}, std::pair{"CHR", CornerKind::ChamferLeg},
                                      std::pair{"RND", CornerKind::Rounding}}) {
    const SiemensWord* w = b.find(address);
    if (!w) continue;
    if (found) throw ParseError({file, b.line, w->column}, "one chamfer or rounding per block", w->text);
    if (w->value <= 0) throw ParseError({file, b.line, w->column}, std::string("a positive length after ") + address + "=", w->text);
    found = CornerRequest{kind, w->value, w->text, b.line};
  }
  return found;
}

// G words a contour block may hold: motion, and the diameter mode.
void requireContourGCodes(const SiemensBlock& b, const std::string& file) {
  for (const SiemensWord& w : b.words) {
    if (w.address != "G") continue;
    const int g = gCode10(w.value);
    if (g == 10 || g == 20 || g == 30 || g == 220 || g == 230) continue;
    throw ParseError({file, b.line, w.column}, "G1, G2, G3 (or G22/G23) in a contour subprogram", w.text);
  }
}

}  // namespace

SiemensContour readSiemensContour(const std::string& name, const SiemensBlocks& blocks, SiemensModal modal) {
  SiemensContour contour;
  contour.name = name;
  contour.file = blocks.file;
  std::optional<Point> position;
  std::vector<std::optional<CornerRequest>> cornerAfter;  // per segment
  // An element per block at most (room at once, not grown element by element).
  contour.segments.reserve(blocks.blocks.size());
  cornerAfter.reserve(blocks.blocks.size());
  for (const SiemensBlock& b : blocks.blocks) {
    requireContourGCodes(b, blocks.file);
    applySiemensModal(b, modal);
    const auto corner = cornerOf(b, blocks.file);
    if (!position) {
      if (!b.find("X") || !b.find("Z")) {
        if (b.endsProgram() && !hasSiemensAxisWord(b)) break;
        throw ParseError({blocks.file, b.line, 1}, "the contour's first point: X and Z in the first block of " + name, b.text);
      }
      if (corner) throw ParseError({blocks.file, b.line, 1}, "no chamfer or rounding at the contour's first point", corner->text);
      position = siemensTarget(b, Point{}, modal);
      continue;
    }
    if (hasSiemensAxisWord(b) && modal.motion == 0) {
      throw ParseError({blocks.file, b.line, 1}, "G1, G2 or G3 for an element of the contour " + name + " (G0 is in force)", b.text);
    }
    const auto seg = hasSiemensAxisWord(b) ? siemensMotionSegment(b, *position, modal, blocks.file) : std::nullopt;
    if (seg) {
      contour.segments.push_back(*seg);
      cornerAfter.push_back(corner);
      position = seg->to;
    } else if (corner) {
      throw ParseError({blocks.file, b.line, 1}, corner->text + " in a block that moves along the contour", b.text);
    }
    if (b.endsProgram()) break;
  }
  // A subprogram without elements (only RET, or a first point and RET) is a program the controller
  // reads; the cycle refuses the contour when it is called: alarm 10931 (LCYC95.ALARMS, checkContour).
  if (contour.segments.empty()) return contour;
  // SIEMENS.CORNER: each chamfer or rounding goes between its block's element and the next one.
  std::vector<Segment> withCorners;
  withCorners.reserve(2 * contour.segments.size());  // at most a corner after each element
  for (std::size_t i = 0; i < contour.segments.size(); ++i) {
    Segment& seg = contour.segments[i];
    if (i > 0 && cornerAfter[i - 1]) {
      if (const auto between = insertCorner(withCorners.back(), seg, *cornerAfter[i - 1])) withCorners.push_back(*between);
    }
    withCorners.push_back(seg);
  }
  if (cornerAfter.back()) {
    throw ParseError({blocks.file, cornerAfter.back()->line, 1}, "an element after the chamfer or rounding " +
                                                                    cornerAfter.back()->text + " (it goes between two)",
                     "the contour's end");
  }
  contour.segments = std::move(withCorners);
  return contour;
}

}  // namespace cyclecert
