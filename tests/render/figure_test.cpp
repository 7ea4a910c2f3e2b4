// Whole figures: PNG decodes to the asked size with the curve inside its plot area only; SVG is
// well formed and grows with the number of branches; time windows restrict what is drawn.
#include "render/figure.h"

#include <gtest/gtest.h>

#include <string>

#include "core/analysis/checked_run.h"
#include "core/run/validate.h"
#include "paper_scene.h"
#include "png_decode.h"
#include "render/axes.h"
#include "render/cylinder_panel.h"
#include "render/layout.h"
#include "render/phase_jumps.h"
#include "render/style.h"
#include "render/track_window.h"
#include "svg_check.h"
#include "synthetic_run.h"

namespace vibro {
namespace {

constexpr std::uint32_t kBranch1 = 0x0072B2;  // series colour 0
constexpr std::uint32_t kBranch2 = 0xD55E00;  // series colour 1

std::uint32_t hex(render::Colour c) {
  return (static_cast<std::uint32_t>(c.r * 255 + 0.5) << 16) |
         (static_cast<std::uint32_t>(c.g * 255 + 0.5) << 8) |
         static_cast<std::uint32_t>(c.b * 255 + 0.5);
}

FigureSpec one_plot(PlotSpec plot, int width = 1200, int height = 800) {
  FigureSpec figure;
  figure.plots = {std::move(plot)};
  figure.width = width;
  figure.height = height;
  return figure;
}

TimePlot time_plot(std::vector<int> pellets) {
  TimePlot plot;
  plot.pellets = std::move(pellets);
  return plot;
}

struct ColourCount {
  long inside = 0, outside = 0;
};

ColourCount count_colour(const testing::Decoded& image, std::uint32_t rgb,
                         const render::Rect& area) {
  ColourCount count;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (testing::near_colour(image.at(x, y), rgb, 6))
        (area.contains({x + 0.5, y + 0.5}) ? count.inside : count.outside)++;
  return count;
}

class FigureTest : public ::testing::Test {
 protected:
  Model model = testing::synthetic_model();
  RunResult run = testing::synthetic_run(model, 6.0);
};

TEST(SeriesColours, AreTheOnesTheTestsLookFor) {
  EXPECT_EQ(hex(render::series_colour(0)), kBranch1);
  EXPECT_EQ(hex(render::series_colour(1)), kBranch2);
}

TEST_F(FigureTest, SyntheticRunHasBranchesAndImpacts) {
  EXPECT_GE(run.tracks[0].branches.size(), 5u);
  int limiter = 0, collision = 0;
  for (const Event& e : run.events)
    limiter += e.kind == EventKind::limiter, collision += e.kind == EventKind::collision;
  EXPECT_GE(limiter, 2);
  EXPECT_GE(collision, 1);
}

TEST_F(FigureTest, PhasePngHasTheAskedSizeAndTheCurveOnlyInsideThePlotArea) {
  const FigureSpec figure = one_plot(PlotSpec{}, 900, 640);
  const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
  ASSERT_TRUE(result.ok()) << result.error->message;
  EXPECT_EQ(result.content_type, "image/png");
  const auto image = testing::decode_png(result.bytes);
  ASSERT_EQ(image.width, 900);
  ASSERT_EQ(image.height, 640);
  const render::Rect area = render::figure_layout(figure)[0].plots[0];
  const ColourCount c = count_colour(image, kBranch1, area);
  EXPECT_GT(c.inside, 100);
  EXPECT_EQ(c.outside, 0);
  // White margins around the plot area: the top-left corner of the figure is background.
  EXPECT_EQ(image.at(2, 2), 0xFFFFFFFFu);
}

TEST_F(FigureTest, TimePanelDrawsEachPelletInItsColourInsideItsArea) {
  const FigureSpec figure = one_plot(time_plot({0, 1}));
  const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
  ASSERT_TRUE(result.ok()) << result.error->message;
  const auto image = testing::decode_png(result.bytes);
  const render::Rect area = render::figure_layout(figure)[0].plots[0];
  for (std::uint32_t colour : {kBranch1, kBranch2}) {
    const ColourCount c = count_colour(image, colour, area);
    EXPECT_GT(c.inside, 100);
    EXPECT_EQ(c.outside, 0);
  }
}

TEST_F(FigureTest, TwoPanelsShareTheImageSideBySide) {
  FigureSpec figure = one_plot(PlotSpec{});
  TimePlot both = time_plot({0});
  both.show_dphi = true;
  figure.plots.push_back(both);
  const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
  ASSERT_TRUE(result.ok()) << result.error->message;
  const auto image = testing::decode_png(result.bytes);
  const auto layouts = render::figure_layout(figure);
  EXPECT_GT(count_colour(image, kBranch1, layouts[0].plots[0]).inside, 50);
  EXPECT_GT(count_colour(image, kBranch1, layouts[1].plots[0]).inside, 50);
  EXPECT_GT(count_colour(image, kBranch1, layouts[1].plots[1]).inside, 50);
}

// A figure of several panels letters them (a), (b) at each cell's top left; a single panel not.
TEST_F(FigureTest, PanelsOfAFigureAreLettered) {
  auto ink_at_top_left = [&](const FigureSpec& figure, std::size_t panel) {
    const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
    EXPECT_TRUE(result.ok());
    const auto image = testing::decode_png(result.bytes);
    const render::Rect cell = render::figure_layout(figure)[panel].cell;
    long ink = 0;
    for (int y = static_cast<int>(cell.y) + 6; y < static_cast<int>(cell.y) + 30; ++y)
      for (int x = static_cast<int>(cell.x) + 8; x < static_cast<int>(cell.x) + 45; ++x)
        ink += (image.at(x, y) & 0xFF) < 100 ? 1 : 0;  // dark: text, not the white margin
    return ink;
  };
  FigureSpec two = one_plot(PlotSpec{});
  two.plots.push_back(time_plot({0}));
  EXPECT_GT(ink_at_top_left(two, 0), 20);
  EXPECT_GT(ink_at_top_left(two, 1), 20);
  EXPECT_EQ(ink_at_top_left(one_plot(PlotSpec{}), 0), 0);
}

TEST_F(FigureTest, TimeWindowRestrictsWhatIsDrawn) {
  // The first branch of pellet 1 ends at its first event: a window before it shows branch 1 only.
  const double first_event = run.tracks[0].branches[0].samples.back().t;
  PhasePlot early;
  early.t_to = 0.8 * first_event;
  const auto image =
      testing::decode_png(render_figure(one_plot(early), model, run, ImageFormat::png).bytes);
  const render::Rect area = render::figure_layout(one_plot(early))[0].plots[0];
  EXPECT_GT(count_colour(image, kBranch1, area).inside, 50);
  EXPECT_EQ(count_colour(image, kBranch2, area).inside, 0);

  const auto full =
      testing::decode_png(render_figure(one_plot(PlotSpec{}), model, run, ImageFormat::png).bytes);
  EXPECT_GT(count_colour(full, kBranch2, area).inside, 50);
}

TEST_F(FigureTest, BranchSelectionDrawsOnlyTheListedBranches) {
  PhasePlot plot;
  plot.branches = {2};
  const FigureSpec figure = one_plot(plot);
  const auto image = testing::decode_png(render_figure(figure, model, run, ImageFormat::png).bytes);
  const render::Rect area = render::figure_layout(figure)[0].plots[0];
  EXPECT_EQ(count_colour(image, kBranch1, area).inside, 0);
  EXPECT_GT(count_colour(image, kBranch2, area).inside, 50);
}

// Stroked paths (curves, guides) as opposed to glyph outlines, which cairo fills.
int stroked_paths(const std::string& svg) { return testing::count_of(svg, "fill:none;"); }

TEST_F(FigureTest, SvgIsWellFormedAndGrowsWithTheBranches) {
  const RenderResult result = render_figure(one_plot(PlotSpec{}), model, run, ImageFormat::svg);
  ASSERT_TRUE(result.ok()) << result.error->message;
  EXPECT_EQ(result.content_type, "image/svg+xml");
  const std::string svg(result.bytes.begin(), result.bytes.end());
  EXPECT_EQ(testing::xml_balance_error(svg), "");
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("width=\"1200px\""), std::string::npos);

