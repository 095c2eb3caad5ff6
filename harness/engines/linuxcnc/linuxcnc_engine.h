#pragma once
// The `linuxcnc` engine: LinuxCNC's interpreter `rs274` (Debian's linuxcnc-uspace, extracted into
// BUILD/linuxcnc by fetch-rs274.sh) as an engine under test. A FANUC-profile case is translated into
// LinuxCNC's G7x dialect (the shape in an O-word sub, G71.1/G72.1/G71/G72 with Q X Z D I R, G7
// diameter mode), run with `rs274 -g`, and its canonical commands are read back into a canonical
// Toolpath. The translation table and what is "not applicable" are in harness/engines/linuxcnc/README.md.
#include <cstddef>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "harness/engines/engine.h"

namespace cyclecert {

// ---- Translation: a spec case in LinuxCNC's syntax -------------------------------------------

struct LinuxCncProgram {
  std::string text;                 // the .ngc program
  std::map<std::string, int> lines;  // a translated block's text → the case's program line it stands for
  Point start;                      // cycle start point A (tool position before the cycle)
  std::string plane = "G18";        // the case program's plane (coordinates are mapped onto (z, x))
  std::vector<Warning> warnings;    // documented translations that touch the result (appended return)
  CycleRecord cycle;                // the cycle as the case states it (moves filled in by the parser)
};

struct LinuxCncTranslation {
  std::optional<LinuxCncProgram> program;  // set when the case can be expressed
  std::string notApplicable;               // else: why not
};

struct LinuxCncOptions {
  // LinuxCNC's G71/G72 end where the profile ends; FANUC returns to the start point (STEP8, DTP).
  // When set, the translator appends the return (as the case's DTP asks) as explicit G0 blocks,
  // marked: the moves get phase "return" and the toolpath a warning that names the translation.
  bool appendReturn = true;
  double timeoutSeconds = 5;                 // per rs274 process
  std::size_t outputCap = 8u * 1024 * 1024;  // bytes of stdout + stderr per rs274 process
};

// Translates one case; `subNumber` is the O-word of the shape sub (distinct per case in a batch).
LinuxCncTranslation translateForLinuxCnc(const SpecCase& c, const LinuxCncOptions& options = {}, int subNumber = 100);

// ---- Reading rs274's canonical output ------------------------------------------------------------

// Markers the translator writes as comments; rs274 echoes them as COMMENT("…") canonical calls.
inline constexpr const char* kMarkCycle = "cyclecert: cycle";    // the cycle block follows
inline constexpr const char* kMarkReturn = "cyclecert: return";  // the appended return follows
inline constexpr const char* kMarkEnd = "cyclecert: end";        // the case's program is over

struct CanonicalParse {
  Toolpath path;            // moves between the cycle marker and the end marker
  bool sawCycle = false;    // the cycle marker was seen
  bool sawEnd = false;      // the end marker was seen
  std::size_t calls = 0;    // canonical calls read
  std::string error;        // a malformed canonical call (garbage output), else empty
};

// Reads the canonical calls of `rs274 -g` (STRAIGHT_TRAVERSE, STRAIGHT_FEED, ARC_FEED, SET_FEED_RATE,
// SELECT_PLANE, COMMENT) from text. Coordinates are rounded to 4 decimals (-0.0000 → 0); moves of
// zero length (repeated targets, zero arcs) are dropped. Lines that are not canonical calls are
// ignored (LinuxCNC's G7x code prints diagnostics on stdout).
CanonicalParse parseCanonical(const std::string& text);

// rs274's message when it stops with an error (stderr: "message\nblock text"), as an alarm with
// code "LINUXCNC"; `lines` maps the echoed block back to the case's line.
Alarm linuxCncAlarm(const std::string& stderrText, const std::map<std::string, int>& lines);

// ---- The engine ---------------------------------------------------------------------------------

class LinuxCncEngine : public Engine {
 public:
  // `buildDir`: where fetch-rs274.sh extracted the package (BUILD/linuxcnc/usr/bin/rs274).
  explicit LinuxCncEngine(std::string buildDir, LinuxCncOptions options = {});
  ~LinuxCncEngine() override;
  LinuxCncEngine(const LinuxCncEngine&) = delete;
  LinuxCncEngine& operator=(const LinuxCncEngine&) = delete;

  std::string name() const override { return "linuxcnc"; }
  std::string description() const override;
  std::string version() const override;
  EngineResult run(const SpecCase& c) override;

  // Several cases in one rs274 process (one start instead of one per case). A case whose
  // translation is not applicable gets that result; when rs274 stops on an error, the case it
  // stopped in gets the alarm and the cases after it are run again in a new batch.
  std::vector<EngineResult> runBatch(const std::vector<SpecCase>& cases) override;

  bool available() const;           // rs274 is there
  std::string rs274Path() const;    // BUILD/linuxcnc/usr/bin/rs274
  std::size_t processesStarted() const { return processes_; }

 private:
  struct Output {
    std::string out, err;
    int exitCode = -1;     // when it exited
    int signal = 0;        // when a signal ended it
    bool timedOut = false;
    bool overCap = false;
    double seconds = 0;
  };
  Output runRs274(const std::string& programText, double timeoutSeconds, std::size_t outputCap);
  std::string privateDir();

  std::string buildDir_;
  std::string root_;  // BUILD/linuxcnc
  LinuxCncOptions options_;
  std::string dir_;   // private HOME of the rs274 processes (made on first use, removed at the end)
  std::size_t processes_ = 0;
};

std::unique_ptr<Engine> makeLinuxCncEngine(const std::string& buildDir);
// With the harness's per-case timeout and output cap (EngineOptions::maxReplyBytes).
std::unique_ptr<Engine> makeLinuxCncEngine(const std::string& buildDir, const EngineOptions& options);

}  // namespace cyclecert
