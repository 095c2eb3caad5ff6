// The SVG toolpath plot: well-formed, one element per move, the right styles, arcs with the right
// flags, labels, escaping, alarms, and degenerate input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>

#include "reports/svg/toolpath_svg.h"

namespace cyclecert {
namespace {

using boost::property_tree::ptree;

// ---- helpers --------------------------------------------------------------------------------

// Parses the document; a parse error fails the calling test.
ptree parseSvg(const std::string& svg) {
  ptree doc;
  std::istringstream in(svg);
  try {
    boost::property_tree::read_xml(in, doc);
  } catch (const boost::property_tree::xml_parser_error& e) {
    ADD_FAILURE() << "not well-formed XML: " << e.what() << "\n" << svg;
  }
  return doc;
}

std::string attr(const ptree& element, const std::string& name) {
  return element.get<std::string>("<xmlattr>." + name, "");
}

bool hasAttr(const ptree& element, const std::string& name) {
  return static_cast<bool>(element.get_child_optional("<xmlattr>." + name));
}

// All elements named `tag` anywhere below `node`, depth first.
void collect(const ptree& node, const std::string& tag, std::vector<ptree>& out) {
  for (const auto& [name, child] : node) {
    if (name == tag) out.push_back(child);
    if (name != "<xmlattr>") collect(child, tag, out);
  }
}

std::vector<ptree> elements(const ptree& doc, const std::string& tag) {
  std::vector<ptree> out;
  collect(doc, tag, out);
  return out;
}

// The children named `tag` of the <g> with the given id.
std::vector<ptree> groupChildren(const ptree& doc, const std::string& id, const std::string& tag) {
  std::vector<ptree> out;
  for (const ptree& g : elements(doc, "g")) {
    if (attr(g, "id") != id) continue;
    for (const auto& [name, child] : g)
      if (name == tag) out.push_back(child);
  }
  return out;
}

// The contents of every <text> element with the given class.
std::vector<std::string> texts(const ptree& doc, const std::string& cls) {
  std::vector<std::string> out;
  for (const ptree& t : elements(doc, "text"))
    if (attr(t, "class") == cls) out.push_back(t.data());
  return out;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> tokens(const std::string& d) {
  std::istringstream in(d);
  std::vector<std::string> out;
  for (std::string t; in >> t;) out.push_back(t);
  return out;
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

Segment line(Point from, Point to) { return Segment{SegmentKind::Line, from, to, {}, 0}; }
Segment arc(SegmentKind kind, Point from, Point to, Point centre) {
  return Segment{kind, from, to, centre, 0};
}

Move rapid(Point to) { return Move{MoveKind::Rapid, SegmentKind::Line, to, {}, {}, {}, MovePhase::Approach, 0, {}}; }
Move feed(Point to, MovePhase phase = MovePhase::SemiFinish, int pass = 0) {
  return Move{MoveKind::Feed, SegmentKind::Line, to, {}, 0.2, {}, phase, pass, {}};
}
Move arcMove(SegmentKind kind, Point to, Point centre) {
  return Move{MoveKind::Feed, kind, to, centre, 0.2, {}, MovePhase::SemiFinish, 0, {}};
}

// A small G71 type I example (Δd = 5, e = 0.5, Δu/2 = 0.25, Δw = 0.5, DTP = 0): A = (5, 30),
// B = (5, 10), a Ø20 shoulder, a concave R5 fillet (G02) up to Ø30, and a taper to Ø54.
PlotInput example() {
  PlotInput in;
  in.title = "G71 example";
  in.finish.segments = {line({5, 10}, {-20, 10}),
                        arc(SegmentKind::ArcCW, {-20, 10}, {-25, 15}, {-20, 15}),
                        line({-25, 15}, {-40, 27})};
  in.rough = in.finish.shifted({0.5, 0.25});
  in.path.start = {5, 30};
  in.path.cycles.push_back(CycleRecord{"G71", 10, {5, 30}, 0, 0, {}, {}, false, {}});
  in.path.moves = {rapid({5.5, 30.25}),          rapid({5.5, 25.25}),
                   feed({-37, 25.25}, MovePhase::Pass, 1),  feed({-36.5, 25.75}, MovePhase::Pass, 1),
                   rapid({5.5, 25.75}),          rapid({5.5, 20.25}),
                   feed({-30.75, 20.25}, MovePhase::Pass, 2), feed({-30.25, 20.75}, MovePhase::Pass, 2),
                   rapid({5.5, 20.75}),          rapid({5.5, 15.25}),
                   feed({-24.5, 15.25}, MovePhase::Pass, 3), feed({-24, 15.75}, MovePhase::Pass, 3),
                   rapid({5.5, 15.75}),          rapid({5.5, 10.25}),
                   feed({-19.5, 10.25}),
                   arcMove(SegmentKind::ArcCW, {-24.5, 15.25}, {-19.5, 15.25}),
                   feed({-39.5, 27.25}),         rapid({-39.5, 30}),
                   rapid({5, 30})};
  return in;
}

// ---- tests ----------------------------------------------------------------------------------

TEST(Svg, IsWellFormedWithSvgRoot) {
  const std::string svg = renderToolpathSvg(example());
  const ptree doc = parseSvg(svg);
  const auto root = doc.get_child_optional("svg");
  ASSERT_TRUE(root);
  EXPECT_EQ(attr(*root, "xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_EQ(attr(*root, "version"), "1.1");
  EXPECT_FALSE(attr(*root, "viewBox").empty());
  EXPECT_EQ(svg.find("<script"), std::string::npos);
  EXPECT_EQ(svg.find("href"), std::string::npos);  // no external references
}

TEST(Svg, OnePathPerMoveRapidsDashedFeedsSolid) {
  const PlotInput in = example();
  const ptree doc = parseSvg(renderToolpathSvg(in));
  const std::vector<ptree> moves = groupChildren(doc, "toolpath", "path");
  ASSERT_EQ(moves.size(), in.path.moves.size());
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const bool isRapid = in.path.moves[i].kind == MoveKind::Rapid;
    SCOPED_TRACE("move " + std::to_string(i));
    EXPECT_EQ(attr(moves[i], "class"), isRapid ? "rapid" : "feed");
    EXPECT_EQ(hasAttr(moves[i], "stroke-dasharray"), isRapid);
    EXPECT_EQ(attr(moves[i], "fill"), "none");
  }
  EXPECT_NE(attr(moves[0], "stroke"), attr(moves[2], "stroke"));  // rapid and feed colours differ
}

TEST(Svg, DrawsFinishSolidAndRoughDashed) {
  const ptree doc = parseSvg(renderToolpathSvg(example()));
  int finish = 0;
  int rough = 0;
  for (const ptree& p : elements(doc, "path")) {
    if (attr(p, "class") == "finish") {
      ++finish;
      EXPECT_FALSE(hasAttr(p, "stroke-dasharray"));
    }
    if (attr(p, "class") == "rough") {
      ++rough;
      EXPECT_TRUE(hasAttr(p, "stroke-dasharray"));
    }
  }
  EXPECT_EQ(finish, 1);
  EXPECT_EQ(rough, 1);
}

// Renders a single arc move and returns the tokens of its path data.
std::vector<std::string> arcPathTokens(SegmentKind kind, Point from, Point to, Point centre) {
  PlotInput in;
  in.path.start = from;
  in.path.moves = {arcMove(kind, to, centre)};
  const std::vector<ptree> moves = groupChildren(parseSvg(renderToolpathSvg(in)), "toolpath", "path");
  if (moves.size() != 1) return {};
  return tokens(attr(moves[0], "d"));
}

// Hand-worked: the CW quarter arc from (z=-20, x=5) to (z=-25, x=10) about (z=-20, x=10) starts
// below its centre and ends left of it. On screen (y down) the start is at angle +90° from the
// centre and the end at 180°: the angle increases, which is SVG's sweep-flag 1. Its reverse (CCW)
// is sweep-flag 0. Both sweep 90°, so large-arc-flag 0.
TEST(Svg, ArcSweepFlagClockwise) {
  const auto t = arcPathTokens(SegmentKind::ArcCW, {-20, 5}, {-25, 10}, {-20, 10});
  ASSERT_EQ(t.size(), 11u);  // M x y A rx ry rotation large sweep x y
  EXPECT_EQ(t[0], "M");
  EXPECT_EQ(t[3], "A");
  EXPECT_EQ(t[4], t[5]);  // circular
  EXPECT_GT(std::stod(t[4]), 0);
  EXPECT_EQ(t[7], "0");  // large-arc
  EXPECT_EQ(t[8], "1");  // sweep: CW
  // The end is left of and above the start on screen.
  EXPECT_LT(std::stod(t[9]), std::stod(t[1]));
  EXPECT_LT(std::stod(t[10]), std::stod(t[2]));
  // Radius 5 mm in pixels equals the horizontal and vertical pixel distances (equal scales).
  EXPECT_NEAR(std::stod(t[4]), std::stod(t[1]) - std::stod(t[9]), 0.01);
  EXPECT_NEAR(std::stod(t[4]), std::stod(t[2]) - std::stod(t[10]), 0.01);
}

TEST(Svg, ArcSweepFlagCounterClockwise) {
  const auto t = arcPathTokens(SegmentKind::ArcCCW, {-25, 10}, {-20, 5}, {-20, 10});
  ASSERT_EQ(t.size(), 11u);
  EXPECT_EQ(t[3], "A");
  EXPECT_EQ(t[7], "0");
  EXPECT_EQ(t[8], "0");  // sweep: CCW
}

TEST(Svg, ArcLargeFlagForMoreThanHalfCircle) {
  // CW from below the centre the long way round to the right of it: 270°.
  const auto t = arcPathTokens(SegmentKind::ArcCW, {0, 0}, {5, 5}, {0, 5});
  ASSERT_EQ(t.size(), 11u);
  EXPECT_EQ(t[7], "1");
  EXPECT_EQ(t[8], "1");
}

TEST(Svg, FullCircleIsTwoArcs) {
  const auto t = arcPathTokens(SegmentKind::ArcCCW, {0, 0}, {0, 0}, {0, 5});
  EXPECT_EQ(std::count(t.begin(), t.end(), "A"), 2);
}

TEST(Svg, EqualScalesOnBothAxes) {
  PlotInput in;
  in.path.moves = {feed({10, 0}), feed({10, 10})};
  const auto moves = groupChildren(parseSvg(renderToolpathSvg(in)), "toolpath", "path");
  ASSERT_EQ(moves.size(), 2u);
  const auto a = tokens(attr(moves[0], "d"));  // M x y L x y
  const auto b = tokens(attr(moves[1], "d"));
  ASSERT_EQ(a.size(), 6u);
  ASSERT_EQ(b.size(), 6u);
  const double alongZ = std::stod(a[4]) - std::stod(a[1]);
  const double alongX = std::stod(b[2]) - std::stod(b[5]);  // X up: y decreases
  EXPECT_GT(alongZ, 0);
  EXPECT_NEAR(alongZ, alongX, 0.01);
}

TEST(Svg, LabelsPassesStartAndDiameters) {
  const ptree doc = parseSvg(renderToolpathSvg(example()));
  const auto passes = texts(doc, "pass-label");
  EXPECT_EQ(passes, (std::vector<std::string>{"1", "2", "3"}));  // once per pass
  EXPECT_TRUE(contains(texts(doc, "start-label"), "A"));
  EXPECT_EQ(elements(doc, "circle").size(), 1u);
  const auto diameters = texts(doc, "diameter");
  for (const char* d : {"\u00D854", "\u00D830", "\u00D820"})
    EXPECT_TRUE(contains(diameters, d)) << d;
  EXPECT_EQ(diameters.size(), 3u);  // x = 10, 15, 27, each once
  EXPECT_TRUE(contains(texts(doc, "title"), "G71 example"));
  EXPECT_EQ(texts(doc, "legend-label").size(), 4u);
}

TEST(Svg, DiameterLabelsAreThinnedAndNeverOverlap) {
  PlotInput in;
  for (int i = 0; i < 200; ++i)
    in.finish.segments.push_back(line({-0.5 * i, 0.1 * i}, {-0.5 * (i + 1), 0.1 * (i + 1)}));
  const ptree doc = parseSvg(renderToolpathSvg(in));
  std::vector<double> ys;
  for (const ptree& t : elements(doc, "text"))
    if (attr(t, "class") == "diameter") ys.push_back(std::stod(attr(t, "y")));
  EXPECT_GE(ys.size(), 2u);
  EXPECT_LE(ys.size(), 12u);
  std::sort(ys.begin(), ys.end());
  for (std::size_t i = 1; i < ys.size(); ++i) EXPECT_GE(ys[i] - ys[i - 1], 12.0);
}

TEST(Svg, EscapesTitle) {
  PlotInput in = example();
  in.title = "a <&> \"b\" 'c'";
  const std::string svg = renderToolpathSvg(in);
  EXPECT_NE(svg.find("a &lt;&amp;&gt; &quot;b&quot; &apos;c&apos;"), std::string::npos);
  EXPECT_EQ(svg.find("<&>"), std::string::npos);
  EXPECT_TRUE(contains(texts(parseSvg(svg), "title"), in.title));  // round trip
}

TEST(Svg, EscapeFunction) {
  EXPECT_EQ(svgEscape("x<y && y>z"), "x&lt;y &amp;&amp; y&gt;z");
  EXPECT_EQ(svgEscape("\"'"), "&quot;&apos;");
  EXPECT_EQ(svgEscape(std::string("a\x01" "b\tc")), "a?b\tc");  // XML forbids most controls
  EXPECT_EQ(svgEscape(""), "");
}

TEST(Svg, WritesAlarm) {
  PlotInput in = example();
  in.path.moves.clear();
  in.path.alarm = Alarm{"PS0064", "shape not monotonic in <Z>", 17, ""};
  const ptree doc = parseSvg(renderToolpathSvg(in));
  const auto alarms = texts(doc, "alarm");
  ASSERT_EQ(alarms.size(), 1u);
  EXPECT_NE(alarms[0].find("PS0064"), std::string::npos);
  EXPECT_NE(alarms[0].find("shape not monotonic in <Z>"), std::string::npos);
  EXPECT_NE(alarms[0].find("line 17"), std::string::npos);
}

TEST(Svg, NoAlarmNoBanner) {
  EXPECT_TRUE(texts(parseSvg(renderToolpathSvg(example())), "alarm").empty());
}

TEST(Svg, DegenerateInputStillParses) {
  // Nothing at all.
  PlotInput empty;
  const std::string a = renderToolpathSvg(empty);
  EXPECT_TRUE(parseSvg(a).get_child_optional("svg"));
  EXPECT_TRUE(groupChildren(parseSvg(a), "toolpath", "path").empty());

  // Everything at one point: zero-length lines and arcs, an arc of radius 0, an arc without centre.
  PlotInput point;
  const Point p{3, 4};
  point.finish.segments = {line(p, p), arc(SegmentKind::ArcCW, p, p, p)};
  point.rough = point.finish;
  point.path.start = p;
  Move noCentre = arcMove(SegmentKind::ArcCW, p, p);
  noCentre.center.reset();
  point.path.moves = {rapid(p), feed(p, MovePhase::Pass, 1), arcMove(SegmentKind::ArcCCW, p, p), noCentre};
  const std::string b = renderToolpathSvg(point);
  const ptree doc = parseSvg(b);
  EXPECT_EQ(groupChildren(doc, "toolpath", "path").size(), 4u);
  EXPECT_EQ(lower(b).find("nan"), std::string::npos);
  EXPECT_EQ(lower(b).find("inf"), std::string::npos);
}

TEST(Svg, NeverWritesNanOrInf) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PlotInput in = example();
  in.path.moves.push_back(rapid({nan, inf}));
  in.path.moves.push_back(arcMove(SegmentKind::ArcCW, {1, 2}, {nan, 0}));
  in.path.moves.push_back(feed({-inf, 5}, MovePhase::Pass, 3));
  in.finish.segments.push_back(line({-40, 27}, {nan, nan}));
  in.path.cycles.push_back(CycleRecord{"G71", 20, {inf, 0}, 0, 0, {}, {}, false, {}});
  const std::string svg = renderToolpathSvg(in);
  parseSvg(svg);
  EXPECT_EQ(lower(svg).find("nan"), std::string::npos);
  EXPECT_EQ(lower(svg).find("inf"), std::string::npos);
}

// ---- the overlay (`cyclecert diff`) ---------------------------------------------------------

// The example with a second engine's toolpath: the same moves but the first retract straight out.
PlotInput overlayExample() {
  PlotInput in = example();
  Toolpath other = in.path;
  other.moves[3].to = {-37, 25.75};
  in.overlay = other;
  in.pathLabel = "reference";
  in.overlayLabel = "mutant:retract-angle";
  Highlight marker;
  marker.label = "first divergence: move 3";
  marker.labelShown = true;
  marker.points = {in.path.moves[3].to, other.moves[3].to};
  in.highlights.push_back(marker);
  return in;
}

TEST(Svg, DiffOverlayDrawsTheSecondToolpathInItsOwnGroupAndColours) {
  const PlotInput in = overlayExample();
  const ptree doc = parseSvg(renderToolpathSvg(in));
  const std::vector<ptree> base = groupChildren(doc, "toolpath", "path");
  const std::vector<ptree> overlay = groupChildren(doc, "overlay", "path");
  ASSERT_EQ(base.size(), in.path.moves.size());
  ASSERT_EQ(overlay.size(), in.overlay->moves.size());
  for (std::size_t i = 0; i < overlay.size(); ++i) {
    SCOPED_TRACE("move " + std::to_string(i));
    const bool isRapid = in.overlay->moves[i].kind == MoveKind::Rapid;
    EXPECT_EQ(attr(overlay[i], "class"), isRapid ? "rapid" : "feed");
    EXPECT_EQ(hasAttr(overlay[i], "stroke-dasharray"), isRapid);
    EXPECT_NE(attr(overlay[i], "stroke"), attr(base[i], "stroke"));  // engine B in its own colours
    // Drawn thinner over the first, so that both show where they coincide.
    EXPECT_LT(std::stod(attr(overlay[i], "stroke-width")), std::stod(attr(base[i], "stroke-width")));
  }
  EXPECT_NE(attr(overlay[0], "stroke"), attr(overlay[2], "stroke"));  // its rapids and feeds differ
  EXPECT_NE(attr(base[3], "d"), attr(overlay[3], "d"));
  EXPECT_EQ(attr(base[5], "d"), attr(overlay[5], "d"));  // move 4 starts where move 3 ends
}

TEST(Svg, DiffOverlayLegendNamesBothToolpaths) {
  const ptree doc = parseSvg(renderToolpathSvg(overlayExample()));
  const auto labels = texts(doc, "legend-label");
  EXPECT_TRUE(contains(labels, "reference (rapid, feed)"));
  EXPECT_TRUE(contains(labels, "mutant:retract-angle (rapid, feed)"));
  EXPECT_TRUE(contains(labels, "finish contour"));
  EXPECT_TRUE(contains(labels, "rough contour"));

  PlotInput longName = overlayExample();
  longName.overlayLabel = "process:" + std::string(200, 'x');
  for (const std::string& l : texts(parseSvg(renderToolpathSvg(longName)), "legend-label")) EXPECT_LT(l.size(), 80u) << l;
}

TEST(Svg, DiffMarkerRingsBothEndsAndShowsItsLabel) {
  const PlotInput in = overlayExample();
  const ptree doc = parseSvg(renderToolpathSvg(in));
  int rings = 0;
  for (const ptree& c : elements(doc, "circle")) rings += attr(c, "class") == "witness-point";
  EXPECT_EQ(rings, 2);
  EXPECT_EQ(texts(doc, "witness-label"), std::vector<std::string>{"first divergence: move 3"});

  // A finding's label stays a tooltip only.
  PlotInput finding = example();
  finding.highlights.push_back(Highlight{"no-gouge: move 2", {}, {}, {{-37, 25.25}}, false});
  EXPECT_TRUE(texts(parseSvg(renderToolpathSvg(finding)), "witness-label").empty());
}

TEST(Svg, DiffOverlayAlarmIsWrittenUnderTheFirst) {
  PlotInput in = overlayExample();
  in.overlay->moves.clear();
  in.overlay->alarm = Alarm{"PS0064", "shape not monotonic", 6, ""};
  const ptree doc = parseSvg(renderToolpathSvg(in));
  const auto alarms = texts(doc, "alarm");
  ASSERT_EQ(alarms.size(), 1u);
  EXPECT_EQ(alarms[0], "ALARM (mutant:retract-angle) PS0064: shape not monotonic (line 6)");
  EXPECT_EQ(groupChildren(doc, "overlay", "path").size(), 0u);

  in.path.alarm = Alarm{"PS0062", "illegal cutting amount", 2, ""};
  const auto both = texts(parseSvg(renderToolpathSvg(in)), "alarm");
  ASSERT_EQ(both.size(), 2u);
  EXPECT_EQ(both[0], "ALARM (reference) PS0062: illegal cutting amount (line 2)");
}

TEST(Svg, DiffWithoutOverlayThePictureIsUnchanged) {
  const std::string svg = renderToolpathSvg(example());
  EXPECT_EQ(svg.find("id=\"overlay\""), std::string::npos);
  const auto labels = texts(parseSvg(svg), "legend-label");
  EXPECT_EQ(labels, (std::vector<std::string>{"finish contour", "rough contour", "rapid", "feed"}));
}

}  // namespace
}  // namespace cyclecert
