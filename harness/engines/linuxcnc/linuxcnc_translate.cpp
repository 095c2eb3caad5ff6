// A FANUC-profile spec case in LinuxCNC's G7x dialect (LinuxCNC 2.9, src/emc/rs274ngc/interp_g7x.cc):
//
//   G18 G21 G90 G40 G94 G91.1 G7          XZ plane, mm, absolute, diameter mode, incremental I/K
//   G0 X<2·A.x> Z<A.z>                    the tool at the cycle start point A
//   o100 sub                              the rough profile: the finish shape shifted by (Δw, Δu/2)
//   G0 X… Z…                                head block A' → B' (G1 for a G01 head)
//   G1 X… Z… / G2|G3 X… Z… I… K…            the shape to C' (I, K: centre − start, radius)
//   o100 endsub
//   (cyclecert: cycle)
//   G71.1 Q100 X<2·A'.x> Z<A'.z> D0 I<Δd> R<e> F<F>   type I: G71.1/G72.1; type II: G71/G72
//   (cyclecert: return)
//   G0 …                                  the return to A the case's DTP asks for (optional)
//   (cyclecert: end)
//   M2
//
// The word-by-word table and what is not applicable are in README.md beside this file.
#include <sstream>

#include "harness/engines/linuxcnc/linuxcnc_engine.h"
#include "oracles/cycle_spec.h"
#include "reference/gcode/parser.h"
#include "reference/interpreter/g_codes.h"
#include "reference/model/number_text.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

namespace {

// A number as LinuxCNC reads it: up to 6 decimals, no trailing zeros, never "-0".
std::string num(double v) { return shortDecimalText(v); }

// "X… Z…" of a point (X as a diameter: G7).
std::string xz(Point p) {
  std::string out = "X";  // appended piece by piece: GCC 12 warns (-Wrestrict) about "literal" + string&&
  out += num(2 * p.x);
  out += " Z";
  out += num(p.z);
  return out;
}

// The parameters whose meaning the translation carries: Δd and e (5132/5133, through I and R), DTP
// (through the appended return), FCV (0001#1: the Series 10/11 one block is read, its D becomes
// Δd and so LinuxCNC's I, G71.FS10.D) and the G code system (3401#6 GSB, #7 GSC: the program is
// read in system B or C, PROG.GSYS.SELECT; the translation writes LinuxCNC's own codes).
bool translatedParameter(const ParamSpec& p) {
  return p.number == "5132" || p.number == "5133" || p.number == "5108#1" || p.number == "0001#1" ||
         p.number == "3401#6" || p.number == "3401#7";
}

// HNC.G71.FST: after the Huazhong G71 the program runs ns…nf again as the finishing path; the
// translator writes one LinuxCNC cycle and nothing after it (and the oracles' reading it builds on
// does not model that run).
std::optional<std::string> huazhongFormat(const Profile& profile) {
  if (profile.roughingFormat != RoughingBlockFormat::HuazhongOneBlock) return std::nullopt;
  return "the Huazhong one-block G71 (profile " + profile.name +
         ") runs ns…nf again after roughing as its finishing path (HNC.G71.FST); the translator writes one "
         "LinuxCNC G71.1/G72.1 cycle and no motion after it";
}

std::string paramLabel(const ParamSpec& p, double value) {
  return (p.mnemonic.empty() ? p.number : p.mnemonic + " (" + p.number + ")") + " = " + num(value);
}

int planeBefore(const Program& program, int line) {
  int plane = 18;
  for (const Block& b : program.blocks) {
    if (b.line > line) break;
    for (const Word* g : b.all('G')) {
      const int g10 = gCode10(g->value);
      if (g10 == 170 || g10 == 180 || g10 == 190) plane = g10 / 10;
    }
  }
  return plane;
}

// Forbidden cycles whose shape the oracles' reading did not finish: nothing faithful to translate.
std::optional<std::string> untranslatableAlarm(const CycleSpec& c) {
  if (!c.forbiddenBy) return std::nullopt;
  const Alarm& a = *c.forbiddenBy;
  const std::string what = a.code + " at line " + std::to_string(a.line) + " (" + a.message + ")";
  if (c.shape.empty()) {
    return "FANUC stops with " + what + " before the cycle's shape is read: nothing to translate";
  }
  if (a.code == "PS0023" || a.code == "PS0041" || a.message.find("in the shape program") != std::string::npos) {
    return "FANUC stops with " + what + " while reading the shape: the shape is incomplete, nothing to translate";
  }
  if (a.code == "PS0065") {
    return "FANUC's rule that block ns states G00/G01 (" + what +
           ") has no LinuxCNC counterpart: the O-sub's blocks are written with explicit motion words";
  }
  return std::nullopt;  // PS0064, PS0329, PS0322, PS0325 (head): the shape is whole; LinuxCNC decides
}

// The line of the program's first G73 pattern repeating block (rules G73.*) — G73 in system A and
// B, G75 in system C (PROG.GSYS.C), as the program's G code system reads it — or nothing.
std::optional<int> patternRepeatingLine(const Program& program, GCodeSystem system) {
  for (const Block& b : program.blocks) {
    for (const Word& w : b.words) {
      if (w.letter != 'G') continue;
      const GCode* g = findGCode(system, gCode10(w.value));
      if (g && g->function == 730) return b.line;
    }
  }
  return std::nullopt;
}

// Text safe inside a LinuxCNC comment: no parentheses (a ')' would end it), printable, short.
std::string commentText(const std::string& text) {
  std::string out;
  for (char ch : text.substr(0, 80)) out += (ch == '(' || ch == ')' || ch < ' ' || ch > '~') ? '_' : ch;
  return out;
}

class Writer {
 public:
  void line(const std::string& text, int sourceLine) {
    out_ << text << '\n';
    lines_.emplace(text, sourceLine);  // 0: a block of the translation's own
  }
  std::string text() const { return out_.str(); }
  std::map<std::string, int>& lines() { return lines_; }

