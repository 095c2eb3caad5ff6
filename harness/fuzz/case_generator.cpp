#include "harness/fuzz/case_generator.h"

#include <algorithm>
#include <array>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "harness/fuzz/g74_1_case_generator.h"
#include "harness/fuzz/generator_parts.h"
#include "harness/fuzz/named_choices.h"
#include "harness/fuzz/siemens_case_generator.h"
#include "harness/spec/program_case.h"
#include "oracles/metamorphic/g_code_writing.h"
#include "reference/interpreter/g_codes.h"

namespace cyclecert {

namespace {

template <typename T>
struct Named {
  T value;
  std::string_view name;
};
constexpr Named<CycleFormat> kFormatNames[] = {
    {CycleFormat::FanucTwoBlocks, "two-block"}, {CycleFormat::Series10OneBlock, "fs10"},
    {CycleFormat::HuazhongOneBlock, "hnc"},     {CycleFormat::HaasOneBlock, "haas"},
    {CycleFormat::SystemB, "gsys-b"},           {CycleFormat::SystemC, "gsys-c"}};
constexpr Named<FuzzCycle> kCycleNames[] = {{FuzzCycle::G71, "g71"},
                                            {FuzzCycle::G72, "g72"},
                                            {FuzzCycle::G73, "g73"},
                                            {FuzzCycle::Lcyc95, "lcyc95"},
                                            {FuzzCycle::Cycle95, "cycle95"},
                                            {FuzzCycle::G74_1, "g74.1"}};
// The group names --cycles takes besides the cycles' own: "all" is every FANUC family (what it
// meant before the Siemens cycles were drawn, so that `--cycles all` keeps a seed's cases),
// "siemens" both SINUMERIK cycles.
struct CycleGroup {
  std::string_view name;
  std::vector<FuzzCycle> cycles;
};
// "g74_1" is G74.1's name as the rule IDs and folders spell it (G74_1.*, gsk/g74_1).
const std::vector<CycleGroup>& cycleGroups() {
  static const std::vector<CycleGroup> groups = {{"all", {FuzzCycle::G71, FuzzCycle::G72, FuzzCycle::G73}},
                                                 {"siemens", {FuzzCycle::Lcyc95, FuzzCycle::Cycle95}},
                                                 {"g74_1", {FuzzCycle::G74_1}}};
  return groups;
}

template <typename T, std::size_t N>
std::string knownNames(const Named<T> (&names)[N]) {
  std::string text;
  for (const Named<T>& n : names) text += std::string(text.empty() ? "" : ", ") + std::string(n.name);
  return text + " or all";
}

template <typename T, std::size_t N>
std::string_view nameOf(const Named<T> (&names)[N], T value) {
  for (const Named<T>& n : names) {
    if (n.value == value) return n.name;
  }
  return "?";
}

// A comma-separated list of names (or "all") as the values they name, each once, in the order given.
template <typename T, std::size_t N>
std::vector<T> parseNames(const Named<T> (&names)[N], std::string_view text, const std::string& what) {
  std::vector<T> values;
  if (text == "all") {
    for (const Named<T>& n : names) values.push_back(n.value);
    return values;
  }
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string_view word = text.substr(from, comma - from);
    const auto* named = std::find_if(std::begin(names), std::end(names), [&](const Named<T>& n) { return n.name == word; });
    if (named == std::end(names)) {
      throw std::invalid_argument("unknown " + what + " '" + std::string(word) + "' in '" + std::string(text) +
                                  "': give a comma-separated list of " + knownNames(names));
    }
    if (std::find(values.begin(), values.end(), named->value) == values.end()) values.push_back(named->value);
    from = comma + 1;
  }
  return values;
}

template <typename T, std::size_t N>
std::string namesText(const Named<T> (&names)[N], const std::vector<T>& values) {
  std::string text;
  for (T v : values) text += std::string(text.empty() ? "" : ",") + std::string(nameOf(names, v));
  return text;
}

}  // namespace

std::string_view cycleFormatName(CycleFormat f) { return nameOf(kFormatNames, f); }
CycleFormats parseCycleFormats(std::string_view text) { return parseNames(kFormatNames, text, "cycle format"); }
std::string cycleFormatsText(const CycleFormats& formats) { return namesText(kFormatNames, formats); }

std::string_view fuzzCycleName(FuzzCycle c) { return nameOf(kCycleNames, c); }
FuzzCycles parseFuzzCycles(std::string_view text) {
  FuzzCycles cycles;
  const auto add = [&](FuzzCycle c) {
    if (std::find(cycles.begin(), cycles.end(), c) == cycles.end()) cycles.push_back(c);
  };
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t comma = std::min(text.find(',', from), text.size());
    const std::string_view word = text.substr(from, comma - from);
    const auto group = std::find_if(cycleGroups().begin(), cycleGroups().end(), [&](const CycleGroup& g) { return g.name == word; });
    if (group != cycleGroups().end()) {
      for (FuzzCycle c : group->cycles) add(c);
    } else {
      // One name: the names' parser says what it knows when it does not know the word.
      try {
        add(parseNames(kCycleNames, word, "cycle").front());
      } catch (const std::invalid_argument&) {
        throw std::invalid_argument("unknown cycle '" + std::string(word) + "' in '" + std::string(text) +
                                    "': give a comma-separated list of lcyc95, cycle95 or siemens (both SINUMERIK "
                                    "cycles), g74.1 (or g74_1: GSK's groove), g71, g72, g73 or all (every FANUC "
                                    "family)");
      }
    }
    from = comma + 1;
  }
  return cycles;
}
std::string fuzzCyclesText(const FuzzCycles& cycles) { return namesText(kCycleNames, cycles); }

