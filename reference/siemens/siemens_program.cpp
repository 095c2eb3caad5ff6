#include "reference/siemens/siemens_program.h"

namespace cyclecert {

namespace {

// a == b for an address of a few letters, compared in place: the runner and the contour reader
// ask a block for its words many times per case, and std::string_view's == calls memcmp.
bool sameAddress(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] != b[k]) return false;
  }
  return true;
}

}  // namespace

const SiemensWord* SiemensBlock::find(std::string_view address) const {
  for (const SiemensWord& w : words) {
    if (sameAddress(w.address, address)) return &w;
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
