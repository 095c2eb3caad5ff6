#pragma once
// Comparing a toolpath with what a metamorphic relation expects of it, within a tolerance.
// (harness/judge/toolpath_compare.h compares move lists the same way for the spec cases; the oracles
// cannot depend on the harness, so this one lives here.)
#include <optional>
#include <string>

#include "reference/model/toolpath.h"

namespace cyclecert {

// The first divergence, described for a person, or nothing when the paths agree: the alarm (both
// or neither, the same code), the start point (when either path has moves), the number of moves,
// and for each move its kind (rapid/feed), shape (line/arc_cw/arc_ccw), end point, centre (arcs)
// and feed (within tol of the larger of 1 and the expected feed: a feed is not a length). Lengths
// agree within tol (mm, on each coordinate). A move that ends within tol of where it starts is no
// move and is skipped on both sides: where a pass level touches an arc's apex, the crossing moves by
// √(2·r·ε) for a rounding ε of the input (1e-13 mm becomes 1e-6 mm), so an engine may emit a piece
// of arc of 1e-7 mm there or not, depending on the last digit of a word. (A full circle also ends
// where it starts; no lathe cycle makes one.) Messages name the moves by their index in each path.
// Phases, passes, rule IDs, warnings and cycle records are not compared.
std::optional<std::string> compareToolpaths(const Toolpath& expected, const Toolpath& actual, double tol);

// The same geometry with fewer moves: consecutive moves of the same kind and feed are joined when
// they continue one another — a run of lines going on forwards, each joint within tol of the line
// from its neighbours, simplified by Douglas–Peucker within tol (the farthest corner kept first, so
// that a run and the same run with points added on its lines keep the same corners), arcs of the
// same direction around the same centre (within tol) — and, as in compareToolpaths, moves that end
// within tol of where they start are dropped.
Toolpath mergeContinuations(const Toolpath& path, double tol);

// compareToolpaths after mergeContinuations of both paths: the relation that splits a block into
// two makes the same geometry with one move more.
std::optional<std::string> compareGeometry(const Toolpath& expected, const Toolpath& actual, double tol);

}  // namespace cyclecert
