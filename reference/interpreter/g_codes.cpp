#include "reference/interpreter/g_codes.h"

#include <array>

namespace cyclecert {

namespace {

using G = GGroup;
using S = GSupport;

// FANUC 0i-TF G code list, system A, for the codes cyclecert reads (PROG.GCODES).
constexpr GCode kTable[] = {
    {0, G::Motion, S::Applied, "G00 positioning"},
    {10, G::Motion, S::Applied, "G01 linear interpolation"},
    {20, G::Motion, S::Applied, "G02 circular interpolation CW"},
    {30, G::Motion, S::Applied, "G03 circular interpolation CCW"},
    {40, G::OneShot, S::Applied, "G04 dwell"},
    {100, G::OneShot, S::NotApplied, "G10 data setting"},
    {170, G::Plane, S::Applied, "G17 XY plane"},
    {180, G::Plane, S::Applied, "G18 ZX plane"},
    {190, G::Plane, S::Applied, "G19 YZ plane"},
    {200, G::Units, S::Applied, "G20 inch input"},
    {210, G::Units, S::Applied, "G21 metric input"},
    {270, G::OneShot, S::Applied, "G27 reference position return check"},
    {280, G::OneShot, S::Applied, "G28 return to reference position"},
    {290, G::OneShot, S::NotPlanned, "G29 return from reference position"},
    {300, G::OneShot, S::Applied, "G30 return to 2nd/3rd/4th reference position"},
    {320, G::Motion, S::NotPlanned, "G32 threading"},
    {400, G::NoseRadiusComp, S::Applied, "G40 tool nose radius compensation cancel"},
    {410, G::NoseRadiusComp, S::Applied, "G41 tool nose radius compensation left"},
    {420, G::NoseRadiusComp, S::Applied, "G42 tool nose radius compensation right"},
    {500, G::OneShot, S::Applied, "G50 coordinate system setting, maximum spindle speed clamp"},
    {520, G::OneShot, S::NotPlanned, "G52 local coordinate system setting"},
    {530, G::OneShot, S::Applied, "G53 machine coordinate system"},
    {540, G::WorkCoordinates, S::Applied, "G54 work coordinate system 1"},
    {550, G::WorkCoordinates, S::Applied, "G55 work coordinate system 2"},
    {560, G::WorkCoordinates, S::Applied, "G56 work coordinate system 3"},
    {570, G::WorkCoordinates, S::Applied, "G57 work coordinate system 4"},
    {580, G::WorkCoordinates, S::Applied, "G58 work coordinate system 5"},
    {590, G::WorkCoordinates, S::Applied, "G59 work coordinate system 6"},
    {650, G::OneShot, S::NotApplied, "G65 macro call"},
    {700, G::OneShot, S::Applied, "G70 finishing cycle"},
    {710, G::OneShot, S::Applied, "G71 stock removal in turning"},
    {720, G::OneShot, S::Applied, "G72 stock removal in facing"},
    {730, G::OneShot, S::NotPlanned, "G73 pattern repeating cycle"},
    {740, G::OneShot, S::NotPlanned, "G74 end-face peck drilling cycle"},
    {741, G::OneShot, S::NotPlanned, "G74.1 axial groove cycle"},
    {750, G::OneShot, S::NotPlanned, "G75 outer diameter grooving cycle"},
    {760, G::OneShot, S::NotPlanned, "G76 threading cycle"},
    {800, G::DrillingCycle, S::Applied, "G80 canned cycle for drilling cancel"},
    {830, G::DrillingCycle, S::NotPlanned, "G83 face drilling cycle"},
    {840, G::DrillingCycle, S::NotPlanned, "G84 face tapping cycle"},
    {850, G::DrillingCycle, S::NotPlanned, "G85 face boring cycle"},
    {870, G::DrillingCycle, S::NotPlanned, "G87 side drilling cycle"},
    {880, G::DrillingCycle, S::NotPlanned, "G88 side tapping cycle"},
    {890, G::DrillingCycle, S::NotPlanned, "G89 side boring cycle"},
    {900, G::Motion, S::NotPlanned, "G90 outer diameter cutting cycle"},
    {920, G::Motion, S::NotPlanned, "G92 threading cycle"},
    {940, G::Motion, S::NotPlanned, "G94 end-face turning cycle"},
    {960, G::SpindleSpeedMode, S::Applied, "G96 constant surface speed control"},
    {970, G::SpindleSpeedMode, S::Applied, "G97 constant surface speed control cancel"},
    {980, G::FeedMode, S::Applied, "G98 feed per minute"},
    {990, G::FeedMode, S::Applied, "G99 feed per revolution"},
};

constexpr int kMostG10 = 999;

// Index (+1) of each code in kTable, 0 when absent: one array read per G word.
constexpr std::array<std::uint8_t, kMostG10 + 1> buildIndex() {
  std::array<std::uint8_t, kMostG10 + 1> index{};
  for (std::size_t i = 0; i < std::size(kTable); ++i) index[kTable[i].g10] = static_cast<std::uint8_t>(i + 1);
  return index;
}
constexpr auto kIndex = buildIndex();
static_assert(std::size(kTable) < 255);

}  // namespace

const GCode* findGCode(int g10) {
  if (g10 < 0 || g10 > kMostG10 || kIndex[g10] == 0) return nullptr;
  return &kTable[kIndex[g10] - 1];
}

int groupNumber(GGroup g) { return static_cast<int>(g); }

void applyModalGCode(int g10, ModalState& s) {
  const GCode* code = findGCode(g10);
  if (!code || code->support != GSupport::Applied) return;
  switch (code->group) {
    case GGroup::Motion: s.motion = g10 / 10; break;
    case GGroup::Plane: s.plane = g10 / 10; break;
    case GGroup::Units: s.inch = g10 == 200; break;
    case GGroup::NoseRadiusComp: s.tnrc = g10 / 10; break;
    case GGroup::WorkCoordinates: s.workCoordinates = g10 / 10; break;
    case GGroup::OneShot:
    case GGroup::SpindleSpeedMode:
    case GGroup::FeedMode:
    case GGroup::DrillingCycle: break;
  }
}

void applyModalGCodes(const Block& b, ModalState& s) {
  for (const Word* g : b.all('G')) applyModalGCode(gCode10(g->value), s);
}

int oneShotCode(const Block& b) {
  int last = 0;
  for (const Word* g : b.all('G')) {
    const int g10 = gCode10(g->value);
    if (const GCode* code = findGCode(g10); code && code->group == GGroup::OneShot) last = g10;
  }
  return last;
}

}  // namespace cyclecert
