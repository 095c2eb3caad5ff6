#pragma once
// The fuzzer's SINUMERIK cases (seed 004: LCYC95 on the 802S/C, CYCLE95 on the 802D; rules
// LCYC95.*, CYCLE95.*): a main program — T1 D1, G0 to a start clear of the part, the cycle's
// parameters and call, M02 — and the contour subprogram L1 it names, which a spec case carries in
// "subprograms".
//
// What is drawn (siemens_case_generator.cpp, SiemensChoices): LCYC95 or CYCLE95; the machining type
// 1…12 (longitudinal/face × external/internal × roughing/finishing/complete); a contour drawn in the
// stock-removal frame and placed for the type, so that it is programmed in the finishing direction
// (longitudinal towards −Z, face towards −X; internal mirrors the depth axis): lines of any slope,
// 45° chamfers, steps, convex and concave quarter arcs (I/K or CR=, the boundary of LCYC95.CONTOUR)
// and shallow arcs (CR=), chamfers CHF=/CHR= and roundings RND= inserted between two elements (lines
// or arcs, SIEMENS.CORNER), and —
// CYCLE95 only — undercuts (lines turned back towards the axis, grooves); the parameters R106…R112 /
// MID, FALZ, FALX, FAL, FF1, FF2 (≠ FF1 nine times in ten), FF3, DT, DAM, _VRT; the contour's blocks
// written with or without spaces. One case in ten carries one invalid parameter (SiemensFault) and
// expects its alarm at the call: the type 0 or 13 (61002), no infeed depth when roughing (61610),
// the contour against the finishing direction or with a half circle (10931). Lengths are whole
// hundredths of a mm (arc radii too), so the program text is exact.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/fuzz/case_generator.h"

namespace cyclecert {

// The contour subprogram's name ("L1").
inline constexpr const char* kSiemensContourName = "L1";

// The main program and the contour subprogram's text.
std::string siemensMainProgram(const FuzzCase& c);
std::string siemensContourProgram(const FuzzCase& c);

// The alarm the case's fault raises at the call (none without a fault).
std::optional<FuzzExpectedAlarm> siemensExpectedAlarm(const FuzzCase& c);

// The spec case's JSON (fuzzSpecCase): id, title, rules, profile, program, subprograms, expect.
nlohmann::json siemensSpecJson(const FuzzCase& c, const std::string& tag);

// One line for a person: cycle, type, contour, parameters, fault.
std::string describeSiemensCase(const FuzzCase& c);

}  // namespace cyclecert
