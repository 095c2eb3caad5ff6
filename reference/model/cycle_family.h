#pragma once
// The roughing cycle families, one type for the reference planners and the oracles: how a cycle's
// passes are laid out and which rules they follow. G71 and G72 rough axis-parallel layers Δd apart
// (cutting along z and along x); G73 follows the whole finish shape d times, shifted by shares of
// the relief (Δi, Δk) (G73.PASS.SHIFT). G70 finishes along the shape once: it is no roughing family.
// The SINUMERIK stock-removal cycles LCYC95 (802S/C, LCYC95.*) and CYCLE95 (802D, CYCLE95.*) rough
// axis-parallel levels in equal steps, retract in each axis and may finish in the same call.
// G74.1 (GSK, seed 002) is no roughing cycle: layers of axial peck cycles empty a trapezoid groove
// (reference/cycles/g74_1.h); no oracle judges it yet.
#include <optional>
#include <string_view>

namespace cyclecert {

enum class CycleFamily { G71, G72, G73, Lcyc95, Cycle95, G74_1 };

// The family's G code (or cycle name) as programs, messages and the toolpath JSON's "cycles" spell it:
// "G71"…, "LCYC95", "CYCLE95", "G74.1".
std::string_view cycleCode(CycleFamily family);
// The family a code names, nullopt for any other code ("G70", "G74"…).
std::optional<CycleFamily> cycleFamilyOfCode(std::string_view code);
// Whether the family is a SINUMERIK stock-removal cycle (LCYC95, CYCLE95), judged by the Siemens
// oracles (oracles/siemens/) rather than the FANUC ones.
bool isSiemensFamily(CycleFamily family);

}  // namespace cyclecert
