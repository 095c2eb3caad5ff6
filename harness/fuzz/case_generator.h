#pragma once
// The fuzzer's cases (`cyclecert fuzz`): RapidCheck generators of G71/G72 (and G73) programs, each
// a spec case without an expectation (the oracles and, with --vs, a second engine judge it; a G73
// case with an invalid parameter expects its alarm).
//
// A case is drawn in the cycle's own frame — cut axis z (cuts run towards −z), depth axis x (passes
// go down towards −x) — and then placed in the machine: G71 cuts along Z with the depth along X,
// G72 the other way round, and each axis may be mirrored, giving the four quadrants (outer/inner,
// towards the chuck/away from it). In the frame the shape starts at B and every segment moves −z
// (or stands still along z: a step) and +x (type I), or also −x (type II: pockets).
//
// What is drawn: lines, 45° chamfers, convex and concave quarter arcs (a quarter arc after a line
// along the cut axis is tangent to it), steps, degenerate segments (zero length, a line split into
// a collinear run); type II pockets; parameters Δd, e, Δu, Δw valid or on their boundary (no
// allowance, A exactly on C's level) and, one at a time, out of range (Δd = 0, a head block in
// G02, A below C's level with Δu, a line turning back along either axis); machine parameters RF1,
// DTP (and, for type II, R16, NSP, RF2 and the pocket clearance 5134); the profiles fanuc-0i-f,
// fanuc-0i-c and gsk; an F word inside ns…nf, which roughing ignores (G71.FST, G72.FST) and G70
// honours; tool-nose radius compensation — G41/G42 before the cycle on the side the tool stands for
// the quadrant, with a nose radius and the tip that points into the cut (or the nose centre), G40
// after the cycles. Lengths are whole hundredths of a mm, so the program text is exact.
//
// The cycle block format is drawn from the formats the run asks for (CycleFormat; by default the
// FANUC two-block format only, so that a seed gives the cases it always gave): the Series 10/11
// one block with D (FANUC profiles, FCV = 1, e in parameter 5133) and the Huazhong one block
// (profile hnc, G71 type I only, no G70: its ns…nf run again after the cycle as the finishing), the
// Haas one block (profile haas: D in program units with a decimal point, R1 for type II, e in
// parameter 5133; G41/G42 in block ns and G40 in block nf when a case has a nose radius, which is
// not drawn yet: see drawCompensation()) and the two blocks written in FANUC G code system B or C
// (3401#6 GSB / #7 GSC: G90 absolute, G95 feed per revolution, and in C the cycles G72–G74; every
// code written through the G code table, oracles/metamorphic/g_code_writing.h).
// Combinations whose collisions the documents themselves cause are not drawn (see caseFrom() and
// fuzzProgram()).
//
// G73 cases (pattern repeating) are drawn when the run asks for them (FuzzCycles, `fuzz --cycles`):
// g73_case_generator.cpp says what is drawn; fuzzProgram() writes them in the two-block format.
// SINUMERIK LCYC95 / CYCLE95 cases (a main program and its contour subprogram) likewise:
// siemens_case_generator.h says what is drawn and how it is written; GSK G74.1 groove cases
// likewise: g74_1_case_generator.h.
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>
#include <rapidcheck.h>

#include "harness/spec/spec_case.h"
#include "reference/profiles/default_profile.h"

