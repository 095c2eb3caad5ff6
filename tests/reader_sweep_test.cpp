// Issue 19, item 3: every dialect's reader fed a table of malformed blocks — an address out of its
// range, an exponent form, a missing value, NaN or inf, a duplicated address, a stray character,
// an unterminated comment or string, a contour subprogram that is missing or calls itself. Each
// must be refused with its line and column and a message naming the address: a ParseError, or a
// controller alarm naming the word's column — never a crash, a hang or a value read wrongly.
// The rows marked "fixed" failed before the change that made them pass (issue 19's sweep).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "harness/engines/reference_plan.h"
#include "reference/model/alarms.h"

namespace cyclecert {
namespace {

struct Malformed {
  std::string name;
  PlanRequest request;
  int line;            // where the refusal must point
  std::string naming;  // what its message must name: the address or word
  // A SINUMERIK cycle's parameter alarm names the parameter and the cycle call's line, no column
  // (the value may come from an R assignment lines before).
  bool columnNamed = true;
};

// How the reader answered: "parse error" / "alarm CODE" / "not supported" / "planned", the
// line and column it gave (column 0: none), and its message.
struct Answer {
  std::string kind;
  int line = 0;
  int column = 0;
  std::string message;
};

// The column an alarm's message names ("… at column 7 …"), or 0.
int columnNamedIn(const std::string& message) {
  const std::string key = "at column ";
  const auto at = message.find(key);
  if (at == std::string::npos) return 0;
  return std::atoi(message.c_str() + at + key.size());
}

Answer answerTo(const PlanRequest& request) {
  try {
    const Toolpath t = planWithReference(request);
    if (!t.alarm) return {"planned", 0, 0, ""};
    return {"alarm " + t.alarm->code, t.alarm->line, columnNamedIn(t.alarm->message), t.alarm->message};
  } catch (const ParseError& e) {
    return {"parse error", e.loc().line, e.loc().column, e.what()};
  } catch (const NotSupported& e) {
    return {"not supported", e.line(), 0, e.what()};
  }
}

PlanRequest fanuc(const std::string& profile, const std::string& program,
                  std::vector<std::pair<std::string, double>> params = {}) {
  return {program, "sweep.nc", profile, std::move(params), {}};
}

PlanRequest siemens(const std::string& profile, const std::string& program, const std::string& contour) {
  PlanRequest r{program, "sweep.mpf", profile, {}, {}};
  r.subprograms = {{"R1", contour, "R1.spf"}};
  return r;
}

// FANUC 0i-F and its two-block G71 (system A), the cycle on lines 3 and 4.
std::string twoBlocks(const std::string& first, const std::string& second,
                      const std::string& shape = "N10 G00 X18;\nN20 G01 Z-12;\nN30 X24 Z-18;\nN40 X28;\n") {
  return "G21;\nG00 X31 Z1;\n" + first + "\n" + second + "\n" + shape + "M30;\n";
}

std::vector<Malformed> fanucTable() {
  const std::string second = "G71 P10 Q40 U0.4 W0.1 F0.2;";
  return {
      {"exponent in the first block", fanuc("fanuc-0i-f", twoBlocks("G71 U1e3 R0.5;", second)), 3, "exponent"},
      {"exponent in the shape", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", second, "N10 G00 X1e1;\nN40 G01 Z-12;\n")), 5,
       "exponent"},
      {"missing value", fanuc("fanuc-0i-f", twoBlocks("G71 U R0.5;", second)), 3, "address U"},
      {"NaN", fanuc("fanuc-0i-f", twoBlocks("G71 Unan R0.5;", second)), 3, "address U"},
      {"inf", fanuc("fanuc-0i-f", twoBlocks("G71 U1 Rinf;", second)), 3, "address R"},
      {"duplicated U (fixed)", fanuc("fanuc-0i-f", twoBlocks("G71 U1 U2 R0.5;", second)), 3, "a second U word"},
      {"duplicated P (fixed)", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", "G71 P10 P20 Q40 U0.4 W0.1 F0.2;")), 4,
       "a second P word"},
      {"duplicated X in the shape (fixed)",
       fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", second, "N10 G00 X18 X19;\nN40 G01 Z-12;\n")), 5, "a second X word"},
      {"stray character", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5 $;", second)), 3, "$"},
      {"unterminated comment", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5 (no end", second)), 3, "')'"},
      {"Δd over its range", fanuc("fanuc-0i-f", twoBlocks("G71 U1000000 R0.5;", second)), 3, "U1000000"},
      {"Δd zero", fanuc("fanuc-0i-f", twoBlocks("G71 U0 R0.5;", second)), 3, "U0"},
      {"e over its range", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R1000000;", second)), 3, "R1000000"},
      {"e negative", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R-0.5;", second)), 3, "R-0.5"},
      {"ns over its range", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", "G71 P100000 Q40 U0.4 W0.1 F0.2;")), 4, "P100000"},
      {"ns with a decimal point", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", "G71 P10.5 Q40 U0.4 W0.1 F0.2;")), 4, "P10.5"},
      {"Δu over its range", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", "G71 P10 Q40 U1000000 W0.1 F0.2;")), 4, "U1000000"},
      {"X over its range", fanuc("fanuc-0i-f", twoBlocks("G71 U1 R0.5;", second, "N10 G00 X1000000000;\nN40 G01 Z-12;\n")), 5,
       "X1000000000"},
      {"sixteen significant digits", fanuc("fanuc-0i-f", twoBlocks("G71 U1.000000000000001 R0.5;", second)), 3, "digits"},
      {"G73 divisions zero", fanuc("fanuc-0i-f", twoBlocks("G73 U4 W2 R0;", "G73 P10 Q40 U0.4 W0.2 F0.2;")), 3, "R0"},
      {"G73 divisions with a decimal point", fanuc("fanuc-0i-f", twoBlocks("G73 U4 W2 R2.5;", "G73 P10 Q40 U0.4 W0.2 F0.2;")),
       3, "R2.5"},
      {"G73 Δi over its range", fanuc("fanuc-0i-f", twoBlocks("G73 U4000000 W2 R2;", "G73 P10 Q40 U0.4 W0.2 F0.2;")), 3,
       "U4000000"},
  };
}

// The one-block formats: Huazhong's G71, Haas's and Series 10/11's G71 P Q U W D, on line 3.
std::string oneBlock(const std::string& cycle) {
  return "G21;\nG00 X42 Z2;\n" + cycle + "\nN10 G00 X2;\nN20 G01 Z-10;\nM30;\n";
}

// G code system C (G71 is metric input, G73 the stock removal in turning): the cycle's first
// block on line 3.
std::string systemC(const std::string& first) {
  return "G71 G40 G94;\nG90 G00 X42 Z2;\n" + first + "\nG73 P10 Q20 U0 W0 F150;\nN10 G00 X2;\nN20 G01 Z-10;\nM30;\n";
}

std::vector<Malformed> oneBlockTable() {
  const std::vector<std::pair<std::string, double>> fs10{{"FCV", 1}};
  return {
      {"Huazhong: exponent", fanuc("hnc", oneBlock("G71 U1e1 R0.5 P10 Q20 X0 Z0 F0.2;")), 3, "exponent"},
      {"Huazhong: Δd over its range", fanuc("hnc", oneBlock("G71 U1000000 R0.5 P10 Q20 X0 Z0 F0.2;")), 3, "U1000000"},
      {"Huazhong: Δx over its range", fanuc("hnc", oneBlock("G71 U1 R0.5 P10 Q20 X1000000 Z0 F0.2;")), 3, "X1000000"},
      {"Huazhong: ns over its range", fanuc("hnc", oneBlock("G71 U1 R0.5 P100000 Q20 X0 Z0 F0.2;")), 3, "P100000"},
      {"Huazhong: e negative", fanuc("hnc", oneBlock("G71 U1 R-0.5 P10 Q20 X0 Z0 F0.2;")), 3, "R-0.5"},
      {"Huazhong: W has no meaning", fanuc("hnc", oneBlock("G71 U1 R0.5 P10 Q20 X0 Z0 W1 F0.2;")), 3, "W1"},
      {"Huazhong: duplicated X (fixed)", fanuc("hnc", oneBlock("G71 U1 R0.5 P10 Q20 X0 X1 Z0 F0.2;")), 3, "a second X word"},
      {"Huazhong: missing value", fanuc("hnc", oneBlock("G71 U1 R0.5 P Q20 X0 Z0 F0.2;")), 3, "address P"},
      {"Haas: exponent (fixed: the message named no exponent)", fanuc("haas", oneBlock("G71 P10 Q20 D1e1 U0 W0 F0.2;")), 3,
       "exponent"},
      {"Haas: D over its range", fanuc("haas", oneBlock("G71 P10 Q20 D1000000 U0 W0 F0.2;")), 3, "D1000000"},
      {"Haas: D zero", fanuc("haas", oneBlock("G71 P10 Q20 D0 U0 W0 F0.2;")), 3, "D0"},
      {"Haas: R other than R1", fanuc("haas", oneBlock("G71 P10 Q20 D1 U0 W0 R-1 F0.2;")), 3, "R-1"},
      {"Haas: duplicated D (fixed)", fanuc("haas", oneBlock("G71 P10 Q20 D1 D2 U0 W0 F0.2;")), 3, "a second D word"},
      {"Haas: inf", fanuc("haas", oneBlock("G71 P10 Q20 Dinf U0 W0 F0.2;")), 3, "address D"},
      {"Series 10/11: D with a decimal point", fanuc("fanuc-0i-f", oneBlock("G71 P10 Q20 U0 W0 D1.5 F0.2;"), fs10), 3, "D1.5"},
      {"Series 10/11: D of ten digits", fanuc("fanuc-0i-f", oneBlock("G71 P10 Q20 U0 W0 D1234567890 F0.2;"), fs10), 3,
       "D1234567890"},
      {"Series 10/11: exponent (fixed: the message named no exponent)",
       fanuc("fanuc-0i-f", oneBlock("G71 P10 Q20 U0 W0 D1e3 F0.2;"), fs10), 3, "exponent"},
      {"Series 10/11: duplicated W (fixed)", fanuc("fanuc-0i-f", oneBlock("G71 P10 Q20 U0 W0 W1 D1000 F0.2;"), fs10), 3,
       "a second W word"},
      {"Series 10/11: G73 I over its range",
       fanuc("fanuc-0i-f", oneBlock("G73 P10 Q20 I4000000 K2 U0.4 W0.2 D3 F0.2;"), fs10), 3, "I4000000"},
      {"system B: exponent", fanuc("fanuc-0i-f", oneBlock("G73 U1e1 R0.5;\nG73 P10 Q20 U0 W0 F0.2;"), {{"GSB", 1}}), 3,
       "exponent"},
      {"system B: Δd over its range",
       fanuc("fanuc-0i-f", oneBlock("G73 U1000000 R0.5;\nG73 P10 Q20 U0 W0 F0.2;"), {{"GSB", 1}}), 3, "U1000000"},
      {"system C: duplicated U (fixed)", fanuc("fanuc-0i-f", systemC("G73 U1 U2 R0.5;"), {{"GSC", 1}}), 3, "a second U word"},
      {"system C: e negative", fanuc("fanuc-0i-f", systemC("G73 U1 R-0.5;"), {{"GSC", 1}}), 3, "R-0.5"},
  };
}

// GSK's G74.1, its seventeen addresses (182#7 = 1 allows it): the blocks on lines 2 and 3.
std::vector<Malformed> g74_1Table() {
  const auto gsk = [](const std::string& first, const std::string& second) {
    return fanuc("gsk", "G00 X50 Z5 F0.1;\n" + first + "\n" + second + "\n", {{"182#7", 1}});
  };
  const std::string groove = "G74.1 X40 Z0 P1 Q2 H-4 D-4;";
  return {
      {"G74.1: A over 90", gsk("G74.1 X40 Z0 P1 Q2 H-4 D-4 A95;", "G74.1 R0.5;"), 2, "A95"},
      {"G74.1: e over its range", gsk(groove, "G74.1 R100;"), 3, "R100"},
      {"G74.1: exponent", gsk("G74.1 X40 Z0 P1 Q2e1 H-4 D-4;", "G74.1 R0.5;"), 2, "exponent"},
      {"G74.1: duplicated H (fixed)", gsk("G74.1 X40 Z0 P1 Q2 H-4 H-5 D-4;", "G74.1 R0.5;"), 2, "a second H word"},
      {"G74.1: V zero", gsk(groove, "G74.1 R0.5 V0;"), 3, "V0"},
      {"G74.1: missing value", gsk(groove, "G74.1 R;"), 3, "address R"},
  };
}

// The contour L4 with the call L4 on its second line.
PlanRequest callingItself(const std::string& rLine) {
  PlanRequest r{"G0 X50 Z2\n_CNAME=\"L4\"\n" + rLine + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", "sweep.mpf",
                "sinumerik-802s", {}, {}};
  r.subprograms = {{"L4", "G1 X20 Z0\nL4\nZ-10\nX40\nRET\n", "L4.spf"}};
  return r;
}

// SINUMERIK: LCYC95 with R parameters (802S) and CYCLE95 with arguments (802D), the contour R1.
std::vector<Malformed> siemensTable() {
  const std::string contour = "G1 X20 Z0\nZ-10\nX40\nRET\n";
  const auto lcyc95 = [&](const std::string& r108Line, const std::string& c = "G1 X20 Z0\nZ-10\nX40\nRET\n") {
    return siemens("sinumerik-802s",
                   "G0 X50 Z2\n_CNAME=\"R1\"\n" + r108Line + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", c);
  };
  const std::string r = "R105=1 R106=0 R108=1 R109=0";
  const auto cycle95 = [&](const std::string& call, const std::string& c = "G1 X20 Z0\nZ-10\nX40\nRET\n") {
    return siemens("sinumerik-802d", "G0 X50 Z2\n" + call + "\nM02\n", c);
  };
  return {
      {"LCYC95: exponent", lcyc95("R105=1 R106=0 R108=1e1 R109=0"), 3, "found e"},
      {"LCYC95: NaN", lcyc95("R105=1 R106=0 R108=nan R109=0"), 3, "R108="},
      {"LCYC95: missing value", lcyc95("R105=1 R106= R108=1 R109=0"), 3, "R106="},
      {"LCYC95: R105 out of its table", lcyc95("R105=99 R106=0 R108=1 R109=0"), 5, "R105", false},
      {"LCYC95: R parameter number over 999", lcyc95(r + " R1000=1"), 3, "R parameter number"},
      {"LCYC95: unterminated string",
       siemens("sinumerik-802s", "G0 X50 Z2\n_CNAME=\"R1\n" + r + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", contour), 2,
       "'\"'"},
      {"LCYC95: missing contour",
       siemens("sinumerik-802s", "G0 X50 Z2\n_CNAME=\"R9\"\n" + r + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", contour), 2,
       "R9"},
      {"LCYC95: stray character", lcyc95(r + " $"), 3, "$"},
      {"LCYC95: duplicated X (fixed)",
       siemens("sinumerik-802s", "G0 X50 X60 Z2\n_CNAME=\"R1\"\n" + r + "\nR110=1 R111=0.3 R112=0.1\nLCYC95\nM02\n", contour),
       1, "one X word per block"},
      {"LCYC95: exponent in the contour", lcyc95(r, "G1 X20 Z0\nZ-1e1\nX40\nRET\n"), 2, "found e"},
      {"LCYC95: the contour calls itself (fixed)", callingItself(r), 2, "the contour calling itself"},
      {"LCYC95: the contour calls a subprogram (fixed)", lcyc95(r, "G1 X20 Z0\nL77\nZ-10\nX40\nRET\n"), 2,
       "subprogram call L77"},
      {"LCYC95: the contour calls a cycle (fixed)", lcyc95(r, "G1 X20 Z0\nLCYC95\nZ-10\nX40\nRET\n"), 2, "cycle call LCYC95"},
      {"CYCLE95: exponent", cycle95("CYCLE95(\"R1\", 1e0, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)"), 2, "argument 2"},
      {"CYCLE95: VARI out of its table", cycle95("CYCLE95(\"R1\", 1, 0, 0, 0, 0.3, 0.15, 0.1, 99, 0, 0, 1)"), 2, "VARI", false},
      {"CYCLE95: MID negative", cycle95("CYCLE95(\"R1\", -1, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)"), 2, "MID", false},
      {"CYCLE95: thirteen arguments", cycle95("CYCLE95(\"R1\", 1, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1, 5)"), 2, "argument 13"},
      {"CYCLE95: unterminated string", cycle95("CYCLE95(\"R1, 1, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)"), 2, "'\"'"},
      {"CYCLE95: unterminated call", cycle95("CYCLE95(\"R1\", 1, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1"), 2, "')'"},
      {"CYCLE95: inf", cycle95("CYCLE95(\"R1\", inf, 0, 0, 0, 0.3, 0.15, 0.1, 1, 0, 0, 1)"), 2, "inf"},
  };
}

void expectRefusedWhereItIs(const Malformed& m) {
  const Answer a = answerTo(m.request);
  SCOPED_TRACE(m.name + " (" + m.request.profile + "): " + a.kind + ", " + a.message);
  EXPECT_TRUE(a.kind == "parse error" || a.kind.rfind("alarm ", 0) == 0) << "refused as a malformed program";
  EXPECT_EQ(a.line, m.line);
  if (m.columnNamed) {
    EXPECT_GT(a.column, 0) << "the refusal names the column";
  }
  EXPECT_NE(a.message.find(m.naming), std::string::npos) << "the message names " << m.naming;
}

TEST(ReaderSweep, FanucTwoBlockFormatsRefuseEachMalformedBlockWhereItIs) {
  for (const Malformed& m : fanucTable()) expectRefusedWhereItIs(m);
}

TEST(ReaderSweep, OneBlockFormatsAndGCodeSystemsRefuseEachMalformedBlockWhereItIs) {
  for (const Malformed& m : oneBlockTable()) expectRefusedWhereItIs(m);
}

TEST(ReaderSweep, G74_1RefusesEachMalformedBlockWhereItIs) {
  for (const Malformed& m : g74_1Table()) expectRefusedWhereItIs(m);
}

TEST(ReaderSweep, SinumerikRefusesEachMalformedBlockWhereItIs) {
  for (const Malformed& m : siemensTable()) expectRefusedWhereItIs(m);
}

}  // namespace
}  // namespace cyclecert
