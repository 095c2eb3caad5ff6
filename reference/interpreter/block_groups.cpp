#include "reference/interpreter/block_groups.h"

#include "reference/interpreter/block_motion.h"
#include "reference/interpreter/g_codes.h"

namespace cyclecert {

namespace {
std::string notInSystemAHint(int g10) {
  if (g10 == 910) return " (G code system A has no G90/G91: U and W are the incremental addresses)";
  if (g10 == 330) return " (a FANUC lathe threads with G32)";
  return "";
}
}  // namespace

CycleAlarm improperGCode(const Block& b, const Word& g) {
  return CycleAlarm(alarm::kImproperGCode, b.line,
                    g.text + " is not a G code of this controller" + notInSystemAHint(gCode10(g.value)));
}

const Word* firstUnknownGCode(const Block& b) {
  for (const Word* g : b.all('G')) {
    if (!findGCode(gCode10(g->value))) return g;
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
  if (!hasAxisWord(b) || axisWordsMeaning(b) != AxisWordsMean::Motion) return;
  throw CycleAlarm(alarm::kArcInCompStartOrCancel, b.line,
                   std::string(compAfter ? "compensation start-up (G" + std::to_string(after.tnrc) + ")"
                                         : "compensation cancel (G40)") +
                       " in a G0" + std::to_string(after.motion) + " block; start or cancel it in a G00/G01 block");
}

}  // namespace cyclecert