  int previous = 0;
  for (int count : {1, 3, 6}) {
    PhasePlot plot;
    for (int b = 1; b <= count; ++b) plot.branches.push_back(b);
    const auto bytes = render_figure(one_plot(plot), model, run, ImageFormat::svg).bytes;
    const std::string text(bytes.begin(), bytes.end());
    const int paths = stroked_paths(text);
    EXPECT_GT(paths, previous) << count << " branches";
    previous = paths;
  }
}

TEST(RealRun, PaperSceneRendersToPngAndCompactSvg) {
  const Model model = testing::paper_model();
  ASSERT_FALSE(validate_model(model));
  const RunResult run = simulate(model, testing::paper_options());
  ASSERT_FALSE(run.tracks.empty());
  FigureSpec figure = one_plot(PlotSpec{});
  figure.plots.push_back(time_plot({0, 1}));
  const RenderResult png = render_figure(figure, model, run, ImageFormat::png);
  ASSERT_TRUE(png.ok()) << png.error->message;
  const auto image = testing::decode_png(png.bytes);
  EXPECT_EQ(image.width, 1200);
  EXPECT_GT(count_colour(image, kBranch1, render::figure_layout(figure)[0].plots[0]).inside, 20);

  const RenderResult svg = render_figure(one_plot(PlotSpec{}), model, run, ImageFormat::svg);
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  EXPECT_LT(svg.bytes.size(), 300u * 1024u);
  EXPECT_EQ(testing::xml_balance_error(std::string(svg.bytes.begin(), svg.bytes.end())), "");
}

// The φ̇ axis fits the data: 0 joins the range only near it (a pellet turning), and a pellet
// looping between 18 and 20 rad/s fills the plot's height instead of a strip at its top.
TEST(AxisRange, ZeroJoinsTheSpeedsOnlyNearThem) {
  using render::Range;
  auto with_zero = [](Range r) { return render::with_zero_if_near(r); };
  EXPECT_EQ(with_zero({5.6, 6.0}).lo, 5.6);
  EXPECT_EQ(with_zero({0.5, 10.0}).lo, 0.0);
  EXPECT_EQ(with_zero({-10.0, -1.0}).hi, 0.0);
  EXPECT_EQ(with_zero({-3.0, -2.0}).hi, -2.0);
  EXPECT_EQ(with_zero({-1.0, 2.0}).lo, -1.0);
}

TEST(RealRun, ALoopingPelletFillsThePlotHeight) {
  Model m;
  m.R = 0.5;
  m.pellets = {{0.1, 0.0, 20.0, {}}};  // over the top and round: φ̇ from 20 down to ~18 rad/s
  SimOptions o;
  o.t_end = 0.6;
  o.record = {true};
  const RunResult run = simulate(m, o);
  const FigureSpec figure = one_plot(PlotSpec{}, 900, 640);
  const RenderResult result = render_figure(figure, m, run, ImageFormat::png);
  ASSERT_TRUE(result.ok()) << result.error->message;
  const auto image = testing::decode_png(result.bytes);
  const render::Rect area = render::figure_layout(figure)[0].plots[0];
  int top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y)
    for (int x = static_cast<int>(area.x); x < static_cast<int>(area.right()); ++x)
      if (testing::near_colour(image.at(x, y), kBranch1, 6))
        top = std::min(top, y), bottom = std::max(bottom, y);
  ASSERT_GE(bottom, 0);
  EXPECT_GT((bottom - top) / area.h, 0.6) << top << " " << bottom;
}

