#pragma once
// Runs a SINUMERIK program (profiles sinumerik-802s and sinumerik-802d; rules SIEMENS.*): the
// main program's G0/G1/G2/G3 moves become moves of phase "program" from the first position the
// program gives in both axes on (PROG.WHOLE, as the FANUC runner draws them); R parameters and
// _CNAME are kept; LCYC95 (802S: R105…R112 read at the call, the contour named by _CNAME) and
// CYCLE95 (802D: its arguments, the contour NPP) are built into a SiemensCycleCall and planned by
// planLcyc95 / planCycle95, whose moves are appended. A controller alarm ends the run and is part
// of the toolpath; NotSupported and ParseError are thrown.
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/profile.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"
#include "reference/siemens/siemens_cycle_parameters.h"
#include "reference/siemens/siemens_cycles.h"
#include "reference/siemens/siemens_motion.h"
#include "reference/siemens/siemens_program.h"
#include "reference/siemens/siemens_subprograms.h"

namespace cyclecert {

// The planners the runner calls (the real ones by default; a test's recording ones to see the
// calls the runner builds).
struct SiemensPlanners {
  std::function<SiemensCycleOutcome(const SiemensCycleCall&, const Lcyc95Parameters&)> lcyc95 = planLcyc95;
  std::function<SiemensCycleOutcome(const SiemensCycleCall&, const Cycle95Parameters&)> cycle95 = planCycle95;
  MachiningTypeLookup typeOf = machiningTypeOf;
};

// How the runner reads texts into blocks and a contour subprogram's blocks into its contour:
// parseSiemensProgram, parseSiemensSubprogram and readSiemensContour when empty. A caller that
// reads the same program twice (the reference engine, then the oracles' reading of it) may pass
// parsers that keep what they parsed; `contour` is asked only for a subprogram the `subprogram`
// parser read (its parse, kept: SiemensSubprograms::kept), and must answer as readSiemensContour.
struct SiemensParsers {
  std::function<std::shared_ptr<const SiemensProgram>(std::string_view text, const std::string& file)> program = {};
  SiemensSubprogramParser subprogram = {};
  std::function<SiemensContour(const std::string& name, const std::shared_ptr<const SiemensBlocks>& blocks,
                               SiemensModal modal)>
      contour = {};
};

struct SiemensRunInput {
  std::string text;                        // the main program (and any subprograms printed after it)
  std::string file;                        // for error messages
  std::vector<GivenSubprogram> subprograms;  // a spec case's "subprograms"
  std::string siblingDirectory;            // searched for NAME.spf / NAME.SPF; empty: none
  ToolOffset tool;                         // the active tool's nose radius and tip
  SiemensParsers parsers = {};
};

// Requires profile.dialect == Dialect::Siemens.
Toolpath planSiemensProgram(const SiemensRunInput& input, const Profile& profile, const SiemensPlanners& planners = {});

}  // namespace cyclecert
