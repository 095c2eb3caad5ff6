#pragma once
// Shared by the libFuzzer targets (tests/fuzz/README.md): the input as text, and the reading
// setting (profile and parameters) picked by its first byte, so that one target covers every
// profile and the parameter-chosen formats.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cyclecert::fuzz {

inline std::string textOf(const std::uint8_t* data, std::size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// A profile and the parameters applied over its defaults.
struct Setting {
  std::string profile;
  std::vector<std::pair<std::string, double>> params;
};

// The FANUC-dialect readings: each profile, then FANUC 0i-F reading Series 10/11 programs
// (0001#1 FCV = 1) and G code systems B and C (3401#6 GSB, 3401#7 GSC).
inline const std::vector<Setting>& fanucSettings() {
  static const std::vector<Setting> settings{
      {"fanuc-0i-f", {}}, {"fanuc-0i-c", {}},         {"gsk", {}},           {"hnc", {}},
      {"haas", {}},       {"fanuc-0i-f", {{"FCV", 1}}}, {"fanuc-0i-f", {{"GSB", 1}}}, {"fanuc-0i-f", {{"GSC", 1}}},
  };
  return settings;
}

// Every reading: the FANUC ones, then the SINUMERIK profiles.
inline const std::vector<Setting>& allSettings() {
  static const std::vector<Setting> settings = [] {
    std::vector<Setting> s = fanucSettings();
    s.push_back({"sinumerik-802s", {}});
    s.push_back({"sinumerik-802d", {}});
    return s;
  }();
  return settings;
}

// The setting the first byte picks (modulo their number), and the rest of the input as the text.
struct Chosen {
  const Setting& setting;
  std::string text;
};
inline Chosen choose(const std::vector<Setting>& settings, const std::uint8_t* data, std::size_t size) {
  if (size == 0) return {settings.front(), ""};
  return {settings[data[0] % settings.size()], textOf(data + 1, size - 1)};
}

}  // namespace cyclecert::fuzz