// The paper scene ends with pellet 1 chattering to rest on limiter 2 (3π/2): its portrait
// marks that as a chatter jump to rest, though no branch ends at the accumulation time, and
// its legend then lists the chatter mark. Limiter impacts and collisions keep their marks.
TEST(RealRun, ThePortraitMarksAChatterSequenceToRest) {
  const Model model = testing::paper_model();
  const RunResult run = simulate(model, testing::paper_options());
  const PelletTrack* track = render::find_track(run, 0);
  ASSERT_NE(track, nullptr);
  const auto jumps = render::velocity_jumps(*track, run.events, PhasePlot{});
  int chatter = 0, limiter = 0, collision = 0;
  for (const render::Jump& j : jumps) {
    if (j.mark == render::event_mark(EventKind::chatter)) {
      ++chatter;
      EXPECT_NEAR(j.before.x, 1.5 * M_PI, 1e-9);
      EXPECT_EQ(j.after.y, 0.0);
    }
    limiter += j.mark == render::event_mark(EventKind::limiter);
    collision += j.mark == render::event_mark(EventKind::collision);
  }
  EXPECT_EQ(chatter, 1);
  EXPECT_GT(limiter, 0);
  EXPECT_GT(collision, 0);
}

// A jump between two branches that no listed impact explains is not marked as an impact (it
// was marked a limiter impact, the default kind); and a pellet that sticks and slips inside its
// friction cone with no limiter (the rest-in-cone preset) shows no impact mark or legend entry.
TEST(RealRun, AJumpWithoutAnImpactIsNotMarkedAsOne) {
  PelletTrack track{0, {{1, {{0.0, 0.1, 0.0}, {1.0, 0.1, 0.0}}}, {2, {{1.0, 0.1, 0.5}}}}};
  const auto jumps = render::velocity_jumps(track, {}, PhasePlot{});
  ASSERT_EQ(jumps.size(), 1u);
  EXPECT_EQ(jumps[0].mark, nullptr);

  Model cone;
  cone.R = 0.5;
  cone.alpha0 = 0.05;
  cone.pellets = {{0.2, 0.03, 0.0, {0.15, 2.0, 0.0}}};
  SimOptions o;
  o.t_end = 10.0;
  o.check = false;
  o.record = {true};
  const RunResult run = simulate(cone, o);
  for (const Event& e : run.events) EXPECT_EQ(render::event_mark(e.kind), nullptr);
  for (const render::Jump& j : render::velocity_jumps(run.tracks.at(0), run.events, PhasePlot{}))
    EXPECT_EQ(j.mark, nullptr) << "at phi = " << j.before.x;
  const RenderResult svg = render_figure(one_plot(PhasePlot{}), cone, run, ImageFormat::svg);
  ASSERT_TRUE(svg.ok());
  EXPECT_EQ(testing::count_of(std::string(svg.bytes.begin(), svg.bytes.end()), "impact"), 0);
}

