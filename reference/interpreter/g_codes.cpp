#include "reference/interpreter/g_codes.h"

#include <algorithm>
#include <array>
#include <vector>

namespace cyclecert {

namespace {

using G = GGroup;
using S = GSupport;

constexpr int kNo = -1;  // the function has no code in that system

// One function and its number ×10 in each system: A, B, C, Huazhong.
struct Row {
  GCode code;
  std::array<int, kGCodeSystems> number;
};

// FANUC 0i-TF G code list (lathe), systems A, B and C, for the codes cyclecert reads (PROG.GCODES,
// PROG.GSYS.B, PROG.GSYS.C); Huazhong (seed 003) as system A but for its modes (PROG.GSYS.HNC).
constexpr Row kTable[] = {
    {{0, G::Motion, S::Applied, "positioning"}, {0, 0, 0, 0}},
    {{10, G::Motion, S::Applied, "linear interpolation"}, {10, 10, 10, 10}},
    {{20, G::Motion, S::Applied, "circular interpolation CW"}, {20, 20, 20, 20}},
    {{30, G::Motion, S::Applied, "circular interpolation CCW"}, {30, 30, 30, 30}},
    {{40, G::OneShot, S::Applied, "dwell"}, {40, 40, 40, 40}},
    {{100, G::OneShot, S::NotApplied, "data setting"}, {100, 100, 100, 100}},
    {{170, G::Plane, S::Applied, "XY plane"}, {170, 170, 170, 170}},
    {{180, G::Plane, S::Applied, "ZX plane"}, {180, 180, 180, 180}},
    {{190, G::Plane, S::Applied, "YZ plane"}, {190, 190, 190, 190}},
    {{200, G::Units, S::Applied, "inch input"}, {200, 200, 700, 200}},
    {{210, G::Units, S::Applied, "metric input"}, {210, 210, 710, 210}},
    {{270, G::OneShot, S::Applied, "reference position return check"}, {270, 270, 270, 270}},
    {{280, G::OneShot, S::Applied, "return to reference position"}, {280, 280, 280, 280}},
    {{290, G::OneShot, S::NotPlanned, "return from reference position"}, {290, 290, 290, 290}},
    {{300, G::OneShot, S::Applied, "return to 2nd/3rd/4th reference position"}, {300, 300, 300, 300}},
    {{320, G::Motion, S::NotPlanned, "threading"}, {320, 330, 330, 320}},
    {{400, G::NoseRadiusComp, S::Applied, "tool nose radius compensation cancel"}, {400, 400, 400, 400}},
    {{410, G::NoseRadiusComp, S::Applied, "tool nose radius compensation left"}, {410, 410, 410, 410}},
    {{420, G::NoseRadiusComp, S::Applied, "tool nose radius compensation right"}, {420, 420, 420, 420}},
    {{500, G::OneShot, S::Applied, "coordinate system setting, maximum spindle speed clamp"}, {500, 920, 920, 500}},
    {{520, G::OneShot, S::NotPlanned, "local coordinate system setting"}, {520, 520, 520, 520}},
    {{530, G::OneShot, S::Applied, "machine coordinate system"}, {530, 530, 530, 530}},
    {{540, G::WorkCoordinates, S::Applied, "work coordinate system 1"}, {540, 540, 540, 540}},
    {{550, G::WorkCoordinates, S::Applied, "work coordinate system 2"}, {550, 550, 550, 550}},
    {{560, G::WorkCoordinates, S::Applied, "work coordinate system 3"}, {560, 560, 560, 560}},
    {{570, G::WorkCoordinates, S::Applied, "work coordinate system 4"}, {570, 570, 570, 570}},
    {{580, G::WorkCoordinates, S::Applied, "work coordinate system 5"}, {580, 580, 580, 580}},
    {{590, G::WorkCoordinates, S::Applied, "work coordinate system 6"}, {590, 590, 590, 590}},
    {{650, G::OneShot, S::NotApplied, "macro call"}, {650, 650, 650, 650}},
    {{700, G::OneShot, S::Applied, "finishing cycle"}, {700, 700, 720, 700}},
    {{710, G::OneShot, S::Applied, "stock removal in turning"}, {710, 710, 730, 710}},
    {{720, G::OneShot, S::Applied, "stock removal in facing"}, {720, 720, 740, 720}},
    {{730, G::OneShot, S::Applied, "pattern repeating cycle"}, {730, 730, 750, 730}},
    {{740, G::OneShot, S::NotPlanned, "end-face peck drilling cycle"}, {740, 740, 760, 740}},
    {{741, G::OneShot, S::Applied, "axial groove cycle"}, {741, 741, kNo, 741}},
    {{750, G::OneShot, S::NotPlanned, "outer diameter grooving cycle"}, {750, 750, 770, 750}},
    {{760, G::OneShot, S::NotPlanned, "threading cycle"}, {760, 760, 780, 760}},
    {{800, G::DrillingCycle, S::Applied, "canned cycle for drilling cancel"}, {800, 800, 800, 800}},
    {{830, G::DrillingCycle, S::NotPlanned, "face drilling cycle"}, {830, 830, 830, 830}},
    {{840, G::DrillingCycle, S::NotPlanned, "face tapping cycle"}, {840, 840, 840, 840}},
    {{850, G::DrillingCycle, S::NotPlanned, "face boring cycle"}, {850, 850, 850, 850}},
    {{870, G::DrillingCycle, S::NotPlanned, "side drilling cycle"}, {870, 870, 870, 870}},
    {{880, G::DrillingCycle, S::NotPlanned, "side tapping cycle"}, {880, 880, 880, 880}},
    {{890, G::DrillingCycle, S::NotPlanned, "side boring cycle"}, {890, 890, 890, 890}},
    {{900, G::Motion, S::NotPlanned, "outer diameter cutting cycle"}, {900, 770, 200, kNo}},
    {{920, G::Motion, S::NotPlanned, "threading cycle"}, {920, 780, 210, 920}},
    {{940, G::Motion, S::NotPlanned, "end-face turning cycle"}, {940, 790, 240, kNo}},
    {{960, G::SpindleSpeedMode, S::Applied, "constant surface speed control"}, {960, 960, 960, 960}},
    {{970, G::SpindleSpeedMode, S::Applied, "constant surface speed control cancel"}, {970, 970, 970, 970}},
    {{980, G::FeedMode, S::Applied, "feed per minute"}, {980, 940, 940, 940}},
    {{990, G::FeedMode, S::Applied, "feed per revolution"}, {990, 950, 950, 950}},
    {{kAbsoluteProgramming, G::Programming, S::Applied, "absolute programming"}, {kNo, 900, 900, 900}},
    {{kIncrementalProgramming, G::Programming, S::Applied, "incremental programming"}, {kNo, 910, 910, 910}},
    {{kOnlyInBC + 980, G::CycleReturn, S::Applied, "canned cycle return to initial level"}, {kNo, 980, 980, kNo}},
    {{kOnlyInBC + 990, G::CycleReturn, S::Applied, "canned cycle return to R point level"}, {kNo, 990, 990, kNo}},
    // Huazhong keeps system A's G98/G99 beside its G94/G95 (the profile read them so before).
    {{980, G::FeedMode, S::Applied, "feed per minute"}, {kNo, kNo, kNo, 980}},
    {{990, G::FeedMode, S::Applied, "feed per revolution"}, {kNo, kNo, kNo, 990}},
};

constexpr int kMostG10 = 999;

// Index (+1) in kTable of each code number per system, 0 when absent: one array read per G word.
using Index = std::array<std::array<std::uint8_t, kMostG10 + 1>, kGCodeSystems>;
constexpr Index buildIndex() {
  Index index{};
  for (std::size_t i = 0; i < std::size(kTable); ++i) {
    for (std::size_t system = 0; system < kGCodeSystems; ++system) {
      const int n = kTable[i].number[system];
      if (n != kNo) index[system][static_cast<std::size_t>(n)] = static_cast<std::uint8_t>(i + 1);
    }
  }
  return index;
}
constexpr Index kIndex = buildIndex();
static_assert(std::size(kTable) < 255);

std::size_t column(GCodeSystem system) { return static_cast<std::size_t>(system); }

// The number ×10 of a function in a system, or kNo.
int numberIn(GCodeSystem system, int function) {
  for (const Row& row : kTable) {
    if (row.code.function == function && row.number[column(system)] != kNo) return row.number[column(system)];
  }
  return kNo;
}

std::string selectingParameter(GCodeSystem system) {
  switch (system) {
    case GCodeSystem::A: return "--param 3401#6=0 --param 3401#7=0";
    case GCodeSystem::B: return "--param 3401#6=1";
    case GCodeSystem::C: return "--param 3401#7=1";
    case GCodeSystem::Huazhong: break;
  }
  return "--profile hnc";
}

}  // namespace

GCodeSystem gCodeSystemOf(const Profile& profile, const MachineParams& params) {
  if (!profile.gCodeSystemByParameters) return profile.gCodeSystem;
  if (params.bit("GSC")) return GCodeSystem::C;
  if (params.bit("GSB")) return GCodeSystem::B;
  return GCodeSystem::A;
}

ModalState initialModalState(const Profile& profile, const MachineParams& params) {
  ModalState s;
  s.inch = profile.inchByDefault;  // PROG.UNITS
  s.gCodeSystem = gCodeSystemOf(profile, params);
  s.gCodeSystemByParameters = profile.gCodeSystemByParameters;
  return s;
}

std::string gCodeSystemName(GCodeSystem system) {
  switch (system) {
    case GCodeSystem::A: return "G code system A";
    case GCodeSystem::B: return "G code system B";
    case GCodeSystem::C: return "G code system C";
    case GCodeSystem::Huazhong: break;
  }
  return "the Huazhong G code list";
}

const GCode* findGCode(GCodeSystem system, int g10) {
  if (g10 < 0 || g10 > kMostG10) return nullptr;
  const std::uint8_t i = kIndex[column(system)][static_cast<std::size_t>(g10)];
  return i == 0 ? nullptr : &kTable[i - 1].code;
}

std::string gCodeLabel(int g10) {
  std::string label = "G" + std::string(g10 < 100 ? "0" : "") + std::to_string(g10 / 10);
  if (g10 % 10 != 0) label += "." + std::to_string(g10 % 10);
  return label;
}

int groupNumber(GGroup g) { return static_cast<int>(g); }

void applyModalGCode(const GCode& code, ModalState& s) {
  if (code.support != GSupport::Applied) return;
  const int f = code.function;
  switch (code.group) {
    case GGroup::Motion: s.motion = f / 10; break;
    case GGroup::Plane: s.plane = f / 10; break;
    case GGroup::Units: s.inch = f == 200; break;
    case GGroup::NoseRadiusComp: s.tnrc = f / 10; break;
    case GGroup::WorkCoordinates: s.workCoordinates = f / 10; break;
    case GGroup::Programming: s.incremental = f == kIncrementalProgramming; break;
    case GGroup::OneShot:
    case GGroup::SpindleSpeedMode:
    case GGroup::FeedMode:
    case GGroup::DrillingCycle:
    case GGroup::CycleReturn: break;
  }
}

void applyModalGCodes(const Block& b, ModalState& s) {
  for (const Word* g : b.all('G')) {
    if (const GCode* code = findGCode(s.gCodeSystem, gCode10(g->value))) applyModalGCode(*code, s);
  }
}

int oneShotFunction(const Block& b, GCodeSystem system) {
  int last = 0;
  for (const Word* g : b.all('G')) {
    if (const GCode* code = findGCode(system, gCode10(g->value)); code && code->group == GGroup::OneShot) {
      last = code->function;
    }
  }
  return last;
}

bool hasGFunction(const Block& b, int function, GCodeSystem system) {
  for (const Word* g : b.all('G')) {
    if (const GCode* code = findGCode(system, gCode10(g->value)); code && code->function == function) return true;
  }
  return false;
}

void applyGroupCodes(const Block& b, GGroup group, ModalState& s) {
  for (const Word* g : b.all('G')) {
    if (const GCode* code = findGCode(s.gCodeSystem, gCode10(g->value)); code && code->group == group) {
      applyModalGCode(*code, s);
    }
  }
}

bool usableInShapeProgram(const GCode& code) {
  switch (code.group) {
    case GGroup::Motion: return code.function <= 30;  // G00–G03, not threading or the single cycles
    case GGroup::SpindleSpeedMode:
    case GGroup::FeedMode:
    case GGroup::NoseRadiusComp:
    case GGroup::Programming: return true;
    case GGroup::OneShot: return code.function == 40;  // dwell
    case GGroup::Units:
    case GGroup::DrillingCycle:
    case GGroup::CycleReturn:
    case GGroup::WorkCoordinates:
    case GGroup::Plane: break;
  }
  return false;
}

std::string otherSystemsMeaning(GCodeSystem system, int g10, bool byParameters) {
  if (system == GCodeSystem::Huazhong) return "";
  const GCode* here = findGCode(system, g10);
  std::string out;
  std::vector<int> told;  // the functions already named (B and C share most)
  for (const GCodeSystem other : {GCodeSystem::A, GCodeSystem::B, GCodeSystem::C}) {
    const GCode* there = findGCode(other, g10);
    if (other == system || !there || (here && here->function == there->function)) continue;
    if (std::find(told.begin(), told.end(), there->function) != told.end()) continue;
    told.push_back(there->function);
    // A profile that does not read 3401 (gsk, haas) reads system A: the FANUC profiles read B/C.
    const std::string how = byParameters ? "" : "--profile fanuc-0i-f ";
    std::string where = gCodeSystemName(other) + " (" + how + selectingParameter(other) + ")";
    for (const GCodeSystem also : {GCodeSystem::B, GCodeSystem::C}) {
      const GCode* same = findGCode(also, g10);
      if (also != other && also != system && same && same->function == there->function) {
        where += " and " + gCodeSystemName(also) + " (" + how + selectingParameter(also) + ")";
      }
    }
    out += "; in " + where + " " + gCodeLabel(g10) + " is " + there->name;
    const int ours = numberIn(system, there->function);
    if (ours != kNo) {
      out += ", which " + gCodeSystemName(system) + " writes " + gCodeLabel(ours);
    } else if (there->function == kIncrementalProgramming || there->function == kAbsoluteProgramming) {
      out += ", which " + gCodeSystemName(system) + " writes with the addresses X/Z (absolute) and U/W (incremental)";
    }
  }
  return out;
}

}  // namespace cyclecert
