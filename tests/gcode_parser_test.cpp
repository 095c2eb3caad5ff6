// parseProgram: blocks, words and their locations, the seed programs, every parse error with its
// exact location and wording, and two RapidCheck properties (round trip; arbitrary bytes never
// crash).
#include "reference/gcode/parser.h"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/program.h"

namespace cyclecert {
namespace {

Program parse(std::string_view text) { return parseProgram(text, "p.nc"); }

// Parses text expecting a ParseError, and returns it.
ParseError parseError(std::string_view text) {
  try {
    parse(text);
  } catch (const ParseError& error) {
    return error;
  }
  ADD_FAILURE() << "no ParseError for: " << text;
  return ParseError({}, "", "");
}

void expectParseError(std::string_view text, int line, int column, const std::string& expected,
                      const std::string& found) {
  SCOPED_TRACE(std::string(text));
  const ParseError error = parseError(text);
  EXPECT_EQ(error.loc().file, "p.nc");
  EXPECT_EQ(error.loc().line, line);
  EXPECT_EQ(error.loc().column, column);
  EXPECT_EQ(error.expected(), expected);
  EXPECT_EQ(error.found(), found);
}

// "G71 U1.5 R1" for a block, to compare blocks at a glance.
std::string wordsOf(const Block& block) {
  std::string text;
  for (const Word& word : block.words) {
    if (!text.empty()) text += ' ';
    text += word.text;
  }
  return text;
}

// --- the seed programs ------------------------------------------------------------------------

// Seed 001 (GSK G72 example). The document prints each block with its comment in a second table
// column; the comment's line break ("转速\n500r/min") is a page-layout artefact and is joined here.
constexpr std::string_view kSeed001O0005 =
    "O0005;\n"
    "G00 X176 Z10 M3 S500 T0202;\t(换2号刀,执行2号刀偏,主轴逆时针转,转速500r/min)\t\n"
    "G72 W2.0 R0.5 F300;\t(进刀量 2mm, 退刀量 0.5mm)\n"
    "G72 P10 Q20 U0.2 W0.1;\t(对 a→d 粗车, X 轴留 0.2mm, Z 轴流 0.1mm 余量)\n"
    "N10 G00 Z-55 S800;\t(快速移动)\n"
    "G01 X160 F120;\t(进刀至 a 点)\n"
    "X80 W20;\t(加工 a→b)\n"
    "W15;\t(加工 b→c)\n"
    "N20 X40 W20;\t(加工 c→d)\n"
    "G70 P10 Q20;\t(精加工 a→d)\n"
    "M30;\t\n";

TEST(Parser, ReadsSeed001ProgramO0005) {
  const Program program = parse(kSeed001O0005);
  EXPECT_EQ(program.file, "p.nc");
  EXPECT_EQ(program.number, 5);
  ASSERT_EQ(program.blocks.size(), 10u);
  const std::vector<std::string> expected = {
      "G00 X176 Z10 M3 S500 T0202", "G72 W2.0 R0.5 F300", "G72 P10 Q20 U0.2 W0.1",
      "G00 Z-55 S800",              "G01 X160 F120",      "X80 W20",
      "W15",                        "X40 W20",            "G70 P10 Q20",
      "M30"};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(wordsOf(program.blocks[i]), expected[i]) << "block " << i;
    EXPECT_EQ(program.blocks[i].line, static_cast<int>(i) + 2) << "block " << i;
  }
  EXPECT_EQ(program.blocks[3].text, "N10 G00 Z-55 S800");
  EXPECT_EQ(program.blocks[3].sequence, 10);
  EXPECT_EQ(program.findSequence(10), 3u);
  EXPECT_EQ(program.findSequence(20), 7u);
  const Block& g72 = program.blocks[1];
  EXPECT_TRUE(g72.hasG(720));
  ASSERT_TRUE(g72.has('W'));
  EXPECT_DOUBLE_EQ(g72.find('W')->value, 2.0);
  EXPECT_TRUE(g72.find('W')->hasDecimalPoint);
  EXPECT_FALSE(g72.find('F')->hasDecimalPoint);
  // A comment after ';' opens a new block that holds nothing else, so it is dropped with it.
  EXPECT_EQ(program.blocks[0].comment, "");
}

TEST(Parser, ReportsTheAnnotationColumnOfSeed001AsNotGCode) {
  // Seed 001 prints "精加工路线程序段" beside the block, outside the parentheses.
  expectParseError("X80 W20;\t(加工 a→b) 精加工路线程序段", 1, 25,
                   "an address letter, a number, a comment or the end of the block", "精");
}

// Seed 003, HNC example 1 (the OCR's "Rl" and "l0" corrected to "R1" and "10").
constexpr std::string_view kSeed003Example1 =
    "N1 G94 G90\n"
    "N2 T0101 (设立坐标系,选 1 号刀)\n"
    "N3 M03 S400 (主轴以 400r/min 正转)\n"
    "N5 G00 X54 Z3 (刀具到循环起点位置)\n"
    "N6 G71U1.5R1P11Q20X0.6Z0.1F100 (粗切量:1.5mm 精切量:X0.6mm、Z0.1mm)\n"
    "N7 G00 X100 Z100 (粗加工后,到换刀点位置)\n"
    "N8 T0303 (精加工起始行,设立坐标系,选 3 号刀)\n"
    "N9 M03 S400 (主轴以 400r/min 正转)\n"
    "N10 G42 G01 X52 Z3 F100 (加入刀尖圆弧半径补偿)\n"
    "N11 G00 X0 (精加工轮廓起始行,到倒角延长线 )\n"
    "N12 G01 X10 Z-2 (精加工 C2 倒角)\n"
    "N13 Z-20 (精加工 10外圆)\n"
    "N14 G02 U10 W-5 R5 (精加工 R5 圆弧)\n"
    "N15 G01 W-10 (精加工 20外圆)\n"
    "N16 G03 U14 W-7 R7 (精加工 R7 圆弧)\n"
    "N17 G01 Z-52 (精加工 34外圆)\n"
    "N18 U10 W-10 (精加工外圆锥)\n"
    "N19 W-25 (精加工 44外圆)\n"
    "N20 X52 (精加工轮廓结束行,退出已加工面 )\n"
    "N21 G40 G00 X100 Z100 (取消半径补偿,返回程序起点位置)\n"
    "N22 M05 (主轴停)\n"
    "N23 M00 (程序暂停)\n"
    "N24 T0202 (设立坐标系,选 2 号刀)\n"
    "N25 M03 S400 (主轴以 400rmin 正转)\n"
    "N26 G0 X52 Z-86 (刀具到起点位置)\n"
    "N27 G01 X0 F100 (切断)\n"
    "N28 G00 X100 Z100 (回对刀点)\n"
    "N29 M05 (主轴停)\n"
    "N30 M30 (主程序结束并复位)\n";

TEST(Parser, ReadsSeed003HncExample1) {
  const Program program = parse(kSeed003Example1);
  EXPECT_FALSE(program.number.has_value());
  ASSERT_EQ(program.blocks.size(), 29u);  // N1–N30 without N4
  const Block& g71 = program.blocks[program.findSequence(6).value()];
  EXPECT_EQ(g71.line, 5);
  EXPECT_EQ(wordsOf(g71), "G71 U1.5 R1 P11 Q20 X0.6 Z0.1 F100");
  EXPECT_EQ(g71.text, "N6 G71U1.5R1P11Q20X0.6Z0.1F100 (粗切量:1.5mm 精切量:X0.6mm、Z0.1mm)");
  EXPECT_EQ(g71.comment, "粗切量:1.5mm 精切量:X0.6mm、Z0.1mm");
  EXPECT_EQ(program.findSequence(11), 9u);
  EXPECT_EQ(program.findSequence(20), 18u);
  EXPECT_FALSE(program.findSequence(4).has_value());
  EXPECT_TRUE(program.blocks[program.findSequence(14).value()].hasG(20));
}

TEST(Parser, ReadsTheHncG71LineWordByWord) {
  const Block block = parse("N6 G71U1.5R1P11Q20X0.6Z0.1F100").blocks.at(0);
  EXPECT_EQ(block.sequence, 6);
  const std::string letters = "GURPQXZF";
  const std::vector<double> values = {71, 1.5, 1, 11, 20, 0.6, 0.1, 100};
  const std::vector<int> columns = {4, 7, 11, 13, 16, 19, 23, 27};
  ASSERT_EQ(block.words.size(), letters.size());
  for (std::size_t i = 0; i < letters.size(); ++i) {
    EXPECT_EQ(block.words[i].letter, letters[i]);
    EXPECT_DOUBLE_EQ(block.words[i].value, values[i]);
    EXPECT_EQ(block.words[i].column, columns[i]);
    EXPECT_EQ(block.words[i].line, 1);
  }
  EXPECT_EQ(block.words[1].text, "U1.5");
}

TEST(Parser, ReportsTheSeed003OcrSlipsPrecisely) {
  // Seed 003 prints "RlP11" (letter l for digit 1) and "W-l0".
  expectParseError("N6 G71U1.5RlP11Q20X0.6Z0.1F100", 1, 12, "a number after address R", "l");
  expectParseError("N14 W-l0", 1, 7, "a digit", "l");
}

// Seed 004, FANUC 0i G73 example.
constexpr std::string_view kSeed004Fanuc =
    "M03S1000\n"
    "T0101\n"
    "G0X70Z2\n"
    "G73U5W0R4\n"
    "G73P10Q11U0.2W0.1F0.1\n"
    "N10G01X50Z0\n"
    "G3X40Z-15R22\n"
    "G2Z-45R25;\n"
    "N11G1Z-50;\n"
    "G70P10Q11\n"
    "G0X100Z200\n"
    "T0100\n";

TEST(Parser, ReadsSeed004FanucG73Program) {
  const Program program = parse(kSeed004Fanuc);
  ASSERT_EQ(program.blocks.size(), 12u);
  EXPECT_EQ(wordsOf(program.blocks[3]), "G73 U5 W0 R4");
  EXPECT_TRUE(program.blocks[3].hasG(730));
  EXPECT_DOUBLE_EQ(program.blocks[3].find('R')->value, 4);
  const Block& n10 = program.blocks[program.findSequence(10).value()];
  EXPECT_EQ(n10.text, "N10G01X50Z0");
  EXPECT_EQ(wordsOf(n10), "G01 X50 Z0");
  EXPECT_TRUE(n10.hasG(10));
  EXPECT_EQ(n10.find('X')->column, 7);
  EXPECT_EQ(program.findSequence(11), 8u);
  EXPECT_DOUBLE_EQ(program.blocks[4].find('F')->value, 0.1);
}

TEST(Parser, RejectsSeed004SinumerikSyntaxClearly) {
  const std::string notInDialect = "an address letter, a number, a comment or the end of the block";
  expectParseError("R105=1 R106=0.3 R108=2 R109=7", 1, 5, notInDialect, "=");
  expectParseError("_CNAME=\"L42\"", 1, 1, notInDialect, "_");
  expectParseError("G2X31. 6Z-39. 5CR=8", 1, 8, "an address letter before the number", "6");
  expectParseError("G02Z-50CR=20", 1, 9, "a number after address C", "R");
  expectParseError("CYCLE95(\"L18\", 1.5)", 1, 2, "a number after address C", "Y");
  expectParseError("LCYC95", 1, 2, "a number after address L", "C");
  expectParseError("T1D1\nM03S800\nG03X20Z-10CR=10", 3, 12, "a number after address C", "R");
}

// --- blocks ---------------------------------------------------------------------------------

TEST(Parser, KeepsEachWordsLetterValueTextAndLocation) {
  const Block block = parse("\n  g01 x 5. z-.25").blocks.at(0);
  ASSERT_EQ(block.words.size(), 3u);
  const Word& x = block.words[1];
  EXPECT_EQ(x.letter, 'X');
  EXPECT_DOUBLE_EQ(x.value, 5.0);
  EXPECT_TRUE(x.hasDecimalPoint);
  EXPECT_EQ(x.text, "x 5.");
  EXPECT_EQ(x.line, 2);
  EXPECT_EQ(x.column, 7);
  EXPECT_DOUBLE_EQ(block.words[2].value, -0.25);
  EXPECT_EQ(block.words[2].text, "z-.25");
  EXPECT_FALSE(block.words[0].hasDecimalPoint);
}

TEST(Parser, ReadsSignedAndPointedNumbersAsWritten) {
  const Block block = parse("X54 X-0.6 U.5 W-10. Z+3 F007").blocks.at(0);
  const std::vector<double> values = {54, -0.6, 0.5, -10, 3, 7};
  ASSERT_EQ(block.words.size(), values.size());
  for (std::size_t i = 0; i < values.size(); ++i) EXPECT_DOUBLE_EQ(block.words[i].value, values[i]);
  EXPECT_EQ(block.words[4].text, "Z+3");
}

TEST(Parser, BlockTextRunsFromFirstToLastTokenOfTheBlock) {
  const Program program = parse("  N10 G01 X5 (go) ;  G00 X1  \n");
  ASSERT_EQ(program.blocks.size(), 2u);
  EXPECT_EQ(program.blocks[0].text, "N10 G01 X5 (go)");
  EXPECT_EQ(program.blocks[1].text, "G00 X1");
  EXPECT_EQ(program.blocks[1].line, 1);
}

TEST(Parser, BlockLineIsTheLineOfItsFirstToken) {
  const Program program = parse("\n\n(first) G01 X1\nZ2");
  ASSERT_EQ(program.blocks.size(), 2u);
  EXPECT_EQ(program.blocks[0].line, 3);
  EXPECT_EQ(program.blocks[1].line, 4);
}

TEST(Parser, DropsBlocksWithoutWordsOrSequenceNumber) {
  const Program program = parse(";;\n\n   \n\t\n(comment only)\n/\n/ (skipped comment)\nO0001\n");
  EXPECT_TRUE(program.blocks.empty());
  EXPECT_EQ(program.number, 1);
}

TEST(Parser, KeepsABlockWithOnlyASequenceNumber) {
  const Program program = parse("N5\nN6;");
  ASSERT_EQ(program.blocks.size(), 2u);
  EXPECT_EQ(program.blocks[0].sequence, 5);
  EXPECT_TRUE(program.blocks[0].words.empty());
  EXPECT_EQ(program.findSequence(6), 1u);
}

TEST(Parser, KeepsNAndOOutOfTheWords) {
  const Program program = parse("O0123 N4 G01 X1");
  EXPECT_EQ(program.number, 123);
  ASSERT_EQ(program.blocks.size(), 1u);
  EXPECT_EQ(program.blocks[0].sequence, 4);
  EXPECT_EQ(wordsOf(program.blocks[0]), "G01 X1");
  EXPECT_FALSE(program.blocks[0].has('N'));
  EXPECT_FALSE(program.blocks[0].has('O'));
}

TEST(Parser, ReadsLeadingZerosInSequenceNumbers) {
  EXPECT_EQ(parse("N00010 G01").blocks.at(0).sequence, 10);
  EXPECT_EQ(parse("N99999 G01").blocks.at(0).sequence, 99999);
}

TEST(Parser, ReadsProgramNumberWithOrWithoutSemicolon) {
  EXPECT_EQ(parse("O0005").number, 5);
  EXPECT_EQ(parse("O0005;\nG00 X1").number, 5);
  EXPECT_EQ(parse("%\nO0005 (MAIN)\nM30\n%\n").number, 5);
}

TEST(Parser, SkipsPercentLines) {
  const Program program = parse("%\nO0001\nG00 X1\nM30\n%\n");
  ASSERT_EQ(program.blocks.size(), 2u);
  EXPECT_EQ(program.blocks[0].line, 3);
  EXPECT_EQ(program.blocks[1].line, 4);
}

// Huazhong names its programs on the '%' line (seed 003's dialect: "%3304").
TEST(Parser, ReadsAProgramNameOnThePercentLine) {
  const Program program = parse("%3304\nG00 X1\nM30\n");
  ASSERT_TRUE(program.percentName);
  EXPECT_EQ(program.percentName->text, "%3304");
  EXPECT_EQ(program.percentName->line, 1);
  EXPECT_FALSE(parse("%\nG00 X1\n%\n").percentName);
  EXPECT_THROW(parse("%33A4\nG00 X1\n"), ParseError);
  EXPECT_THROW(parse("%3304\n%3305\nG00 X1\n"), ParseError);
}

TEST(Parser, ReadsCrLfInput) {
  const Program program = parse("%\r\nO0001\r\nN1 G00 X1\r\nN2 G01 Z-2 (a;b)\r\n%\r\n");
  EXPECT_EQ(program.number, 1);
  ASSERT_EQ(program.blocks.size(), 2u);
  EXPECT_EQ(program.blocks[0].text, "N1 G00 X1");
  EXPECT_EQ(program.blocks[1].text, "N2 G01 Z-2 (a;b)");
  EXPECT_EQ(program.blocks[1].line, 4);
  EXPECT_EQ(program.blocks[1].comment, "a;b");
}

TEST(Parser, ReadsCommentsHoldingSemicolonsAndChineseText) {
  // "G01 X5 " is 7 bytes; the comment takes bytes 8–25, so Z stands at column 27.
  const Block block = parse("G01 X5 (进刀;至 a 点) Z3").blocks.at(0);
  EXPECT_EQ(wordsOf(block), "G01 X5 Z3");
  EXPECT_EQ(block.comment, "进刀;至 a 点");
  EXPECT_EQ(block.words[2].column, 27);
}

TEST(Parser, JoinsTheCommentsOfABlock) {
  EXPECT_EQ(parse("(a) G01 (b)X1(c)").blocks.at(0).comment, "a b c");
}

TEST(Parser, ReadsBlockDelete) {
  const Program program = parse("/N10 G01 X5\n/ G00 Z1\nG00 X2");
  ASSERT_EQ(program.blocks.size(), 3u);
  EXPECT_TRUE(program.blocks[0].blockDelete);
  EXPECT_EQ(program.blocks[0].sequence, 10);
  EXPECT_EQ(program.blocks[0].text, "/N10 G01 X5");
  EXPECT_TRUE(program.blocks[1].blockDelete);
  EXPECT_FALSE(program.blocks[2].blockDelete);
}

TEST(Parser, ReadsAnEmptyProgram) {
  EXPECT_TRUE(parse("").blocks.empty());
  EXPECT_FALSE(parse("").number.has_value());
}

// --- Block and Program queries ------------------------------------------------------------------

TEST(Parser, BlockQueriesFindWordsByAddress) {
  const Block block = parse("G01 G74.1 X5 X6").blocks.at(0);
  EXPECT_EQ(block.find('X')->text, "X5");
  EXPECT_EQ(block.find('Z'), nullptr);
  std::vector<std::string> xs, zs;
  for (const Word* x : block.all('X')) xs.push_back(x->text);
  for (const Word* z : block.all('Z')) zs.push_back(z->text);
  ASSERT_EQ(xs.size(), 2u);
  EXPECT_EQ(xs[1], "X6");
  EXPECT_TRUE(zs.empty());
  EXPECT_TRUE(block.has('G'));
  EXPECT_FALSE(block.has('Z'));
  EXPECT_TRUE(block.hasG(741));
  EXPECT_TRUE(block.hasG(10));
  EXPECT_FALSE(block.hasG(1));
  EXPECT_FALSE(block.hasG(740));
}

TEST(Parser, FindSequenceGivesTheFirstMatchingBlock) {
  const Program program = parse("N1 G00\nN2 G01\nN2 G02");
  EXPECT_EQ(program.findSequence(2), 1u);
  EXPECT_FALSE(program.findSequence(3).has_value());
}

TEST(Parser, GCode10ScalesAndRounds) {
  EXPECT_EQ(gCode10(1), 10);
  EXPECT_EQ(gCode10(0), 0);
  EXPECT_EQ(gCode10(74.1), 741);
  EXPECT_EQ(gCode10(71), 710);
  EXPECT_EQ(gCode10(std::numeric_limits<double>::quiet_NaN()), -1);
  EXPECT_EQ(gCode10(1e300), -1);
}

// --- errors ---------------------------------------------------------------------------------

TEST(Parser, RejectsALetterWithoutANumber) {
  expectParseError("X;", 1, 2, "a number after address X", ";");
  expectParseError("G01 x\nZ5", 1, 6, "a number after address X", "end of line");
  expectParseError("G01 X", 1, 6, "a number after address X", "end of input");
  expectParseError("G01 X(c)5", 1, 6, "a number after address X", "a comment");
  expectParseError("G01 XZ5", 1, 6, "a number after address X", "Z");
  expectParseError("G01 X/", 1, 6, "a number after address X", "/");
}

TEST(Parser, RejectsANumberWithoutALetter) {
  expectParseError("G01 54", 1, 5, "an address letter before the number", "54");
  expectParseError("G01 X1 -2.5", 1, 8, "an address letter before the number", "-2.5");
  expectParseError("X1.\n.5", 2, 1, "an address letter before the number", ".5");
}

TEST(Parser, RejectsASecondDecimalPoint) {
  expectParseError("G01 X1.2.3", 1, 9, "a single decimal point in a number", ".");
}

TEST(Parser, RejectsNonFiniteSpellings) {
  expectParseError("Xinf", 1, 2, "a finite number after address X", "inf");
  expectParseError("G0 XNaN", 1, 5, "a finite number after address X", "NaN");
  expectParseError("Z INFINITY", 1, 3, "a finite number after address Z", "INFINITY");
  expectParseError("X-inf", 1, 2, "a finite number", "-inf");
}

TEST(Parser, RejectsAbsurdNumbers) {
  expectParseError("X1234567890.123456", 1, 2, "a number of at most 15 significant digits",
                   "1234567890.123456");
  expectParseError("X1.0000000000000000", 1, 2, "a number of at most 15 significant digits",
                   "1.0000000000000000");
  const std::string underflow = "0." + std::string(400, '0') + "1";
  expectParseError("X" + underflow, 1, 2, "a number within the range of a double", underflow);
}

TEST(Parser, AcceptsFifteenSignificantDigitsAndLeadingZeros) {
  const Block block = parse("X123456789.012345 Z-0.000000000000000000001").blocks.at(0);
  EXPECT_EQ(block.words[0].value, 123456789.012345);
  EXPECT_EQ(block.words[1].value, -1e-21);
}

TEST(Parser, RejectsCharactersOutsideTheDialect) {
  const std::string notInDialect = "an address letter, a number, a comment or the end of the block";
  expectParseError("G01 X#1", 1, 6, notInDialect, "#");
  expectParseError("G01 X[#1+2]", 1, 6, notInDialect, "[");
  expectParseError("G00\nG01 X=5", 2, 6, notInDialect, "=");
  expectParseError("G01 X1 \"", 1, 8, notInDialect, "\"");
}

TEST(Parser, RejectsAnUnclosedComment) {
  expectParseError("G00 X1\nG01 X2 (to a", 2, 13, "')' to close the comment opened at column 8",
                   "end of input");
  // Seed 001 as printed: the comment continues on the next line.
  expectParseError("G00 X176;\t(换2号刀,转速\n500r/min)", 1, 29,
                   "')' to close the comment opened at column 11", "end of line");
}

TEST(Parser, RejectsBadSequenceNumbers) {
  expectParseError("N10. G01", 1, 2, "a sequence number without sign or decimal point", "10.");
  expectParseError("N-5 G01", 1, 2, "a sequence number without sign or decimal point", "-5");
  expectParseError("N+5 G01", 1, 2, "a sequence number without sign or decimal point", "+5");
  expectParseError("N123456 G01", 1, 2, "a sequence number of at most 5 digits", "123456");
  expectParseError("N10 N20 G01", 1, 5, "one sequence number per block", "N20");
  expectParseError("N G01", 1, 3, "a number after address N", "G");
}

TEST(Parser, RejectsBadProgramNumbers) {
  expectParseError("O5.", 1, 2, "a program number without sign or decimal point", "5.");
  expectParseError("O-5", 1, 2, "a program number without sign or decimal point", "-5");
  expectParseError("O1\nG00 X1\nO2", 3, 1, "one program number per file", "O2");
  expectParseError("O;", 1, 2, "a number after address O", ";");
}

TEST(Parser, RejectsBlockDeleteInsideABlock) {
  expectParseError("G01 / X5", 1, 5, "'/' only at the start of a block", "/");
  expectParseError("N10 /G01", 1, 5, "'/' only at the start of a block", "/");
}

TEST(Parser, ErrorMessageNamesFileLineColumnExpectedAndFound) {
  EXPECT_STREQ(parseError("G00 X1\nG01 Z;").what(),
               "p.nc:2:6: expected a number after address Z, found ;");
  EXPECT_STREQ(parseError("N123456").what(),
               "p.nc:1:2: expected a sequence number of at most 5 digits, found 123456");
}

// --- properties -----------------------------------------------------------------------------

constexpr std::string_view kWordLetters = "ABCDEFGHIJKLMPQRSTUVWXYZ";  // all but N and O

struct PrintedWord {
  std::string text;
  char letter = 0;
  double value = 0;
  bool hasDecimalPoint = false;
};

// A random word printed as a programmer might: either case, optional sign, digits with at most 15
// significant ones, decimal point optional ("5.", ".5"), blanks between letter and number.
PrintedWord randomWord() {
  PrintedWord word;
  word.letter = *rc::gen::elementOf(kWordLetters);
  const bool lowerCase = *rc::gen::arbitrary<bool>();
  const std::int64_t mantissa = *rc::gen::oneOf(rc::gen::inRange<std::int64_t>(0, 1000),
                                                rc::gen::inRange<std::int64_t>(0, 1'000'000'000'000'000));
  const int decimals = *rc::gen::inRange(0, 8);
  const std::string sign = *rc::gen::element<std::string>("", "+", "-");
  const bool pointAfterWholeNumber = *rc::gen::arbitrary<bool>();
  const bool dropLeadingZero = *rc::gen::arbitrary<bool>();

  std::string digits = std::to_string(mantissa);
  if (decimals > 0) {
    if (digits.size() < static_cast<std::size_t>(decimals) + 1) {
      digits.insert(0, static_cast<std::size_t>(decimals) + 1 - digits.size(), '0');
    }
    digits.insert(digits.size() - static_cast<std::size_t>(decimals), ".");
    if (dropLeadingZero && digits.starts_with("0.")) digits.erase(0, 1);
  } else if (pointAfterWholeNumber) {
    digits += '.';
  }
  const std::string gap = *rc::gen::element<std::string>("", "", " ", "\t", "  ");
  word.text = std::string(1, lowerCase ? static_cast<char>(word.letter - 'A' + 'a') : word.letter) +
              gap + sign + digits;
  // Both sides are exact, so the quotient is the correctly rounded value of the printed decimal.
  const double magnitude = static_cast<double>(mantissa) / std::pow(10.0, decimals);
  word.value = sign == "-" ? -magnitude : magnitude;
  word.hasDecimalPoint = digits.find('.') != std::string::npos;
  return word;
}

RC_GTEST_PROP(ParserProperties, PrintedWordsParseBackToTheSameLettersAndValues, ()) {
  const int count = *rc::gen::inRange(1, 12);
  const bool withSequence = *rc::gen::arbitrary<bool>();
  const long sequence = *rc::gen::inRange(0L, 100000L);
  std::string line = withSequence ? "N" + std::to_string(sequence) : "";
  std::vector<PrintedWord> words;
  for (int i = 0; i < count; ++i) {
    words.push_back(randomWord());
    line += *rc::gen::element<std::string>("", " ", "\t", "  ") + words.back().text;
  }
  line += *rc::gen::element<std::string>("", ";", "\n", "\r\n", " ;");

  const Program program = parseProgram(line, "prop.nc");
  RC_ASSERT(program.blocks.size() == 1u);
  const Block& block = program.blocks[0];
  RC_ASSERT(block.words.size() == words.size());
  if (withSequence) RC_ASSERT(block.sequence == sequence);
  for (std::size_t i = 0; i < words.size(); ++i) {
    RC_ASSERT(block.words[i].letter == words[i].letter);
    RC_ASSERT(block.words[i].value == words[i].value);
    RC_ASSERT(block.words[i].hasDecimalPoint == words[i].hasDecimalPoint);
    RC_ASSERT(block.words[i].text == words[i].text);
  }
}

// Bytes weighted towards G-code so that inputs get past the first character often.
rc::Gen<std::string> gcodeLikeBytes() {
  const std::string alphabet = "GMXZUWNORPQF019.-+ ;\n\r\t()%/#=";
  return rc::gen::container<std::string>(
      rc::gen::weightedOneOf<char>({{4, rc::gen::elementOf(alphabet)},
                                    {1, rc::gen::arbitrary<char>()}}));
}

// A seed program with a few bytes replaced, inserted or deleted: mostly valid text that reaches
// the deeper paths (N and O checks, UTF-8 comments, number limits) random bytes rarely reach.
rc::Gen<std::string> damagedSeedProgram() {
  return rc::gen::exec([] {
    std::string text(*rc::gen::element(kSeed001O0005, kSeed003Example1, kSeed004Fanuc));
    const int damages = *rc::gen::inRange(0, 4);
    for (int i = 0; i < damages; ++i) {
      const std::size_t at = *rc::gen::inRange<std::size_t>(0, text.size());
      const char byte = *rc::gen::oneOf(rc::gen::elementOf(std::string("#(.;-%/9\n")),
                                        rc::gen::arbitrary<char>());
      switch (*rc::gen::inRange(0, 3)) {
        case 0:
          text[at] = byte;
          break;
        case 1:
          text.insert(at, 1, byte);
          break;
        default:
          text.erase(at, 1);
      }
    }
    return text;
  });
}

// Line count and the byte length of each line, so that error locations can be checked.
std::vector<std::size_t> lineLengths(std::string_view text) {
  std::vector<std::size_t> lengths{0};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'))) {
      lengths.push_back(0);
    } else if (text[i] != '\r') {
      ++lengths.back();
    }
  }
  return lengths;
}

RC_GTEST_PROP(ParserProperties, AnyBytesEitherParseOrThrowParseError, ()) {
  const std::string text = *rc::gen::oneOf(gcodeLikeBytes(), rc::gen::arbitrary<std::string>(),
                                           damagedSeedProgram());
  try {
    const Program program = parseProgram(text, "fuzz.nc");
    for (const Block& block : program.blocks) {
      RC_ASSERT(block.line >= 1);
      for (const Word& word : block.words) {
        RC_ASSERT(word.letter >= 'A' && word.letter <= 'Z');
        RC_ASSERT(word.letter != 'N' && word.letter != 'O');
        RC_ASSERT(std::isfinite(word.value));
      }
    }
  } catch (const ParseError& error) {
    const std::vector<std::size_t> lengths = lineLengths(text);
    RC_ASSERT(error.loc().file == "fuzz.nc");
    RC_ASSERT(error.loc().line >= 1);
    RC_ASSERT(static_cast<std::size_t>(error.loc().line) <= lengths.size());
    RC_ASSERT(error.loc().column >= 1);
    // +1: an error may point just past the line's last byte ("end of line", "end of input").
    RC_ASSERT(static_cast<std::size_t>(error.loc().column) <=
              lengths[static_cast<std::size_t>(error.loc().line) - 1] + 1);
    RC_ASSERT(!error.expected().empty());
    RC_ASSERT(!error.found().empty());
  }
}

}  // namespace
}  // namespace cyclecert
