#pragma once
// The canonical toolpath JSON (see README "Toolpath JSON"):
// {"profile", "units": "mm", "plane", "start": {x, z}, "moves": [{kind, shape, to, center?, feed?,
//  dwell?, phase?, pass?, rules?}], "alarm": null | {code, message, line}, "warnings": [...], "cycles": [...]}
// x is the radius in mm; "dwell" the seconds the tool dwells at the move's end (≥ 0, optional).
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "reference/model/toolpath.h"

namespace cyclecert {

// Parses a JSON document; invalid JSON (a NaN token, a number beyond a double, a truncated file…)
// throws ToolpathFormatError naming the file, the field as a JSON pointer (e.g. "/moves/3/to/x"),
// the line and column, and what the parser expected.
nlohmann::json parseJsonDocument(const std::string& text, const std::string& file);

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

// A whole toolpath as an engine writes it (only "moves" is required; "start" defaults to the first
// move's position being reached from an unknown point, so give it). Every error names the field as
// a JSON pointer, e.g. "/moves/3/center: expected the arc's centre at equal distance from its end
// points (1.2 mm from the start, 1.5 mm from the end)". A toolpath with no moves and no alarm is
// valid: a cycle can have nothing to cut (the reference plans none when the start point is already
// on the level where the shape ends).
Toolpath toolpathFromJson(const nlohmann::json& j);
Move moveFromJson(const nlohmann::json& j, const std::string& where);
// {"code": "PS0064", "message"?, "line"?, "when"?}; `where` names it in the error (as does every
// field of the wrong type: "/alarm/message: expected the alarm's message (a string), found 3").
Alarm alarmFromJson(const nlohmann::json& j, const std::string& where);

std::string kindName(MoveKind k);
std::string shapeName(SegmentKind s);

}  // namespace cyclecert