namespace {


// A segment of the shape: a line of any slope (a 45° chamfer one time in four), or a quarter arc;
// a zero-length line now and then (degenerate input an engine must survive).
rc::Gen<FuzzSegment> genSegment() {
  return rc::gen::apply(
      [](int shape, int along, int up) {
        switch (shape) {
          case 0: return FuzzSegment{FuzzSegment::Line, along, up};
          case 1: return FuzzSegment{FuzzSegment::Line, along, along};  // chamfer
          case 2: return FuzzSegment{FuzzSegment::ConvexArc, along, along};
          case 3: return FuzzSegment{FuzzSegment::ConcaveArc, along, along};
          case 4: return FuzzSegment{FuzzSegment::Line, along, 0};  // along the cut axis
          case 5: return FuzzSegment{FuzzSegment::Line, 0, up};     // a step
          default: return FuzzSegment{FuzzSegment::Line, 0, 0};     // zero length
        }
      },
      rc::gen::weightedElement<int>({{6, 0}, {3, 1}, {3, 2}, {3, 3}, {3, 4}, {3, 5}, {1, 6}}),
      rc::gen::inRange(10, 600), rc::gen::inRange(10, 300));
}

// Splits one line into two collinear halves (an engine must not treat the join as a corner).
std::vector<FuzzSegment> withCollinearRun(std::vector<FuzzSegment> segs, int at) {
  if (segs.empty()) return segs;
  const std::size_t i = static_cast<std::size_t>(at) % segs.size();
  FuzzSegment& s = segs[i];
  if (s.kind != FuzzSegment::Line || s.along % 2 || s.up % 2 || (s.along == 0 && s.up == 0)) return segs;
  s.along /= 2;
  s.up /= 2;
  segs.insert(segs.begin() + static_cast<long>(i), s);
  return segs;
}

// The sixteen choices 0…9 a G71/G72 case draws first (field by field in the order drawn), by the
// decision each makes.
struct RoughingChoices {
  int profile;          // the profile (profileChosen)
  int cycle;            // G72 when odd, G71 when even (when the run asks for both)
  int mirrorCut;        // the cut axis runs the other way when 1 (mod 4)
  int mirrorDepth;      // the depth axis runs the other way when 1 (mod 4)
  int typeII;           // type II when 1 (mod 3)
  int headMotion;       // block ns in G02 (out of range) when 9, else G00 (even) or G01 (odd)
  // One draw, two uses (named twice so that each use says what it picks, as it always did): the
  // segment split into a collinear run and the segment that may turn back (both mod the count).
  int collinearRunAt, turnBackAt;
  int noDepthOfCut;     // Δd 0 (out of range) when 9
  int turnBack;         // the segment at turnBackAt turns back along the cut axis when 9, the depth axis when 8
  int noDepthAllowance;  // no Δu when < 2
  int noCutAllowance;    // no Δw when < 3
  int startLevel;        // A exactly on C's level plus Δu when 0, below C's level (out of range) when 9
  // One draw, two uses: DTP = 1 when 2 (mod 7), RF1 = 1 when 1 (mod 5).
  int dtp, rf1;
  // One draw, two uses: R16 = 1 when odd, NSP = 1 when 1 (mod 3) (type II).
  int r16, nsp;
  int rf2;              // RF2 = 1 when 1 (mod 4) (type II)
  int finish;           // a G70 follows when 0 (mod 3)
};

RoughingChoices roughingChoicesFrom(const std::vector<int>& drawn) {
  const auto at = [&](std::size_t i) { return choiceAt(drawn, i); };
  return {at(0), at(1), at(2),  at(3),  at(4),  at(5),  at(6),  at(6),  at(7),  at(8),
          at(9), at(10), at(11), at(12), at(12), at(13), at(13), at(14), at(15)};
}

// The six choices 0…9 drawn after the rest (so that adding them left the other draws as they
// were), by the decision each makes.
struct LaterChoices {
  int shapeFeed;     // an F in the shape when ≥ 7: 7, 8, 9 pick F0.1, F0.05, F0.3
  int shapeFeedAt;   // on which block (mod the segments + 1; 0 block ns)
  int compensation;  // tool-nose radius compensation when ≥ 7
  int noseRadius;    // 0.2, 0.4, 0.8 (mod 3)
  int unused;        // drawn, read by nothing (kept: the draws after it stay as they were)
  int clearance;     // the pocket clearance 5134 (kClearances)
};

LaterChoices laterChoicesFrom(const std::vector<int>& drawn) {
  const auto at = [&](std::size_t i) { return choiceAt(drawn, i); };
  return {at(0), at(1), at(2), at(3), at(4), at(5)};
}

// What RapidCheck draws for one case; caseFrom() turns it into a case, step by step.
struct Draws {
  RoughingChoices choice;
  std::vector<FuzzSegment> segments;
  std::vector<int> downs;   // type II: which segments go down
  int depthOfCut, retract, allowanceDepth, allowanceCut, above, along, b;  // hundredths
  LaterChoices later;  // an F in the shape and where, compensation, its nose radius, 5134
  CycleFormat format = CycleFormat::FanucTwoBlocks;  // drawn last, and only when the run asks for several
  int onlyCycle = 0;  // 71 or 72 when the run asks for that one only (not drawn: chosen); 0 both
};

void chooseCycle(FuzzCase& c, const RoughingChoices& choice, int onlyCycle) {
  c.profile = profileChosen(choice.profile);
  c.cycle = onlyCycle ? onlyCycle : choice.cycle % 2 ? 72 : 71;
  c.mirrorCut = choice.mirrorCut % 4 == 1;
  c.mirrorDepth = choice.mirrorDepth % 4 == 1;
  c.typeII = choice.typeII % 3 == 1;
  c.headMotion = choice.headMotion == 9 ? 2 : choice.headMotion % 2;  // G02 (out of range: PS0065) one time in ten
  c.finish = choice.finish % 3 == 0;
}

// What the format can write: the Series 10/11 format and G code systems B/C are FANUC's (a GSK
// draw becomes 0i-F's); the Haas one is profile haas's; the Huazhong one is profile hnc's, and seed
// 003 gives G71 without pockets only, and no G70 (its finishing is the run of ns…nf after the
// cycle, HNC.G71.FST).
void fitToFormat(FuzzCase& c, CycleFormat format) {
  c.format = format;
  const bool fanucOnly =
      format == CycleFormat::Series10OneBlock || format == CycleFormat::SystemB || format == CycleFormat::SystemC;
  if (fanucOnly && c.profile == "gsk") c.profile = "fanuc-0i-f";
  if (format == CycleFormat::HaasOneBlock) c.profile = "haas";
  if (format != CycleFormat::HuazhongOneBlock) return;
  c.profile = "hnc";
  c.cycle = 71;
  c.typeII = false;
  c.finish = false;
}

// Type II: some lines go down (pockets). A step (no length along the cut axis) never does: down
// and up again at one cut coordinate is a slot of no width, the shape running back over itself.
void makePockets(FuzzCase& c, const std::vector<int>& downs) {
  for (std::size_t i = 0; i < c.segments.size() && i < downs.size(); ++i) {
    const FuzzSegment& s = c.segments[i];
    if (downs[i] % 3 == 0 && s.kind == FuzzSegment::Line && s.along > 0) c.segments[i].up = -s.up;
  }
}

// Out of range one time in ten: a line that turns back along the cut axis (PS0064), or — type I,
// where the shape must also be monotone along the depth axis — along the depth axis (PS0329).
void turnBack(FuzzCase& c, int choice, int at) {
  FuzzSegment& s = c.segments[static_cast<std::size_t>(at) % c.segments.size()];
  if (s.kind != FuzzSegment::Line) return;
  // Only a turn back: the shape as a whole still runs forward along the cut axis.
  int along = 0;
  for (const FuzzSegment& other : c.segments) along += other.along;
  if (choice == 9 && s.along > 0 && along - 2 * s.along > 0) s.along = -s.along;
  if (choice == 8 && !c.typeII && s.up > 0) s.up = -s.up;
}

void drawShape(FuzzCase& c, const Draws& d) {
  c.segments = withCollinearRun(d.segments, d.choice.collinearRunAt);
  if (c.segments.size() > 8) c.segments.resize(8);
  if (c.segments.empty()) c.segments.push_back({FuzzSegment::Line, 500, 300});
  // A shape with no length along the cut axis (steps only) has nothing to rough.
  if (std::all_of(c.segments.begin(), c.segments.end(), [](const FuzzSegment& s) { return s.along == 0; })) {
    c.segments.front().along = 100;
  }
  if (c.typeII) makePockets(c, d.downs);
  turnBack(c, d.choice.turnBack, d.choice.turnBackAt);
  // B is raised by the deepest dip, so that no pocket reaches below where B was drawn.
  int lowest = 0, x = 0;
  for (const FuzzSegment& s : c.segments) lowest = std::min(lowest, x += s.up);
  c.b = d.b - lowest;
}

void drawCycleParameters(FuzzCase& c, const Draws& d) {
  c.depthOfCut = d.choice.noDepthOfCut == 9 ? 0 : d.depthOfCut;  // Δd 0: out of range (PS0062)
  c.retract = d.retract;
  // Allowances: none (boundary) or with the quadrant (valid). G71.T2.DW0: with pockets the
  // allowance along the cut axis is 0, else the manual itself says the tool cuts into a side
  // wall — a gouge the rules predict is no finding against an engine.
  c.allowanceDepth = d.choice.noDepthAllowance < 2 ? 0 : d.allowanceDepth;
  c.allowanceCut = d.choice.noCutAllowance < 3 || c.typeII ? 0 : d.allowanceCut;
}

// A above C by more than the depth allowance (valid), exactly on it (boundary), or — with a depth
// allowance, where G71.LIMIT.HEIGHT forbids it — below C's level but still above B (out of range).
// One out-of-range draw at a time: where two alarms apply, the documents do not say which the
// controller raises first.
void placeStart(FuzzCase& c, const Draws& d) {
  int highest = 0, x = 0;
  for (const FuzzSegment& s : c.segments) highest = std::max(highest, x += s.up);
  const bool otherOutOfRange = d.choice.turnBack >= 8 || c.depthOfCut == 0 || c.headMotion == 2;
  // Huazhong documents no height check (HNC.G71.FMT's interpretation): a start below C there is no
  // alarm but the programmer's collision — the return to A runs through the part — so not drawn.
  const bool heightChecked = c.format != CycleFormat::HuazhongOneBlock;
  const bool belowC = d.choice.startLevel == 9 && c.allowanceDepth > 0 && c.cycle == 71 && highest > 20 &&
                      !otherOutOfRange && heightChecked;
  c.startAbove = d.choice.startLevel == 0 ? c.allowanceDepth
                 : belowC                    ? -std::min(d.above / 4 + 1, highest - 10)
                                             : c.allowanceDepth + d.above;
  c.startAlong = d.along;
}

void drawMachineParameters(FuzzCase& c, const RoughingChoices& choice) {
  c.dtp = choice.dtp % 7 == 2;
  // RF1 skips the semi-finish, so a straight return (DTP = 1, GSK's only return) leaves from
  // beside the last pass: with Δw it runs back through the allowance, as documented — a hazard of
  // the documents, not a deviation, so that combination is not drawn.
  const bool straightReturn = c.dtp || c.profile == "gsk";
  c.rf1 = choice.rf1 % 5 == 1 && !(straightReturn && c.allowanceCut > 0);
  // R16, NSP and RF2 are type II's parameters.
  c.r16 = c.typeII && choice.r16 % 2;
  c.nsp = c.typeII && choice.nsp % 3 == 1;
  c.rf2 = c.typeII && choice.rf2 % 4 == 1;
}

// An F word inside ns…nf three times in ten, on block ns or on one of the segments: roughing
// ignores it (G71.FST, G72.FST), G70 runs at it from that block on (G70.EX).
void drawShapeFeed(FuzzCase& c, const LaterChoices& later) {
  if (later.shapeFeed < 7) return;
  static constexpr int kFeeds[] = {10, 5, 30};  // never the cycle's F0.2
  c.shapeFeed = kFeeds[later.shapeFeed - 7];
  c.shapeFeedAt = later.shapeFeedAt % static_cast<int>(c.segments.size() + 1);
}

// Tool-nose radius compensation (G71.TNRC.CANCEL, G71.CHECK) in three type I cases of ten: G41/G42
// on the tool's side, a nose radius of 0.2, 0.4 or 0.8 and the tip that points into the cut (a G70
// after the cycle runs compensated too). Not with an out-of-range draw: the compensated shape may
// itself be one the checks forbid (PS0041, PS0064, PS0322, PS0329), and where two alarms apply the
// documents do not say which comes first. Not drawn (yet): type II (G71.TNRC.ZERO asks for pockets
// to be programmed A→A' outside the work first, which the generator does not write) and tips that
// do not point into the cut (oracles/README.md, known limitations).
void drawCompensation(FuzzCase& c, const LaterChoices& later) {
  const bool outOfRange = c.depthOfCut == 0 || c.headMotion == 2 || c.startAbove < 0 ||
                          std::any_of(c.segments.begin(), c.segments.end(), [&](const FuzzSegment& s) {
                            return s.along < 0 || (!c.typeII && s.up < 0);
                          });
  if (later.compensation < 7 || outOfRange || c.typeII) return;
  // Not drawn (yet) for the Haas block: G41/G42 in block ns with G40 in block nf (HAAS.TNRC.SHAPE,
  // which fuzzProgram() writes) gives paths the oracles reject (material left at the end of the
  // shape, gouges where G40 is on an arc): the reference and the oracles must first agree on what
  // G40 in block nf does to G70's last move.
  if (c.format == CycleFormat::HaasOneBlock) return;
  static constexpr int kRadii[] = {20, 40, 80};
  c.noseRadius = kRadii[later.noseRadius % 3];
  c.tip = tipIntoTheCut(c);
}

// Type II's pocket clearance (5134, G71.T2.POCKET.EXIT) six times in ten: where the rapid
// approach into a pocket stops and cutting feed begins.
void drawClearance(FuzzCase& c, int choice) {
  static constexpr int kClearances[] = {0, 0, 0, 0, 10, 25, 50, 100, 200, 50};
  if (c.typeII) c.clearance = kClearances[choice];
}

FuzzCase caseFrom(const Draws& d) {
  FuzzCase c;
  chooseCycle(c, d.choice, d.onlyCycle);
  fitToFormat(c, d.format);
  drawCycleParameters(c, d);
  drawShape(c, d);
  placeStart(c, d);
  drawMachineParameters(c, d.choice);
  drawShapeFeed(c, d.later);
  drawCompensation(c, d.later);
  drawClearance(c, d.later.clearance);
  return c;
}

bool asks(const FuzzCycles& cycles, FuzzCycle c) { return std::find(cycles.begin(), cycles.end(), c) != cycles.end(); }

// The G71/G72 cases: G71 or G72 drawn when the run asks for both, else the one it asks for.
rc::Gen<FuzzCase> genRoughingCase(const CycleFormats& formats, const FuzzCycles& cycles) {
  const bool g71 = asks(cycles, FuzzCycle::G71), g72 = asks(cycles, FuzzCycle::G72);
  const int onlyCycle = g71 && g72 ? 0 : g71 ? 71 : 72;
  // One format: nothing drawn (the draws before it are RapidCheck's splits in order, unchanged).
  rc::Gen<CycleFormat> format = formats.size() == 1 ? rc::gen::just(formats.front()) : rc::gen::elementOf(formats);
  return rc::gen::apply(
      [onlyCycle](std::vector<int> choice, std::vector<FuzzSegment> segments, std::vector<int> downs, int dd, int e,
                  int du, int dw, int above, int along, int b, std::vector<int> later, CycleFormat format) {
        return caseFrom({roughingChoicesFrom(choice), std::move(segments), std::move(downs), dd, e, du, dw, above,
                         along, b, laterChoicesFrom(later), format, onlyCycle});
      },
      rc::gen::container<std::vector<int>>(16, rc::gen::inRange(0, 10)),  // RoughingChoices
      // Segments: 8 at most are kept (drawShape), after one of the first 10 may be split in two.
      firstOf(10, genSegment()),
      firstOf(8, rc::gen::inRange(0, 99)),  // which segments go down: the first 8
      rc::gen::inRange(50, 300),   // Δd 0.5 … 3 mm
      rc::gen::inRange(1, 200),    // e
      rc::gen::inRange(1, 100),    // Δu/2
      rc::gen::inRange(1, 60),     // Δw
      rc::gen::inRange(1, 500),    // A above C
      rc::gen::inRange(0, 400),    // A's cut coordinate
      rc::gen::inRange(0, 3000),   // B's depth coordinate
      rc::gen::container<std::vector<int>>(6, rc::gen::inRange(0, 10)),  // LaterChoices
      std::move(format));
}

// The G73 cases (g73_case_generator.cpp): the formats apply to G71/G72 only.
rc::Gen<FuzzCase> genPatternRepeatingCase(const CycleFormats&, const FuzzCycles&) { return genG73Case(); }

// The SINUMERIK cases (siemens_case_generator.cpp): LCYC95 and CYCLE95 share one generator (the
// cycle is one of its choices); the formats apply to G71/G72 only.
rc::Gen<FuzzCase> genSinumerikCase(const CycleFormats&, const FuzzCycles& cycles) { return genSiemensCase(cycles); }

// The G74.1 groove cases (g74_1_case_generator.cpp): the formats apply to G71/G72 only.
rc::Gen<FuzzCase> genGrooveCase(const CycleFormats&, const FuzzCycles&) { return genG74_1Case(); }

// Which generator draws each cycle family's cases: G71 and G72 share one (the cycle is one of its
// choices), G73 has its own. A run that asks for families of more than one picks the generator
// with RapidCheck's weightedOneOf, in this table's order, each weighted by how many of the asked
// families it draws (so a seed keeps its case).
struct FamilyGenerator {
  std::vector<FuzzCycle> families;
  rc::Gen<FuzzCase> (*generator)(const CycleFormats& formats, const FuzzCycles& cycles);
};
const std::vector<FamilyGenerator>& familyGenerators() {
  static const std::vector<FamilyGenerator> generators = {
      {{FuzzCycle::G71, FuzzCycle::G72}, genRoughingCase},
      {{FuzzCycle::G73}, genPatternRepeatingCase},
      {{FuzzCycle::Lcyc95, FuzzCycle::Cycle95}, genSinumerikCase},
      {{FuzzCycle::G74_1}, genGrooveCase},  // last: a run without G74.1 draws as before it was added
  };
  return generators;
}

// RapidCheck's weightedOneOf (which takes an initializer list only) over a vector: the same draws.
rc::Gen<FuzzCase> weightedOneOf(std::vector<std::pair<std::size_t, rc::Gen<FuzzCase>>> weighted) {
  std::vector<std::size_t> weights;
  std::vector<rc::Gen<FuzzCase>> generators;
  for (auto& [weight, generator] : weighted) {
    weights.push_back(weight);
    generators.push_back(std::move(generator));
  }
  return rc::gen::join(rc::Gen<rc::Gen<FuzzCase>>(
      rc::gen::detail::WeightedElementGen<rc::Gen<FuzzCase>>(std::move(weights), std::move(generators))));
}

}  // namespace

