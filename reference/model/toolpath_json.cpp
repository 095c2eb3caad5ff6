#include "reference/model/toolpath_json.h"

#include <cmath>
#include <optional>

namespace cyclecert {

using nlohmann::json;

namespace {

// Follows the JSON pointer of the value being read, so that a parse error can name its field.
class PointerTracker : public nlohmann::json_sax<json> {
 public:
  std::string pointer() const {
    std::string p;
    for (const Frame& f : stack_) {
      if (!f.array && f.key.empty()) break;  // an object whose first key is not read yet
      p += "/" + (f.array ? std::to_string(f.index) : f.key);
    }
    return p;
  }
  std::string error;

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& k) override {
    stack_.back().key = k;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
    error = e.what();
    return false;
  }

 private:
  struct Frame {
    bool array;
    std::size_t index = 0;
    std::string key;
  };
  // A finished value moves an array on to its next index.
  bool value() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
    return true;
  }
  bool open(bool array) {
    stack_.push_back({array, 0, {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return value();
  }
  std::vector<Frame> stack_;
};

std::pair<int, int> lineAndColumn(const std::string& text, std::size_t offset) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return {line, column};
}

}  // namespace

json parseJsonDocument(const std::string& text, const std::string& file) {
  try {
    return json::parse(text);
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number beyond a double
    PointerTracker tracker;
    json::sax_parse(text, &tracker);
    const std::string field = tracker.pointer().empty() ? "(document)" : tracker.pointer();
    std::string where = file;
    if (const auto* pe = dynamic_cast<const json::parse_error*>(&e)) {
      const auto [line, column] = lineAndColumn(text, pe->byte > 0 ? pe->byte - 1 : 0);
      where += ":" + std::to_string(line) + ":" + std::to_string(column);
    }
    throw ToolpathFormatError(where + ": " + field + ": expected valid JSON (" + e.what() + ")");
  }
}

std::string kindName(MoveKind k) { return k == MoveKind::Rapid ? "rapid" : "feed"; }

std::string shapeName(SegmentKind s) {
  switch (s) {
    case SegmentKind::Line: return "line";
    case SegmentKind::ArcCW: return "arc_cw";
    case SegmentKind::ArcCCW: return "arc_ccw";
  }
  return "line";
}

json toJson(Point p) { return json{{"x", p.x}, {"z", p.z}}; }

json toJson(const Move& m) {
  json j{{"kind", kindName(m.kind)}, {"shape", shapeName(m.shape)}, {"to", toJson(m.to)}};
  if (m.center) j["center"] = toJson(*m.center);
  if (m.feed) j["feed"] = *m.feed;
  if (m.dwell) j["dwell"] = *m.dwell;
  if (m.phase != MovePhase::None) j["phase"] = phaseName(m.phase);
  if (m.pass > 0) j["pass"] = m.pass;
  if (!m.rules.empty()) j["rules"] = m.rules;
  if (m.singleBlockStop) j["stop"] = true;
  return j;
}

json toJson(const Toolpath& t) {
  json moves = json::array();
  for (const Move& m : t.moves) moves.push_back(toJson(m));
  json warnings = json::array();
  for (const Warning& w : t.warnings) warnings.push_back({{"line", w.line}, {"message", w.message}});
  json cycles = json::array();
  for (const CycleRecord& c : t.cycles) {
    json shape = json::array();
    for (const Segment& s : c.shape) {
      json seg{{"shape", shapeName(s.kind)}, {"from", toJson(s.from)}, {"to", toJson(s.to)}, {"line", s.sourceLine}};
      if (s.isArc()) seg["center"] = toJson(s.center);
      shape.push_back(seg);
    }
    cycles.push_back({{"code", c.code}, {"line", c.line}, {"start", toJson(c.start)},
                      {"first_move", c.firstMove}, {"move_count", c.moveCount},
                      {"shape", shape}, {"allowance", toJson(c.allowance)}, {"compensated", c.compensated}});
  }
  json alarm = nullptr;
  if (t.alarm) {
    alarm = {{"code", t.alarm->code}, {"message", t.alarm->message}, {"line", t.alarm->line}};
    if (!t.alarm->when.empty()) alarm["when"] = t.alarm->when;
  }
  return json{{"profile", t.profile}, {"units", "mm"},   {"plane", t.plane},
              {"start", toJson(t.start)}, {"moves", moves}, {"alarm", alarm},
              {"warnings", warnings},      {"cycles", cycles}};
}

namespace {
[[noreturn]] void fail(const std::string& where, const std::string& expected) {
  throw ToolpathFormatError(where + ": expected " + expected);
}

double finiteNumber(const json& j, const std::string& where) {
  if (!j.is_number()) fail(where, "a number");
  const double v = j.get<double>();
  if (!std::isfinite(v)) fail(where, "a finite number");
  return v;
}

// A coordinate beyond any controller's travel is not a plan: the largest programmable value is
// 999999.999 mm (FANUC IS-B, 8 digits) or 99999.9999 inch (2,540,000 mm). Bounding it here keeps
// the oracles' geometry (arc flattening, regions) within what doubles measure to 1 µm.
constexpr double kLargestCoordinateMm = 1e7;

double coordinate(const json& j, const std::string& where) {
  const double v = finiteNumber(j, where);
  if (std::abs(v) > kLargestCoordinateMm) {
    fail(where, "a coordinate within ±10,000,000 mm (beyond any machine's travel), found " + j.dump().substr(0, 40));
  }
  return v;
}

// j[key] when it is there; a value of another type is an error naming where/key and `expected`.
std::optional<std::string> optionalString(const json& j, const char* key, const std::string& where,
                                          const std::string& expected) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  if (!j[key].is_string()) fail(where + "/" + key, expected + " (a string), found " + j[key].dump().substr(0, 80));
  return j[key].get<std::string>();
}

std::optional<int> optionalInteger(const json& j, const char* key, const std::string& where,
                                   const std::string& expected) {
  if (!j.contains(key) || j[key].is_null()) return std::nullopt;
  const json& v = j[key];
  if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() > 1000000000) {
    fail(where + "/" + key, expected + " (an integer), found " + v.dump().substr(0, 80));
  }
  return v.get<int>();
}

