// feeds: cutting moves run at the cycle's F (G71.FST, G72.FST: F inside ns…nf is ignored by the
// roughing cycle), or at an F of the finishing shape when the program has a G70 (G70.EX).
#include <cmath>
#include <sstream>

#include "oracles/oracles.h"

namespace cyclecert {

namespace {

class FeedsOracle : public Oracle {
 public:
  std::string id() const override { return "feeds"; }
  std::vector<std::string> rules() const override { return {"G71.FST", "G72.FST", "G70.EX"}; }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    const JudgeInput& in = ctx.in;
    if (in.path.alarm || in.program.cycles.empty()) return;
    std::vector<double> allowed;
    for (const CycleSpec& c : in.program.cycles) allowed.push_back(c.feed);
    if (in.program.hasFinishingCycle) allowed.insert(allowed.end(), in.program.finishingFeeds.begin(), in.program.finishingFeeds.end());
    for (std::size_t i = 0; i < in.path.moves.size(); ++i) {
      const Move& m = in.path.moves[i];
      if (m.kind != MoveKind::Feed) continue;
      if (!m.feed || *m.feed <= 0) {
        out.push_back(finding(*this, i, "a cutting move without a feed rate"));
        continue;
      }
      bool ok = false;
      for (double f : allowed) ok = ok || std::abs(*m.feed - f) <= 1e-9 * std::max(1.0, f);
      if (!ok && !in.program.motionAfterCycles) {
        std::ostringstream s;
        s << "cutting move at F" << *m.feed << ", but the cycle's F is " << in.program.cycles.front().feed;
        out.push_back(finding(*this, i, s.str()));
      }
    }
  }
};

}  // namespace

std::unique_ptr<Oracle> makeFeedsOracle() { return std::make_unique<FeedsOracle>(); }

}  // namespace cyclecert