rc::Gen<FuzzCase> genFuzzCase(const CycleFormats& formats, const FuzzCycles& cycles) {
  if (formats.empty()) throw std::invalid_argument("genFuzzCase: no cycle format to draw from");
  if (cycles.empty()) throw std::invalid_argument("genFuzzCase: no cycle to draw from");
  std::vector<std::pair<std::size_t, rc::Gen<FuzzCase>>> weighted;
  for (const FamilyGenerator& g : familyGenerators()) {
    const auto asked = std::count_if(g.families.begin(), g.families.end(), [&](FuzzCycle f) { return asks(cycles, f); });
    if (asked > 0) weighted.push_back({static_cast<std::size_t>(asked), g.generator(formats, cycles)});
  }
  // One generator: nothing drawn to choose it (a seed gives the cases it gave before G73 was drawn).
  if (weighted.size() == 1) return weighted.front().second;
  return weightedOneOf(std::move(weighted));
}

// Frame directions as the machine sees them: G71 keeps the axes (each may be mirrored), G72
// exchanges them.
namespace {
struct MachineSigns {
  int cutZ, cutX, depthZ, depthX;  // the frame's +z and +x in machine Z and X (−1, 0, +1)
};
MachineSigns machineSigns(const FuzzCase& c) {
  const int cut = c.mirrorCut ? -1 : 1, depth = c.mirrorDepth ? -1 : 1;
  return c.cycle != 72 ? MachineSigns{cut, 0, 0, depth} : MachineSigns{0, cut, depth, 0};
}
}  // namespace