// "phase": one of the spellings of MovePhase; absent (or null) for a move without a phase. Any other
// value is an error that lists the spellings accepted.
MovePhase phaseFromJson(const json& j, const std::string& where) {
  const auto field = j.find("phase");
  if (field == j.end() || field->is_null()) return MovePhase::None;
  const std::string* text = field->get_ptr<const std::string*>();
  const std::optional<MovePhase> phase = text ? phaseNamed(*text) : std::nullopt;
  if (phase) return *phase;
  const std::string accepted = "one of " + phaseNamesText() + " (or no \"phase\")";
  if (!text) fail(where + "/phase", accepted + " (a string), found " + field->dump().substr(0, 80));
  fail(where + "/phase", accepted + ", found \"" + text->substr(0, 80) + "\"");
}

}  // namespace

Point pointFromJson(const json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "an object {\"x\": radius, \"z\": z}");
  for (const char* axis : {"x", "z"}) {
    if (!j.contains(axis)) fail(where + "/" + axis, "a number (field missing)");
  }
  return {coordinate(j["z"], where + "/z"), coordinate(j["x"], where + "/x")};
}

Move moveFromJson(const json& j, const std::string& where) {
  if (!j.is_object()) fail(where, "a move object");
  Move m;
  if (!j.contains("kind") || !j["kind"].is_string()) fail(where + "/kind", "\"rapid\" or \"feed\"");
  const std::string kind = j["kind"];
  if (kind == "rapid") m.kind = MoveKind::Rapid;
  else if (kind == "feed") m.kind = MoveKind::Feed;
  else fail(where + "/kind", "\"rapid\" or \"feed\", found \"" + kind + "\"");
  const std::string shape = optionalString(j, "shape", where, "\"line\", \"arc_cw\" or \"arc_ccw\"").value_or("line");
  if (shape == "line") m.shape = SegmentKind::Line;
  else if (shape == "arc_cw") m.shape = SegmentKind::ArcCW;
  else if (shape == "arc_ccw") m.shape = SegmentKind::ArcCCW;
  else fail(where + "/shape", "\"line\", \"arc_cw\" or \"arc_ccw\", found \"" + shape + "\"");
  if (!j.contains("to")) fail(where + "/to", "a point (field missing)");
  m.to = pointFromJson(j["to"], where + "/to");
  if (m.shape != SegmentKind::Line) {
    if (!j.contains("center")) fail(where + "/center", "a point for an arc (field missing)");
    m.center = pointFromJson(j["center"], where + "/center");
  }
  if (j.contains("feed")) m.feed = finiteNumber(j["feed"], where + "/feed");
  if (j.contains("dwell")) {
    m.dwell = finiteNumber(j["dwell"], where + "/dwell");
    if (*m.dwell < 0) fail(where + "/dwell", "the seconds the tool dwells after the move, ≥ 0, found " + j["dwell"].dump());
  }
  m.phase = phaseFromJson(j, where);
  m.pass = optionalInteger(j, "pass", where, "a pass number ≥ 0").value_or(0);
  if (j.contains("stop")) {
    if (!j["stop"].is_boolean()) fail(where + "/stop", "true or false");
    m.singleBlockStop = j["stop"].get<bool>();
    m.stopGiven = true;
  }
  return m;
}

