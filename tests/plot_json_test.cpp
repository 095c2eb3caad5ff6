// A plot kept as JSON in a results file draws the same picture when read back, and a malformed
// one is an error naming its field.
#include <gtest/gtest.h>

#include "reference/model/toolpath_json.h"
#include "reports/svg/plot_json.h"

namespace cyclecert {
namespace {

PlotInput samplePlot() {
  PlotInput p;
  p.title = "no-gouge <fail>";
  Segment line{SegmentKind::Line, {0, 10}, {-20, 10}, {}, 4};
  Segment arc{SegmentKind::ArcCW, {-20, 10}, {-25, 15}, {-25, 10}, 5};
  p.finish.segments = {line, arc};
  p.rough.segments = {line.shifted({0.1, 0.3}), arc.shifted({0.1, 0.3})};
  p.path.start = {2, 20};
  Move approach, pass;
  approach.to = {2, 12};
  pass.kind = MoveKind::Feed;
  pass.to = {-20, 12};
  pass.feed = 0.2;
  p.path.moves = {approach, pass};
  p.stock = {{{2, 0}, {2, 20}, {-30, 20}, {-30, 0}}};
  Highlight h;
  h.label = "move 1";
  h.regions = {{{-1, 10}, {-2, 10}, {-2, 11}}};
  h.segments = {line};
  h.points = {{-20, 12}};
  h.labelShown = true;
  p.highlights.push_back(h);
  p.overlay = p.path;
  p.pathLabel = "linuxcnc";
  p.overlayLabel = "reference";
  return p;
}

TEST(PlotJson, ReadBackDrawsTheSamePicture) {
  const PlotInput p = samplePlot();
  const nlohmann::json j = plotToJson(p);
  const PlotInput back = plotFromJson(nlohmann::json::parse(j.dump()));
  EXPECT_EQ(renderToolpathSvg(back), renderToolpathSvg(p));
  EXPECT_EQ(plotToJson(back), j);
}

TEST(PlotJson, AMalformedPlotNamesItsField) {
  nlohmann::json j = plotToJson(samplePlot());
  j["finish"][1].erase("center");
  EXPECT_THROW(
      {
        try {
          plotFromJson(j);
        } catch (const ToolpathFormatError& e) {
          EXPECT_NE(std::string(e.what()).find("/finish/1/center"), std::string::npos) << e.what();
          throw;
        }
      },
      ToolpathFormatError);
  j = plotToJson(samplePlot());
  j["path"]["moves"][1]["to"]["x"] = "twelve";
  try {
    plotFromJson(j);
    FAIL() << "accepted a malformed path";
  } catch (const ToolpathFormatError& e) {
    EXPECT_NE(std::string(e.what()).find("/path/moves/1/to/x"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cyclecert
