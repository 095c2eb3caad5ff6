#pragma once
// Huazhong (HNC) G71 of seed 003: one block `G71 U(Δd) R(r) P(ns) Q(nf) X(Δx) Z(Δz) F S T`
// (rules HNC.G71.*). The roughing itself is FANUC's type I (reference/cycles/type1_roughing.*);
// what differs is how the block is read, and that execution goes on with the block after G71, so
// the blocks up to ns and then ns…nf run as the finishing pass (HNC.G71.FST, HNC.G71.RETURN).
#include "reference/cycles/roughing_cycle.h"

namespace cyclecert {

bool readsHuazhongG71(const CycleCall& call);

// HNC.G71.PQ: a G71 block without P and Q cannot run (PS0061, dated "cycle block").
[[noreturn]] void refuseHuazhongG71WithoutPQ(const CycleCall& call);

// HNC.G71.FMT: U = Δd (radius, unsigned) and R = r go to parameters 5132/5133 like FANUC's first
// block; X = Δx (diameter, signed: halved) and Z = Δz (signed) are the allowances. Throws
// CycleAlarm (PS0061, PS0003) or NotSupported (another plane than G18).
SecondBlock readHuazhongG71Block(const CycleCall& call);

// HNC.G71.SUB: ns…nf may call subprograms; the reference does not follow them (NotSupported).
void refuseSubprogramsInHuazhongShape(const CycleCall& call, const SecondBlock& sb);

// Seed 003 gives the format without pockets: type I only. Block ns with a Z word as well is
// NotSupported (the seed's A→A' may be any line, which the type I plan does not model).
void checkHuazhongHead(const CycleCall& call, const ShapeProgram& shape);

// HNC.G71.FST, HNC.G71.RETURN: after roughing the tool is back at the cycle start and the program
// goes on with the block after G71 (never skips ns…nf).
std::size_t huazhongResumeIndex(const CycleCall& call);

// Seed 003 describes G71 only: a G72 under the Huazhong format is NotSupported, not read as FANUC's.
void refuseG72UnderHuazhong(const CycleCall& call);

}  // namespace cyclecert
