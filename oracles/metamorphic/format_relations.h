#pragma once
// "Same cycle, other format": a FANUC two-block G71/G72 program written in a one-block format must
// give the same path (oracles/metamorphic/README.md).
//
// - fs10-one-block: the FANUC Series 10/11 program format (parameter 0001#1 FCV = 1,
//   G71.FS10.*): `G71 U(Δd) R(e); G71 P Q U W F;` becomes `G71 P Q U W D(Δd) F;` with D in least
//   input increments (0.001 mm) and e in parameter 5133. Expected: the same toolpath.
// - hnc-one-block: the Huazhong single block of seed 003 (profile hnc, HNC.G71.*): `G71 U(Δd)
//   R(e) P Q X(Δu) Z(Δw) F;`, whose ns…nf then run again as the finishing, in place of FANUC's G70
//   P Q after the cycle. Expected: the same toolpath without G70's last rapid back to the start.
// - haas-one-block: the Haas one block (profile haas, HAAS.G71.*): `G71 P Q U W D(Δd, mm) [R1] F;`,
//   R1 for type II, e in parameter 5133 (Setting 73). Expected: the same toolpath.
// - gsys-b, gsys-c: the program in FANUC G code system B / C (3401#6 GSB / #7 GSC, PROG.GSYS.*):
//   the codes renamed through the G code table, G90/G91 for absolute/incremental words. Expected:
//   the same toolpath.
#include "oracles/metamorphic/relations.h"

namespace cyclecert {

Relation series10OneBlockRelation();
Relation huazhongOneBlockRelation();
Relation haasOneBlockRelation();
Relation gCodeSystemBRelation();
Relation gCodeSystemCRelation();

}  // namespace cyclecert
