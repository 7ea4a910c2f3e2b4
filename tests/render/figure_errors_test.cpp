// Bad requests are error values naming the field, never exceptions or images.
#include <gtest/gtest.h>

#include "render/figure.h"
#include "synthetic_run.h"

namespace vibro {
namespace {

class FigureErrors : public ::testing::Test {
 protected:
  std::string field_of(const FigureSpec& figure, ImageFormat format = ImageFormat::png) {
    const RenderResult result = render_figure(figure, model, run, format);
    EXPECT_FALSE(result.ok());
    EXPECT_TRUE(result.bytes.empty());
    if (result.ok()) return "";
    EXPECT_FALSE(result.error->message.empty());
    return result.error->field;
  }

  FigureSpec figure() {
    FigureSpec f;
    f.plots = {PlotSpec{}};
    return f;
  }

  Model model = testing::synthetic_model();
  RunResult run = testing::synthetic_run(model, 1.0);
};

TEST_F(FigureErrors, PelletOutOfRange) {
  FigureSpec f = figure();
  f.plots.push_back(PlotSpec{});
  std::get<PhasePlot>(f.plots[1]).pellet = 2;
  EXPECT_EQ(field_of(f), "plots[1].pellet");
  std::get<PhasePlot>(f.plots[1]).pellet = -1;
  EXPECT_EQ(field_of(f), "plots[1].pellet");
  TimePlot time;
  time.pellets = {0, 5};
  f.plots[1] = time;
  EXPECT_EQ(field_of(f), "plots[1].pellets[1]");
}

TEST_F(FigureErrors, SizeZeroOrOverTheLimit) {
  FigureSpec f = figure();
  f.width = 0;
  EXPECT_EQ(field_of(f), "width");
  f.width = 1200;
  f.height = Limits{}.height + 1;
  EXPECT_EQ(field_of(f), "height");
}

// The figure's size and panel count against the Limits it is given (the server's, tightened),
// each side within its limit and the area over its own: the error names width, as a server's
// 400 always has.
TEST_F(FigureErrors, SizeAgainstTightenedLimits) {
  Limits limits;
  limits.width = 1000;
  limits.pixels = 500'000;
  FigureSpec f = figure();
  f.width = 1001;
  f.height = 400;
  auto error = validate_figure(f, model, ImageFormat::png, limits);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "width");
  EXPECT_EQ(error->message, "must be in [64, 1000] px");
  f.width = 1000;
  f.height = 600;
  error = validate_figure(f, model, ImageFormat::png, limits);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "width");
  EXPECT_EQ(error->message, "width × height = 600000 px is over the server's limit of 500000 px");
  f.height = 500;
  EXPECT_FALSE(validate_figure(f, model, ImageFormat::png, limits));
  limits.plots = 1;
  f.plots.push_back(PlotSpec{});
  error = validate_figure(f, model, ImageFormat::png, limits);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "plots");
}

TEST_F(FigureErrors, SvgWithA3DPanel) {
  FigureSpec f = figure();
  f.plots.push_back(CylinderPlot{});
  EXPECT_EQ(field_of(f, ImageFormat::svg), "plots[1].kind");
  const RenderResult result = render_figure(f, model, run, ImageFormat::svg);
  EXPECT_NE(result.error->message.find("PNG"), std::string::npos);
}

TEST_F(FigureErrors, TrackNotRecorded) {
  RunResult only_first = run;
  only_first.tracks.resize(1);
  FigureSpec f = figure();
  std::get<PhasePlot>(f.plots[0]).pellet = 1;
  const RenderResult result = render_figure(f, model, only_first, ImageFormat::png);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error->field, "plots[0].pellet");
}

TEST_F(FigureErrors, WindowsBranchesAndOverlays) {
  FigureSpec f = figure();
  std::get<PhasePlot>(f.plots[0]).t_from = 2.0;
  std::get<PhasePlot>(f.plots[0]).t_to = 1.0;
  EXPECT_EQ(field_of(f), "plots[0].t_to");
  f = figure();
  std::get<PhasePlot>(f.plots[0]).t_from = -1.0;
  EXPECT_EQ(field_of(f), "plots[0].t_from");
  f = figure();
  std::get<PhasePlot>(f.plots[0]).branches = {1, 0};
  EXPECT_EQ(field_of(f), "plots[0].branches[1]");
  f = figure();
  std::get<PhasePlot>(f.plots[0]).first_integral_through =
      PhasePoint{0.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_EQ(field_of(f), "plots[0].first_integral");  // the JSON field
}

TEST_F(FigureErrors, NoPlots) {
  FigureSpec f = figure();
  f.plots.clear();
  EXPECT_EQ(field_of(f), "plots");
  f.plots.assign(Limits{}.plots + 1, PlotSpec{});
  EXPECT_EQ(field_of(f), "plots");
}

TEST_F(FigureErrors, ValidateBeforeSimulating) {
  FigureSpec f = figure();
  std::get<PhasePlot>(f.plots[0]).pellet = 7;
  const auto error = validate_figure(f, model, ImageFormat::png);
  ASSERT_TRUE(error);
  EXPECT_EQ(error->field, "plots[0].pellet");
  EXPECT_FALSE(validate_figure(figure(), model, ImageFormat::svg));
}

// A spec built in code is held to what a scene's reader holds it to: the same checks
// (render/plot_validate.h) for its axis ranges and its camera.
TEST_F(FigureErrors, RangesAndCamerasBuiltInCode) {
  FigureSpec f = figure();
  std::get<PhasePlot>(f.plots[0]).dphi_range = AxisLimits{1.0, 1.0};
  EXPECT_EQ(field_of(f), "plots[0].dphi_range");
  CylinderPlot cylinder;
  cylinder.camera.elevation_deg = 95.0;
  f.plots = {cylinder};
  EXPECT_EQ(field_of(f), "plots[0].camera.elevation");
  std::get<CylinderPlot>(f.plots[0]).camera = Camera{};
  std::get<CylinderPlot>(f.plots[0]).camera.distance = 0.5;
  EXPECT_EQ(field_of(f), "plots[0].camera.distance");
}

}  // namespace
}  // namespace vibro
