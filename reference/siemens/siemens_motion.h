#pragma once
// A SINUMERIK motion block as a plane segment (rules SIEMENS.ARC, SIEMENS.DIAMETER): X is a
// diameter under G23 (802S) / DIAMON (802D) and a radius under G22 / DIAMOF; Z is longitudinal.
// G2/G3 take the centre from CR= (the radius: positive for an arc of at most 180°, negative for
// more) or from I/K (the centre relative to the start: K along Z, I along X as a radius).
#include <optional>

#include "reference/model/geometry.h"
#include "reference/siemens/siemens_program.h"

namespace cyclecert {

// The modal state a Siemens block is read in.
struct SiemensModal {
  int motion = 0;             // 0, 1, 2, 3
  bool diameterX = true;      // G23 / DIAMON (the power-on state the seed's programs assume)
};

// SIEMENS.ARC: the alarm for an arc the controller cannot make (interpretation: SINUMERIK's 14040
// "error in end point of circle").
inline constexpr const char* kSiemensCircleEndPointAlarm = "14040";

// The modal changes of the block (G0…G3, G22/G23, DIAMON/DIAMOF), applied to `m`.
void applySiemensModal(const SiemensBlock& b, SiemensModal& m);

// The point the block's X/Z words reach from `from` (unchanged axes keep their value).
Point siemensTarget(const SiemensBlock& b, Point from, const SiemensModal& m);
bool hasSiemensAxisWord(const SiemensBlock& b);

// The block's move from `from` as a segment in `motion` (0…3); nothing when it does not move.
// Throws CycleAlarm 14040 for an impossible arc, ParseError for an arc without CR or I/K.
std::optional<Segment> siemensMotionSegment(const SiemensBlock& b, Point from, const SiemensModal& m,
                                            const std::string& file);

}  // namespace cyclecert
