#pragma once
// A profile: dialect + controller model. It decides what the documents leave to the controller:
// parameter defaults, which shape-program G codes are tolerated, and the alarm texts.
#include <string>
#include <string_view>
#include <vector>

#include "reference/interpreter/g_code_system.h"
#include "reference/model/params.h"

namespace cyclecert {

// How a G71 block gives the cycle's values. FANUC: two blocks `G71 U(Δd) R(e);` and `G71 P Q U(Δu)
// W(Δw) F S T;` (G71.FMT.ZX; one block with FCV = 1, G71.FS10.FMT). Huazhong: one block
// `G71 U(Δd) R(r) P(ns) Q(nf) X(Δx) Z(Δz) F S T`, after which execution goes on with the block
// after G71, so ns…nf run again as the finishing pass (HNC.G71.FMT, HNC.G71.FST). Haas: FANUC's
// two blocks, or one block `G71/G72 P Q U W D I K F S T [R1]` with D = Δd in program units and I/K
// the rough-pass allowance (HAAS.G71.FMT); reference/cycles/series10_format.h reads both one-block
// forms.
enum class RoughingBlockFormat { FanucTwoBlocks, HuazhongOneBlock, HaasOneBlock };

// The language a profile reads programs in: ISO words with FANUC's canned cycles (FANUC, GSK,
// Huazhong, Haas: reference/gcode), or SINUMERIK's (R parameters, `;` comments, cycle calls by
// name with contour subprograms: reference/siemens).
enum class Dialect { Fanuc, Siemens };

// Which SINUMERIK control a Siemens profile models (seed 004): the 802S/C calls LCYC95 with R105…R112
// and switches diameter programming with G23/G22; the 802D calls CYCLE95(…) and writes DIAMON/DIAMOF.
enum class SiemensControl { None, Sinumerik802S, Sinumerik802D };

struct Profile {
  std::string name;         // "fanuc-0i-f", "gsk"
  std::string description;
  std::string seed;         // the source document the profile follows
  MachineParams defaults;   // parameter values before the case's or the CLI's settings
  // GSK (seed 001) accepts G40/G41/G42 inside ns…nf and ignores them during roughing; FANUC 0i-F
  // raises PS0325 unless NT1 (issue 3).
  bool toleratesTnrcInShape = false;
  // Haas (HAAS.TNRC.SHAPE): G41/G42 in block ns of a roughing shape compensates the shape the cycle
  // roughs (its manual's examples put them there); FANUC 0i-F alarms PS0325.
  bool compensatesTnrcInShape = false;
  // G71.T2.ORDER: 0i-F roughs a pocket to its bottom before the next (depth first); 0i-C cuts
  // every pocket at one level before going deeper.
  bool pocketsLevelByLevel = false;
  // PROG.UNITS: the input unit of a program that commands neither G20 nor G21 (the power-on
  // state of group 06, parameter INI (0000#2) on FANUC). Every current profile is metric.
  bool inchByDefault = false;
  // "millimetres" or "inches": the default unit's name, for the warning that assumes it.
  std::string defaultUnitsName() const { return inchByDefault ? "inches" : "millimetres"; }
  RoughingBlockFormat roughingFormat = RoughingBlockFormat::FanucTwoBlocks;
  // PROG.GSYS.SELECT: the G code system the profile reads programs in (Huazhong's own for hnc), and
  // whether FANUC's parameter 3401#6 GSB / #7 GSC may choose system B or C instead (gCodeSystemOf).
  GCodeSystem gCodeSystem = GCodeSystem::A;
  bool gCodeSystemByParameters = false;
  // Huazhong names a program on its first line "%3304" (seed 003's programs); FANUC, GSK and Haas
  // write O3304, and '%' alone frames the program.
  bool namesProgramsWithPercent = false;
  Dialect dialect = Dialect::Fanuc;
  SiemensControl siemensControl = SiemensControl::None;  // Dialect::Siemens only
};

const Profile* findProfile(std::string_view name);
const std::vector<Profile>& allProfiles();

}  // namespace cyclecert