namespace cyclecert {

// How the roughing cycle is written (rules G71.FMT.ZX, G71.FS10.FMT, HNC.G71.FMT, HAAS.G71.FMT,
// PROG.GSYS.B, PROG.GSYS.C).
enum class CycleFormat {
  FanucTwoBlocks,    // `G71 U(Δd) R(e); G71 P Q U(Δu) W(Δw) F;` (G72 alike), every profile
  Series10OneBlock,  // `G71 P Q U(Δu) W(Δw) D(Δd in 0.001 mm) F;` with FCV = 1 and 5133 = e, FANUC profiles
  HuazhongOneBlock,  // `G71 U(Δd) R(e) P Q X(Δu) Z(Δw) F;` on profile hnc; ns…nf then run as finishing
  HaasOneBlock,      // `G71 P Q U(Δu) W(Δw) D(Δd, mm) [R1] F;` with 5133 = e on profile haas
  SystemB,           // the two blocks in G code system B (3401#6 = 1), FANUC profiles
  SystemC,           // the two blocks in G code system C (3401#7 = 1): G73/G74 roughing, G72 finishing
};
using CycleFormats = std::vector<CycleFormat>;

// "two-block", "fs10", "hnc", "haas", "gsys-b", "gsys-c": the names `cyclecert fuzz --formats` takes.
std::string_view cycleFormatName(CycleFormat f);
// A comma-separated list of those names, or "all". Throws std::invalid_argument naming the word
// it did not know and the names it knows.
CycleFormats parseCycleFormats(std::string_view text);
// The names joined by commas, as --formats takes them.
std::string cycleFormatsText(const CycleFormats& formats);
inline const CycleFormats kDefaultCycleFormats = {CycleFormat::FanucTwoBlocks};

// The cycles the fuzzer draws (`cyclecert fuzz --cycles`): G71 and G72 (axis-parallel roughing,
// drawn as they always were), G73 (pattern repeating, g73_case_generator.cpp), and SINUMERIK
// LCYC95 (802S/C) and CYCLE95 (802D) (siemens_case_generator.cpp), and GSK's G74.1 axial
// trapezoid groove (g74_1_case_generator.cpp).
enum class FuzzCycle { G71, G72, G73, Lcyc95, Cycle95, G74_1 };
using FuzzCycles = std::vector<FuzzCycle>;
// "g71", "g72", "g73", "lcyc95", "cycle95", "g74.1" (also spelt "g74_1"): the names `cyclecert
// fuzz --cycles` takes.
std::string_view fuzzCycleName(FuzzCycle c);
// A comma-separated list of those names and of two group names: "all" (every FANUC family: g71,
// g72, g73 — as it meant before the Siemens cycles were drawn, so that a run keeps its cases) and
// "siemens" (lcyc95, cycle95); "all,siemens,g74.1" is every cycle. Throws std::invalid_argument naming
// the word it did not know and the names it knows.
FuzzCycles parseFuzzCycles(std::string_view text);
// The names joined by commas, as --cycles takes them.
std::string fuzzCyclesText(const FuzzCycles& cycles);
// The default: G71 and G72, so that a seed gives the cases it always gave.
inline const FuzzCycles kDefaultFuzzCycles = {FuzzCycle::G71, FuzzCycle::G72};

// A G73 case's one invalid parameter (at most one per case), with the alarm it must raise.
enum class G73Fault {
  None,
  NoDivisions,          // R0 in the first G73 block: PS0062 there (G73.D.RANGE)
  FractionalDivisions,  // R2.5: PS0003 there (G73.D.RANGE)
  MissingQ,             // the second block without Q: PS0061 there (G73.FMT)
  ArcHead,              // block ns in G02: PS0065 at block ns (G73.ALARMS)
};

// A SINUMERIK case's one invalid parameter (at most one per case), with the alarm it must raise at
// the cycle's call (LCYC95.ALARMS).
enum class SiemensFault {
  None,
  MachiningType,     // R105 / VARI 0 or 13: 61002
  NoInfeedDepth,     // R108 / MID 0 with a type that roughs: 61610
  AgainstDirection,  // the contour programmed against the finishing direction: 10931
  ArcOverQuarter,    // a half circle appended to the contour: 10931
};

// One piece of a SINUMERIK contour in the stock-removal frame (reference/siemens/
// siemens_roughing_frame.h: cut towards −z, the stock above, +x): `along` hundredths towards −z
// (≥ 0), `up` hundredths towards +x (negative: down, into an undercut). Arcs: a quarter circle
// (along = |up| = the radius; convex bulges towards the stock), a shallow arc over the chord
// (along, up) of radius 2·along (41.4°, written with CR=), or — the fault only — a half circle
// over the chord (2·along, 0).
struct SiemensSegment {
  enum Kind { Line, ConvexQuarter, ConcaveQuarter, ConvexShallow, ConcaveShallow, HalfCircle } kind = Line;
  int along = 0;
  int up = 0;
  // A chamfer or rounding the controller inserts at this line's end, before the next line (CHF=
  // chamfer length, CHR= leg length, RND= radius), `cornerSize` hundredths.
  enum Corner { NoCorner, Chamfer, ChamferLeg, Rounding } corner = NoCorner;
  int cornerSize = 0;
  bool centreWords = false;  // a quarter arc written with I/K (else CR=)
};

// The SINUMERIK part of a case (FuzzCase::cycle 95).
struct SiemensFuzzCase {
  bool cycle95 = false;   // CYCLE95 on profile sinumerik-802d, else LCYC95 on sinumerik-802s
  int type = 1;           // R105 / VARI as written: 1…12 (0 or 13 with SiemensFault::MachiningType)
  std::vector<SiemensSegment> segments;  // from the contour's first point, in the frame
  int base = 100;         // hundredths between the part and the axis (or the bore's edge and the start)
  int allowance = 0;      // R106 / FAL, hundredths
  int allowanceZ = 0, allowanceX = 0;  // FALZ, FALX (CYCLE95), hundredths (X a radius)
  int maxInfeed = 100;    // R108 / MID, hundredths (0 with SiemensFault::NoInfeedDepth)
  int infeedAngle = 0;    // R109, degrees (LCYC95)
  int retract = 100;      // R110 / _VRT, hundredths
  int roughingFeed = 30, undercutFeed = 15, finishingFeed = 10;  // R111/FF1, FF2, R112/FF3: hundredths of mm/rev
  int dwell = 0;          // DT, tenths of a second (CYCLE95)
  int interruptLength = 0;  // DAM, hundredths (CYCLE95; 0: never)
  int startClear = 200;   // the program's G0 start beyond the cycle's start, hundredths in each axis
  bool compact = false;   // the contour's blocks written without spaces (G1X20Z-5)
  SiemensFault fault = SiemensFault::None;
};

// A G74.1 case's one invalid value (at most one per case: docs/g74_1.md §1's ranges and alarms),
// with the alarm it must raise (g74_1ExpectedAlarm()).
enum class G74_1Fault {
  None,
  DepthOut,            // H0, H10000 or no H: PS0003 at the groove block (I3, I2)
  WidthOut,            // D0 or D-10000: PS0003 at the groove block (I3)
  AngleAOut,           // A0 or A95: PS0003 at the groove block
  AngleBOut,           // B0 or B90.5: PS0003 at the groove block
  SlopeOut,            // L90 or L-1: PS0003 at the groove block
  StepNotPositive,     // P0 or a negative Q: PS0062 at the groove block
  StepTooLarge,        // P over its range (increments or mm): PS0003 at the groove block
  MissingPeck,         // no Q: PS0061 at the groove block
  DecimalPoint,        // P with a decimal point, read in increments (182#7 = 0): PS0007 at the groove block
  WordNotTaken,        // an R in the groove block: PS0009 there
  RetractOut,          // R100 or R-1: PS0003 at the second block
  LayerNotPositive,    // V0 or V-1: PS0062 at the second block
  AllowanceOut,        // U10000 or W-10000: PS0003 at the second block
  ToolWidthOut,        // I10000 or I-10000: PS0003 at the second block
  PathTypeOut,         // J3 or J-1: PS0003 at the second block
  CornerOut,           // r1 = A100 or r4 = E-1: PS0003 at the second block
  CornerDigitOut,      // P2 or P11111 (a b d e): PS0003 at the second block
  ToolWiderThanFloor,  // I wider than the groove's floor: PS0062 at the second block (I12)
  SlopeNotBelowFlank,  // ∠p ≥ ∠a, no groove: PS0062 at the second block (I9)
};

// The G74.1 part of a case (FuzzCase::cycle 741, profile gsk): the groove and how to cut it, in
// the words' own units — hundredths of a mm (X a diameter, as written; h a radius; d, Δi, Δu
// diameters), whole degrees.
struct G74_1FuzzCase {
  int startX = 4000, startZ = 0;        // S: X (diameter) and Z of the groove block
  int beforeX = 5000, beforeZ = 500;    // where the tool stands before the cycle (the G00 block)
  int depth = -400, width = -400;       // h (radius) and d (diameter), signed: their directions
  int angleA = 90, angleB = 90, slope = 0;
  bool writeAngles = false;             // A90 B90 L0 written although they are the defaults
  int radialStep = 100, peck = 200;     // Δi (diameter), Δk
  int retract = 50;                     // e
  int layerDepth = 0;                   // Δv; 0: no V (one layer)
  int allowanceX = 0, allowanceZ = 0;   // Δu (diameter), Δw; written with this sign (read as magnitudes, I4)
  int toolWidth = 0;                    // I; 0: no I (a pointed tool)
  int pathType = 0;                     // J 0/1/2
  bool writeJ = false;                  // J0 written although it is the default
  std::array<int, 4> corners{};         // r1 r2 r3 r4 (A B D E of the second block), radius
  int cornerKinds = -1;                 // P(abde) of the second block as four bits a b d e (1: round); −1: no P
  bool stepsInMm = false;               // parameter 182#7 = 1: P and Q in mm, else in increments (IS-C)
  G74_1Fault fault = G74_1Fault::None;
  int faultVariant = 0;                 // which of the fault's two spellings (even/odd)
};

struct FuzzSegment {
  enum Kind { Line, ConvexArc, ConcaveArc } kind = Line;
  int along = 0;  // hundredths along −z of the frame (≥ 0)
  int up = 0;     // hundredths along +x of the frame (negative: down, into a pocket; type II only)
};

struct FuzzCase {
  CycleFormat format = CycleFormat::FanucTwoBlocks;
  std::string profile = std::string(kDefaultProfileName);
  int cycle = 71;             // 71, 72 or 73 (G73 is drawn in G71's frame: cut along Z, depth along X)
  bool mirrorCut = false;     // the cut axis runs the other way (towards +Z for G71)
  bool mirrorDepth = false;   // the depth axis runs the other way (inner work for G71)
  bool typeII = false;
  int headMotion = 0;         // block ns: 0 G00, 1 G01, 2 G02 (out of range: PS0065)
  int b = 0;                  // B's depth coordinate, hundredths
  int startAbove = 0;         // A above C's level, hundredths (negative: below, out of range)
  int startAlong = 0;         // A's (and so B's: block ns moves the depth axis only) cut coordinate
  std::vector<FuzzSegment> segments;
  int depthOfCut = 100, retract = 50;       // Δd, e (hundredths; Δd 0 is out of range)
  int allowanceDepth = 0, allowanceCut = 0;  // along the frame's depth and cut axes (radius, hundredths)
  bool rf1 = false, dtp = false, r16 = false, nsp = false, rf2 = false;
  bool finish = false;        // a G70 P Q follows the cycle
  // An F word inside ns…nf: on block ns (0) or on segment k − 1 (k ≥ 1); none for −1.
  int shapeFeedAt = -1;
  int shapeFeed = 0;          // hundredths of mm/rev, never the cycle's F0.2
  int noseRadius = 0;         // hundredths; 0: no compensation (G40 throughout)
  int tip = 0;                // imaginary tip direction 0…9 (reference/model/offset.h)
  int clearance = 0;          // parameter 5134, hundredths (type II; 0: the default)
  // G73 only: the total relief along the frame's depth (Δi, radius) and cut (Δk) axes, hundredths
  // (≥ 0: away from the part), the number of divisions d, B's distance ahead of A along the cut
  // axis beyond the relief (the head block ns moves both axes), and the one invalid parameter.
  int reliefDepth = 0, reliefCut = 0;
  int divisions = 1;
  int startAhead = 0;
  G73Fault g73Fault = G73Fault::None;
  // SINUMERIK cases (cycle 95) only; profile sinumerik-802s (LCYC95) or sinumerik-802d (CYCLE95).
  SiemensFuzzCase siemens;
  // G74.1 cases (cycle 741) only; profile gsk.
  G74_1FuzzCase groove;
};

// A SINUMERIK case (LCYC95 or CYCLE95).
inline bool isSiemensCase(const FuzzCase& c) { return c.cycle == 95; }
// A G74.1 groove case.
inline bool isGrooveCase(const FuzzCase& c) { return c.cycle == 741; }

// Where a case's spec case and regressions go: "<profile>/g71", …, "sinumerik-802s/lcyc95",
// "sinumerik-802d/cycle95", "gsk/g74_1".
std::string fuzzCaseFolder(const FuzzCase& c);

// G41 or G42: the side of the shape the tool stands on in the case's quadrant (the frame's G42,
// turned over once by each mirror and by G72's exchange of the axes).
int compensationCode(const FuzzCase& c);
// The imaginary tip that points into the cut in the case's quadrant: from the nose centre towards
// the part (−x of the frame) and along the cut (−z of the frame), as the machine's tip chart names it.
int tipIntoTheCut(const FuzzCase& c);

// The generator the fuzzer draws from: each case's format is one of `formats` (not empty) and its
// cycle one of `cycles` (not empty). With the defaults, no format is drawn and the cases are those
// drawn before formats and cycles were. G73 cases are written in the two-block format only (the
// formats apply to the G71/G72 cases); with G71/G72 and G73 both asked for, a case is G73 one time
// in (1 + the number of G71/G72 asked for).
rc::Gen<FuzzCase> genFuzzCase(const CycleFormats& formats = kDefaultCycleFormats,
                              const FuzzCycles& cycles = kDefaultFuzzCycles);
// The G73 cases alone (g73_case_generator.cpp).
rc::Gen<FuzzCase> genG73Case();
// The SINUMERIK cases alone (siemens_case_generator.cpp): LCYC95 or CYCLE95 as `cycles` asks (both:
// either, one time in two).
rc::Gen<FuzzCase> genSiemensCase(const FuzzCycles& cycles);
// The G74.1 groove cases alone (g74_1_case_generator.cpp).
rc::Gen<FuzzCase> genG74_1Case();

// The alarm a case must raise, as its code and program line, or none (only G73, SINUMERIK and G74.1
// cases say; the oracles judge the G71/G72 cases' alarms from the program).
struct FuzzExpectedAlarm {
  std::string code;
  int line = 0;
};
std::optional<FuzzExpectedAlarm> expectedAlarm(const FuzzCase& c);

// The case's program text (in its format, one block per line). A SINUMERIK case's: the main
// program with its contour printed after it (a line `L1.spf`, then its blocks), as seed 004 prints
// them — one text the reference plans as it is.
std::string fuzzProgram(const FuzzCase& c);

// The case as a spec case: id "<fuzzCaseFolder>/fuzz-<tag>", the program, profile, parameters (a
// SINUMERIK case: the main program and its contour in "subprograms"), and an expectation of
// "oracles" only, or the alarm of its one invalid parameter (specs/README.md). `tag` names it (e.g.
// the case seed).
SpecCase fuzzSpecCase(const FuzzCase& c, const std::string& tag);

// The spec-case JSON every family's drawn case shares: id "<fuzzCaseFolder>/fuzz-<tag>", its title
// (describeFuzzCase), rules, profile and program, the tool when it has a nose radius; every oracle as
// its expectation, or — a case with one invalid value — the alarm `alarm`, whose derivation is
// `alarmDerivation`. The family adds its own (parameters, subprograms).
nlohmann::json drawnCaseJson(const FuzzCase& c, const std::string& tag, nlohmann::json rules, std::string program,
                             const std::optional<FuzzExpectedAlarm>& alarm, const std::string& alarmDerivation);

// The case for a person, one line: cycle, quadrant, type, segments, parameters.
std::string describeFuzzCase(const FuzzCase& c);

}  // namespace cyclecert