int compensationCode(const FuzzCase& c) {
  // Seen from +Y, travelling −z with the tool at +x is the right (offset.h's worked example): G42.
  const int reversals = (c.cycle == 72) + c.mirrorCut + c.mirrorDepth;
  return reversals % 2 == 0 ? 42 : 41;
}

int tipIntoTheCut(const FuzzCase& c) {
  // The frame's (−z, −x) in the machine's Z and X, then the chart: 1 (+Z,+X), 2 (−Z,+X), 3 (−Z,−X), 4 (+Z,−X).
  const MachineSigns m = machineSigns(c);
  const int z = -m.cutZ - m.depthZ, x = -m.cutX - m.depthX;
  return x > 0 ? (z > 0 ? 1 : 2) : (z > 0 ? 4 : 3);
}

namespace {

GCodeSystem gCodeSystemOf(CycleFormat f) {
  switch (f) {
    case CycleFormat::SystemB: return GCodeSystem::B;
    case CycleFormat::SystemC: return GCodeSystem::C;
    case CycleFormat::HuazhongOneBlock: return GCodeSystem::Huazhong;
    case CycleFormat::FanucTwoBlocks:
    case CycleFormat::Series10OneBlock:
    case CycleFormat::HaasOneBlock: break;
  }
  return GCodeSystem::A;
}

// The G codes a case's program writes, as its G code system writes them (PROG.GSYS.*), from the
// G code table: worked out once per system, not per case.
struct ProgramCodes {
  std::string motion[4];  // G00 G01 G02 G03
  std::string roughing[2];  // G71 G72 (system C: G73 G74)
  std::string finishing;    // G70 (system C: G72)
  std::string compensation[3];  // G40 G41 G42
  std::string modes;  // systems B/C: absolute programming and feed per revolution ("G90 G95"); A: none
};

ProgramCodes programCodesIn(GCodeSystem s) {
  ProgramCodes c;
  for (int m = 0; m < 4; ++m) c.motion[m] = gCodeWrittenIn(s, 10 * m);
  c.roughing[0] = gCodeWrittenIn(s, 710);
  c.roughing[1] = gCodeWrittenIn(s, 720);
  c.finishing = gCodeWrittenIn(s, 700);
  for (int k = 0; k < 3; ++k) c.compensation[k] = gCodeWrittenIn(s, 400 + 10 * k);
  if (s == GCodeSystem::B || s == GCodeSystem::C) {
    c.modes = gCodeWrittenIn(s, kAbsoluteProgramming) + " " + gCodeWrittenIn(s, 990);
  }
  return c;
}

const ProgramCodes& programCodes(CycleFormat f) {
  static const std::array<ProgramCodes, kGCodeSystems> codes = {
      programCodesIn(GCodeSystem::A), programCodesIn(GCodeSystem::B), programCodesIn(GCodeSystem::C),
      programCodesIn(GCodeSystem::Huazhong)};
  return codes[static_cast<std::size_t>(gCodeSystemOf(f))];
}

// Hundredths of a millimetre with a decimal point ("3.", "1.5"): HAAS.G71.D reads D in the program's
// units, which a word without a decimal point would not be on every controller.
std::string mmWithPoint(long hundredths) {
  std::string text = mm(hundredths);
  if (text.find('.') == std::string::npos) text += '.';
  return text;
}

// The frame placed in the machine: a frame point (along the cut axis, along the depth axis) as
// program words. G71 cuts along Z, G72 along X; a mirrored axis runs the other way; offsets keep
// every radius positive (≥ 1 mm) for either axis that carries X.
struct Placement {
  const FuzzCase& c;
  const ProgramCodes& codes;
  long cutOffset = 0, depthOffset = 0;