Alarm alarmFromJson(const json& a, const std::string& where) {
  if (!a.is_object() || !a.contains("code") || !a["code"].is_string()) fail(where, "null or {\"code\": …, \"line\": …}");
  return Alarm{a["code"], optionalString(a, "message", where, "the alarm's message").value_or(""),
               optionalInteger(a, "line", where, "the program line number ≥ 0").value_or(0),
               optionalString(a, "when", where, "\"cycle block\", \"before the cycle\" or \"during the cycle\"")
                   .value_or("")};
}

Toolpath toolpathFromJson(const json& j) {
  if (!j.is_object()) fail("(document)", "a toolpath object with \"moves\"");
  Toolpath t;
  if (j.contains("profile") && j["profile"].is_string()) t.profile = j["profile"];
  if (j.contains("plane") && j["plane"].is_string()) t.plane = j["plane"];
  if (j.contains("alarm") && !j["alarm"].is_null()) t.alarm = alarmFromJson(j["alarm"], "/alarm");
  if (!j.contains("moves")) fail("/moves", "an array of moves (field missing)");
  if (!j["moves"].is_array()) fail("/moves", "an array of moves");
  if (j["moves"].size() > kMostMovesPerToolpath) {
    fail("/moves", "at most " + std::to_string(kMostMovesPerToolpath) + " moves (a real cycle makes hundreds), found " +
                       std::to_string(j["moves"].size()));
  }
  if (j.contains("start")) t.start = pointFromJson(j["start"], "/start");
  for (std::size_t i = 0; i < j["moves"].size(); ++i) {
    const std::string where = "/moves/" + std::to_string(i);
    t.moves.push_back(moveFromJson(j["moves"][i], where));
    const Move& m = t.moves.back();
    if (m.center) {
      const double r0 = distance(t.from(i), *m.center), r1 = distance(m.to, *m.center);
      if (std::abs(r0 - r1) > 1e-3 * std::max(1.0, r0)) {
        fail(where + "/center", "the arc's centre at equal distance from its end points (" + std::to_string(r0) +
                                    " mm from the start, " + std::to_string(r1) + " mm from the end)");
      }
    }
  }
  return t;
}

}  // namespace cyclecert
