#pragma once
// What G71 and G72 share: the two-block format with address sharing (G71.ADDR.SHARED, G72.FMT),
// modal Δd and e held in parameters 5132/5133 (G71.DD.MODAL, G71.E.MODAL, G72.DD), the address
// ranges (G72.RANGE), and the type I plan in the cycle frame.

#include "reference/cycles/cycle_call.h"
#include "reference/cycles/monotonic_check.h"
#include "reference/cycles/shape_program.h"
#include "reference/cycles/type1_roughing.h"
#include "reference/model/alarms.h"
#include "reference/model/cycle_family.h"

#include <string>
#include <string_view>

namespace cyclecert {

// A roughing cycle's dialect: its code and which plane address carries Δd in the first block.
struct RoughingFormat {
  // What the one-block forms (Series 10/11, Haas) add to the block with P and Q: G71/G72's depth of
  // cut D (and Haas's I, K, R1), or G73's relief I, K and divisions D (G73.FS10.FMT).
  enum class OneBlockWords { DepthOfCut, PatternRepeating };
  std::string code;  // "G71", "G72", "G73"
  char depthOfCutAddress;
  OneBlockWords oneBlockWords = OneBlockWords::DepthOfCut;
};

// The first block (no P/Q): Δd and e, written into parameters 5132/5133 for the rest of the program.
void applyFirstBlock(const CycleCall& call, const RoughingFormat& format);

// The second block's values, in physical mm.
struct SecondBlock {
  const Word* p = nullptr;
  const Word* q = nullptr;
  double allowanceFirst = 0;   // Δw (along the plane's 1st axis)
  double allowanceSecond = 0;  // Δu/2 on a diameter axis, Δu otherwise (along the 2nd axis)
  double feed = 0;
  Point roughAllowance;        // Haas I (x, radius) and K (z): left by the rough passes on top (HAAS.G71.IK)
  bool typeIIRequested = false;// Haas R1 (HAAS.G71.R1)

  // What the rough passes leave on the finish shape: Δw and Δu/2, plus Haas's K and I (HAAS.G71.IK).
  Point leftByRoughing() const { return {allowanceFirst + roughAllowance.z, allowanceSecond + roughAllowance.x}; }
};

// Reads and range-checks the block with P and Q. Throws CycleAlarm (PS0061, PS0003, PS0011).
SecondBlock readSecondBlock(const CycleCall& call, const RoughingFormat& format);

// How a cycle sits in the plane: G71 cuts along the plane's 1st axis; G72 along its 2nd, so it plans
// with the axes exchanged. The monotonic checks name the plane's axes (PS0064 1st, PS0329 2nd).
struct RoughingFrame {
  CycleFamily family;     // G71, G72: the rule IDs the moves cite (roughing_rules.h)
  bool transposed;        // G72
  AxisCheck cutAxis;      // monotonic check along the cut axis
  AxisCheck depthAxis;    // type I: the shape must retreat along the depth axis
};

// The two types share the format, the parameters and the checks before any move.
CycleOutcome planTypeI(const CycleCall& call, const ShapeProgram& shape, const SecondBlock& sb,
                       const RoughingFrame& frame);
CycleOutcome planTypeII(const CycleCall& call, const ShapeProgram& shape, const SecondBlock& sb,
                        const RoughingFrame& frame);

// Runs `plan` (reading and checking the shape, then planning) and dates the shape's alarms:
// "before the cycle" with FCK (5104#2) = 1, else "during the cycle" (G71.CHECK, G71.CHECK.FCK).
template <class Plan>
CycleOutcome withShapeAlarmTiming(const CycleCall& call, Plan plan) {
  try {
    return plan();
  } catch (CycleAlarm& a) {
    if (a.alarm().when.empty()) a.setWhen(call.params.bit("FCK") ? "before the cycle" : "during the cycle");
    throw;
  }
}

// PROG.CAP.PASSES: the planners' bounds, checked from the counts before planning (G71/G72 here,
// G73, G74.1, LCYC95/CYCLE95 with their own counts). A real G71/G72 makes tens to hundreds of
// passes; a Δd of 0.001 mm over a 500 mm deep shape would make 500,000 and take gigabytes. Above
// kMostRoughingPasses passes, kMostCycleMoves moves at most (passes × the shape's segments, type
// II), or kMostPassSegments passes × segments (PROG.CAP.WORK: each type I pass meets the shape;
// 10,000 passes over 200,000 segments took 22 s and 1 GB before this bound), the cycle is
// NotSupported with the count.
inline constexpr double kMostRoughingPasses = 10'000;
inline constexpr double kMostCycleMoves = 250'000;
inline constexpr double kMostPassSegments = 10'000'000;

// PROG.CAP.WORK: the refusal of a cycle whose `passes` × `segments` is beyond kMostPassSegments
// (NotSupported at `line`); `why` says what gave the passes ("Δd 0.001 mm over 1000 mm").
[[noreturn]] void refuseWorkBeyondTheCap(std::string_view cycle, double passes, std::size_t segments,
                                         const std::string& why, int line);

// PROG.CAP.WORK: refuses (refuseWorkBeyondTheCap) when `passes` × `segments` is beyond
// kMostPassSegments. `why()` gives the message's reason, asked for only then: every cycle is
// checked, and building the message each time cost more than the check.
template <typename Why>
void requireWorkWithinTheCap(std::string_view cycle, double passes, std::size_t segments, const Why& why, int line) {
  if (passes * static_cast<double>(segments) > kMostPassSegments) {
    refuseWorkBeyondTheCap(cycle, passes, segments, why(), line);
  }
}

// Δd from parameter 5132 (programmed values overwrite it): PS0062 if not positive.
double depthOfCut(const CycleCall& call, const std::string& code);

}  // namespace cyclecert
