#pragma once
// A profile: dialect + controller model. It decides what the documents leave to the controller:
// parameter defaults, which shape-program G codes are tolerated, and the alarm texts.
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/params.h"

namespace cyclecert {

struct Profile {
  std::string name;         // "fanuc-0i-f", "gsk"
  std::string description;
  std::string seed;         // the source document the profile follows
  MachineParams defaults;   // parameter values before the case's or the CLI's settings
  // GSK (seed 001) accepts G40/G41/G42 inside ns…nf and ignores them during roughing; FANUC 0i-F
  // raises PS0325 unless NT1 (issue 3).
  bool toleratesTnrcInShape = false;
  // G71.T2.ORDER: 0i-F roughs a pocket to its bottom before the next (depth first); 0i-C cuts
  // every pocket at one level before going deeper.
  bool pocketsLevelByLevel = false;
  // PROG.UNITS: the input unit of a program that commands neither G20 nor G21 (the power-on
  // state of group 06, parameter INI (0000#2) on FANUC). Every current profile is metric.
  bool inchByDefault = false;
  // "millimetres" or "inches": the default unit's name, for the warning that assumes it.
  std::string defaultUnitsName() const { return inchByDefault ? "inches" : "millimetres"; }
};

const Profile* findProfile(std::string_view name);
const std::vector<Profile>& allProfiles();

}  // namespace cyclecert
