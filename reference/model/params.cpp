#include "reference/model/params.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <unordered_map>

#include "reference/model/ascii.h"

namespace cyclecert {

const std::vector<ParamSpec>& MachineParams::catalogue() {
  // Defaults are the controller's shipped values (FANUC 0i-F: all zero); profiles override them.
  static const std::vector<ParamSpec> specs = {
      {"5132", "", false, 0.0, "mm (radius)",
       "Depth of cut Δd of G71/G72 when the first cycle block gives none; a programmed Δd overwrites it",
       {"G71.DD.MODAL", "G72.DD"}},
      {"5133", "", false, 0.0, "mm (radius)",
       "Retract amount e of G71/G72 when the first cycle block gives none; a programmed e overwrites it",
       {"G71.E.MODAL", "G72.DD"}},
      {"5135", "", false, 0.0, "mm (radius, signed)",
       "Relief Δi of G73 along the plane's 2nd axis (X), a radius value, when the first G73 block gives none; a "
       "programmed Δi overwrites it",
       {"G73.PARAMS", "G73.FMT"}, true},
      {"5136", "", false, 0.0, "mm (signed)",
       "Relief Δk of G73 along the plane's 1st axis (Z) when the first G73 block gives none; a programmed Δk "
       "overwrites it",
       {"G73.PARAMS", "G73.FMT"}, true},
      {"5137", "", false, 0.0, "count",
       "Number of divisions d (rough passes) of G73 when the first G73 block gives none; a programmed d overwrites "
       "it; 0 (the shipped value) makes a G73 without R alarm PS0062",
       {"G73.PARAMS", "G73.D.RANGE"}, false, true},
      {"5145", "", false, 0.0, "mm",
       "Allowed non-monotonic motion on the plane's 1st axis (Z) before alarm PS0064",
       {"G71.T1.ALARM"}},
      {"5146", "", false, 0.0, "mm (radius)",
       "Allowed non-monotonic motion on the plane's 2nd axis (X) before alarm PS0329",
       {"G71.T1.ALARM"}},
      {"5105#1", "RF1", true, 0.0, "bit",
       "1: type I G71/G72 makes no semi-finish pass after the last rough cut",
       {"G71.T1.SEMIFIN"}},
      {"5108#1", "DTP", true, 0.0, "bit",
       "1: type I G71/G72 return straight from the shape's end point to the cycle start",
       {"G71.DTP", "G72.STEP8"}},
      {"5134", "", false, 0.0, "mm (radius)",
       "Type II: clearance above the surface at which the rapid approach into a pocket stops and cutting feed begins",
       {"G71.T2.POCKET.EXIT"}},
      {"5105#2", "RF2", true, 0.0, "bit", "1: type II G71/G72 makes no semi-finish pass", {"G71.T2.RETURN"}},
      {"5108#0", "R16", true, 0.0, "bit",
       "1: type II keeps cutting along blocks parallel to the cut axis when following the shape after a cut",
       {"G71.CHAMFER"}},
      {"5108#3", "NSP", true, 0.0, "bit", "1: type II avoids repeating paths (implies R16 = 1)", {"G71.NSP"}},
      {"5102#2", "QSR", true, 0.0, "bit",
       "1: before the cycle, check that the block named by Q exists (GSK's manual uses this bit for automatic type recognition)",
       {"G71.CHECK.QSR", "G72.TYPE.SELECT"}},
      {"5104#2", "FCK", true, 0.0, "bit", "1: check the finish shape (and Q) before the cycle moves",
       {"G71.CHECK.FCK"}},
      {"5106#2", "NT1", true, 0.0, "bit", "1: G40/G41/G42 inside a G71/G72/G73 shape are ignored without alarm",
       {"G71.TNRC.NT1"}},
      {"5106#3", "NT2", true, 0.0, "bit", "1: nose-radius compensation commanded inside a G70 shape is honoured",
       {"G71.TNRC.NT2"}},
      {"5102#7", "CSB", true, 0.0, "bit",
       "Single block in a cycle: 0 stops at the end of each cutting cycle, 1 after each block",
       {"G72.SINGLE"}},
      {"0001#1", "FCV", true, 0.0, "bit",
       "1: FANUC Series 10/11 program format: one-block G71/G72 P Q U W I K D F S T (D = Δd in least input increments)",
       {"G71.FS10.FMT", "G71.FS10.D", "G71.FS10.FCV0"}},
      {"8133#0", "SSC", true, 0.0, "bit",
       "1: constant surface speed control is enabled (G96/G97 inside ns…nf are then ignored by the cycle)",
       {"G71.CSS"}},
      {"182#7", "", true, 0.0, "bit",
       "GSK NO182.7: 0 reads P(Δi) and Q(Δk) of G74.1 in least input increments (IS-C: 0.0001 mm, as seed 002's "
       "example O0008: P30000 = 3 mm), 1 in mm (inch)",
       {"G74_1.ADDR", "G74_1.EX.O0008"}},
      {"3401#6", "GSB", true, 0.0, "bit",
       "1: G code system B (G90/G91 absolute/incremental, G92 coordinate setting, G94/G95 feed modes, "
       "G77/G78/G79 single cycles); FANUC profiles",
       {"PROG.GSYS.SELECT", "PROG.GSYS.B"}},
      {"3401#7", "GSC", true, 0.0, "bit",
       "1: G code system C (as B, with G70/G71 inch/metric and G72–G78 the multiple repetitive cycles); "
       "takes precedence over GSB; FANUC profiles",
       {"PROG.GSYS.SELECT", "PROG.GSYS.C"}},
  };
  return specs;
}

namespace {
std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}
}  // namespace

