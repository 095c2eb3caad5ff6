// The SINUMERIK reader (issue 16, item 1; rules SIEMENS.LEX, SIEMENS.SUB.PRINTED): each construct
// of seed 004's programs, and each error with its line and column.
#include <gtest/gtest.h>

#include <string>

#include "reference/model/program.h"
#include "reference/siemens/siemens_parser.h"

namespace cyclecert {
namespace {

SiemensBlock onlyBlock(const std::string& text) {
  const SiemensProgram p = parseSiemensProgram(text, "t.mpf");
  EXPECT_EQ(p.main.blocks.size(), 1u) << text;
  return p.main.blocks.at(0);
}

// The error's location and what it says was expected.
struct ErrorAt {
  int line = 0, column = 0;
  std::string message;
};
ErrorAt errorOf(const std::string& text) {
  try {
    parseSiemensProgram(text, "t.mpf");
  } catch (const ParseError& e) {
    return {e.loc().line, e.loc().column, e.what()};
  }
  return {0, 0, "no error"};
}

void expectError(const std::string& text, int line, int column, const std::string& inMessage) {
  const ErrorAt e = errorOf(text);
  EXPECT_EQ(e.line, line) << e.message;
  EXPECT_EQ(e.column, column) << e.message;
  EXPECT_NE(e.message.find(inMessage), std::string::npos) << e.message;
  EXPECT_NE(e.message.find("t.mpf:"), std::string::npos) << e.message;
}

TEST(SiemensParser, WordsWithoutSpacesAreSplitAtEachAddress) {
  const SiemensBlock b = onlyBlock("G3X20.8Z-25.8K-15I0\n");
  ASSERT_EQ(b.words.size(), 5u);
  EXPECT_EQ(b.words[0].address, "G");
  EXPECT_EQ(b.words[0].value, 3);
  EXPECT_EQ(b.words[1].address, "X");
  EXPECT_DOUBLE_EQ(b.words[1].value, 20.8);
  EXPECT_EQ(b.words[2].text, "Z-25.8");
  EXPECT_EQ(b.words[2].column, 8);
  EXPECT_DOUBLE_EQ(b.words[3].value, -15);
  EXPECT_EQ(b.words[4].address, "I");
}

TEST(SiemensParser, ASemicolonStartsACommentToTheEndOfTheLine) {
  const SiemensProgram p = parseSiemensProgram("G0X50Z2 ; to the start; Z5\n; a comment line\nG1Z0\n", "t.mpf");
  ASSERT_EQ(p.main.blocks.size(), 2u);  // the comment line is no block; "Z5" after ';' is no word
  EXPECT_EQ(p.main.blocks[0].words.size(), 3u);
  EXPECT_EQ(p.main.blocks[0].text, "G0X50Z2");
  EXPECT_EQ(p.main.blocks[1].line, 3);
}

TEST(SiemensParser, NamedAddressesTakeTheirValueAfterTheEqualsSign) {
  const SiemensBlock b = onlyBlock("G2X31.6Z-39.5CR=8 CHF=1.5 CHR=2 RND=0.5\n");
  ASSERT_NE(b.find("CR"), nullptr);
  EXPECT_EQ(b.find("CR")->value, 8);
  EXPECT_EQ(b.find("CR")->text, "CR=8");
  EXPECT_EQ(b.find("CHF")->value, 1.5);
  EXPECT_EQ(b.find("CHR")->value, 2);
  EXPECT_EQ(b.find("RND")->value, 0.5);
}

TEST(SiemensParser, SeveralRParameterAssignmentsOnALine) {
  const SiemensBlock b = onlyBlock("R105=1 R106=0.3 R108=2 R109=7\n");
  ASSERT_EQ(b.rAssignments.size(), 4u);
  EXPECT_EQ(b.rAssignments[0].number, 105);
  EXPECT_EQ(b.rAssignments[0].value, 1);
  EXPECT_EQ(b.rAssignments[1].number, 106);
  EXPECT_DOUBLE_EQ(b.rAssignments[1].value, 0.3);
  EXPECT_EQ(b.rAssignments[3].column, 24);
}

TEST(SiemensParser, AStringVariableTakesTheSubprogramsName) {
  const SiemensBlock b = onlyBlock("_CNAME=\"L42\"\n");
  ASSERT_EQ(b.strings.size(), 1u);
  EXPECT_EQ(b.strings[0].name, "_CNAME");
  EXPECT_EQ(b.strings[0].value, "L42");
}

TEST(SiemensParser, ACycleWithoutArgumentsAndOneWithEmptyArguments) {
  EXPECT_EQ(onlyBlock("LCYC95\n").cycle->name, "LCYC95");
  EXPECT_FALSE(onlyBlock("LCYC95\n").cycle->withArguments);
  const SiemensBlock b = onlyBlock("CYCLE95(\"L18\", 1.5, , 0.3,)\n");
  ASSERT_TRUE(b.cycle);
  EXPECT_EQ(b.cycle->name, "CYCLE95");
  ASSERT_EQ(b.cycle->arguments.size(), 5u);
  EXPECT_EQ(*b.cycle->arguments[0].text, "L18");
  EXPECT_EQ(*b.cycle->arguments[1].number, 1.5);
  EXPECT_TRUE(b.cycle->arguments[2].empty());
  EXPECT_EQ(*b.cycle->arguments[3].number, 0.3);
  EXPECT_TRUE(b.cycle->arguments[4].empty());
}

TEST(SiemensParser, SubprogramCallsToolWordsSequenceNumbersAndKeywords) {
  const SiemensBlock call = onlyBlock("N10 L42\n");
  EXPECT_EQ(call.sequence, 10);
  ASSERT_TRUE(call.subprogramCall);
  EXPECT_EQ(call.subprogramCall->text, "L42");
  const SiemensBlock tool = onlyBlock("T1D1\n");
  EXPECT_EQ(tool.find("T")->value, 1);
  EXPECT_EQ(tool.find("D")->value, 1);
  EXPECT_TRUE(onlyBlock("DIAMON\n").hasKeyword("DIAMON"));
  EXPECT_TRUE(onlyBlock("RET\n").endsProgram());
  EXPECT_TRUE(onlyBlock("M17\n").endsProgram());
  EXPECT_TRUE(onlyBlock("M02\n").endsProgram());
  EXPECT_FALSE(onlyBlock("M05\n").endsProgram());
}

TEST(SiemensParser, ASubprogramPrintedAfterTheMainProgramsEnd) {
  const SiemensProgram p = parseSiemensProgram("G0X50Z2\nM02\nL42.spf\nG1X0Z0\nG1Z-10\nM02\n", "t.mpf");
  ASSERT_EQ(p.main.blocks.size(), 2u);
  ASSERT_EQ(p.printed.size(), 1u);
  EXPECT_EQ(p.printed[0].name, "L42");
  EXPECT_EQ(p.printed[0].headingLine, 3);
  ASSERT_EQ(p.printed[0].body.blocks.size(), 3u);
  EXPECT_EQ(p.printed[0].body.blocks[0].line, 4);
}

TEST(SiemensParser, CrLfLineEndsAndLowerCaseAreRead) {
  const SiemensProgram p = parseSiemensProgram("g0x50z2\r\nm02\r\nl18.SPF\r\ng1x0z0\r\nret\r\n", "t.mpf");
  ASSERT_EQ(p.printed.size(), 1u);
  EXPECT_EQ(p.printed[0].name, "L18");
  EXPECT_EQ(p.main.blocks[0].find("X")->value, 50);
}

TEST(SiemensParser, ErrorsNameLineColumnAndWhatWasExpected) {
  // The seed's OCR: a space inside a number leaves a number without an address.
  expectError("G1X0Z0\nG3X20. 8Z-25.8\n", 2, 8, "expected an address");
  expectError("G1 X\n", 1, 5, "a number after address X, found end of line");
  expectError("R105 1\n", 1, 6, "'=' after R105");
  expectError("R105=\n", 1, 6, "a number after R105=");
  expectError("G2X10CR8\n", 1, 8, "'=' after CR");
  expectError("_CNAME=L42\n", 1, 8, "a subprogram name in double quotes");
  expectError("_CNAME=\"L42\n", 1, 12, "'\"' to close the string");
  expectError("CYCLE95(\"L18\" 1.5)\n", 1, 15, "',' or ')' after argument 1 of CYCLE95");
  expectError("G1 #5\n", 1, 4, "an address");
  expectError("G1 Y5\n", 1, 4, "an address (G X Z I K F S T D M N L)");
  expectError("X=5\n", 1, 2, "a number right after address X");
  expectError("N1.5 G1\n", 1, 2, "a block number N0…N9999");
  expectError("G1 X1.2.3\n", 1, 8, "a single decimal point");
  expectError("L42.spf\nG1X0Z0\n", 1, 1, "the program's end (M02, M30, M17 or RET) before the subprogram heading");
  expectError("M02\nG0X5\n", 2, 1, "nothing after the end at line 1 but a subprogram heading");
}

// The lexer scans plain numbers itself and leaves the rest to the FANUC lexer (siemens_lexer.cpp):
// both read the same numbers, and what the FANUC reader refuses keeps its message and column.
TEST(SiemensParser, NumbersAreReadByTheFanucReadersRules) {
  const SiemensBlock b = onlyBlock("G1 X+1. Z-.5 F007\n");
  ASSERT_EQ(b.words.size(), 4u);
  EXPECT_EQ(b.words[1].text, "X+1.");
  EXPECT_EQ(b.words[1].value, 1);
  EXPECT_EQ(b.words[2].text, "Z-.5");
  EXPECT_EQ(b.words[2].value, -0.5);
  EXPECT_EQ(b.words[3].value, 7);
  expectError("G1 X-\n", 1, 6, "a digit");
  expectError("G1 X-.Z1\n", 1, 7, "a digit");
  expectError("G1 X-inf\n", 1, 5, "a finite number");
  expectError("G1 X1.2.3\n", 1, 8, "a single decimal point");
  expectError("G1 X1234567890.123456\n", 1, 5, "a number of at most 15 significant digits");
}

TEST(SiemensParser, ASubprogramGivenOnItsOwnHasNoHeadings) {
  EXPECT_EQ(parseSiemensSubprogram("G1X0Z0\nZ-5\nM17\n", "L1.spf").blocks.size(), 3u);
  try {
    parseSiemensSubprogram("G1X0Z0\nM17\nL2.spf\n", "L1.spf");
    FAIL() << "a heading inside a subprogram file was accepted";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.loc().line, 3);
    EXPECT_NE(std::string(e.what()).find("a heading NAME.spf only in a main program"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cyclecert