  std::string words(long cut, long depth) const {
    const long pc = c.mirrorCut ? cutOffset - cut : cutOffset + cut;
    const long pd = c.mirrorDepth ? depthOffset - depth : depthOffset + depth;
    const long z = c.cycle != 72 ? pc : pd;  // G73 is drawn in G71's frame
    const long x = c.cycle != 72 ? pd : pc;  // a radius: the X word is the diameter
    return "X" + mm(2 * x) + " Z" + mm(z);
  }
  // Convex in the frame is G03 for G71 (outer, towards the chuck); exchanging the axes and each
  // mirror reverse the sense.
  const std::string& arcCode(FuzzSegment::Kind k) const {
    const int reversals = (c.cycle == 72) + c.mirrorCut + c.mirrorDepth;
    const bool ccw = (k == FuzzSegment::ConvexArc) == (reversals % 2 == 0);
    return codes.motion[ccw ? 3 : 2];
  }
  // Allowances along the frame's axes as the cycle's words: U (diameter) and W, or X and Z in the
  // Huazhong block (HNC.G71.FMT: X = Δx on the diameter, Z = Δz).
  std::string allowanceWords() const {
    const long depth = c.mirrorDepth ? -c.allowanceDepth : c.allowanceDepth;
    const long cut = c.mirrorCut ? -c.allowanceCut : c.allowanceCut;
    const long x = c.cycle != 72 ? depth : cut, z = c.cycle != 72 ? cut : depth;
    const bool huazhong = c.format == CycleFormat::HuazhongOneBlock;
    return (huazhong ? "X" : "U") + mm(2 * x) + (huazhong ? " Z" : " W") + mm(z);
  }
};

// The cycle's block(s) in the case's format, each ending with ";\n".
std::string cycleBlocks(const FuzzCase& c, const Placement& place) {
  const std::string& g = place.codes.roughing[c.cycle == 71 ? 0 : 1];
  switch (c.format) {
    case CycleFormat::Series10OneBlock:  // G71.FS10.D: D in least input increments (0.001 mm)
      return g + " P10 Q20 " + place.allowanceWords() + " D" + std::to_string(10 * c.depthOfCut) + " F0.2;\n";
    case CycleFormat::HuazhongOneBlock:
      return g + " U" + mm(c.depthOfCut) + " R" + mm(c.retract) + " P10 Q20 " + place.allowanceWords() + " F0.2;\n";
    case CycleFormat::HaasOneBlock:  // HAAS.G71.D: D in mm; HAAS.G71.R1: R1 selects type II
      return g + " P10 Q20 " + place.allowanceWords() + " D" + mmWithPoint(c.depthOfCut) + (c.typeII ? " R1" : "") +
             " F0.2;\n";
    case CycleFormat::FanucTwoBlocks:
    case CycleFormat::SystemB:
    case CycleFormat::SystemC:
      break;
  }
  return g + (c.cycle == 71 ? " U" : " W") + mm(c.depthOfCut) + " R" + mm(c.retract) + ";\n" + g + " P10 Q20 " +
         place.allowanceWords() + " F0.2;\n";
}

// G73.FMT: the frame's values as the program's words — Δi (a radius, never doubled) and Δk with the
// incremental addresses U and W, signed by the quadrant; d with R (the faults: R0, R2.5).
std::string g73FirstBlock(const FuzzCase& c) {
  const std::string r = c.g73Fault == G73Fault::NoDivisions           ? "0"
                        : c.g73Fault == G73Fault::FractionalDivisions ? "2.5"
                                                                      : std::to_string(c.divisions);
  return "G73 U" + mm(c.mirrorDepth ? -c.reliefDepth : c.reliefDepth) + " W" +
         mm(c.mirrorCut ? -c.reliefCut : c.reliefCut) + " R" + r + ";\n";
}

// The shape's points in the frame (along the cut, depth), from B by each segment, with the
// highest and lowest depth and the furthest point back along the cut.
struct ShapeWalk {
  std::vector<std::pair<long, long>> points;
  long top = 0, bottom = 0, behind = 0;
};

ShapeWalk walkShape(const FuzzCase& c) {
  ShapeWalk w;
  w.points.reserve(c.segments.size());
  long along = c.startAlong, depth = c.b;
  w.top = w.bottom = c.b;
  w.behind = c.startAlong;
  for (const FuzzSegment& s : c.segments) {
    along -= s.along;
    depth += s.up;
    w.points.push_back({along, depth});
    w.top = std::max(w.top, depth);
    w.bottom = std::min(w.bottom, depth);
    w.behind = std::min(w.behind, along);
  }
  return w;
}

// A G73 case's program (two-block format, G code system A): A, the two G73 blocks, the shape from
// block ns (which moves both axes, from A to B) to block nf, G70 when drawn. Its shape ends at its
// highest point (g73_case_generator.cpp), so each pass's rapid back to A stays above the part.
std::string g73Program(const FuzzCase& c) {
  const ShapeWalk walk = walkShape(c);
  const std::vector<std::pair<long, long>>& points = walk.points;
  const long top = walk.top, bottom = walk.bottom;
  const long aAlong = c.startAlong + c.reliefCut + c.allowanceCut + c.startAhead;
  const long aDepth = top + c.reliefDepth + c.allowanceDepth + c.startAbove;
  const ProgramCodes& codes = programCodes(CycleFormat::FanucTwoBlocks);
  Placement place{c, codes};
  place.depthOffset = c.mirrorDepth ? aDepth + 100 : -bottom + 100;  // every radius ≥ 1 mm
  std::string p;
  p.reserve(512);
  p += codes.motion[0] + " " + place.words(aAlong, aDepth) + ";\n";
  p += g73FirstBlock(c);
  p += std::string("G73 P10") + (c.g73Fault == G73Fault::MissingQ ? "" : " Q20") + " " + place.allowanceWords() +
       " F0.2;\n";
  // G73.ALARMS: block ns in G02 (an arc from A to B of a radius that spans them) is PS0065.
  const bool arcHead = c.g73Fault == G73Fault::ArcHead;
  p += "N10 " + codes.motion[arcHead ? 2 : c.headMotion] + " " + place.words(c.startAlong, c.b) +
       (arcHead ? " R" + mm(2 * (aAlong - c.startAlong) + 2 * (aDepth - c.b) + 100) : "") + ";\n";
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const FuzzSegment& s = c.segments[i];
    if (i + 1 == c.segments.size()) p += "N20 ";
    // A quarter arc going down (−x of the frame) turns the other way for the same bulge.
    const FuzzSegment::Kind kind = s.up >= 0 || s.kind == FuzzSegment::Line ? s.kind
                                   : s.kind == FuzzSegment::ConvexArc       ? FuzzSegment::ConcaveArc
                                                                            : FuzzSegment::ConvexArc;
    if (s.kind == FuzzSegment::Line) p += codes.motion[1] + " " + place.words(points[i].first, points[i].second);
    else p += place.arcCode(kind) + " " + place.words(points[i].first, points[i].second) + " R" + mm(s.along);
    p += ";\n";
  }
  if (c.finish) p += codes.finishing + " P10 Q20;\n";
  p += "M30;\n";
  return p;
}

}  // namespace

