#pragma once
// What a program asks of each roughing cycle, read from the program alone — never from a planner —
// so that the oracles can judge any engine's toolpath: the cycle's start point, finish shape,
// allowances, Δd, e, F, type and the parameters in force, and whether the rules forbid the shape.
#include <optional>
#include <string>
#include <vector>

#include "oracles/groove/groove_spec.h"
#include "oracles/siemens/siemens_cycle_spec.h"
#include "reference/model/cycle_family.h"
#include "reference/model/geometry.h"
#include "reference/model/params.h"
#include "reference/model/profile.h"
#include "reference/model/program.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

struct CycleSpec {
  std::string code;              // "G71", "G72" or "G73", for messages (the family decides)
  CycleFamily family = CycleFamily::G71;
  int line = 0;                  // the block with P and Q
  bool typeII = false;
  Point start;                   // A, plane coordinates (z = 1st axis, x = 2nd axis, radius)
  std::vector<Segment> shape;    // the finish shape A → B → … → C (compensated under G41/G42)
  Point allowance;               // the rough profile is `shape` shifted by this
  double depthOfCut = 0;         // Δd
  double retract = 0;            // e
  double feed = 0;               // F of the cycle
  bool semiFinish = true;        // RF1 (type I) / RF2 (type II) = 0
  bool directReturn = false;     // DTP
  bool noRepeatedPath = false;   // NSP: the second A'→B' of type II with pockets is a rapid
  bool headIsRapid = true;       // block ns is G00 (else G01): infeeds are rapids, else feeds (G72.STEP2)
  double clearance = 0;          // 5134: type II's rapid approach into a pocket stops this short (G71.T2.POCKET.EXIT)
  // G73 (G73.FMT, G73.PARAMS): the total relief (Δk along z, Δi along x, radius; signed), from the
  // first G73 block's W/U (or the Series 10/11 block's K/I) or parameters 5136/5135, and d, the
  // number of divisions (R, D or 5137).
  Point relief;
  int divisions = 0;
  bool patternRepeating() const { return family == CycleFamily::G73; }
  // G73.PASS.SHIFT, G73.D1: how far apart two passes stand — the shift (Δk, Δi)/(d − 1) between
  // consecutive passes, as a length (the whole relief for d = 1, whose one pass removes it all).
  double divisionStep() const;
  // depth-per-pass: the thickest layer one feed may remove — Δd for G71/G72 (along the depth axis),
  // the division step for G73 (along the relief, the direction its material is measured in).
  double layerLimit() const { return patternRepeating() ? divisionStep() : depthOfCut; }
  // The frame: G71 (and G73, whose relief sets its material's frame) cuts along z (the plane's 1st
  // axis), G72 along x.
  bool cutsAlongZ() const { return family != CycleFamily::G72; }
  // Sign of the infeed on the depth axis (from A towards B) and of the cut on the cut axis.
  int depthDirection() const;
  int cutDirection() const;
  std::vector<Segment> roughProfile() const;  // shape shifted by the allowance
  // Set when the documented checks forbid this cycle (independent of any engine): the alarm the
  // controller must raise.
  std::optional<Alarm> forbiddenBy;
};

// A block that moves the tool after a Huazhong G71, in program order (HNC.G71.FST: the program goes
// on with the block after G71, so ns…nf run again, as the finishing run, when it reaches them).
struct ProgramMove {
  int line = 0;
  Point end;               // where the block leaves the tool (plane coordinates)
  bool rapid = true;       // G00, else a cutting feed
  bool arc = false;        // G02/G03
  double feed = 0;         // the F in force (HNC.G71.FST: set between G71 and ns, else the G71 block's)
  bool finishing = false;  // one of ns…nf: the finishing run
};

