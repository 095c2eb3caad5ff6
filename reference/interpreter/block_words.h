#pragma once
// What the words of a block may hold, checked as the controller reads the block (PROG.RANGE,
// PROG.ADDRESS in specs/rules.json):
//  - a dimension or feed word (X Y Z U V W I J K R F) outside ±999999.999 mm, ±99999.9999 inch
//    (FANUC 0i-TF, increment system IS-B) is alarm PS0003;
//  - an address the block's commands give no meaning is alarm PS0009 (improper NC-address), e.g.
//    an E word outside a threading block — "X1e308" is read as X1 and E308, never as an exponent;
//  - a second word of an address in one block (G and M apart) is alarm PS0009;
//  - G01 chamfering and corner rounding (I, K, C or R in a G01 block) are NotSupported.
// Each alarm names the word's line and column.
#include <string>

#include "reference/interpreter/modal_state.h"
#include "reference/model/program.h"

namespace cyclecert {

// The range every dimension and feed word must stay within (PS0003), as the table's metric or
// inch column; the cycle addresses have narrower ones (reference/gcode/address_ranges.h). First,
// one word of an address per block, G and M apart: a second is PS0009 (checkOneWordPerAddress);
// a minus sign after F, S or T is PS0006 (PROG.SIGN).
void checkWordRanges(const Block& b, bool inch);
void checkOneWordPerAddress(const Block& b);

// A block that moves along the plane (group 01, G00–G03, with the state's plane and motion after
// the block's own codes): PS0009 for an address such a block does not use.
void checkMotionBlockAddresses(const Block& b, int motion, const ModalState& s);

// "; a number with an exponent ("1e308") is not a G-code number: write the value in full" when
// `w` is an E standing right after another word's number ("X1e308", "D1e3"), else "": for the
// messages of every reader that refuses an E.
std::string exponentHint(const Block& b, const Word& w);

// Any block: PS0009 for an E word (thread lead: FANUC lathes read it in G32/G76/G92 only, which
// the reference does not plan).
void checkNoThreadLead(const Block& b);

// A block of a shape program (ns…nf), read by the cycle with its own modal state `s` (motion
// already updated by the block): the three checks above.
void checkShapeBlockWords(const Block& b, const ModalState& s);

}  // namespace cyclecert
