// libFuzzer target: the FANUC-dialect reader (reference/gcode and the interpreter) under every
// profile and the parameter-chosen formats (first byte: tests/fuzz/fuzz_input.h). The lexer runs to
// the end of the input, the parser reads the program, the request is read with the profile's
// parameters, and the oracles read its cycles (readProgramSpec). Expected refusals: ParseError,
// NotSupported, and the oracles' std::runtime_error for a program they cannot read. Anything else
// escaping, a crash, a hang or a huge allocation is a finding.
#include <cstddef>
#include <cstdint>

#include "harness/engines/reference_plan.h"
#include "oracles/cycle_spec.h"
#include "reference/gcode/lexer.h"
#include "reference/gcode/parser.h"
#include "reference/model/alarms.h"
#include "tests/fuzz/fuzz_input.h"

namespace cyclecert {
namespace {

void lexToTheEnd(const std::string& text) {
  try {
    Lexer lexer(text, "fuzz.nc");
    while (lexer.next().kind != TokenKind::EndOfInput) {
    }
  } catch (const ParseError&) {
  }
}

void readWithTheOracles(const ReadRequest& read) {
  try {
    readProgramSpec(*read.program, *read.profile, read.params, ToolOffset{});
  } catch (const ParseError&) {
  } catch (const NotSupported&) {
  } catch (const std::runtime_error&) {  // documented: a program the oracles cannot read
  }
}

}  // namespace
}  // namespace cyclecert

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace cyclecert;
  const fuzz::Chosen chosen = fuzz::choose(fuzz::fanucSettings(), data, size);
  lexToTheEnd(chosen.text);
  PlanRequest request{chosen.text, "fuzz.nc", chosen.setting.profile, chosen.setting.params, {}};
  try {
    readWithTheOracles(readRequest(request));
  } catch (const ParseError&) {
  } catch (const NotSupported&) {
  }
  return 0;
}
