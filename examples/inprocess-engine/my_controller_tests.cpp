// My Controller under cyclecert, inside our own GoogleTest suite.
#include <cyclecert/gtest.h>

#include "my_controller_engine.h"

// MyControllerSpecs.<case>: every spec case the package installed, judged as `cyclecert check`
// judges it — the hand-derived expectation and every oracle.
CYCLECERT_SPEC_TESTS(MyControllerSpecs, cyclecert::gtest::installedSpecsDir(), my_controller::makeEngine);

// 200 generated G71/G72 cases through every oracle, failures shrunk and printed with their seed.
CYCLECERT_FUZZ_TEST(MyControllerFuzz, G71AndG72, my_controller::makeEngine, 200)

// The engine interface used directly: a program of our own.
TEST(MyController, PlansTheSeedsG71Example) {
  cyclecert::SpecCase c;
  c.id = "my-controller/g71-example";
  c.profile = "fanuc-0i-f";
  c.program = "G0 X100 Z2\nG71 U2 R0.5\nG71 P10 Q20 U0.5 W0.1 F0.2\nN10 G0 X40\nG1 Z-30\nX60 Z-50\nN20 X100\nG70 P10 Q20\n";
  const cyclecert::EngineResult r = my_controller::makeEngine()->run(c);
  ASSERT_EQ(r.kind, cyclecert::EngineResult::Planned) << r.detail;
  EXPECT_FALSE(r.path.moves.empty());
}
