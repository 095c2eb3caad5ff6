#include "reference/model/cycle_family.h"

#include <array>

namespace cyclecert {

namespace {

constexpr std::array kFamilies{CycleFamily::G71, CycleFamily::G72, CycleFamily::G73, CycleFamily::Lcyc95,
                               CycleFamily::Cycle95, CycleFamily::G74_1};

}  // namespace

std::string_view cycleCode(CycleFamily family) {
  switch (family) {
    case CycleFamily::G71: return "G71";
    case CycleFamily::G72: return "G72";
    case CycleFamily::G73: return "G73";
    case CycleFamily::Lcyc95: return "LCYC95";
    case CycleFamily::Cycle95: return "CYCLE95";
    case CycleFamily::G74_1: return "G74.1";
  }
  return "G71";
}

std::optional<CycleFamily> cycleFamilyOfCode(std::string_view code) {
  for (CycleFamily f : kFamilies) {
    if (cycleCode(f) == code) return f;
  }
  return std::nullopt;
}

bool isSiemensFamily(CycleFamily family) {
  switch (family) {
    case CycleFamily::G71:
    case CycleFamily::G72:
    case CycleFamily::G73:
    case CycleFamily::G74_1: return false;
    case CycleFamily::Lcyc95:
    case CycleFamily::Cycle95: return true;
  }
  return false;
}

}  // namespace cyclecert