// A scene sets the axes: a swing of ±0.3 rad on a φ axis of [−1, 1] fills the middle of the
// plot only; wrapped, the same swing a turn on is drawn on one turn, [−π, π).
TEST(RealRun, AScenesAxisLimitsAndWrapHold) {
  auto columns = [](const Model& m, const PhasePlot& plot, double t_end) {
    SimOptions o;
    o.t_end = t_end;
    o.record = {true};
    const RunResult run = simulate(m, o);
    const FigureSpec figure = one_plot(plot, 900, 640);
    const RenderResult result = render_figure(figure, m, run, ImageFormat::png);
    EXPECT_TRUE(result.ok());
    const auto image = testing::decode_png(result.bytes);
    const render::Rect area = render::figure_layout(figure)[0].plots[0];
    double left = 1.0, right = 0.0;
    for (int y = static_cast<int>(area.y); y < static_cast<int>(area.bottom()); ++y)
      for (int x = static_cast<int>(area.x); x < static_cast<int>(area.right()); ++x)
        if (testing::near_colour(image.at(x, y), kBranch1, 6)) {
          left = std::min(left, (x - area.x) / area.w);
          right = std::max(right, (x - area.x) / area.w);
        }
    return std::pair{left, right};
  };
  Model swing;
  swing.R = 0.5;
  swing.pellets = {{0.1, 0.3, 0.0, {}}};
  PhasePlot limited;
  limited.phi_range = AxisLimits{-1.0, 1.0};
  const auto [l1, r1] = columns(swing, limited, 1.0);  // past half a swing (0.71 s)
  EXPECT_NEAR(l1, 0.35, 0.03);
  EXPECT_NEAR(r1, 0.65, 0.03);

  // The same swing a turn further on: wrapped, it is drawn about 0 in the middle of [−π, π).
  Model turned = swing;
  turned.pellets[0].phi0 += 2.0 * M_PI;
  PhasePlot wrapped;
  wrapped.wrap = true;
  const auto [l2, r2] = columns(turned, wrapped, 1.0);
  EXPECT_NEAR(l2, 0.5 - 0.3 / (2.0 * M_PI), 0.01);
  EXPECT_NEAR(r2, 0.5 + 0.3 / (2.0 * M_PI), 0.01);
}

