// A SINUMERIK program is read twice per judged case — by the reference engine and by the oracles'
// reading (harness/judge/siemens_reading.h) — and parsed once (issue 16's throughput): the Siemens runner
// reads its texts through the parsers it is given (SiemensRunInput::parsers), and the harness's
// (siemensRunInputFor) keep what they parsed. What they share must be the same parse, a text that
// does not parse must fail every time, and a subprogram no cycle names must stay unparsed.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "harness/engines/reference_plan.h"
#include "reference/model/program.h"
#include "reference/profiles/default_profile.h"
#include "reference/siemens/siemens_contour.h"
#include "reference/siemens/siemens_parser.h"
#include "reference/siemens/siemens_runner.h"

namespace cyclecert {
namespace {

const char* const kMain = "G0X50Z2\n_CNAME=\"L42\"\nR105=1 R106=0.3 R108=2 R109=7\nR110=1.5 R111=0.4 R112=0.25\nLCYC95\nM02\n";
const char* const kContour = "G1X20Z0\nZ-20\nX40\nZ-30\nM17\n";

PlanRequest requestFor(const std::string& main, const std::string& contour) {
  PlanRequest r;
  r.programText = main;
  r.file = "case.json#/program";
  r.profile = "sinumerik-802s";
  r.subprograms.push_back({"L42", contour, "case.json#/subprograms/L42"});
  return r;
}

TEST(SiemensSharedParse, TheSameTextIsParsedOnceAndSharedAnotherIsParsedAgain) {
  const PlanRequest request = requestFor(kMain, kContour);
  const SiemensRunInput first = siemensRunInputFor(request), second = siemensRunInputFor(request);
  const auto a = first.parsers.program(request.programText, request.file);
  const auto b = second.parsers.program(request.programText, request.file);
  EXPECT_EQ(a.get(), b.get());
  const auto other = second.parsers.program(std::string(kMain) + "; another\n", request.file);
  EXPECT_NE(a.get(), other.get());
  EXPECT_NE(a.get(), second.parsers.program(request.programText, "elsewhere.mpf").get());  // errors name the file
  const auto sub = first.parsers.subprogram(kContour, "case.json#/subprograms/L42");
  EXPECT_EQ(sub.get(), second.parsers.subprogram(kContour, "case.json#/subprograms/L42").get());
  EXPECT_EQ(sub->blocks.size(), 5u);
}

TEST(SiemensSharedParse, ATextThatDoesNotParseFailsEveryTime) {
  const SiemensRunInput input = siemensRunInputFor(requestFor(kMain, kContour));
  for (int i = 0; i < 2; ++i) EXPECT_THROW(input.parsers.program("G0X50Z2\nR105=\n", "bad.mpf"), ParseError) << i;
}

// The runner plans what its parser gives, not its own parse of the text: the parse is shared, not
// repeated.
TEST(SiemensSharedParse, TheRunnerReadsTheProgramItsParserGives) {
  SiemensRunInput input{"G0X50Z2\nM02\n", "t.mpf", {}, "", ToolOffset{}};
  input.parsers.program = [](std::string_view, const std::string& file) {
    return std::make_shared<const SiemensProgram>(parseSiemensProgram("G0X50Z2\nG1X40Z0\nM02\n", file));
  };
  const Toolpath path = planSiemensProgram(input, *findProfile("sinumerik-802s"));
  ASSERT_EQ(path.moves.size(), 1u);
  EXPECT_NEAR(path.moves[0].to.x, 20, 1e-12);  // X40, a diameter: the path is drawn in radius
}

// As before the parses were shared: a subprogram is parsed when a cycle first names it, so one that
// nothing names may be malformed.
TEST(SiemensSharedParse, ASubprogramNoCycleNamesIsNotParsed) {
  PlanRequest request = requestFor(kMain, kContour);
  request.subprograms.push_back({"L99", "G1X0Z0\nR105=\n", "case.json#/subprograms/L99"});
  const Toolpath path = planWithReference(request);
  EXPECT_FALSE(path.alarm);
  EXPECT_FALSE(path.moves.empty());
  request.subprograms.front().text = "G1X0Z0\nR105=\n";  // now the one LCYC95 reads
  EXPECT_THROW(planWithReference(request), ParseError);
}

// The contour a cycle reads from a kept subprogram parse is read once too: the harness's reader
// (siemensRunInputFor) answers a second run of the same text — the judge's reading after the
// engine's — with the contour it read the first time, the same segments.
TEST(SiemensSharedParse, TheContourOfAKeptParseIsReadOnceAnotherModalStateReadsItAgain) {
  const PlanRequest request = requestFor(kMain, kContour);
  const SiemensRunInput input = siemensRunInputFor(request);
  const auto blocks = input.parsers.subprogram(kContour, "case.json#/subprograms/L42");
  const SiemensContour first = input.parsers.contour("L42", blocks, SiemensModal{});
  const SiemensContour again = siemensRunInputFor(request).parsers.contour("L42", blocks, SiemensModal{});
  ASSERT_EQ(first.segments.size(), 3u);  // (0, 10) → (−20, 10) → (−20, 20) → (−30, 20), x radius
  ASSERT_EQ(again.segments.size(), first.segments.size());
  for (std::size_t i = 0; i < first.segments.size(); ++i) {
    EXPECT_EQ(again.segments[i].from, first.segments[i].from) << i;
    EXPECT_EQ(again.segments[i].to, first.segments[i].to) << i;
  }
  EXPECT_NEAR(first.segments[1].to.x, 20, 1e-12);
  // Read with another modal state (G22: X a radius) the same blocks give another contour.
  const SiemensContour inRadius = input.parsers.contour("L42", blocks, SiemensModal{0, false});
  ASSERT_EQ(inRadius.segments.size(), 3u);
  EXPECT_NEAR(inRadius.segments[1].to.x, 40, 1e-12);
}

// The runner asks its contour reader only for a subprogram its subprogram parser read: one printed
// after the main program is read by readSiemensContour from the program's own parse.
TEST(SiemensSharedParse, TheRunnerAsksItsContourReaderOnlyForAKeptParse) {
  int asked = 0;
  const auto counting = [&asked](const std::string& name, const std::shared_ptr<const SiemensBlocks>& blocks,
                                 SiemensModal modal) {
    ++asked;
    return readSiemensContour(name, *blocks, modal);
  };
  SiemensRunInput given{kMain, "t.mpf", {{"L42", kContour, "t#/subprograms/L42"}}, "", ToolOffset{}};
  given.parsers.contour = counting;
  const Toolpath withReader = planSiemensProgram(given, *findProfile("sinumerik-802s"));
  EXPECT_EQ(asked, 1);
  given.parsers.contour = {};
  const Toolpath without = planSiemensProgram(given, *findProfile("sinumerik-802s"));
  ASSERT_EQ(withReader.moves.size(), without.moves.size());
  for (std::size_t i = 0; i < without.moves.size(); ++i) EXPECT_EQ(withReader.moves[i].to, without.moves[i].to) << i;
  SiemensRunInput printed{std::string(kMain) + "L42.spf\n" + kContour, "t.mpf", {}, "", ToolOffset{}};
  printed.parsers.contour = counting;
  EXPECT_FALSE(planSiemensProgram(printed, *findProfile("sinumerik-802s")).moves.empty());
  EXPECT_EQ(asked, 1);
}

}  // namespace
}  // namespace cyclecert
