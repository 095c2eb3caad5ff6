#pragma once
// cyclecert inside your GoogleTest suite: every spec case, or a fuzz property, as a test of your
// in-process engine — in the spirit of RapidCheck's RC_GTEST_PROP. Link `cyclecert::gtest` (the
// installed package: find_package(cyclecert CONFIG)); examples/inprocess-engine/ shows it whole.
//
//   std::unique_ptr<cyclecert::Engine> makeMyEngine();   // your engine (harness/engines/engine.h)
//
//   // One test per spec case: MyEngineSpecs.<case id>, judged as `cyclecert check` judges it (the
//   // hand-derived expectation and every oracle). A case your engine calls not applicable is skipped
//   // with its reason.
//   CYCLECERT_SPEC_TESTS(MyEngineSpecs, cyclecert::gtest::installedSpecsDir(), makeMyEngine);
//
//   // A fuzz property: N generated cases (G71/G72 by default) through your engine and every
//   // oracle, each failure shrunk; the failure message prints the seed and the shrunk program.
//   // CYCLECERT_FUZZ_SEED=S in the environment replays a run; CYCLECERT_FUZZ_CASES=N changes N.
//   CYCLECERT_FUZZ_TEST(MyEngineFuzz, G71AndG72, makeMyEngine, 500);
//
// The macros register tests at static-initialisation time, so gtest_main (or your own main calling
// RUN_ALL_TESTS) runs them with the rest of your suite; --gtest_filter selects cases as usual.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>

#include "harness/engines/engine.h"
#include "harness/fuzz/fuzz_run.h"
#include "harness/run/check_run.h"
#include "harness/spec/spec_case.h"

