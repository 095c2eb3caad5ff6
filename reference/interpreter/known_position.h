#pragma once
// Which axes' work coordinates the reference knows (PROG.POSITION in specs/rules.json). At the
// start of a program none: the tool stands wherever the last program left it. An absolute word
// (X, Y, Z, or G50's coordinate setting) makes its axis known; G28/G30 (return to a reference
// position) and G53 (machine coordinates) make the commanded axes unknown again, since cyclecert
// does not model where the reference positions lie in work coordinates.
#include <string>

namespace cyclecert {

class KnownPosition {
 public:
  struct Why {
    int line = 0;          // the block that lost the position, 0 at the start of the program
    std::string command;   // "G28", "G53", … (empty at the start)
    bool viaIntermediatePoint = false;  // G28/G30: the tool left from the intermediate point
  };

  bool known(char axis) const { return !slot(axis).unknown; }
  const Why& whyUnknown(char axis) const { return slot(axis).why; }
  void learn(char axis) { slot(axis).unknown = false; }
  void forget(char axis, Why why) { slot(axis) = {true, std::move(why)}; }

  // "position of X unknown after G28 at line 4" / "… at the start of the program".
  std::string describe(char axis) const {
    const Why& w = whyUnknown(axis);
    return std::string("position of ") + axis + " unknown " +
           (w.line == 0 ? std::string("at the start of the program (no positioning block yet)")
                        : "after " + w.command + " at line " + std::to_string(w.line));
  }

 private:
  struct Slot {
    bool unknown = true;
    Why why;
  };
  Slot& slot(char axis) { return axis == 'X' ? x_ : axis == 'Y' ? y_ : z_; }
  const Slot& slot(char axis) const { return axis == 'X' ? x_ : axis == 'Y' ? y_ : z_; }
  Slot x_, y_, z_;
};

}  // namespace cyclecert