const ParamSpec* MachineParams::find(std::string_view name) {
  name = trimmed(name);
  // As the catalogue spells it (the planners ask so, dozens of times per program), then in any case.
  static const std::unordered_map<std::string_view, const ParamSpec*> bySpelling = [] {
    std::unordered_map<std::string_view, const ParamSpec*> names;
    for (const ParamSpec& p : catalogue()) {
      names.emplace(p.number, &p);
      if (!p.mnemonic.empty()) names.emplace(p.mnemonic, &p);
    }
    return names;
  }();
  if (const auto found = bySpelling.find(name); found != bySpelling.end()) return found->second;
  for (const ParamSpec& p : catalogue()) {
    if (equalIgnoringCase(p.number, name) || (!p.mnemonic.empty() && equalIgnoringCase(p.mnemonic, name))) return &p;
  }
  return nullptr;
}

MachineParams::MachineParams() {
  for (const ParamSpec& p : catalogue()) values_.push_back(p.defaultValue);
}

static const ParamSpec& require(std::string_view name) {
  const ParamSpec* p = MachineParams::find(name);
  if (!p) {
    throw UnknownParam("unknown parameter '" + std::string(name) +
                       "' (see `cyclecert params`; name it by number like 5105#1 or mnemonic like RF1)");
  }
  return *p;
}

// Where a parameter's value is kept: its place in the catalogue.
static std::size_t indexOf(const ParamSpec& p) { return static_cast<std::size_t>(&p - MachineParams::catalogue().data()); }

double MachineParams::get(std::string_view name) const { return values_[indexOf(require(name))]; }

void MachineParams::set(std::string_view name, double value) {
  const ParamSpec& p = require(name);
  const auto label = [&p] { return p.mnemonic.empty() ? p.number : p.number + " (" + p.mnemonic + ")"; };
  if (!std::isfinite(value)) throw std::invalid_argument("parameter " + label() + ": value must be a finite number");
  if (p.isBit && value != 0 && value != 1) {
    throw std::invalid_argument("parameter " + label() + " is a bit: expected 0 or 1");
  }
  if (!p.isBit && !p.isSigned && value < 0) throw std::invalid_argument("parameter " + label() + ": expected a value ≥ 0");
  if (p.isCount && value != std::floor(value)) throw std::invalid_argument("parameter " + label() + ": expected a whole number");
  values_[indexOf(p)] = value;
}

void MachineParams::setFromText(std::string_view assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string_view::npos) {
    throw std::invalid_argument("parameter '" + std::string(assignment) + "': expected NAME=VALUE");
  }
  const std::string_view value = trimmed(assignment.substr(eq + 1));
  double v = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || ec != std::errc() || end != value.data() + value.size()) {
    throw std::invalid_argument("parameter '" + std::string(assignment) + "': expected a number after '='");
  }
  set(assignment.substr(0, eq), v);
}

}  // namespace cyclecert
