#pragma once
// The active tool offset as the cycles need it: nose radius and imaginary tool-nose direction.

namespace cyclecert {

struct ToolOffset {
  double noseRadius = 0;  // mm
  int tip = 0;            // imaginary tip direction 0…9 (FANUC chart, X up, Z right; 0 and 9: the nose centre)
};

}  // namespace cyclecert
