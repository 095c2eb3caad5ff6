// The tokenizer on its own: token kinds, exact source text, 1-based line and byte column, and the
// lexical errors with their location and wording.
#include "reference/gcode/lexer.h"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "reference/model/program.h"

namespace cyclecert {
namespace {

using K = TokenKind;

std::vector<TokenKind> kindsOf(std::string_view source) {
  std::vector<TokenKind> kinds;
  for (const Token& token : tokenize(source, "t.nc")) kinds.push_back(token.kind);
  return kinds;
}

std::vector<std::string> textsOf(std::string_view source) {
  std::vector<std::string> texts;
  for (const Token& token : tokenize(source, "t.nc")) texts.emplace_back(token.text);
  return texts;
}

// Tokenizes source expecting a ParseError, and returns it.
ParseError lexError(std::string_view source) {
  try {
    tokenize(source, "t.nc");
  } catch (const ParseError& error) {
    return error;
  }
  ADD_FAILURE() << "no ParseError for: " << source;
  return ParseError({}, "", "");
}

void expectLexError(std::string_view source, int line, int column, const std::string& expected,
                    const std::string& found) {
  SCOPED_TRACE(std::string(source));
  const ParseError error = lexError(source);
  EXPECT_EQ(error.loc().file, "t.nc");
  EXPECT_EQ(error.loc().line, line);
  EXPECT_EQ(error.loc().column, column);
  EXPECT_EQ(error.expected(), expected);
  EXPECT_EQ(error.found(), found);
}

// --- words and numbers -----------------------------------------------------------------------

TEST(Lexer, SplitsWordsWrittenWithoutSpaces) {
  EXPECT_EQ(textsOf("G71U1.5R1P11Q20"),
            (std::vector<std::string>{"G", "71", "U", "1.5", "R", "1", "P", "11", "Q", "20", ""}));
  EXPECT_EQ(kindsOf("G71U1.5"),
            (std::vector<TokenKind>{K::Letter, K::Number, K::Letter, K::Number, K::EndOfInput}));
}

TEST(Lexer, ReadsEveryNumberForm) {
  EXPECT_EQ(textsOf("X54 X-0.6 U.5 W-10. Z+3 X007"),
            (std::vector<std::string>{"X", "54", "X", "-0.6", "U", ".5", "W", "-10.", "Z", "+3",
                                      "X", "007", ""}));
}

TEST(Lexer, GivesLettersInUpperCaseButKeepsTheSourceText) {
  const std::vector<Token> tokens = tokenize("g1x2", "t.nc");
  EXPECT_EQ(tokens[0].letter(), 'G');
  EXPECT_EQ(tokens[0].text, "g");
  EXPECT_EQ(tokens[2].letter(), 'X');
}

TEST(Lexer, AllowsBlanksBetweenLetterAndNumber) {
  const std::vector<Token> tokens = tokenize("X \t54", "t.nc");
  ASSERT_EQ(tokens.size(), 3u);
  EXPECT_EQ(tokens[0].column, 1);
  EXPECT_EQ(tokens[1].text, "54");
  EXPECT_EQ(tokens[1].column, 4);
}

TEST(Lexer, CountsColumnsFromOneInBytes) {
  const std::vector<Token> tokens = tokenize("G01  X5", "t.nc");
  EXPECT_EQ(tokens[0].column, 1);
  EXPECT_EQ(tokens[1].column, 2);
  EXPECT_EQ(tokens[2].column, 6);
  EXPECT_EQ(tokens[3].column, 7);
  EXPECT_EQ(tokens[2].offset, 5u);
}

TEST(Lexer, EndOfInputRepeatsOnceReached) {
  Lexer lexer("X1", "t.nc");
  lexer.next();
  lexer.next();
  EXPECT_EQ(lexer.next().kind, K::EndOfInput);
  EXPECT_EQ(lexer.next().kind, K::EndOfInput);
}

// --- block ends and lines -----------------------------------------------------------------------

TEST(Lexer, SemicolonAndLineEndsEndBlocks) {
  EXPECT_EQ(kindsOf("X1;Y2\nZ3"),
            (std::vector<TokenKind>{K::Letter, K::Number, K::EndOfBlock, K::Letter, K::Number,
                                    K::EndOfBlock, K::Letter, K::Number, K::EndOfInput}));
}

TEST(Lexer, NumbersLinesFromOneAndRestartsColumns) {
  const std::vector<Token> tokens = tokenize("G1\n\n  X2", "t.nc");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[2].line, 1);  // the first '\n'
  EXPECT_EQ(tokens[2].column, 3);
  EXPECT_EQ(tokens[3].line, 2);  // the blank line's '\n'
  EXPECT_EQ(tokens[3].column, 1);
  EXPECT_EQ(tokens[4].line, 3);
  EXPECT_EQ(tokens[4].column, 3);
}

TEST(Lexer, TreatsCrLfAsOneLineEnd) {
  const std::vector<Token> tokens = tokenize("G1\r\nX2\r\n", "t.nc");
  ASSERT_EQ(tokens.size(), 7u);
  EXPECT_EQ(tokens[2].kind, K::EndOfBlock);
  EXPECT_EQ(tokens[2].text, "\r\n");
  EXPECT_EQ(tokens[3].line, 2);
  EXPECT_EQ(tokens[3].column, 1);
  EXPECT_EQ(tokens[5].text, "\r\n");
  EXPECT_EQ(tokens[6].line, 3);
}

TEST(Lexer, TreatsALoneCarriageReturnAsALineEnd) {
  const std::vector<Token> tokens = tokenize("G1\rX2", "t.nc");
  EXPECT_EQ(tokens[2].text, "\r");
  EXPECT_EQ(tokens[3].line, 2);
}

TEST(Lexer, SkipsAByteOrderMark) {
  const std::vector<Token> tokens = tokenize("\xEF\xBB\xBFG1", "t.nc");
  EXPECT_EQ(tokens[0].text, "G");
  EXPECT_EQ(tokens[0].column, 1);
}

// --- comments -------------------------------------------------------------------------------

TEST(Lexer, ReadsACommentAsOneToken) {
  const std::vector<Token> tokens = tokenize("G1 (tool 2; fast) X2", "t.nc");
  ASSERT_EQ(tokens.size(), 6u);
  EXPECT_EQ(tokens[2].kind, K::Comment);
  EXPECT_EQ(tokens[2].text, "(tool 2; fast)");
  EXPECT_EQ(tokens[2].commentBody(), "tool 2; fast");  // ';' inside a comment ends nothing
  EXPECT_EQ(tokens[3].column, 19);
}

TEST(Lexer, CountsTheBytesOfUtf8CommentsInColumns) {
  // "主轴" is 6 bytes, so the comment takes columns 1–8 and X stands at column 10.
  const std::vector<Token> tokens = tokenize("(主轴) X5", "t.nc");
  EXPECT_EQ(tokens[0].commentBody(), "主轴");
  EXPECT_EQ(tokens[1].column, 10);
}

TEST(Lexer, DoesNotNestComments) {
  // The first ')' closes the comment; the second one is a stray character.
  expectLexError("(a (b) c)", 1, 9, "an address letter, a number, a comment or the end of the block",
                 ")");
}

TEST(Lexer, RejectsACommentUnclosedAtTheLineEnd) {
  expectLexError("G01 (abc\nX5", 1, 9, "')' to close the comment opened at column 5", "end of line");
  expectLexError("G01 (abc\r\nX5", 1, 9, "')' to close the comment opened at column 5",
                 "end of line");
}

TEST(Lexer, RejectsACommentUnclosedAtTheEndOfInput) {
  expectLexError("X1\n(主轴", 2, 8, "')' to close the comment opened at column 1", "end of input");
}

// --- '%', '/', program number -----------------------------------------------------------------

TEST(Lexer, ReadsPercentLinesAsProgramMarkers) {
  EXPECT_EQ(kindsOf("%\nO0005;\n  % \n"),
            (std::vector<TokenKind>{K::ProgramMarker, K::EndOfBlock, K::Letter, K::Number,
                                    K::EndOfBlock, K::EndOfBlock, K::ProgramMarker, K::EndOfBlock,
                                    K::EndOfInput}));
}

TEST(Lexer, RejectsPercentSharingItsLine) {
  expectLexError("G01 %", 1, 5, "'%' only on a line of its own", "%");
  expectLexError("% G01", 1, 3, "the end of the line after '%'", "G");
  expectLexError("%;", 1, 2, "the end of the line after '%'", ";");
}

TEST(Lexer, ReadsSlashAsBlockDelete) {
  EXPECT_EQ(kindsOf("/N10"), (std::vector<TokenKind>{K::BlockDelete, K::Letter, K::Number,
                                                     K::EndOfInput}));
}

// --- lexical errors -------------------------------------------------------------------------

TEST(Lexer, RejectsCharactersOutsideTheDialect) {
  const std::string expected = "an address letter, a number, a comment or the end of the block";
  expectLexError("#1=5", 1, 1, expected, "#");
  expectLexError("G01 X[1]", 1, 6, expected, "[");
  expectLexError("R105=1", 1, 5, expected, "=");  // SINUMERIK R parameters
  expectLexError("_CNAME=\"L42\"", 1, 1, expected, "_");
  expectLexError("X1\nG01 主", 2, 5, expected, "主");  // a whole UTF-8 character
  expectLexError("G1\x01", 1, 3, expected, "byte 0x01");
  expectLexError("G1\xFF", 1, 3, expected, "byte 0xFF");  // not UTF-8
  expectLexError("G1\xE4\xB8", 1, 3, expected, "byte 0xE4");  // UTF-8 cut short
  expectLexError("G1\fX1", 1, 3, expected, "byte 0x0C");
}

TEST(Lexer, RejectsASecondDecimalPoint) {
  expectLexError("X1.2.3", 1, 5, "a single decimal point in a number", ".");
  expectLexError("X1..", 1, 4, "a single decimal point in a number", ".");
}

TEST(Lexer, RejectsASignOrPointWithoutDigits) {
  expectLexError("X-", 1, 3, "a digit", "end of input");
  expectLexError("X-;", 1, 3, "a digit", ";");
  expectLexError("X.\n", 1, 3, "a digit", "end of line");
  expectLexError("X+-1", 1, 3, "a digit", "-");
  expectLexError("X- 5", 1, 3, "a digit", "a space");
}

TEST(Lexer, RejectsSignedNonFiniteSpellings) {
  expectLexError("X-inf", 1, 2, "a finite number", "-inf");
  expectLexError("G0 Z+NaN", 1, 5, "a finite number", "+NaN");
}

TEST(Lexer, ErrorMessageNamesFileLineAndColumn) {
  EXPECT_STREQ(lexError("G1\nX#").what(),
               "t.nc:2:2: expected an address letter, a number, a comment or the end of the block, "
               "found #");
}

// --- helpers -------------------------------------------------------------------------------

TEST(Lexer, DescribesSourceCharactersForMessages) {
  EXPECT_EQ(describeSourceAt("ab", 1), "b");
  EXPECT_EQ(describeSourceAt("ab", 2), "end of input");
  EXPECT_EQ(describeSourceAt("a\n", 1), "end of line");
  EXPECT_EQ(describeSourceAt("a\r\n", 1), "end of line");
  EXPECT_EQ(describeSourceAt(" ", 0), "a space");
  EXPECT_EQ(describeSourceAt("\t", 0), "a tab");
  EXPECT_EQ(describeSourceAt("→", 0), "→");
  EXPECT_EQ(describeSourceAt("\xF0\x9F\x94\xA7", 0), "\xF0\x9F\x94\xA7");  // 4-byte sequence
  EXPECT_EQ(describeSourceAt("\xC0\x80", 0), "byte 0xC0");                // overlong NUL
  EXPECT_EQ(describeSourceAt("\xED\xA0\x80", 0), "byte 0xED");            // surrogate
  EXPECT_EQ(describeSourceAt(std::string_view("\0", 1), 0), "byte 0x00");
}

TEST(Lexer, RecognisesNonFiniteSpellings) {
  EXPECT_EQ(nonFiniteSpellingAt("inf", 0), "inf");
  EXPECT_EQ(nonFiniteSpellingAt("X-Infinity", 1), "-Infinity");
  EXPECT_EQ(nonFiniteSpellingAt("nanZ5", 0), "nan");
  EXPECT_EQ(nonFiniteSpellingAt("INFZ5", 0), "INF");
  EXPECT_EQ(nonFiniteSpellingAt("in", 0), "");
  EXPECT_EQ(nonFiniteSpellingAt("I5", 0), "");
  EXPECT_EQ(nonFiniteSpellingAt("x", 5), "");
}

// readNumber's value of a plain decimal is from_chars' to the bit (its fast path divides the digits
// by a power of ten): random numbers of up to 15 significant digits, every place of the point, both
// signs, leading and trailing zeros.
TEST(Lexer, ReadsPlainDecimalsToTheBitAsFromChars) {
  std::mt19937_64 random(20261127);
  for (int n = 0; n < 200000; ++n) {
    const int digits = 1 + static_cast<int>(random() % 17);
    std::string text;
    const int sign = static_cast<int>(random() % 3);
    if (sign == 1) text += '-';
    if (sign == 2) text += '+';
    const int point = static_cast<int>(random() % (digits + 2)) - 1;  // -1: none
    for (int d = 0; d < digits; ++d) {
      if (d == point) text += '.';
      text += static_cast<char>('0' + random() % 10);
    }
    if (point == digits) text += '.';
    const NumberReading r = readNumber(text);
    const std::string_view body = text[0] == '+' ? std::string_view(text).substr(1) : std::string_view(text);
    double expected = 0;
    std::from_chars(body.data(), body.data() + body.size(), expected);
    if (significantDigits(text) > kMostSignificantDigits) {
      EXPECT_NE(r.expected, nullptr) << text;
      continue;
    }
    ASSERT_EQ(r.expected, nullptr) << text;
    ASSERT_EQ(std::memcmp(&r.value, &expected, sizeof expected), 0) << text << " " << r.value << " " << expected;
  }
  EXPECT_EQ(std::signbit(readNumber("-0.0").value), true);
  EXPECT_NE(readNumber(".").expected, nullptr);
  EXPECT_NE(readNumber("1.2.3").expected, nullptr);
  EXPECT_EQ(readNumber("0.0000000000000000000000005").value, 5e-25);  // past the fast path's 22 decimals
}

// leadingPlainNumber: the plain number a text starts with (its end where the plain number ends),
// its value only within the fast reading's terms; none before a second point.
TEST(Lexer, ReadsTheLeadingPlainNumber) {
  const LeadingNumber n = leadingPlainNumber("-12.5Z3");
  EXPECT_EQ(n.length, 5u);
  EXPECT_EQ(n.value, -12.5);
  EXPECT_EQ(leadingPlainNumber("+.5)").length, 3u);
  EXPECT_EQ(leadingPlainNumber("7.,").value, 7.0);
  EXPECT_EQ(leadingPlainNumber("1.2.3").length, 0u);  // the FANUC lexer's to refuse
  EXPECT_EQ(leadingPlainNumber("-.X").length, 0u);
  EXPECT_EQ(leadingPlainNumber("").length, 0u);
  const LeadingNumber many = leadingPlainNumber("1234567890123456 ");  // 16 significant digits
  EXPECT_EQ(many.length, 16u);
  EXPECT_FALSE(many.value);
  const LeadingNumber fine = leadingPlainNumber("0.0000000000000000000000005");  // 25 decimals
  EXPECT_EQ(fine.length, 27u);
  EXPECT_FALSE(fine.value);
}

}  // namespace
}  // namespace cyclecert