std::optional<FuzzExpectedAlarm> expectedAlarm(const FuzzCase& c) {
  if (isSiemensCase(c)) return siemensExpectedAlarm(c);
  if (isGrooveCase(c)) return g74_1ExpectedAlarm(c);
  if (c.cycle != 73) return std::nullopt;
  // The lines of g73Program(): 1 A, 2 the first G73 block, 3 the second, 4 block ns.
  switch (c.g73Fault) {
    case G73Fault::NoDivisions: return FuzzExpectedAlarm{"PS0062", 2};
    case G73Fault::FractionalDivisions: return FuzzExpectedAlarm{"PS0003", 2};
    case G73Fault::MissingQ: return FuzzExpectedAlarm{"PS0061", 3};
    case G73Fault::ArcHead: return FuzzExpectedAlarm{"PS0065", 4};
    case G73Fault::None: break;
  }
  return std::nullopt;
}

std::string fuzzProgram(const FuzzCase& c) {
  if (c.cycle == 73) return g73Program(c);
  if (isSiemensCase(c)) return siemensMainProgram(c) + kSiemensContourName + ".spf\n" + siemensContourProgram(c);
  if (isGrooveCase(c)) return g74_1Program(c);
  // The frame's points: B, then each segment's end; C is the highest.
  // Block ns moves the depth axis only (W0 / U0 in type II), so B stands at A's cut coordinate.
  const ShapeWalk walk = walkShape(c);
  const std::vector<std::pair<long, long>>& points = walk.points;
  const long top = walk.top, bottom = walk.bottom, behind = walk.behind;
  const long startDepth = top + c.startAbove, startAlong = c.startAlong;
  const ProgramCodes& codes = programCodes(c.format);
  Placement place{c, codes};
  // Whichever axis carries X must stay ≥ 1 mm in radius over everything drawn.
  const long margin = 100;
  const bool cutIsX = c.cycle == 72;
  const long cutLow = behind, cutHigh = startAlong, depthLow = std::min(bottom, startDepth), depthHigh = std::max(top, startDepth);
  if (cutIsX) {
    place.cutOffset = c.mirrorCut ? cutHigh + margin : -cutLow + margin;
  } else {
    place.depthOffset = c.mirrorDepth ? depthHigh + margin : -depthLow + margin;
  }
  std::string p;  // appended to: a fifth cheaper than through an ostringstream
  p.reserve(512);
  if (!codes.modes.empty()) p += codes.modes + ";\n";  // systems B/C: G90 G95 (PROG.GSYS.INCREMENTAL)
  p += codes.motion[0] + " " + place.words(startAlong, startDepth) + ";\n";
  // G71.TNRC.PLACE: compensation is commanded before the cycle, cancelled after it (and its G70);
  // on Haas in block ns and cancelled in block nf (HAAS.TNRC.SHAPE, its manual's examples).
  const bool haas = c.format == CycleFormat::HaasOneBlock;
  const std::string& compensation = codes.compensation[compensationCode(c) == 41 ? 1 : 2];
  if (c.noseRadius > 0 && !haas) p += compensation + ";\n";
  const std::string shapeFeed = " F" + mm(c.shapeFeed);
  p += cycleBlocks(c, place);
  // Block ns moves the depth axis only (type I), or both axes with a zero incremental word of the
  // cut axis (type II) — in systems B/C, which have no U/W, an absolute word at A's cut coordinate.
  const std::string bWords = place.words(startAlong, c.b);
  const bool absoluteOnly = !codes.modes.empty();
  const std::string depthWord = c.typeII && absoluteOnly ? bWords
                                : c.cycle == 71          ? bWords.substr(0, bWords.find(' '))
                                                         : bWords.substr(bWords.find(' ') + 1);
  p += "N10 ";
  if (c.noseRadius > 0 && haas) p += compensation + " ";
  p += codes.motion[c.headMotion] + " " + depthWord + (c.typeII && !absoluteOnly ? (c.cycle == 71 ? " W0" : " U0") : "");
  if (c.headMotion == 2) p += " R1";
  if (c.shapeFeedAt == 0) p += shapeFeed;
  p += ";\n";
  for (std::size_t i = 0; i < c.segments.size(); ++i) {
    const FuzzSegment& s = c.segments[i];
    if (i + 1 == c.segments.size()) {
      p += "N20 ";
      // HAAS.TNRC.SHAPE: compensation started in block ns ends in block nf (the G70 of the shape
      // needs it there, NT2).
      if (c.noseRadius > 0 && haas) p += codes.compensation[0] + " ";
    }
    if (s.kind == FuzzSegment::Line) p += codes.motion[1] + " " + place.words(points[i].first, points[i].second);
    else p += place.arcCode(s.kind) + " " + place.words(points[i].first, points[i].second) + " R" + mm(s.along);
    if (c.shapeFeedAt == static_cast<int>(i) + 1) p += shapeFeed;
    p += ";\n";
  }
  // G70 returns to A in one rapid (G70.EX): where a peak stands between C and A at A's height that
  // rapid crosses the part — the programmer's collision on any controller, so not generated.
  if (c.finish && points.back().second == top) p += codes.finishing + " P10 Q20;\n";
  if (c.noseRadius > 0 && !haas) p += codes.compensation[0] + ";\n";
  p += "M30;\n";
  return p;
}

