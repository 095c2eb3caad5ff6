#include "reference/interpreter/block_groups.h"

#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/g_codes.h"

namespace cyclecert {

CycleAlarm improperGCode(const Block& b, const Word& g, const ModalState& s) {
  const GCodeSystem system = s.gCodeSystem;
  return CycleAlarm(alarm::kImproperGCode, b.line,
                    g.text + " is not a G code of this controller in " + gCodeSystemName(system) +
                        otherSystemsMeaning(system, gCode10(g.value), s.gCodeSystemByParameters));
}

std::string notPlannedReason(const Block& b, const Word& g, const ModalState& s) {
  const GCodeSystem system = s.gCodeSystem;
  const int g10 = gCode10(g.value);
  const GCode* code = findGCode(system, g10);
  std::string why = gCodeLabel(g10) + " " + (code ? code->name : "") + " is not planned by the reference yet";
  // In system A, G92 is the threading cycle: a G92 block with an S word and no axis word is most
  // likely system B/C's spindle speed clamp.
  if (system == GCodeSystem::A && g10 == 920 && b.has('S') && !hasAxisWord(b)) {
    why += " (in G code system A, G92 is the threading cycle; the maximum spindle speed clamp is G50 S)";
  }
  return why + otherSystemsMeaning(system, g10, s.gCodeSystemByParameters);
}

const Word* firstUnknownGCode(const Block& b, GCodeSystem system) {
  for (const Word* g : b.all('G')) {
    if (!findGCode(system, gCode10(g->value))) return g;
  }
  return nullptr;
}

void checkCompensationChange(const Block& b, const ModalState& before, const ModalState& after) {
  const bool compBefore = before.tnrc != 40, compAfter = after.tnrc != 40;
  if (compBefore && compAfter && before.plane != after.plane) {
    throw CycleAlarm(alarm::kPlaneChangeInComp, b.line,
                     "G" + std::to_string(after.plane) + " while G" + std::to_string(before.tnrc) +
                         " is in force; cancel the compensation with G40 before changing the plane");
  }
  if (compBefore == compAfter || (after.motion != 2 && after.motion != 3)) return;
  if (!hasAxisWord(b) || axisWordsMeaning(b, after.gCodeSystem) != AxisWordsMean::Motion) return;
  throw CycleAlarm(alarm::kArcInCompStartOrCancel, b.line,
                   std::string(compAfter ? "compensation start-up (G" + std::to_string(after.tnrc) + ")"
                                         : "compensation cancel (G40)") +
                       " in a G0" + std::to_string(after.motion) + " block; start or cancel it in a G00/G01 block");
}

}  // namespace cyclecert