 private:
  std::ostringstream out_;
  std::map<std::string, int> lines_;
};

}  // namespace

LinuxCncTranslation translateForLinuxCnc(const SpecCase& c, const LinuxCncOptions& options, int subNumber) {
  const auto notApplicable = [](std::string why) {
    LinuxCncTranslation t;
    t.notApplicable = std::move(why);
    return t;
  };
  if (c.mdi) return notApplicable("MDI mode: the case is about FANUC's MDI rule (PS0067); LinuxCNC has no such mode rule");
  const std::string profileName = profileNameOrDefault(c.profile);
  const Profile* profile = findProfile(profileName);
  if (!profile) return notApplicable("unknown profile '" + profileName + "'");
  if (auto why = huazhongFormat(*profile)) return notApplicable(*why);
  if (profile->dialect == Dialect::Siemens) {
    return notApplicable("a SINUMERIK program (" + profile->name + "): LinuxCNC has no LCYC95/CYCLE95 and reads no " +
                         "R parameters or contour subprograms of this kind");
  }

  MachineParams params = profile->defaults;
  std::vector<std::string> inexpressible;
  for (const auto& [name, value] : c.params) {
    try {
      params.set(name, value);
    } catch (const std::exception& e) {
      return notApplicable(std::string("bad parameter: ") + e.what());
    }
    const ParamSpec* spec = MachineParams::find(name);
    if (spec && !translatedParameter(*spec) && value != profile->defaults.get(spec->number)) {
      inexpressible.push_back(paramLabel(*spec, value));
    }
  }

  Program program;
  try {
    program = parseProgram(c.program, c.file + "#/program");
  } catch (const std::exception& e) {
    return notApplicable(std::string("the translator cannot read the program: ") + e.what());
  }
  // Before the parameters: a G73 case's 5135–5137 are not why it cannot be translated.
  if (const auto line = patternRepeatingLine(program, gCodeSystemOf(*profile, params))) {
    return notApplicable("LinuxCNC's G73 is a drilling cycle (chip-break peck): FANUC's G73 pattern repeating "
                         "cycle (line " + std::to_string(*line) + ") has no LinuxCNC counterpart");
  }
  if (!inexpressible.empty()) {
    std::string list;
    for (const std::string& p : inexpressible) list += (list.empty() ? "" : ", ") + p;
    return notApplicable("FANUC parameters without a LinuxCNC counterpart: " + list);
  }
  for (const Block& b : program.blocks) {
    if (b.hasG(410) || b.hasG(420)) {
      return notApplicable("nose-radius compensation (G41/G42 at line " + std::to_string(b.line) +
                           "): LinuxCNC refuses G71/G72 with cutter compensation on, and FANUC's cycle works on "
                           "the compensated shape");
    }
  }
  ProgramSpec spec;
  try {
    spec = readProgramSpec(program, *profile, params, c.tool.value_or(ToolOffset{}), false);
  } catch (const std::exception& e) {
    return notApplicable(std::string("the translator cannot read the program's cycles: ") + e.what());
  }
  if (spec.cycles.empty()) return notApplicable("the program has no G71/G72 roughing cycle");
  if (spec.cycles.size() > 1) {
    return notApplicable("the translator handles programs with one roughing cycle; this one has " +
                         std::to_string(spec.cycles.size()));
  }
  if (spec.hasFinishingCycle) {
    return notApplicable("G70 finishing is not translated: LinuxCNC's G70 (Q sub, D/E/P passes) rapids onto the "
                         "shape and does not return to the start point");
  }
  const CycleSpec& cy = spec.cycles.front();
  if (cy.patternRepeating()) return notApplicable("G73 is not translated: LinuxCNC's G73 is a drilling cycle");
  if (auto why = untranslatableAlarm(cy)) return notApplicable(*why);
  if (spec.motionAfterCycles) return notApplicable("motion after the cycle is not translated");
  if (spec.motionBeforeCycles) {
    return notApplicable("motion before the cycle is not translated (the translation starts at the cycle start point)");
  }

  const std::vector<Segment> rough = cy.roughProfile();
  const Point a = cy.start;
  const Point a1 = a + cy.allowance;  // A'
  const bool g71 = cy.family == CycleFamily::G71;
  const std::string sub = "o" + std::to_string(subNumber);

  Writer w;
  w.line("(cyclecert: " + commentText(c.id.empty() ? std::string("case") : c.id) + ")", 0);
  w.line("G18 G21 G90 G40 G94 G91.1 G7", 0);
  w.line("G0 " + xz(a), 0);
  w.line(sub + " sub", cy.line);
  for (std::size_t i = 0; i < rough.size(); ++i) {
    const Segment& s = rough[i];
    const int line = s.sourceLine > 0 ? s.sourceLine : cy.line;
    if (i == 0) {
      w.line(std::string(cy.headIsRapid ? "G0 " : "G1 ") + xz(s.to), line);
    } else if (!s.isArc()) {
      w.line("G1 " + xz(s.to), line);
    } else {
      w.line(std::string(s.kind == SegmentKind::ArcCW ? "G2 " : "G3 ") + xz(s.to) + " I" + num(s.center.x - s.from.x) +
                 " K" + num(s.center.z - s.from.z),
             line);
    }
  }
  w.line(sub + " endsub", cy.line);
  w.line(std::string("(") + kMarkCycle + ")", 0);
  const std::string code = cy.code + (cy.typeII ? "" : ".1");
  w.line(code + " Q" + std::to_string(subNumber) + " " + xz(a1) + " D0 I" + num(cy.depthOfCut) + " R" + num(cy.retract) +
             " F" + num(cy.feed),
         cy.line);

  LinuxCncProgram p;
  if (options.appendReturn) {
    w.line(std::string("(") + kMarkReturn + ")", 0);
    std::string how;
    if (cy.directReturn && !cy.typeII) {
      w.line("G0 " + xz(a), cy.line);
      how = "straight (DTP = 1)";
    } else {
      // DTP = 0 (and type II): along the depth axis to A's depth, then along the cut axis to A.
      w.line(g71 ? "G0 X" + num(2 * a.x) : "G0 Z" + num(a.z), cy.line);
      w.line(g71 ? "G0 Z" + num(a.z) : "G0 X" + num(2 * a.x), cy.line);
      how = "along the depth axis, then the cut axis";
    }
    p.warnings.push_back({cy.line, "linuxcnc translation: the return to the start point (" + how +
                                       ") is appended by cyclecert; LinuxCNC's " + code + " ends where the profile ends"});
  }
  w.line(std::string("(") + kMarkEnd + ")", 0);
  w.line("M2", 0);

  p.text = w.text();
  p.lines = std::move(w.lines());
  p.start = a;
  p.plane = "G" + std::to_string(planeBefore(program, cy.line));
  p.cycle.code = cy.code;
  p.cycle.line = cy.line;
  p.cycle.start = a;
  p.cycle.shape = cy.shape;
  p.cycle.allowance = cy.allowance;
  LinuxCncTranslation t;
  t.program = std::move(p);
  return t;
}

}  // namespace cyclecert