// API.md "Exports": in SVG the labels stay text, as <text> elements a reader can search and
// select, not glyph outlines; the XML stays well formed with '<' and '&' in a title.
TEST(RealRun, SvgKeepsItsLabelsAsText) {
  const Model model = testing::paper_model();
  const RunResult run = simulate(model, testing::paper_options());
  FigureSpec figure = one_plot(PlotSpec{});
  TimePlot titled = time_plot({0, 1});
  titled.title = "φ(t) < 2π & more";
  figure.plots.push_back(titled);
  const RenderResult svg = render_figure(figure, model, run, ImageFormat::svg);
  ASSERT_TRUE(svg.ok());
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_EQ(testing::xml_balance_error(text), "");
  EXPECT_EQ(text.find("<symbol"), std::string::npos);  // no glyph outlines
  for (const char* label : {">Phase portrait, pellet 1<", ">φ [rad]<", ">limiter 1 (mobile)<",
                            ">(a)<", ">φ(t) &lt; 2π &amp; more<", ">3π/2<"})
    EXPECT_NE(text.find(label), std::string::npos) << label;
  EXPECT_LT(text.rfind("<text"), text.rfind("</svg>"));
}

TEST(RealRun, CylinderPanelCompositesIntoPng) {
  if (!cylinder_panels_available()) GTEST_SKIP() << "built without render/gl";
  const Model model = testing::synthetic_model();
  const RunResult run = testing::synthetic_run(model, 3.0);
  CylinderPlot plot;
  const FigureSpec figure = one_plot(plot, 600, 500);
  const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
  if (!result.ok()) {
    // Only OSMesa missing at run time may fail, and it must name the panel.
    EXPECT_EQ(result.error->field, "plots[0].kind");
    GTEST_SKIP() << result.error->message;
  }
  const auto image = testing::decode_png(result.bytes);
  ASSERT_EQ(image.width, 600);
  const render::Rect area = render::figure_layout(figure)[0].plots[0];
  long coloured = 0;
  for (int y = static_cast<int>(area.y); y < area.bottom(); ++y)
    for (int x = 0; x < image.width; ++x) coloured += (image.at(x, y) & 0xFFFFFFu) != 0xFFFFFFu;
  EXPECT_GT(coloured, 1000);
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// The 3-D view says what it shows: φ at the floor's quarter turns, φ̇ at the axis's ends and the
// limiters by number, each inside the panel and drawn (ink under its anchor).
TEST(RealRun, TheCylinderViewIsLabelled) {
  if (!cylinder_panels_available()) GTEST_SKIP() << "built without render/gl";
  const Model model = testing::synthetic_model();
  const RunResult run = testing::synthetic_run(model, 3.0);
  CylinderPlot plot;
  const FigureSpec figure = one_plot(plot, 900, 700);
  const RenderResult result = render_figure(figure, model, run, ImageFormat::png);
  if (!result.ok()) GTEST_SKIP() << result.error->message;
  const auto image = testing::decode_png(result.bytes);
  const auto layouts = render::figure_layout(figure);
  const render::Style style = render::style_for(figure.width, figure.height);
  const render::PanelInput<CylinderPlot> in{plot, model, run, layouts[0], style};
  const auto labels = render::cylinder_labels(in);
  ASSERT_EQ(labels.size(), 4u + 2u + model.limiters.size());
  std::vector<std::string> texts;
  for (const auto& label : labels) texts.push_back(label.text);
  EXPECT_EQ(texts[0], "0");
  EXPECT_EQ(texts[1], "\u03c0/2");
  EXPECT_EQ(texts.back(), "limiter " + std::to_string(model.limiters.size()));
  const render::Rect& cell = layouts[0].cell;
  for (const auto& label : labels) {
    EXPECT_TRUE(cell.contains(label.at)) << label.text;
    long ink = 0;
    for (int y = static_cast<int>(label.at.y) - 5; y <= static_cast<int>(label.at.y) + 5; ++y)
      for (int x = static_cast<int>(label.at.x) - 12; x <= static_cast<int>(label.at.x) + 12; ++x)
        ink += (image.at(x, y) & 0xFF) < 90 ? 1 : 0;
    EXPECT_GT(ink, 3) << label.text;
  }
}

}  // namespace
}  // namespace vibro
