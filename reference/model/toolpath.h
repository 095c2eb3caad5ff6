#pragma once
// The canonical result of any engine: moves in physical coordinates (mm, x = radius, plane mapped
// onto ZX), or an alarm. The reference annotates each move with its phase and the rule IDs behind it.
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/geometry.h"

namespace cyclecert {

enum class MoveKind { Rapid, Feed };

// Which part of the program a move belongs to (the reference labels every move; other engines need
// not). JSON spells them as below (README "Toolpath JSON"); None is a move without a phase (no
// "phase" in JSON).
enum class MovePhase {
  None,
  Approach,    // "approach": from the cycle start A to the shifted start A'
  Pass,        // "pass": a roughing pass (Move::pass numbers it)
  SemiFinish,  // "semi-finish": along the rough profile after the passes
  Finish,      // "finish": G70's finishing pass
  Return,      // "return": back to the cycle start
  Program,     // "program": a block outside the cycles (positioning between them…)
};

// The JSON spelling of a phase ("" for None), and its reading: nullopt for any other text.
std::string_view phaseName(MovePhase p);
std::optional<MovePhase> phaseNamed(std::string_view name);
// Every spelling phaseNamed reads, for messages: "\"approach\", \"pass\", … or \"program\"".
std::string phaseNamesText();

struct Move {
  MoveKind kind = MoveKind::Rapid;
  SegmentKind shape = SegmentKind::Line;
  Point to;
  std::optional<Point> center;  // arcs only
  std::optional<double> feed;   // feeds only (mm/min or mm/rev as programmed)
  // Seconds the tool dwells at the move's end before the next move (CYCLE95's DT at each
  // interruption for chip breaking, CYCLE95.DAM); none when it goes straight on. JSON "dwell".
  std::optional<double> dwell;
  MovePhase phase = MovePhase::None;
  int pass = 0;                 // pass number for MovePhase::Pass (1-based), else 0
  std::vector<std::string> rules;
  bool singleBlockStop = false;  // in single-block mode the machine stops after this move (G72.SINGLE)
  bool stopGiven = false;        // read from JSON that states "stop" (an expectation compares it then)
};

// A controller alarm: the code (e.g. "PS0064"), its message, and the program line it names.
struct Alarm {
  std::string code;
  std::string message;
  int line = 0;
  // When the controller raises it (cycles only): "cycle block" (reading the G71/G72 blocks),
  // "before the cycle" (QSR/FCK pre-checks: no move yet), "during the cycle" (found while the
  // cycle runs: on a machine some passes may already have been made). Empty elsewhere.
  std::string when;
};

struct Warning {
  int line = 0;
  std::string message;
};

// Where one canned cycle's moves sit in the toolpath.
struct CycleRecord {
  std::string code;  // "G71", "G72"
  int line = 0;      // line of the block with P and Q
  Point start;       // cycle start point A
  std::size_t firstMove = 0;
  std::size_t moveCount = 0;
  std::vector<Segment> shape;  // the finish shape A → B → C of ns…nf
  Point allowance;             // the rough profile is `shape` shifted by this (Δw, Δu/2)
  bool compensated = false;    // `shape` is the imaginary tool-nose path under G41/G42
  // The rough profile where it is no shift of `shape` (G74.1: each flank and the floor moved into the
  // groove by its allowance); empty for the cycles whose rough profile roughProfile() shifts.
  std::vector<Segment> roughShape;

  std::vector<Segment> roughProfile() const;
};

// PROG.CAP.MOVES: the most moves a toolpath holds — the reference's plan of a program (each cycle
// is bounded before it is planned: reference/cycles/roughing_cycle.h) and any engine's toolpath
// the harness reads (toolpath_json.h); a move takes some 2 kB with its rule IDs.
inline constexpr std::size_t kMostMovesPerToolpath = 1'000'000;

struct Toolpath {
  std::string profile;
  std::string plane = "G18";  // the program's plane; coordinates are mapped onto (z = 1st, x = 2nd axis)
  Point start;                // tool position before the first move
  std::vector<Move> moves;
  std::optional<Alarm> alarm;
  std::vector<Warning> warnings;
  std::vector<CycleRecord> cycles;

  // The position before move i (the previous move's end, or `start`).
  Point from(std::size_t i) const { return i == 0 ? start : moves[i - 1].to; }
  // Move i as a geometric segment.
  Segment segment(std::size_t i) const;
};

}  // namespace cyclecert