namespace cyclecert::gtest {

using EngineFactory = std::function<std::unique_ptr<Engine>()>;

// The spec suite the package installed (share/cyclecert/specs), as its CMake config recorded it in
// CYCLECERT_SPECS_DIR (set on the cyclecert::gtest target); "" when built without it.
inline std::string installedSpecsDir() {
#ifdef CYCLECERT_SPECS_DIR
  return CYCLECERT_SPECS_DIR;
#else
  return "";
#endif
}

// A spec case's id as a test name: letters and digits, the rest '_' ("gsk/g74_1/o0008" →
// "gsk_g74_1_o0008").
inline std::string testNameOf(const std::string& caseId) {
  std::string name = caseId;
  for (char& ch : name) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  return name;
}

// What one case's result says to a GoogleTest reader: nothing for a pass.
inline std::string failureText(const CaseResult& r) {
  std::ostringstream s;
  s << r.caseId << " (" << r.file << "): " << r.verdict;
  if (!r.detail.empty()) s << ": " << r.detail;
  for (const Finding& f : r.findings) {
    s << "\n  " << f.oracle;
    if (f.move) s << " at move " << *f.move;
    s << ": " << f.message;
  }
  if (!r.reproduce.empty()) s << "\n  reproduce: " << r.reproduce;
  return s.str();
}

// Runs one spec case through a new engine from `make`, as `cyclecert check` does.
inline void checkOneSpecCase(const EngineFactory& make, const std::string& file) {
  const std::unique_ptr<Engine> engine = make();
  const CaseResult r = checkCase(*engine, loadSpecCase(file));
  if (r.verdict == "not-applicable") GTEST_SKIP() << r.caseId << ": " << r.detail;
  if (r.verdict != "pass") ADD_FAILURE() << failureText(r);
}

// Registers Suite.<case> for every spec case under specsDir/cases. A suite that cannot be read
// registers one failing test that says why, rather than none.
inline int registerSpecCases(const char* suite, const std::string& specsDir, EngineFactory make, const char* file,
                             int line) {
  std::vector<std::string> files;
  std::string error;
  try {
    if (specsDir.empty() || !std::filesystem::is_directory(specsDir + "/cases")) {
      error = "no spec suite at '" + specsDir + "' (expected a folder holding cases/; the installed one is "
              "cyclecert::gtest::installedSpecsDir())";
    } else {
      files = findSpecCaseFiles(specsDir + "/cases");
    }
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!error.empty()) {
    ::testing::RegisterTest(suite, "SpecSuiteIsReadable", nullptr, nullptr, file, line,
                            [error]() -> ::testing::Test* {
                              struct Unreadable : ::testing::Test {
                                std::string why;
                                explicit Unreadable(std::string w) : why(std::move(w)) {}
                                void TestBody() override { ADD_FAILURE() << why; }
                              };
                              return new Unreadable(error);
                            });
    return 0;
  }
  struct OneCase : ::testing::Test {
    EngineFactory make;
    std::string caseFile;
    OneCase(EngineFactory m, std::string f) : make(std::move(m)), caseFile(std::move(f)) {}
    void TestBody() override { checkOneSpecCase(make, caseFile); }
  };
  for (const std::string& caseFile : files) {
    std::string id;
    try {
      id = loadSpecCase(caseFile).id;
    } catch (const std::exception&) {
      id = std::filesystem::path(caseFile).stem().string();  // the test itself reports the error
    }
    ::testing::RegisterTest(suite, testNameOf(id).c_str(), nullptr, caseFile.c_str(), file, line,
                            [make, caseFile]() -> ::testing::Test* { return new OneCase(make, caseFile); });
  }
  return static_cast<int>(files.size());
}

// An environment variable as a number, or `fallback` when it is unset.
inline std::uint64_t numberFromEnvironment(const char* name, std::uint64_t fallback) {
  const char* text = std::getenv(name);
  if (text == nullptr || *text == '\0') return fallback;
  return std::strtoull(text, nullptr, 0);
}

// The fuzz property: `cases` generated cases (seed from CYCLECERT_FUZZ_SEED, else `seed`) through
// the engine and every oracle; each failure shrunk and reported with its case seed, the oracle,
// the shrunk program and the command that shows it again.
inline void checkFuzzProperty(const EngineFactory& make, const char* suite, const char* name, long cases,
                              std::uint64_t seed, const FuzzCycles& cycles = kDefaultFuzzCycles) {
  FuzzOptions options;
  options.seed = numberFromEnvironment("CYCLECERT_FUZZ_SEED", seed);
  options.cases = static_cast<long>(numberFromEnvironment("CYCLECERT_FUZZ_CASES", static_cast<std::uint64_t>(cases)));
  options.cycles = cycles;
  options.outDir = ::testing::TempDir() + "cyclecert-fuzz-" + suite + "-" + name;
  options.regressionsDir = "";
  const std::unique_ptr<Engine> engine = make();
  std::ostringstream progress;
  const FuzzSummary summary = runFuzz(*engine, nullptr, options, progress);
  std::error_code ignored;
  std::filesystem::remove_all(options.outDir, ignored);
  if (summary.clean()) return;
  std::ostringstream s;
  s << summary.fail + summary.engineFailure << " of " << summary.run << " generated cases failed (seed "
    << options.seed << "; CYCLECERT_FUZZ_SEED=" << options.seed << " replays the run)";
  for (const FuzzFailure& f : summary.failures) {
    s << "\n- case seed " << f.caseSeed << ": " << f.kind << ": " << f.detail << "\n  shrunk program:\n"
      << fuzzProgram(f.shrunk);
  }
  ADD_FAILURE() << s.str();
}

}  // namespace cyclecert::gtest

#define CYCLECERT_GTEST_CONCAT_INNER(a, b) a##b
#define CYCLECERT_GTEST_CONCAT(a, b) CYCLECERT_GTEST_CONCAT_INNER(a, b)

// One test Suite.<case id> per spec case under specsDir/cases, for engines made by `factory`.
#define CYCLECERT_SPEC_TESTS(Suite, specsDir, factory)                                                    \
  [[maybe_unused]] static const int CYCLECERT_GTEST_CONCAT(cyclecert_spec_tests_, Suite) =               \
      ::cyclecert::gtest::registerSpecCases(#Suite, specsDir, factory, __FILE__, __LINE__)

// TEST(Suite, Name): `cases` generated G71/G72 cases through an engine made by `factory`, seed 1
// unless CYCLECERT_FUZZ_SEED says otherwise.
#define CYCLECERT_FUZZ_TEST(Suite, Name, factory, cases) \
  TEST(Suite, Name) { ::cyclecert::gtest::checkFuzzProperty(factory, #Suite, #Name, cases, 1); }
