#pragma once
// The profile read when none is named — by the reference (after the program's header), LinuxCNC's
// translation, the mutants, `cyclecert diff`, the fuzzer's cases and the metamorphic relations:
// FANUC Series 0i-F, decided here once.
#include <string>
#include <string_view>

#include "reference/model/profile.h"

namespace cyclecert {

inline constexpr std::string_view kDefaultProfileName = "fanuc-0i-f";

// `name`, or the default profile's name when `name` is empty (an unknown name stays as it is: the
// caller reports it).
inline std::string profileNameOrDefault(std::string_view name) {
  return std::string(name.empty() ? kDefaultProfileName : name);
}

// The default profile itself.
const Profile& defaultProfile();

}  // namespace cyclecert
