#pragma once
// The fuzzer's G74.1 cases (GSK axial trapezoid groove, seed 002, rules G74_1.*; docs/g74_1.md
// derives the cycle by hand): a program of three blocks and M30 on profile gsk —
//
//   G00 X Z F0.1;                                   (line 1: where the tool stands, in air)
//   G74.1 X Z P(Δi) Q(Δk) H(h) D(d) [A] [B] [L];    (line 2: the groove)
//   G74.1 R(e) [V] [U] [W] [I] [J] [A B D E] [P];   (line 3: how to cut it)
//
// What is drawn (g74_1_case_generator.cpp, GrooveChoices): the groove start S, h and d with both
// signs (the four directions: feeds towards −Z or +Z, steps towards −X or +X), the flank angles ∠a
// and ∠b (90° half the time, else sharp: 20°…89°), the slope ∠p (0, else below ∠a), the corners
// r1…r4 (chamfers or rounds, P(abde) written or not), Δi, Δk, e, Δv (absent, or several layers),
// Δu and Δw (absent, either, both; now and then written negative: I4 reads their magnitude), the
// tool width I (absent: a pointed tool; one case in a hundred a pointed tool with a nose radius and a tip under
// G41/G42 on its own line before the groove block, docs/g74_1.md I26), J0 (written or not), J1, J2,
// and parameter 182#7 both
// ways (P and Q in IS-C increments or in mm). The start point before the cycle stands over the
// groove's mouth, in air. A valid draw is fitted so that the tool can cut the groove: the corners,
// the allowances and the tool width are kept within what the flanks and the floor leave (the
// reference's GrooveDoesNotFit alarm stays rare), and Δi, Δk and Δv are kept large enough that a
// case makes no more than a few thousand moves. One case in ten carries one invalid value
// (G74_1Fault: each range of docs/g74_1.md §1, a missing Q, a decimal point in P read in
// increments, a word the block does not take, a tool wider than the floor, a slope not below ∠a)
// and expects its alarm at its block. Lengths are whole hundredths of a mm and angles whole degrees,
// so the program text is exact.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "harness/fuzz/case_generator.h"

namespace cyclecert {

// The case's program text (the three blocks and M30).
std::string g74_1Program(const FuzzCase& c);

// The alarm the case's fault raises, at the groove block (line 2) or the second block (line 3);
// none without a fault.
std::optional<FuzzExpectedAlarm> g74_1ExpectedAlarm(const FuzzCase& c);

// The spec case's JSON (fuzzSpecCase): id, title, rules, profile, params (182#7), program, expect.
nlohmann::json g74_1SpecJson(const FuzzCase& c, const std::string& tag);

// One line for a person: directions, angles, corners, steps, layers, allowances, tool, J, fault.
std::string describeG74_1Case(const FuzzCase& c);

}  // namespace cyclecert
