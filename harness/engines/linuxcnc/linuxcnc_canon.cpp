// Reading `rs274 -g` output: one canonical call per line,
//
//      16 N..... STRAIGHT_TRAVERSE(20.0000, 0.0000, 5.0000, 0.0000, 0.0000, 0.0000)
//      47 N..... ARC_FEED(-14.0000, 12.0000, -14.0000, 7.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)
//
// STRAIGHT_TRAVERSE/STRAIGHT_FEED(x, y, z, a, b, c[, u, v, w]); in the XZ plane
// ARC_FEED(end z, end x, centre z, centre x, rotation, y, a, b, c[, u, v, w]), rotation > 0
// counter-clockwise with Z right and X up (G3), < 0 clockwise (G2). Coordinates are radius values
// even in G7 diameter mode (checked against rs274 2.9.0~pre1), in mm since the translation says G21.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "harness/engines/linuxcnc/linuxcnc_engine.h"

namespace cyclecert {

namespace {

double round4(double v) {
  const double r = std::round(v * 1e4) / 1e4;
  return r == 0 ? 0.0 : r;  // -0.0000 → 0
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

struct Call {
  std::string name;
  std::string args;  // between the parentheses
};

// "   16 N..... NAME(ARGS)" → {NAME, ARGS}; nothing for any other line.
std::optional<Call> readCall(const std::string& line) {
  std::size_t i = 0;
  while (i < line.size() && line[i] == ' ') ++i;
  const std::size_t digits = i;
  while (i < line.size() && std::isdigit(static_cast<unsigned char>(line[i]))) ++i;
  if (i == digits || i >= line.size() || line[i] != ' ') return std::nullopt;
  while (i < line.size() && line[i] == ' ') ++i;
  if (i >= line.size() || line[i] != 'N') return std::nullopt;
  while (i < line.size() && line[i] != ' ') ++i;
  while (i < line.size() && line[i] == ' ') ++i;
  const std::size_t name = i;
  while (i < line.size() && (std::isupper(static_cast<unsigned char>(line[i])) || line[i] == '_' ||
                             std::isdigit(static_cast<unsigned char>(line[i])))) {
    ++i;
  }
  if (i == name || i >= line.size() || line[i] != '(') return std::nullopt;
  const std::size_t close = line.rfind(')');
  if (close == std::string::npos || close < i) return std::nullopt;
  return Call{line.substr(name, i - name), line.substr(i + 1, close - i - 1)};
}

// The numbers of a call; false when one is not a number.
bool numbers(const std::string& args, std::vector<double>& out) {
  out.clear();
  std::size_t start = 0;
  while (start <= args.size()) {
    std::size_t comma = args.find(',', start);
    if (comma == std::string::npos) comma = args.size();
    const std::string field = trim(args.substr(start, comma - start));
    if (field.empty()) return false;
    char* end = nullptr;
    const double v = std::strtod(field.c_str(), &end);
    if (end != field.c_str() + field.size() || !std::isfinite(v)) return false;
    out.push_back(v);
    start = comma + 1;
  }
  return true;
}

}  // namespace

CanonicalParse parseCanonical(const std::string& text) {
  CanonicalParse r;
  Point at;                   // the tool position (z, x radius), also before the cycle
  double feed = 0;
  bool xzPlane = false;
  bool inCycle = false, inReturn = false;
  std::vector<double> v;
  std::istringstream in(text);
  std::string line;
  int lineNo = 0;
  const auto fail = [&](const std::string& why) {
    if (r.error.empty()) r.error = "rs274 output line " + std::to_string(lineNo) + ": " + why + ": " + trim(line);
  };
  while (std::getline(in, line)) {
    ++lineNo;
    const auto call = readCall(line);
    if (!call) continue;  // diagnostics, "executing", …
    ++r.calls;
    const std::string& n = call->name;
    if (n == "COMMENT") {
      const std::string c = trim(call->args);
      const std::string body = c.size() >= 2 && c.front() == '"' && c.back() == '"' ? c.substr(1, c.size() - 2) : c;
      if (body == kMarkCycle) {
        inCycle = true;
        r.sawCycle = true;
        r.path.start = at;
      } else if (body == kMarkReturn) {
        inReturn = true;
      } else if (body == kMarkEnd) {
        r.sawEnd = true;
        inCycle = false;
      }
      continue;
    }
    if (n == "SELECT_PLANE") {
      xzPlane = trim(call->args) == "CANON_PLANE_XZ";
      continue;
    }
    if (n == "SET_FEED_RATE") {
      if (!numbers(call->args, v) || v.size() != 1) {
        fail("SET_FEED_RATE without one number");
        continue;
      }
      feed = v[0];
      continue;
    }
    const bool traverse = n == "STRAIGHT_TRAVERSE", straightFeed = n == "STRAIGHT_FEED", arc = n == "ARC_FEED";
    if (!traverse && !straightFeed && !arc) continue;  // spindle, units, offsets, …
    if (!numbers(call->args, v)) {
      fail("a coordinate is not a number");
      continue;
    }
    Move m;
    if (arc) {
      if (v.size() < 6) {
        fail("ARC_FEED with fewer than 6 numbers");
        continue;
      }
      if (!xzPlane) {
        fail("ARC_FEED outside the XZ plane");
        continue;
      }
      const double rotation = v[4];
      if (rotation == 0 || std::abs(rotation) > 1) {
        std::ostringstream turns;
        turns << rotation;  // any finite double (a cast to long is undefined beyond its range)
        fail("ARC_FEED with rotation " + turns.str() + " (full turns)");
        continue;
      }
      m.kind = MoveKind::Feed;
      m.shape = rotation > 0 ? SegmentKind::ArcCCW : SegmentKind::ArcCW;
      m.to = {round4(v[0]), round4(v[1])};
      m.center = Point{round4(v[2]), round4(v[3])};
      m.feed = feed;
    } else {
      if (v.size() < 3) {
        fail(n + " with fewer than 3 numbers");
        continue;
      }
      m.kind = traverse ? MoveKind::Rapid : MoveKind::Feed;
      m.shape = SegmentKind::Line;
      m.to = {round4(v[2]), round4(v[0])};
      if (straightFeed) m.feed = feed;
    }
    // Zero-length moves (rs274 repeats the point it stands on; a G7x arc never makes a full turn).
    if (m.to == at) continue;
    at = m.to;
    if (!inCycle) continue;  // positioning before the cycle
    if (inReturn) m.phase = MovePhase::Return;
    r.path.moves.push_back(std::move(m));
  }
  return r;
}

Alarm linuxCncAlarm(const std::string& stderrText, const std::map<std::string, int>& lines) {
  std::vector<std::string> kept;
  std::istringstream in(stderrText);
  std::string line;
  while (std::getline(in, line)) {
    // rs274 prints "executing" when it starts (sometimes glued to the end of its last line).
    for (std::size_t p; (p = line.find("executing")) != std::string::npos;) line.erase(p, 9);
    line = trim(line);
    if (!line.empty()) kept.push_back(line);
  }
  Alarm a;
  a.code = "LINUXCNC";
  a.message = kept.empty() ? "rs274 stopped with an error and no message" : kept.front();
  // The message is followed by the block it stopped in: the case line that block was translated
  // from. (Lines before the message are diagnostics of LinuxCNC's G7x code on stderr.)
  for (std::size_t i = kept.size(); i-- > 1;) {
    if (const auto it = lines.find(kept[i]); it != lines.end()) {
      a.message = kept[i - 1];
      a.line = it->second;
      break;
    }
  }
  return a;
}

}  // namespace cyclecert