namespace {
// The rule a G73 case exercises: its fault's, else the cycle's format.
const char* g73Rule(G73Fault f) {
  switch (f) {
    case G73Fault::NoDivisions:
    case G73Fault::FractionalDivisions: return "G73.D.RANGE";
    case G73Fault::ArcHead: return "G73.ALARMS";
    case G73Fault::MissingQ:
    case G73Fault::None: break;
  }
  return "G73.FMT";
}

const char* g73FaultText(G73Fault f) {
  switch (f) {
    case G73Fault::NoDivisions: return ", R0 (PS0062)";
    case G73Fault::FractionalDivisions: return ", R2.5 (PS0003)";
    case G73Fault::MissingQ: return ", no Q (PS0061)";
    case G73Fault::ArcHead: return ", block ns in G02 (PS0065)";
    case G73Fault::None: break;
  }
  return "";
}

std::string describeG73Case(const FuzzCase& c) {
  std::ostringstream s;
  s << "G73, " << (c.mirrorDepth ? "inner" : "outer") << ", cut " << (c.mirrorCut ? "reversed" : "forward") << ", "
    << c.segments.size() << " segment(s), " << c.profile << ", d " << c.divisions << ", Δi " << mm(c.reliefDepth)
    << " Δk " << mm(c.reliefCut) << ", Δu/2 " << mm(c.allowanceDepth) << " Δw " << mm(c.allowanceCut)
    << (c.finish ? ", G70" : "") << g73FaultText(c.g73Fault);
  return s.str();
}
}  // namespace

