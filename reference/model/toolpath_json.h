#pragma once
// The canonical toolpath JSON (see README "Toolpath JSON"):
// {"profile", "units": "mm", "plane", "start": {x, z}, "moves": [{kind, shape, to, center?, feed?,
//  phase?, pass?, rules?}], "alarm": null | {code, message, line}, "warnings": [...], "cycles": [...]}
// x is the radius in mm.
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "reference/model/toolpath.h"

namespace cyclecert {

nlohmann::json toJson(Point p);
nlohmann::json toJson(const Move& m);
nlohmann::json toJson(const Toolpath& t);

// A JSON value that is not a valid toolpath or move: the message names the field (a JSON pointer
// such as "/moves/3/to/x") and what was expected.
class ToolpathFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

Point pointFromJson(const nlohmann::json& j, const std::string& where);
Move moveFromJson(const nlohmann::json& j, const std::string& where);

std::string kindName(MoveKind k);
std::string shapeName(SegmentKind s);

}  // namespace cyclecert
