// The branch plot: a continued periodic motion drawn stable solid and unstable dashed, its
// bifurcations marked and named in the legend and beside the marks (as text in SVG), alone or
// over the bifurcation diagram of the same parameter; without a branch it is refused.
#include <gtest/gtest.h>

#include <string>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/sweep.h"
#include "png_decode.h"
#include "render/figure.h"
#include "svg_check.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

using testing::impact_oscillator;

SimOptions options() {
  SimOptions o;
  o.rtol = 1e-10;
  o.atol = 1e-13;
  o.check = false;
  return o;
}

struct Continued {
  ContinuationSpec spec{"model.pellets[0].Omega", 5.0, 100};
  OrbitBranch branch;
};

// From Ω = 6 down through the period doubling near 5.56.
Continued continued() {
  Continued c;
  OrbitSpec spec;
  spec.guess = {{0.15, 0.1}};
  const PeriodicOrbit orbit = find_periodic_orbit(impact_oscillator(6.0), options(), spec);
  EXPECT_TRUE(orbit.converged);
  c.branch = continue_orbit(impact_oscillator(6.0), options(), orbit, c.spec);
  EXPECT_TRUE(c.branch.reached);
  return c;
}

RenderResult draw(const Continued& c, ImageFormat format, const SweepSpec* sweep_spec = nullptr,
                  const SweepResult* sweep = nullptr) {
  FigureSpec figure;
  figure.plots = {BranchPlot{}};
  PanelData data{nullptr, std::nullopt, BranchData{c.branch, c.spec}};
  if (sweep_spec && sweep) data.sweep.emplace(SweepData{*sweep_spec, *sweep});
  return render_figure(figure, impact_oscillator(6.0), RunResult{}, format, data);
}

long dark_pixels(const testing::Decoded& image) {
  long n = 0;
  for (std::uint32_t p : image.argb)
    n += ((p >> 16) & 0xff) < 80 && (p & 0xff) < 80 && ((p >> 8) & 0xff) < 80;
  return n;
}

TEST(BranchPlot, DrawsStableAndUnstableStretchesAndNamesTheDoubling) {
  const Continued c = continued();
  const RenderResult svg = draw(c, ImageFormat::svg);
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_EQ(testing::xml_balance_error(text), "");
  EXPECT_EQ(testing::count_of(text, ">PD<"), 1);
  EXPECT_EQ(testing::count_of(text, ">stable periodic motion<"), 1);
  EXPECT_EQ(testing::count_of(text, ">unstable periodic motion<"), 1);
  EXPECT_GE(testing::count_of(text, "stroke-dasharray"), 1);
  const RenderResult png = draw(c, ImageFormat::png);
  ASSERT_TRUE(png.ok());
  EXPECT_GT(dark_pixels(testing::decode_png(png.bytes)), 2000);  // the curve, not only text
  const RenderResult pdf = draw(c, ImageFormat::pdf);
  ASSERT_TRUE(pdf.ok());
}

TEST(BranchPlot, DrawsOverTheBifurcationDiagramOfTheSameParameter) {
  const Continued c = continued();
  SweepSpec spec;
  spec.axis = {"model.pellets[0].Omega", 5.0, 6.0, 12};
  spec.transient = 30;
  spec.record = 8;
  const SweepResult sweep = run_sweep(impact_oscillator(5.0), options(), spec, {});
  const RenderResult alone = draw(c, ImageFormat::svg);
  const RenderResult over = draw(c, ImageFormat::svg, &spec, &sweep);
  ASSERT_TRUE(over.ok()) << over.error->message;
  const std::string text(over.bytes.begin(), over.bytes.end());
  EXPECT_EQ(testing::count_of(text, ">PD<"), 1);
  EXPECT_GT(over.bytes.size(), alone.bytes.size());  // the cloud of section points beneath
}

TEST(BranchPlot, WithoutABranchItIsRefused) {
  FigureSpec figure;
  figure.plots = {BranchPlot{}};
  const RenderResult r =
      render_figure(figure, impact_oscillator(6.0), RunResult{}, ImageFormat::png);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error->field, "plots[0].kind");
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

// The bifurcation_curves kind: the curves in the plane of the two parameters, named in the
// legend; without curves it is refused, naming the panel's kind.
TEST(BifurcationCurvesPlot, DrawsTheCurvesAloneAndWithoutThemIsRefused) {
  const ContinuationSpec spec{"model.pellets[0].Omega", 5.0, 100};
  const FollowSpec follow{BifurcationKind::period_doubling, "model.limiters[0].k", 0.6, 0.95};
  OrbitBranch branch;
  const std::vector<BifurcationCurve> curves = {
      {BifurcationKind::period_doubling, {{5.45, 0.6}, {5.56, 0.8}, {5.58, 0.95}}, true, true, ""}};
  FigureSpec figure;
  BranchPlot plot;
  plot.curves = true;
  figure.plots = {plot};
  const PanelData data{nullptr, std::nullopt, BranchData{branch, spec, &curves, &follow}};
  const RenderResult svg =
      render_figure(figure, impact_oscillator(6.0), RunResult{}, ImageFormat::svg, data);
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_NE(text.find("Bifurcation curves"), std::string::npos);
  EXPECT_NE(text.find("period doubling"), std::string::npos);
  EXPECT_NE(text.find("k of limiter 1"), std::string::npos);

  const PanelData without{nullptr, std::nullopt, BranchData{branch, spec}};
  const RenderResult refused =
      render_figure(figure, impact_oscillator(6.0), RunResult{}, ImageFormat::png, without);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error->field, "plots[0].kind");
}

}  // namespace
}  // namespace vibro
