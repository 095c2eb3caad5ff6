#include "oracles/metamorphic/relations.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "oracles/metamorphic/format_relations.h"
#include "oracles/metamorphic/groove_program.h"
#include "oracles/metamorphic/groove_relations.h"
#include "oracles/metamorphic/siemens_relations.h"
#include "oracles/metamorphic/lathe_program.h"
#include "oracles/metamorphic/path_compare.h"
#include "oracles/metamorphic/word_edit.h"
#include "reference/gcode/writer.h"
#include "reference/interpreter/plane.h"
#include "reference/model/alarms.h"
#include "reference/model/params.h"

namespace cyclecert {

namespace {

// ---- rewriting words ------------------------------------------------------------------------------

// G02 ↔ G03: a mirror, or an exchange of the axes, reverses the direction of every arc. Swapping
// every G02/G03 word swaps the modal arc mode too.
void reverseArcCode(Word& w) {
  const int g10 = gCode10(w.value);
  if (g10 == 20) setValue(w, 3);
  if (g10 == 30) setValue(w, 2);
}

using WordChange = std::function<void(const BlockInfo&, WordRole, Word&)>;

Program mapWords(const Program& source, const LatheProgram& lathe, const WordChange& change) {
  Program out = source;
  for (std::size_t i = 0; i < out.blocks.size(); ++i) {
    for (Word& w : out.blocks[i].words) change(lathe.blocks[i], roleOf(lathe.blocks[i], w), w);
  }
  return out;
}

bool isLength(WordRole role) {
  switch (role) {
    case WordRole::AbsFirst:
    case WordRole::AbsSecond:
    case WordRole::IncFirst:
    case WordRole::IncSecond:
    case WordRole::CentreFirst:
    case WordRole::CentreSecond:
    case WordRole::ArcRadius:
    case WordRole::DepthOfCut:
    case WordRole::Retract:
    case WordRole::AllowanceFirst:
    case WordRole::AllowanceSecond:
    case WordRole::ReliefFirst:
    case WordRole::ReliefSecond:
      return true;
    default:
      return false;
  }
}

// ---- parameters ---------------------------------------------------------------------------------

std::string parameterNumber(const std::string& name) {
  const ParamSpec* spec = MachineParams::find(name);
  return spec ? spec->number : name;
}

// The length parameters a program's geometry depends on: Δd, e, the type II clearance, the
// monotonic tolerances along the 1st and the 2nd axis, G73's reliefs Δi and Δk (5137, d, is a count).
bool isLengthParameter(const std::string& name) {
  const std::string n = parameterNumber(name);
  return n == "5132" || n == "5133" || n == "5134" || n == "5145" || n == "5146" || n == "5135" || n == "5136";
}

// The settings with one signed length parameter negated (a mirror of G73's relief, 5135 or 5136).
ParamSettings negated(ParamSettings params, const std::string& number) {
  for (auto& [name, value] : params) {
    if (parameterNumber(name) == number) value = -value;
  }
  return params;
}

// The relations that hold for G73 as for G71/G72 read with it (lathe_program.h).
std::optional<LatheProgram> readWithG73(const Program& p, const ParamSettings& params, std::string& whyNot) {
  return readLatheProgram(p, params, whyNot, LatheFamilies::WithPatternRepeating);
}

// The parameter a first block's word writes (G71.DD.MODAL, G71.E.MODAL, G73.PARAMS), if any.
std::optional<std::string> parameterOf(WordRole role) {
  switch (role) {
    case WordRole::DepthOfCut: return "5132";
    case WordRole::Retract: return "5133";
    case WordRole::ReliefSecond: return "5135";
    case WordRole::ReliefFirst: return "5136";
    case WordRole::Divisions: return "5137";
    default: return std::nullopt;
  }
}

// ---- expected paths -----------------------------------------------------------------------------

Toolpath samePath(const Toolpath& t) { return t; }

std::optional<FollowUp> followUp(Program program, ParamSettings params,
                                 std::function<Toolpath(const Toolpath&)> expected) {
  return FollowUp{std::move(program), std::move(params), std::move(expected), ""};
}

// ---- the relations ------------------------------------------------------------------------------

Relation mirrorZ() {
  Relation r;
  r.id = "mirror-z";
  r.description =
      "Mirror in Z (z → −z): Z, W and K words change sign, and so does the allowance Δw (W of the P/Q "
      "block of G71 and G72); G72's Δd (W of its first block) does not; G02 ↔ G03. The cycle now runs "
      "towards the other end of the part (the other pair of FANUC's four patterns). Expected: the "
      "toolpath with z → −z and every arc reversed. Handles the vocabulary of lathe_program.h."
      " Also G73 (Δk and 5136 negated as well) and G74.1 programs (Z, W and h negated: groove_relations.h); README \"Families\".";
  r.rules = {"G71.QUAD", "G71.ALLOW.UNITS", "G72.ALLOW", "G72.POINTS", "G71.T1.RETRACT45", "G72.RETRACT"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return mirrorGrooveZ(p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    Program out = mapWords(p, *lathe, [](const BlockInfo&, WordRole role, Word& w) {
      switch (role) {
        case WordRole::AbsFirst:
        case WordRole::IncFirst:
        case WordRole::CentreFirst:
        case WordRole::AllowanceFirst:
        case WordRole::ReliefFirst:
          setValue(w, -w.value);
          break;
        case WordRole::MotionCode:
          reverseArcCode(w);
          break;
        default:
          break;
      }
    });
    return followUp(std::move(out), negated(params, "5136"),
                    [](const Toolpath& t) { return mapToolpath(t, [](Point q) { return Point{-q.z, q.x}; }, true); });
  };
  r.compare = compareToolpaths;
  return r;
}

Relation mirrorX() {
  Relation r;
  r.id = "mirror-x";
  r.description =
      "Mirror in X, outer ↔ inner: x → 2·x0 − x (radius) about the radius x0 = the program's largest "
      "radius rounded up to a whole mm (at least 1), so that every radius stays ≥ 0 — a turned outer "
      "contour becomes a bored inner one. X words (diameters) become 4·x0 − X; U and I words and the "
      "allowance Δu (U of the P/Q block) change sign; G71's Δd (U of its first block) does not; "
      "G02 ↔ G03. Expected: x → 2·x0 − x and every arc reversed. Handles the vocabulary of "
      "lathe_program.h."
      " Also G73 (Δi and 5135 negated as well; x0 covers the passes) and G74.1 programs (d negated: groove_relations.h); README \"Families\".";
  r.rules = {"G71.QUAD", "G71.ALLOW.UNITS", "G71.LIMIT.HEIGHT", "G72.ALLOW", "G72.POINTS"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return mirrorGrooveX(p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    const double x0 = std::max(1.0, std::ceil(lathe->reach.xMax));
    Program out = mapWords(p, *lathe, [x0](const BlockInfo&, WordRole role, Word& w) {
      switch (role) {
        case WordRole::AbsSecond:
          setValue(w, 4 * x0 - w.value);
          break;
        case WordRole::IncSecond:
        case WordRole::CentreSecond:
        case WordRole::AllowanceSecond:
        case WordRole::ReliefSecond:
          setValue(w, -w.value);
          break;
        case WordRole::MotionCode:
          reverseArcCode(w);
          break;
        default:
          break;
      }
    });
    return followUp(std::move(out), negated(params, "5135"), [x0](const Toolpath& t) {
      return mapToolpath(t, [x0](Point q) { return Point{q.z, 2 * x0 - q.x}; }, true);
    });
  };
  r.compare = compareToolpaths;
  return r;
}

Relation scale(double k) {
  Relation r;
  r.id = "scale-k";
  r.description =
      "Scale every length by k (registered with k = 2.5): X Z U W I K and the arcs' R, Δd, e, Δu, Δw, "
      "and the length parameters 5132, 5133, 5134, 5145, 5146 among the settings. F is not scaled: "
      "it is a rate (mm/min or mm/rev) that the cycle copies onto its cutting moves, not a length of "
      "the geometry. Expected: every point × k, feeds unchanged. Handles the vocabulary of "
      "lathe_program.h."
      " Also G73 (Δi, Δk, 5135, 5136 scaled; d not), G74.1 programs and SINUMERIK texts (transformSiemens); README \"Families\".";
  r.rules = {"G71.OP", "G71.DD.MODAL", "G71.E.MODAL", "G72.DD", "G71.ALLOW.UNITS", "G72.ALLOW", "G71.FST"};
  // The relation scales the program, not the tool: a compensated path (a SINUMERIK finish with a
  // nose radius) does not scale with it.
  r.outside = [](const SourceRun& run) { return run.noseRadius; };
  r.transform = [k](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return scaleGroove(k, p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    Program out = mapWords(p, *lathe, [k](const BlockInfo&, WordRole role, Word& w) {
      if (isLength(role)) setValue(w, k * w.value);
    });
    ParamSettings scaled = params;
    for (auto& [name, value] : scaled) {
      if (isLengthParameter(name)) value *= k;
    }
    return followUp(std::move(out), std::move(scaled),
                    [k](const Toolpath& t) { return mapToolpath(t, [k](Point q) { return k * q; }, false); });
  };
  r.transformSiemens = [k](const SiemensSource& s, const ParamSettings& params, std::string& whyNot) {
    return scaleSiemens(k, s, params, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation translateZ(double dz) {
  Relation r;
  r.id = "translate-z";
  r.description =
      "Translate along Z by dz (registered with dz = 12.5 mm): every Z word + dz; W, K, R, the cycle "
      "words unchanged (they are relative). Expected: z + dz. Handles the vocabulary of "
      "lathe_program.h."
      " Also G73, G74.1 programs and SINUMERIK texts (transformSiemens); README \"Families\".";
  r.rules = {"G72.POINTS", "G71.OP", "G72.STEP5", "G71.DTP"};
  r.transform = [dz](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return translateGroove(Point{dz, 0}, p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    Program out = mapWords(p, *lathe, [dz](const BlockInfo&, WordRole role, Word& w) {
      if (role == WordRole::AbsFirst) setValue(w, w.value + dz);
    });
    return followUp(std::move(out), params, [dz](const Toolpath& t) {
      return mapToolpath(t, [dz](Point q) { return Point{q.z + dz, q.x}; }, false);
    });
  };
  r.transformSiemens = [dz](const SiemensSource& s, const ParamSettings& params, std::string& whyNot) {
    return translateSiemens(Point{dz, 0}, s, params, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation translateX(double dx) {
  Relation r;
  r.id = "translate-x";
  r.description =
      "Translate outwards along X by dx on the radius (registered with dx = 5 mm): every X word + 2·dx "
      "(diameters); U, I, the cycle words unchanged. Not a symmetry of the part — a shape that reached "
      "the spindle axis no longer does, and G96's spindle speeds change — but one of the documented "
      "algorithm, whose every step is relative to the start point A, the allowances and Δd: an engine "
      "that treats x = 0 or absolute radii specially fails it. Outwards only, so radii stay ≥ 0. "
      "Expected: x + dx. Handles the vocabulary of lathe_program.h."
      " Also G73, G74.1 programs and SINUMERIK texts (transformSiemens); README \"Families\".";
  r.rules = {"G72.POINTS", "G71.OP", "G71.LIMIT.HEIGHT"};
  r.transform = [dx](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return translateGroove(Point{0, dx}, p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    Program out = mapWords(p, *lathe, [dx](const BlockInfo&, WordRole role, Word& w) {
      if (role == WordRole::AbsSecond) setValue(w, w.value + 2 * dx);
    });
    return followUp(std::move(out), params, [dx](const Toolpath& t) {
      return mapToolpath(t, [dx](Point q) { return Point{q.z, q.x + dx}; }, false);
    });
  };
  r.transformSiemens = [dx](const SiemensSource& s, const ParamSettings& params, std::string& whyNot) {
    return translateSiemens(Point{0, dx}, s, params, whyNot);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation splitSegment() {
  Relation r;
  r.id = "split-segment";
  r.description =
      "Split the longest motion of the first roughing cycle's shape after block ns into two blocks "
      "meeting at its midpoint (a line) or its mid-angle point (an arc: same centre and direction; "
      "R arcs get R |R| for both halves, I/K arcs I/K from each half's start). Both halves are written "
      "with absolute X Z; the first keeps the block's G, F, S, T, M words, the second its N. Block ns "
      "is never split (for type I it alone defines B). Expected: the same geometry — compared after "
      "joining consecutive moves that continue one another (mergeContinuations), since the semi-finish "
      "and finishing passes trace the split block as two moves. Refuses a G70 that does not start at "
      "its cycle's start point. Handles the vocabulary of lathe_program.h."
      " Also G73 (README \"Families\").";
  r.rules = {"G71.T1.SEMIFIN", "G72.STEP3", "G72.STEP7", "G71.T2.FOLLOW", "G71.T2.VALLEY", "G70.EX"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    if (lathe->cycles.empty()) {
      whyNot = "no G71/G72 cycle: nothing to split";
      return std::nullopt;
    }
    const RoughingCycleInfo& cycle = lathe->cycles.front();
    std::optional<std::size_t> longest;
    double longestLength = 0;
    for (std::size_t i = cycle.ns + 1; i <= cycle.nf; ++i) {
      const auto& seg = lathe->blocks[i].segment;
      if (seg && seg->length() > longestLength) {
        longest = i;
        longestLength = seg->length();
      }
    }
    if (!longest) {
      whyNot = "the shape has no motion after block ns";
      return std::nullopt;
    }
    auto out = splitBlock(p, *longest, whyNot);
    if (!out) return std::nullopt;
    return followUp(std::move(*out), params, samePath);
  };
  r.compare = compareGeometry;
  return r;
}

Relation absoluteIncremental() {
  Relation r;
  r.id = "abs-inc";
  r.description =
      "Absolute ⇄ incremental in the shape programs (ns…nf of every G71/G72): each X becomes U, each "
      "Z becomes W, and each U becomes X, each W becomes Z, with the value that reaches the same point "
      "from where the block starts (U = X − 2·x, diameters). A type II head's W0/U0 becomes an "
      "absolute word and still commands the axis. Blocks outside the shapes are left alone. Refuses "
      "a G70 that does not start at its cycle's start point. Expected: the same toolpath. Handles "
      "the vocabulary of lathe_program.h. Also G73 (README \"Families\").";
  r.rules = {"G71.FMT.ZX", "G72.FMT", "G71.HEAD.NOX", "G71.TYPE.SELECT", "G72.TYPE.SELECT"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe || !finishesAtCycleStarts(p, *lathe, whyNot)) return std::nullopt;
    Program out = mapWords(p, *lathe, [](const BlockInfo& info, WordRole role, Word& w) {
      if (!info.shapeOf) return;
      const Point from = info.before.planePoint();
      switch (role) {
        case WordRole::AbsFirst: rename(w, 'W', w.value - from.z); break;
        case WordRole::AbsSecond: rename(w, 'U', w.value - 2 * from.x); break;
        case WordRole::IncFirst: rename(w, 'Z', from.z + w.value); break;
        case WordRole::IncSecond: rename(w, 'X', 2 * from.x + w.value); break;
        default: break;
      }
    });
    return followUp(std::move(out), params, samePath);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation radiusCentre() {
  Relation r;
  r.id = "r-ik";
  r.description =
      "R ⇄ I/K arcs: every G02/G03 block with R gets I K instead (the centre from the arc's start, "
      "radius values, I along X, K along Z), every one with I/K gets R (negative for an arc of more "
      "than 180°). Refuses an I/K arc whose end is off the circle by more than 1e-6 mm (R would "
      "place the centre elsewhere) and a G70 that does not start at its cycle's start point. "
      "Expected: the same toolpath. Handles the vocabulary of lathe_program.h."
      " Also G73, and SINUMERIK texts (transformSiemens: CR= ⇄ I/K in program and subprograms); README \"Families\".";
  r.rules = {"G71.FMT.ZX", "G72.FMT", "G71.T1.MONO", "G71.T1.SEMIFIN", "G70.EX"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe || !finishesAtCycleStarts(p, *lathe, whyNot)) return std::nullopt;
    Program out = p;
    for (std::size_t i = 0; i < out.blocks.size(); ++i) {
      const auto& seg = lathe->blocks[i].segment;
      if (!seg || !seg->isArc()) continue;
      Block& b = out.blocks[i];
      const bool byRadius = b.has('R');
      std::erase_if(b.words, [](const Word& w) { return w.letter == 'R' || w.letter == 'I' || w.letter == 'K'; });
      if (byRadius) {
        b.words.push_back(makeWord('I', seg->center.x - seg->from.x, true));
        b.words.push_back(makeWord('K', seg->center.z - seg->from.z, true));
        continue;
      }
      const double radius = seg->radius();
      if (std::abs(distance(seg->to, seg->center) - radius) > 1e-6) {
        whyNot = "line " + std::to_string(b.line) + ": the arc's end is not on its circle (R would move the centre)";
        return std::nullopt;
      }
      const bool overHalf = std::abs(sweep(*seg)) > std::numbers::pi + 1e-9;
      b.words.push_back(makeWord('R', overHalf ? -radius : radius, true));
    }
    return followUp(std::move(out), params, samePath);
  };
  r.transformSiemens = radiusCentreSiemens;
  r.compare = compareToolpaths;
  return r;
}

Relation plane(int gCode) {
  const PlaneAxes to = planeAxes(gCode);
  Relation r;
  r.id = "plane-g" + std::to_string(gCode);
  r.description =
      gCode == 17
          ? "G18 → G17 for G71 (G71.FMT.XY: `G71 V(Δd) R(e); G71 P Q U(Δw) V(Δu)`): the 1st axis Z becomes "
            "X (a diameter: values doubled), the 2nd axis X becomes Y (a radius: values halved). Z → X "
            "2·Z, X → Y X/2, W → U 2·W, U → V U/2, K → I, I → J, Δd U → V, Δw W → U 2·Δw, Δu U → V Δu/2; "
            "G18 → G17 (a G17 block first when the program has none). Expected: the same toolpath (every "
            "plane is mapped onto z = 1st axis, x = 2nd axis). G72 is refused: the seeds give the "
            "planes' formats for G71 only. Handles the vocabulary of lathe_program.h. G73 (G73.PLANE): Δk and "
            "Δi go to the plane's 1st and 2nd incremental addresses as they are (never halved, G73.FMT)."
          : "G18 → G19 for G71 (G71.FMT.YZ: `G71 W(Δd) R(e); G71 P Q V(Δw) W(Δu)`): the 1st axis Z becomes "
            "Y, the 2nd axis X becomes Z (both radius: X values halved). Z → Y, X → Z X/2, W → V, U → W "
            "U/2, K → J, I → K, Δd U → W, Δw W → V, Δu U → W Δu/2; G18 → G19 (a G19 block first when the "
            "program has none). Expected: the same toolpath. G72 is refused: the seeds give the planes' "
            "formats for G71 only. Handles the vocabulary of lathe_program.h. G73 (G73.PLANE): Δk → V, Δi → W "
            "as they are (never halved, G73.FMT).";
  r.rules = {gCode == 17 ? "G71.FMT.XY" : "G71.FMT.YZ", "G71.FMT.ZX", "G71.ALLOW.UNITS", "G71.ADDR.SHARED", "G73.PLANE"};
  r.transform = [gCode, to](const Program& p, const ParamSettings& params,
                            std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    for (const RoughingCycleInfo& c : lathe->cycles) {
      if (c.code == 72) {
        whyNot = "line " + std::to_string(p.blocks[c.block].line) + ": G72 in another plane is not documented";
        return std::nullopt;
      }
    }
    // Physical lengths (z, x radius) written in the target plane's programming of each axis.
    const double first = to.firstDiameter ? 2.0 : 1.0, second = to.secondDiameter ? 2.0 : 1.0;
    Program out = mapWords(p, *lathe, [&](const BlockInfo&, WordRole role, Word& w) {
      switch (role) {
        case WordRole::AbsFirst: rename(w, to.first, first * w.value); break;
        case WordRole::AbsSecond: rename(w, to.second, second * w.value / 2); break;
        case WordRole::IncFirst: rename(w, to.firstInc, first * w.value); break;
        case WordRole::IncSecond: rename(w, to.secondInc, second * w.value / 2); break;
        case WordRole::CentreFirst: rename(w, to.firstArc, w.value); break;
        case WordRole::CentreSecond: rename(w, to.secondArc, w.value); break;
        case WordRole::DepthOfCut: rename(w, to.secondInc, w.value); break;  // G71.ADDR.SHARED
        case WordRole::AllowanceFirst: rename(w, to.firstInc, first * w.value); break;
        case WordRole::AllowanceSecond: rename(w, to.secondInc, second * w.value / 2); break;
        // G73.FMT, G73.PLANE: Δk and Δi are distances along the plane's axes, never halved or doubled.
        case WordRole::ReliefFirst: rename(w, to.firstInc, w.value); break;
        case WordRole::ReliefSecond: rename(w, to.secondInc, w.value); break;
        default: break;
      }
    });
    commandFromTheStart(out, 180, gCode);
    return followUp(std::move(out), params, samePath);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation metricInch() {
  Relation r;
  r.id = "metric-inch";
  r.description =
      "G21 → G20: every length ÷ 25.4 (X Z U W I K, the arcs' R, Δd, e, Δu, Δw) and F ÷ 25.4 (mm/min → "
      "in/min, mm/rev → in/rev); G21 words become G20 and a G20 block comes first when the program does "
      "not start with one. Numbers are written with 15 significant digits, not rounded to the inch "
      "increment (0.0001 in): rounding would move pass levels and could change the number of passes, a "
      "discrete change no tolerance covers. Parameters are unchanged (cyclecert keeps length "
      "parameters in mm). S (G96's surface speed) is not converted: it does not change the toolpath. "
      "Expected: the same toolpath (always in mm), within a tolerance covering the printed digits. Also G73 (Δi, Δk "
      "converted, d not) and G74.1 programs (groove_relations.h: P/Q in increments only when whole); README "
      "\"Families\".";
  r.rules = {"G72.RANGE", "G71.ALLOW.UNITS", "G71.FST"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    if (isGrooveProgram(p)) return metricInchGroove(p, params, whyNot);
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    Program out = mapWords(p, *lathe, [](const BlockInfo&, WordRole role, Word& w) {
      if (isLength(role) || role == WordRole::Feed) setValue(w, w.value / kMmPerInch);
    });
    commandFromTheStart(out, 210, 20);
    return followUp(std::move(out), params, samePath);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation parameterDefault() {
  Relation r;
  r.id = "param-default";
  r.description =
      "Programmed Δd/e → parameters: the first block of the cycle (G71 U(Δd) R(e), G72 W(Δd) R(e)) loses "
      "Δd, e and its cycle code — its other words (F S T M) stay as a plain block, an empty block "
      "goes — and the settings gain 5132 = Δd and 5133 = e (what the block would have written). Only "
      "a program with exactly one first block, before its first P/Q block, is handled (later first "
      "blocks would change the parameters between cycles). G73's first block U(Δi) W(Δk) R(d) goes to "
      "5135, 5136 and 5137 (G73.PARAMS; a d that is not a whole number is refused: the block alarms "
      "PS0003, the parameter would not). Expected: the same toolpath.";
  r.rules = {"G71.DD.MODAL", "G71.E.MODAL", "G72.DD", "G71.ADDR.SHARED", "G73.PARAMS"};
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    std::optional<std::size_t> first;
    for (std::size_t i = 0; i < lathe->blocks.size(); ++i) {
      if (lathe->blocks[i].kind != BlockKind::CycleFirst) continue;
      if (first) {
        whyNot = "line " + std::to_string(p.blocks[i].line) + ": a second first block (only one is handled)";
        return std::nullopt;
      }
      first = i;
    }
    if (!first) {
      whyNot = "no first G71/G72 block (Δd, e) or G73 block (Δi, Δk, d): nothing to move into parameters";
      return std::nullopt;
    }
    if (lathe->cycles.empty() || lathe->cycles.front().block < *first) {
      whyNot = "line " + std::to_string(p.blocks[*first].line) + ": the first block does not come before the first cycle";
      return std::nullopt;
    }
    Program out = p;
    ParamSettings settings = params;
    Block& b = out.blocks[*first];
    for (const Word& w : b.words) {
      if (const auto number = parameterOf(roleOf(lathe->blocks[*first], w))) {
        if (*number == "5137" && (w.value != std::floor(w.value) || w.value > 99'999'999)) {
          whyNot = "line " + std::to_string(b.line) + ": " + w.text +
                   ": not a whole number of divisions (PS0003 in the block; parameter 5137 would be read otherwise)";
          return std::nullopt;
        }
        settings.push_back({*number, w.value});
      }
    }
    if (dropFirstBlockWords(b, lathe->blocks[*first])) out.blocks.erase(out.blocks.begin() + static_cast<std::ptrdiff_t>(*first));
    return followUp(std::move(out), std::move(settings), samePath);
  };
  r.compare = compareToolpaths;
  return r;
}

Relation transpose() {
  Relation r;
  r.id = "transpose";
  r.description =
      "Transpose Z ⇄ X, G71 ⇄ G72: (z, x) → (x, z + c), c = the program's most negative z rounded up to "
      "a whole mm (0 when z ≥ 0), so that the new radii stay ≥ 0. Words: Z → X 2·(Z + c), X → Z X/2, "
      "W → U 2·W, U → W U/2, K → I, I → K; G71 ↔ G72 with Δd moving between U (G71) and W (G72), "
      "Δw (W) → Δu U 2·Δw, Δu (U) → Δw W Δu/2; G02 ↔ G03; parameters 5145 ⇄ 5146 (the monotonic "
      "tolerances follow their axes). A type I head that moved X only now moves Z only. Expected: "
      "(z, x) → (x, z + c), every arc reversed, alarms PS0064 ⇄ PS0329. G71.LIMIT.HEIGHT has no G72 "
      "counterpart, so a G72 program whose shape passes its start point's z in the allowance's "
      "direction alarms PS0322 once transposed: the relation then fails by design. Handles the "
      "vocabulary of lathe_program.h. G73 stays G73: its reliefs exchange axes, Δk (W) → Δi U, Δi (U, a "
      "radius) → Δk W, with parameters 5135 ⇄ 5136 (README \"Families\").";
  r.rules = {"G72.FMT", "G72.POINTS", "G72.DD", "G72.ALLOW", "G71.OP", "G72.STEP3", "G72.RETRACT", "G72.TYPE.SELECT"};
  // G71.LIMIT.HEIGHT (PS0322) has no G72 counterpart: such a source fails the relation by design.
  r.outside = [](const SourceRun& run) { return run.alarm == alarm::kOverStartPoint; };
  r.transform = [](const Program& p, const ParamSettings& params, std::string& whyNot) -> std::optional<FollowUp> {
    const auto lathe = readWithG73(p, params, whyNot);
    if (!lathe) return std::nullopt;
    const double c = std::max(0.0, std::ceil(-lathe->reach.zMin));
    Program out = mapWords(p, *lathe, [c](const BlockInfo& info, WordRole role, Word& w) {
      switch (role) {
        case WordRole::AbsFirst: rename(w, 'X', 2 * (w.value + c)); break;
        case WordRole::AbsSecond: rename(w, 'Z', w.value / 2); break;
        case WordRole::IncFirst: rename(w, 'U', 2 * w.value); break;
        case WordRole::IncSecond: rename(w, 'W', w.value / 2); break;
        case WordRole::CentreFirst: rename(w, 'I', w.value); break;
        case WordRole::CentreSecond: rename(w, 'K', w.value); break;
        case WordRole::DepthOfCut: rename(w, info.cycle == 71 ? 'W' : 'U', w.value); break;
        case WordRole::AllowanceFirst: rename(w, 'U', 2 * w.value); break;
        case WordRole::AllowanceSecond: rename(w, 'W', w.value / 2); break;
        case WordRole::ReliefFirst: rename(w, 'U', w.value); break;   // Δk becomes Δi, a radius value
        case WordRole::ReliefSecond: rename(w, 'W', w.value); break;  // Δi (a radius) becomes Δk
        case WordRole::MotionCode: reverseArcCode(w); break;
        case WordRole::CycleCode:
          if (gCode10(w.value) == 710 || gCode10(w.value) == 720) setValue(w, gCode10(w.value) == 710 ? 72 : 71);
          break;
        default: break;
      }
    });
    ParamSettings swapped = params;
    for (auto& [name, value] : swapped) {
      const std::string n = parameterNumber(name);
      if (n == "5145") name = "5146";
      if (n == "5146") name = "5145";
      if (n == "5135") name = "5136";  // G73's reliefs follow their axes too
      if (n == "5136") name = "5135";
    }
    return followUp(std::move(out), std::move(swapped), [c](const Toolpath& t) {
      Toolpath e = mapToolpath(t, [c](Point q) { return Point{q.x, q.z + c}; }, true);
      if (e.alarm && e.alarm->code == "PS0064") e.alarm->code = "PS0329";
      else if (e.alarm && e.alarm->code == "PS0329") e.alarm->code = "PS0064";
      return e;
    });
  };
  r.compare = compareToolpaths;
  return r;
}

}  // namespace

Toolpath mapToolpath(const Toolpath& path, const std::function<Point(Point)>& map, bool mirrors) {
  Toolpath out = path;
  out.start = map(path.start);
  for (Move& m : out.moves) {
    m.to = map(m.to);
    if (m.center) m.center = map(*m.center);
    if (mirrors) m.shape = reversedKind(m.shape);
  }
  // Not compared (path_compare.h): the cycle records would need the map's linear part too.
  out.cycles.clear();
  out.warnings.clear();
  return out;
}

Relation scaleRelation(double k) { return scale(k); }
Relation translateZRelation(double dz) { return translateZ(dz); }
Relation translateXRelation(double dxRadius) { return translateX(dxRadius); }

const std::vector<Relation>& allRelations() {
  static const std::vector<Relation> relations = {
      mirrorZ(),        mirrorX(),     translateZ(12.5), translateX(5), scale(2.5),          splitSegment(),
      absoluteIncremental(), radiusCentre(), plane(17), plane(19), metricInch(), parameterDefault(), transpose(),
      series10OneBlockRelation(), huazhongOneBlockRelation(), haasOneBlockRelation(), gCodeSystemBRelation(),
      gCodeSystemCRelation(),
  };
  return relations;
}

const Relation* findRelation(std::string_view id) {
  for (const Relation& r : allRelations()) {
    if (r.id == id) return &r;
  }
  return nullptr;
}

bool relationJudges(const Relation& r, const SourceRun& run) {
  if (run.alarm == alarm::kOutOfRange) return false;
  return !r.outside || !r.outside(run);
}

std::optional<std::string> checkRelation(const Relation& relation, const FollowUp& followUp, const Toolpath& source,
                                         const Toolpath& actual, double tol) {
  return relation.compare(followUp.expectedPath(source), actual, tol);
}

std::optional<Program> splitBlock(const Program& source, std::size_t blockIndex, std::string& whyNot) {
  const auto lathe = readLatheProgram(source, whyNot, LatheFamilies::WithPatternRepeating);
  if (!lathe || !finishesAtCycleStarts(source, *lathe, whyNot)) return std::nullopt;
  if (blockIndex >= source.blocks.size()) {
    whyNot = "no block " + std::to_string(blockIndex);
    return std::nullopt;
  }
  const BlockInfo& info = lathe->blocks[blockIndex];
  const Block& original = source.blocks[blockIndex];
  const std::string where = "line " + std::to_string(original.line) + ": ";
  if (!info.shapeOf || info.head) {
    whyNot = where + "only a shape block after block ns can be split";
    return std::nullopt;
  }
  if (!info.segment) {
    whyNot = where + "the block does not move";
    return std::nullopt;
  }
  const Segment& s = *info.segment;
  const Point mid = pointAt(s, 0.5);
  const Word* radius = original.find('R');
  // The end point as absolute words, and for arcs the centre (or the radius) from `from`.
  const auto motionWords = [&](Point from, Point to) {
    std::vector<Word> words = {makeWord('X', 2 * to.x, true), makeWord('Z', to.z, true)};
    if (!s.isArc()) return words;
    if (radius) {
      words.push_back(makeWord('R', std::abs(radius->value), true));  // each half is at most 180°
    } else {
      words.push_back(makeWord('I', s.center.x - from.x, true));
      words.push_back(makeWord('K', s.center.z - from.z, true));
    }
    return words;
  };

  Block firstHalf = original;
  firstHalf.sequence.reset();  // the N (perhaps nf's) goes with the half that ends where the block did
  std::erase_if(firstHalf.words, [](const Word& w) { return std::string_view("XZUWIKR").find(w.letter) != std::string_view::npos; });
  for (Word& w : motionWords(s.from, mid)) firstHalf.words.push_back(std::move(w));
  Block secondHalf;
  secondHalf.line = original.line;
  secondHalf.sequence = original.sequence;
  secondHalf.blockDelete = original.blockDelete;
  secondHalf.words = motionWords(mid, s.to);

  Program out = source;
  out.blocks[blockIndex] = firstHalf;
  out.blocks.insert(out.blocks.begin() + static_cast<std::ptrdiff_t>(blockIndex) + 1, secondHalf);
  return out;
}

}  // namespace cyclecert
