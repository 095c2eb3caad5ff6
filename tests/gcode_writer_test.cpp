// The G-code writer: what it writes, and that parsing what it writes gives back the same words.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "reference/gcode/parser.h"
#include "reference/gcode/writer.h"

namespace cyclecert {
namespace {

// Same blocks, N numbers, block-delete flags and words (letter, value exactly, decimal point).
void expectSameWords(const Program& a, const Program& b) {
  EXPECT_EQ(a.number, b.number);
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    SCOPED_TRACE("block " + std::to_string(i) + ": " + a.blocks[i].text);
    EXPECT_EQ(a.blocks[i].sequence, b.blocks[i].sequence);
    EXPECT_EQ(a.blocks[i].blockDelete, b.blocks[i].blockDelete);
    ASSERT_EQ(a.blocks[i].words.size(), b.blocks[i].words.size());
    for (std::size_t k = 0; k < a.blocks[i].words.size(); ++k) {
      const Word& x = a.blocks[i].words[k];
      const Word& y = b.blocks[i].words[k];
      EXPECT_EQ(x.letter, y.letter);
      EXPECT_EQ(x.value, y.value) << x.text << " vs " << y.text;
      EXPECT_EQ(x.hasDecimalPoint, y.hasDecimalPoint) << x.text << " vs " << y.text;
    }
  }
}

void expectRoundTrip(const std::string& text) {
  const Program first = parseProgram(text, "source.nc");
  const std::string written = writeProgram(first);
  SCOPED_TRACE(written);
  expectSameWords(first, parseProgram(written, "written.nc"));
}

TEST(GcodeWriter, WritesOneBlockPerLineWithoutComments) {
  const Program p = parseProgram("O0005;\n%\nG00 X54 Z3 (start);\n/N11 G1 x10. Z-2.000 F0.2 T0202;\nN20 G74.1 R0.5;\n", "p.nc");
  EXPECT_EQ(writeProgram(p), "O0005;\nG00 X54 Z3;\n/N11 G1 X10. Z-2.000 F0.2 T0202;\nN20 G74.1 R0.5;\n");
}

TEST(GcodeWriter, AWordWhoseTextNoLongerSaysItsValueIsFormatted) {
  Program p = parseProgram("G1 Z-2.000 T0202;", "p.nc");
  p.blocks[0].words[1].value = 7.5;  // changed without its text
  EXPECT_EQ(writeBlock(p.blocks[0]), "G1 Z7.5 T0202");
  p.blocks[0].words[0].hasDecimalPoint = true;
  EXPECT_EQ(formatWord(p.blocks[0].words[0]), "G1.");
}

TEST(GcodeWriter, NumbersArePlainDecimalsNeverExponents) {
  EXPECT_EQ(formatNumber(0.0000001, false), "0.0000001");
  EXPECT_EQ(formatNumber(123456789, false), "123456789");
  EXPECT_EQ(formatNumber(-0.0, false), "0");
  EXPECT_EQ(formatNumber(54, true), "54.");
  EXPECT_EQ(formatNumber(-0.6, true), "-0.6");
  EXPECT_EQ(formatNumber(0.1 + 0.2, false), "0.3");  // 0.30000000000000004 has 17 digits: rounded to 15
  EXPECT_EQ(formatNumber(54 / 25.4, false), "2.1259842519685");
  EXPECT_EQ(formatWord(makeWord('G', 2)), "G02");
  EXPECT_EQ(formatWord(makeWord('M', 30)), "M30");
}

TEST(GcodeWriter, ComputedValuesAreReadableAndClose) {
  for (double v : {1 / 3.0, 2 * std::sqrt(2.0), -1e-12, 99999.99999999, 54 / 25.4 * 7}) {
    const std::string text = "X" + formatNumber(v, true) + ";";
    const Program p = parseProgram(text, "v.nc");
    EXPECT_NEAR(p.blocks[0].words[0].value, v, std::abs(v) * 1e-14 + 1e-300) << text;
  }
}

TEST(GcodeWriter, RoundTripKeepsEveryWord) {
  expectRoundTrip(
      "G00 X54 Z3;\nG71 U1.5 R1;\nG71 P11 Q20 U0.6 W0.1 F100;\nN11 G00 X0;\nN12 G01 X10 Z-2;\nN13 Z-20;\n"
      "N14 G02 U10 W-5 R5;\nN15 G01 W-10;\nN16 G03 U14 W-7 R7;\nN17 G01 Z-52;\nN18 U10 W-10;\nN19 W-25;\n"
      "N20 X52;\nG70 P11 Q20;\nM30;\n");
  expectRoundTrip("G00 X.5 Z-.25 I-0.0061 K123456.789012345 F0.0002;\nG00 X+5 Z-0;\n/N99999 M3 S500 T0202;\n");
}

// Every program of the corpus (tests run from the project root; skipped elsewhere).
TEST(GcodeWriter, RoundTripOfTheCorpus) {
  const std::filesystem::path corpus = "corpus";
  if (!std::filesystem::exists(corpus)) GTEST_SKIP() << "run from the project root to read corpus/";
  int programs = 0;
  for (const auto& entry : std::filesystem::directory_iterator(corpus)) {
    if (entry.path().extension() != ".nc") continue;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    Program p;
    try {
      p = parseProgram(text.str(), entry.path().string());
    } catch (const ParseError&) {
      continue;  // SINUMERIK programs are not in the dialect; the parser's tests cover them
    }
    SCOPED_TRACE(entry.path().string());
    expectSameWords(p, parseProgram(writeProgram(p), "written.nc"));
    ++programs;
  }
  EXPECT_GT(programs, 3);
}

}  // namespace
}  // namespace cyclecert
