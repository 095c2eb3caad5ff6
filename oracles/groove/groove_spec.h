#pragma once
// What a G74.1 program asks of its groove (GSK, seed 002 §3.23.7; rules G74_1.*), read by the
// oracles from the program's two blocks — never from the reference planner: the groove's start S,
// the directions of h and d, its depth, floor width, angles and corners, the cutting words of the
// second block, and the groove's outline (finish and rough profile) built from docs/g74_1.md §3–§5.
//
// The groove's own frame (docs/g74_1.md §2): u is the distance from S along d's X direction
// (radius), w the depth below the start level towards the floor (along h's Z direction). A local
// point is a `Point` with z = w and x = u.
#include <array>
#include <optional>
#include <vector>

#include "reference/interpreter/modal_state.h"
#include "reference/model/geometry.h"
#include "reference/model/params.h"
#include "reference/model/program.h"
#include "reference/model/tool.h"
#include "reference/model/toolpath.h"

namespace cyclecert {

inline Point grooveUW(double u, double w) { return {w, u}; }

enum class GrooveCornerShape { Chamfer, Round };  // P(abde)'s digit 0, 1

// r1 (the mouth at S), r2 (the mouth at the far end), r3 (the floor near S), r4 (the floor far end).
struct GrooveCornerSpec {
  double size = 0;  // chamfer width or round radius (mm, radius value); 0: sharp
  GrooveCornerShape shape = GrooveCornerShape::Chamfer;
};

// A closed groove outline in the local frame: the chain from the mouth on the start side, down the
// near flank, along the floor, up the far flank to the mouth on the far side (both chain ends lie
// on the mouth line, which closes it).
struct GrooveOutline {
  std::vector<Segment> chain;
  Point nearMouth;         // S (finish) or S' (rough): the near flank on the mouth line, before r1
  double floorDepth = 0;   // w of the floor
  double floorFrom = 0, floorTo = 0;  // u of the floor's flat part (after r3, before r4)
  Point floorNear, floorFar;  // the trapezoid's floor vertices N and F, before r3 and r4 cut them
};

struct GrooveSpec {
  int line = 0;             // the second G74.1 block (the cycle runs there)
  int grooveLine = 0;       // the first block (the groove)
  Point before;             // where the tool stands before the cycle (and returns to: I20)
  double feed = 0;          // F in force (I21: 0 allowed)
  Point start;              // S = (Z, X/2), plane coordinates
  int depthSign = -1;       // sh = sign(h): the Z direction of the feeds
  int widthSign = -1;       // sd = sign(d): the X direction of the steps
  double depth = 0;         // |h| (radius)
  double floorWidth = 0;    // |d| / 2 (radius)
  double angleA = 90, angleB = 90, slope = 0;  // ∠a, ∠b, ∠p (degrees)
  std::array<GrooveCornerSpec, 4> corners{};   // r1, r2, r3, r4
  double radialStep = 0;    // Δi / 2 (Δi is a diameter)
  double peck = 0;          // Δk
  double retract = 0;       // e
  std::optional<double> layerDepth;  // Δv; none: one layer
  double flankAllowance = 0;  // Δu / 2
  double floorAllowance = 0;  // Δw
  double toolWidth = 0;       // r of the grooving tool (I); 0: a pointed tool
  // I26: a pointed tool under G41/G42 with a nose radius R: the control point the moves give is the
  // imaginary tip, the nose centre + tipShift (plane); 0: a point (or a blade).
  double noseRadius = 0;
  Point tipShift;
  int pathType = 0;           // J: 0 rough, 1 rough + finish, 2 finish
  // The alarm the controller must stop with (G74_1.RANGE, I6b), read from the program; the
  // outlines below are not built then.
  std::optional<Alarm> forbiddenBy;
  GrooveOutline finish;     // §3 (local)
  GrooveOutline rough;      // §5: each side moved into the groove by its allowance (local)

  bool roughs() const { return pathType != 2; }
  bool finishes() const { return pathType != 0; }
  // The outline the cycle's last pass leaves: the finish profile with J1/J2, the rough one with J0.
  const GrooveOutline& target() const { return finishes() ? finish : rough; }
  // Local (w = z, u = x) ↔ plane.
  Point toPlane(Point local) const { return {start.z + depthSign * local.z, start.x + widthSign * local.x}; }
  Point toLocal(Point plane) const { return {depthSign * (plane.z - start.z), widthSign * (plane.x - start.x)}; }
  Segment toPlane(const Segment& local) const;
  // A move's control point (plane) as the point the tool is judged by (local): the programmed point,
  // or a nose's lowest point along h (I26: the centre, the tip − tipShift, + R along h), which the
  // steps treat as a point tool's: on the start level when the nose touches it from above.
  Point judgedPoint(Point control) const { return toLocal(control - tipShift) + grooveUW(0, noseRadius); }
  // And back: the control point (plane) of a local point the tool is judged by.
  Point controlPoint(Point judged) const { return toPlane(judged - grooveUW(0, noseRadius)) + tipShift; }
  // The rough start A11 (local, as judgedPoint): the blade's start-side edge on the rough near flank
  // at w = 0 (§6); a nose touching the rough near flank's line and the start level (I26).
  Point roughStart() const;
  // The finish start: S shifted by the tool width along d (I12).
  Point finishStart() const { return grooveUW(toolWidth, 0); }
  // The rough depth W = |h| − Δw and the layers' tops: 0, Δv, 2Δv, … below W (I16).
  double roughDepth() const { return depth - floorAllowance; }
  std::vector<double> layerTops() const;
};

// G74_1.FMT, G74_1.ADDR, G74_1.RANGE: the groove spec of the second G74.1 block `cutting`, with the
// first block `groove` before it (nullptr: none, PS0061). `state` is the modal state at the second
// block; its position is the point before the cycle. Alarms go to forbiddenBy; a first block's own
// alarm names its line (the controller raises it there).
// `tool`: the nose radius and tip in force (a pointed tool under G41/G42: I26, I27).
GrooveSpec readGrooveSpec(const Block* groove, const Block& cutting, const ModalState& state,
                          const MachineParams& params, const ToolOffset& tool = {});

// The alarm the first G74.1 block raises by itself (the controller reads it there: G74_1.RANGE), or
// nothing.
std::optional<Alarm> grooveBlockAlarm(const Block& groove, const ModalState& state, const MachineParams& params);

// I1: a G74.1 block with X or Z gives the groove.
bool givesTheGroove(const Block& b);

}  // namespace cyclecert
