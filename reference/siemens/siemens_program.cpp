#include "reference/siemens/siemens_program.h"

namespace cyclecert {

const SiemensWord* SiemensBlock::find(std::string_view address) const {
  for (const SiemensWord& w : words) {
    if (w.address == address) return &w;
  }
  return nullptr;
}

bool SiemensBlock::hasKeyword(std::string_view name) const {
  for (const SiemensKeyword& k : keywords) {
    if (k.name == name) return true;
  }
  return false;
}

bool SiemensBlock::endsProgram() const {
  if (hasKeyword("RET")) return true;
  for (const SiemensWord& w : words) {
    if (w.address == std::string_view("M") && (w.value == 2 || w.value == 17 || w.value == 30)) return true;
  }
  return false;
}

}  // namespace cyclecert
