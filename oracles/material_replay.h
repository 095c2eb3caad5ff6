#pragma once
// One replay of a toolpath on the material model, shared by the geometric oracles (no-gouge,
// rapids-in-air, complete, depth-per-pass): computed once per judgement.
#include <optional>
#include <vector>

#include "oracles/judgement.h"
#include "oracles/material/material.h"
#include "oracles/material/material_model.h"

namespace cyclecert {

// Thickness is measured along the depth axis. Where an arc runs nearly parallel to that axis, a
// chord error of δ becomes a depth error of δ / sin θ, so the profile a thickness is measured
// against is flattened far finer than the material (whose vertices lie on the arcs exactly):
// 1e-6 mm keeps that error under 6e-5 mm down to θ = 1°, far inside every tolerance.
inline constexpr double kMeasuringChord = 1e-6;

struct MaterialReplay {
  // The one roughing cycle judged — or, for a SINUMERIK program, its stock-removal calls on one
  // contour (`cycle` null): their moves are judged against the material in the plane, the part below
  // the roughing profile or the finishing path (replayMaterial says how).
  const CycleSpec* cycle = nullptr;
  // SINUMERIK: the call whose roughing sets the stock (the first call; or the finishing call of a
  // program that only finishes) and the last call that finishes (nullptr when none does).
  const SiemensCycleSpec* siemens = nullptr;
  const SiemensCycleSpec* siemensFinishing = nullptr;
  // The moves replayed and judged: all, or up to the end of a Huazhong finishing run
  // (movesJudgedAgainstThePart, run_after_cycle.h).
  std::size_t judgedMoves = 0;
  Point away;                        // from the part towards the start side, along the depth axis
  double reach = 0;
  BgRegion stock;
  // SINUMERIK: the allowance layer between the roughing profile and the finishing path, when the
  // implied stock is that layer (the call only finishes): kept for the documented crossing of the
  // rapid to the contour start, which would otherwise build the same region again.
  std::optional<BgRegion> siemensAllowanceLayer;
  std::vector<Segment> target;       // the surface roughing must leave: the rough profile, or the
                                     // finish shape when a G70 follows
  bool targetIsGraph = false;        // isGraphOverCutAxis(target) in away's frame, found once
  BgRegion part;                     // everything beyond `target`: no move may enter it
  // Material the cycle leaves standing by its rules, which completeness does not ask for: LCYC95's
  // undercuts when the call only roughs (no undercut roughing, CYCLE95.UNDERCUT note).
  BgRegion leftAlone;
  // The same, prepared for no-gouge's crossing tests: the region below the profile when it is a
  // graph over the cut axis, else the part's rings.
  std::optional<RegionBelowGraph> partBelowProfile;
  CrossingRegion partForCrossing;
  std::vector<Crossing> rapidCrossings;                   // per move: material a rapid crosses (empty for feeds)
  // Per move: material the pocket-entry oracle's continuations of a rapid cross (pocketEntryProbes,
  // oracles.h); empty unless that oracle judges the cycle.
  std::vector<Crossing> pocketEntryCrossings;
  // Per move: the layer a feed removes where it may be thicker than the layer limit (Δd, or G73's
  // division step: CycleSpec::layerLimit) — nothing for the feeds a
  // bound shows remove no more, and for those on the finish shape (G70 removes the allowance).
  std::vector<std::optional<Thickest>> removedThickness;
  std::optional<MaterialModel> model;  // after the last move (always set by replayMaterial)

  const BgRegion& remaining() const { return model->remaining(); }  // made when first asked for
  // crossingOf(part, move, …) (material_model.h).
  Crossing partCrossing(const Segment& move, double epsilon, double chordTolerance) const;
};

// The part (grown by the allowances, when `profile` is the rough profile): the region the profile
// encloses with a bottom line `reach` beyond its deepest point. A profile that turns back a little
// (within 5145/5146) keeps the undercut beneath its overhang outside the part.
BgRegion partRegionOf(const std::vector<Segment>& profile, Point away, double reach, double chordTolerance);

// The stock a cycle implies: for G73 the near-net blank (nearNetBlankProfile); else between the
// start point's level and the finish shape over the shape's span along the cut axis — that band
// minus the part region, so that a shape touching the start level (a collar) splits it cleanly;
// built from the shape's outline, piece by piece, where the shape is a graph over the cut axis.
BgRegion impliedStockOf(const CycleSpec& c, Point away, double reach, double chordTolerance);

// The region without its skins: what remains when it is shifted by ± `width` along the cut axis
// (perpendicular to `away`) and intersected with itself — slivers narrower than 2·width along the
// cut axis disappear, layers that are thin along the depth axis but wide stay.
BgRegion withoutSkins(const BgRegion& region, Point away, double width);

// Whether the material (without skins narrower than 2·`skin` along the cut axis: withoutSkins)
// over the cut coordinates [c0, c1] may stand thicker than `limit` above `profile` (a graph over
// the cut axis), measured as thickestAbove does with kMeasuringChord: false when the model's top
// without skins (MaterialModel::topWithoutSkinsWithin) stays below the limit by a margin far above
// the booleans' rounding — then the material without skins measures no thicker, and the oracles,
// which report only what that measure confirms, spare making the material. No Boost.
bool mayStandThickerWithoutSkins(const MaterialModel& model, double c0, double c1, const std::vector<Segment>& profile,
                                 double skin, double limit);

// A move along the finish shape when a G70 follows (its finishing pass, within the tolerance at
// both ends and the middle): it removes the allowance, not a roughing layer.
bool onFinishShape(const JudgeInput& in, const CycleSpec& c, const Segment& move);

// G73's near-net blank's profile: the shape after block ns grown by the relief and the allowance
// (the first pass's path, G73.PASS.SHIFT); the blank is everything behind it (impliedStockOf).
std::vector<Segment> nearNetBlankProfile(const CycleSpec& c);

// Direction from the part towards the cycle's start side along its depth axis.
Point awayFrom(const CycleSpec& c);

// The side the part stands on, from its shape: for G71/G72 awayFrom's direction; for G73 an axis
// over whose other axis the shape is a graph (partSideOf in material_replay.cpp says which).
Point partSideOf(const CycleSpec& c);

// The material still standing after move `k` (0-based; after the whole path for k ≥ the move
// count), as outlines for a plot: the replay stopped there. Nothing when the program is not one the
// geometric oracles judge.
std::optional<std::vector<std::vector<Point>>> materialAfter(const JudgeInput& in, std::size_t k);

// Nothing when the program is not one the geometric oracles judge (not exactly one roughing cycle
// the rules allow, or the engine alarmed). Throws std::invalid_argument for an unusable stock.
std::optional<MaterialReplay> replayMaterial(const JudgeInput& in);

}  // namespace cyclecert