std::string fuzzCaseFolder(const FuzzCase& c) {
  if (isSiemensCase(c)) return c.profile + (c.siemens.cycle95 ? "/cycle95" : "/lcyc95");
  if (isGrooveCase(c)) return c.profile + "/g74_1";
  return c.profile + "/g" + std::to_string(c.cycle);
}

SpecCase fuzzSpecCase(const FuzzCase& c, const std::string& tag) {
  if (isSiemensCase(c)) return specCaseFrom(siemensSpecJson(c, tag), "fuzz:" + tag);
  if (isGrooveCase(c)) return specCaseFrom(g74_1SpecJson(c, tag), "fuzz:" + tag);
  nlohmann::json params = nlohmann::json::object();
  if (c.rf1) params["RF1"] = 1;
  if (c.dtp) params["DTP"] = 1;
  if (c.r16) params["R16"] = 1;
  if (c.nsp) params["NSP"] = 1;
  if (c.rf2) params["RF2"] = 1;
  if (c.clearance > 0) params["5134"] = c.clearance / 100.0;
  // G71.FS10.FMT: the one block reads D with FCV = 1; e has no address there, 5133 gives it.
  if (c.format == CycleFormat::Series10OneBlock) {
    params["FCV"] = 1;
    params["5133"] = c.retract / 100.0;
  }
  // HAAS.G71.SETTINGS: the Haas block has no address for e either: Setting 73, here 5133.
  if (c.format == CycleFormat::HaasOneBlock) params["5133"] = c.retract / 100.0;
  if (c.format == CycleFormat::SystemB) params["3401#6"] = 1;  // PROG.GSYS.SELECT
  if (c.format == CycleFormat::SystemC) params["3401#7"] = 1;
  // The writer of a regression names the failing rules.
  const char* rule = c.format == CycleFormat::Series10OneBlock   ? "G71.FS10.FMT"
                     : c.format == CycleFormat::HuazhongOneBlock ? "HNC.G71.FMT"
                     : c.format == CycleFormat::HaasOneBlock     ? "HAAS.G71.FMT"
                     : c.format == CycleFormat::SystemB          ? "PROG.GSYS.B"
                     : c.format == CycleFormat::SystemC          ? "PROG.GSYS.C"
                     : c.cycle == 71                             ? "G71.QUAD"
                                                                 : "G72.FMT";
  if (c.cycle == 73) rule = g73Rule(c.g73Fault);
  nlohmann::json j = drawnCaseJson(c, tag, {rule}, fuzzProgram(c), expectedAlarm(c),
                                   "generated by cyclecert fuzz with one invalid G73 parameter: the alarm its rule "
                                   "names, at its block");
  j["params"] = params;
  return specCaseFrom(std::move(j), "fuzz:" + tag);
}

nlohmann::json drawnCaseJson(const FuzzCase& c, const std::string& tag, nlohmann::json rules, std::string program,
                             const std::optional<FuzzExpectedAlarm>& alarm, const std::string& alarmDerivation) {
  // Field by field, not from an initializer list (which builds each pair as an array first): a
  // case is drawn for every case a fuzz run judges.
  nlohmann::json j = nlohmann::json::object();
  j["id"] = fuzzCaseFolder(c) + "/fuzz-" + tag;
  j["title"] = "fuzz case " + tag + ": " + describeFuzzCase(c);
  j["rules"] = std::move(rules);
  j["profile"] = c.profile;
  j["program"] = std::move(program);
  j["expect"] = alarm ? alarmExpectation(alarm->code, alarm->line) : everyOracleExpectation();
  j["derivation"] = alarm ? alarmDerivation : kGeneratedCaseDerivation;
  if (c.noseRadius > 0) j["tool"] = {{"nose_radius", c.noseRadius / 100.0}, {"tip", c.tip}};
  return j;
}

std::string describeFuzzCase(const FuzzCase& c) {
  if (c.cycle == 73) return describeG73Case(c);
  if (isSiemensCase(c)) return describeSiemensCase(c);
  if (isGrooveCase(c)) return describeG74_1Case(c);
  std::ostringstream s;
  s << "G" << c.cycle << (c.typeII ? " type II" : " type I") << ", " << (c.mirrorDepth ? "inner" : "outer") << ", cut "
    << (c.mirrorCut ? "reversed" : "forward") << ", " << c.segments.size() << " segment(s), " << c.profile;
  if (c.format == CycleFormat::SystemB || c.format == CycleFormat::SystemC) {
    s << ", G code system " << (c.format == CycleFormat::SystemB ? "B" : "C");
  } else if (c.format != CycleFormat::FanucTwoBlocks) {
    s << ", " << cycleFormatName(c.format) << " one-block format";
  }
  for (const auto& [set, name] : {std::pair{c.rf1, "RF1"}, {c.dtp, "DTP"}, {c.r16, "R16"}, {c.nsp, "NSP"}, {c.rf2, "RF2"}}) {
    if (set) s << ", " << name << "=1";
  }
  if (c.clearance > 0) s << ", 5134=" << mm(c.clearance);
  if (c.shapeFeedAt >= 0) s << ", F" << mm(c.shapeFeed) << " in the shape";
  if (c.noseRadius > 0) s << ", G" << compensationCode(c) << " nose radius " << mm(c.noseRadius) << " tip " << c.tip;
  return s.str();
}

}  // namespace cyclecert
