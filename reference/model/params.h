#pragma once
// MachineParams: the controller parameters the rules name, each with its number ("5132", "5105#1"),
// its mnemonic where FANUC gives one ("RF1"), its default and the rule IDs it serves. A parameter
// can be named either way: set("5105#1", 1) and set("RF1", 1) are the same.
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace cyclecert {

struct ParamSpec {
  std::string number;    // "5132" or "5105#1" (bit 1 of parameter 5105)
  std::string mnemonic;  // "RF1", or empty when the manual names none
  bool isBit = false;
  double defaultValue = 0;
  std::string unit;      // "mm (radius)", "bit", …
  std::string description;
  std::vector<std::string> rules;
  bool isSigned = false;  // a signed length (G73's relief Δi, Δk): negative values are accepted
  bool isCount = false;   // a whole number (G73's divisions d)
};

class UnknownParam : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class MachineParams {
 public:
  MachineParams();  // every parameter at its catalogue default

  static const std::vector<ParamSpec>& catalogue();
  // The spec for a number or mnemonic (case-insensitive), or nullptr.
  static const ParamSpec* find(std::string_view nameOrNumber);

  double get(std::string_view nameOrNumber) const;  // throws UnknownParam
  bool bit(std::string_view nameOrNumber) const { return get(nameOrNumber) != 0; }
  // Throws UnknownParam for an unknown name, std::invalid_argument for a bad value (a bit that is
  // not 0/1, a negative or non-finite length).
  void set(std::string_view nameOrNumber, double value);
  // "NAME=VALUE" as given on the command line.
  void setFromText(std::string_view assignment);

 private:
  std::vector<double> values_;  // in the catalogue's order
};

}  // namespace cyclecert
