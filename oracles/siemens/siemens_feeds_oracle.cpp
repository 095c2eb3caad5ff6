// siemens-feeds: every feed of the call at the parameter's feed — roughing at R111 / FF1, CYCLE95's
// undercuts at FF2 (CYCLE95.UNDERCUT, CYCLE95.PARAMS: "roughing feed outside undercuts, feed in
// undercuts"), the finishing pass at R112 / FF3 (LCYC95.FINISH, CYCLE95.FINISH; LCYC95.PARAMS:
// R111 has no effect when finishing, R112 none when roughing). Feeds compared exactly.
#include <cmath>

#include "oracles/oracles.h"
#include "oracles/siemens/siemens_moves.h"
#include "reference/model/number_text.h"

namespace cyclecert {

namespace {

class SiemensFeedsOracle : public Oracle {
 public:
  std::string id() const override { return "siemens-feeds"; }
  std::vector<std::string> rules() const override {
    return {"LCYC95.PARAMS", "LCYC95.ROUGH", "LCYC95.FINISH", "CYCLE95.PARAMS", "CYCLE95.ROUGH", "CYCLE95.UNDERCUT",
            "CYCLE95.FINISH"};
  }
  bool judges(CycleFamily f) const override { return isSiemensFamily(f); }

  void judge(const JudgeContext& ctx, std::vector<Finding>& out) const override {
    for (const SiemensCycleMoves& call : *ctx.siemensCalls) judgeCall(call, out);
  }

 private:
  void judgeCall(const SiemensCycleMoves& m, std::vector<Finding>& out) const {
    const bool cycle95 = m.c.isCycle95();
    for (const FeedRun& cut : m.roughing) {
      for (std::size_t i = cut.begin; i < cut.end; ++i) {
        if (cycle95 && inUndercut(m.c, m.from(i), m.to(i), m.tol)) {
          judgeFeed(m, i, m.c.undercutFeed, "in an undercut, at FF2", out);
        } else {
          judgeFeed(m, i, m.c.roughingFeed, cycle95 ? "roughing, at FF1" : "roughing, at R111", out);
        }
      }
    }
    for (std::size_t i = m.finishing.begin; i < m.finishing.end; ++i) {
      judgeFeed(m, i, m.c.finishingFeed, cycle95 ? "finishing, at FF3" : "finishing, at R112", out);
    }
  }

  // `what` a literal: no string is made for a feed that is right (most names are too long to be
  // kept in a std::string without allocating).
  void judgeFeed(const SiemensCycleMoves& m, std::size_t i, double expected, const char* what,
                 std::vector<Finding>& out) const {
    const std::optional<double> feed = m.in.path.moves[i].feed;
    if (feed && std::abs(*feed - expected) <= 1e-9 * std::max(1.0, std::abs(expected))) return;
    out.push_back(m.report(*this, i, "a feed at " + (feed ? shortDecimalText(*feed) : std::string("no F")) + "; " + what +
                                         "=" + shortDecimalText(expected)));
  }
};

}  // namespace

std::unique_ptr<Oracle> makeSiemensFeedsOracle() { return std::make_unique<SiemensFeedsOracle>(); }

}  // namespace cyclecert