struct ProgramSpec {
  std::vector<CycleSpec> cycles;
  bool hasFinishingCycle = false;  // a G70 follows: its feeds come from the shape
  std::vector<double> finishingFeeds;  // the F words of G70 shapes
  bool motionAfterCycles = false;  // positioning or cutting blocks run after the last cycle
  bool motionBeforeCycles = false;
  // PROG.WHOLE: the blocks that move the tool from a known position before the first cycle (the
  // approach, a facing cut…): an engine that draws them puts their moves before the cycle's.
  std::vector<ProgramMove> movesBeforeCycles;
  // … and after the last cycle (a G70 counts): a part-off, the way home. They belong to no cycle,
  // so the oracles judge the path up to them. `cyclesEnd` is where the last cycle leaves the tool
  // (its start point).
  std::vector<ProgramMove> movesAfterCycles;
  Point cyclesEnd;  // … and before the first, from a known position (drawn: PROG.WHOLE)
  std::optional<int> firstCycleBlockLine;  // the first G70/G71/G72 block
  std::vector<Alarm> finishingAlarms;      // G70 blocks the rules forbid (G71.TNRC.NT2)
  std::optional<Alarm> mdiAlarm;           // the program runs in MDI mode (G72.MDI)
  std::optional<Alarm> blockAlarm;         // a block's G codes alone are refused (PROG.GROUP.*); reading stops there
  // HNC.G71.FST: the blocks that move the tool after the program's last Huazhong G71 (its finishing
  // run of ns…nf among them, which makes hasFinishingCycle true). Empty for other programs.
  std::vector<ProgramMove> runAfterHuazhong;
  // SINUMERIK programs (profiles sinumerik-802s/-802d): the profile's stock-removal cycle, each call
  // as the front end reads it (harness/judge/siemens_reading.h), and the alarm the controller must stop
  // with (LCYC95.ALARMS: 61002, 61610, 10931), read from the program. `cycles` stays empty.
  std::optional<CycleFamily> siemensFamily;
  std::vector<SiemensCycleSpec> siemensCycles;
  std::optional<Alarm> siemensAlarm;
  // A program with a G74.1 groove cycle (GSK, seed 002): its blocks are not read as moves; under the
  // gsk profile in G18 each second block (the cycle) is read into a GrooveSpec (oracles/groove/), and
  // a first block the rules forbid by itself gives one with only its alarm.
  bool hasGrooveCycle = false;
  std::vector<GrooveSpec> grooves;

  // The program's one roughing cycle when it has exactly one that the rules allow (what the
  // geometric oracles judge), else nullptr.
  const CycleSpec* singleRoughingCycle() const;
  // The program's one G74.1 cycle when it has exactly one and the rules allow it, else nullptr.
  const GrooveSpec* singleGroove() const;
  // The program's one SINUMERIK cycle call when it has exactly one and no alarm stops it, else nullptr.
  const SiemensCycleSpec* singleSiemensCycle() const;
  // The program's SINUMERIK calls when no alarm stops it and all of them machine one contour in one
  // frame (the seed's L42: roughing, then finishing), in program order; else none. The material
  // oracles judge such a program as one part.
  std::vector<const SiemensCycleSpec*> siemensCallsOnOneContour() const;
  // The family the oracles are chosen by (Oracle::judges): a SINUMERIK program's cycle, G74.1 for a
  // program with a groove cycle, else the one roughing cycle's; nothing for other programs (every
  // oracle judges them).
  std::optional<CycleFamily> judgedFamily() const;
  // The first cycle the rules forbid, or nullptr.
  const CycleSpec* firstForbidden() const;
  // The alarm the controller must stop with: the earliest one in the program, if any.
  std::optional<Alarm> firstAlarm() const;
};

// Reads the program's G71/G72/G73 cycles. Throws ParseError for malformed text and std::runtime_error
// for programs the oracles cannot read (with the reason).
ProgramSpec readProgramSpec(const Program& program, const Profile& profile, const MachineParams& params,
                            const ToolOffset& tool, bool mdi = false);

}  // namespace cyclecert
