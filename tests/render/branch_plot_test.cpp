// The branch plot: a continued periodic motion drawn stable solid, unstable dashed and neutral
// dotted, its bifurcations marked and named in the legend and beside the marks (as text in SVG),
// alone or over the bifurcation diagram of the same parameter; without a branch it is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/sweep.h"
#include "png_decode.h"
#include "render/branch_marks.h"
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

// A frictionless forced pendulum's small swing, far from its stop, never strikes: its map keeps
// areas and its multipliers lie on the unit circle. Its branch is drawn neutral (dotted, named so),
// not unstable.
TEST(BranchPlot, DrawsANeutralBranchDottedNotUnstable) {
  Model model;
  model.pellets = {{0.1, 0.0, 0.01506, {0.01035936, 15.06011952143807, M_PI / 2}}};
  model.limiters = {{1.0, 0.7, false, -1, {}}};
  OrbitSpec spec;
  spec.transient = 0;
  spec.guess = {{0.0, 0.01506}};
  const PeriodicOrbit orbit = find_periodic_orbit(model, options(), spec);
  ASSERT_TRUE(orbit.converged) << orbit.message;
  Continued c;
  c.spec = {"model.pellets[0].Omega", 16.0, 12};
  c.branch = continue_orbit(model, options(), orbit, c.spec);
  ASSERT_GE(c.branch.points.size(), 3u) << c.branch.message;
  FigureSpec figure;
  figure.plots = {BranchPlot{}};
  const RenderResult svg = render_figure(figure, model, RunResult{}, ImageFormat::svg,
                                         {nullptr, std::nullopt, {{c.branch, c.spec}}});
  ASSERT_TRUE(svg.ok()) << svg.error->message;
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_EQ(testing::count_of(text, ">unstable periodic motion<"), 0);
  EXPECT_EQ(testing::count_of(text, ">stable periodic motion<"), 0);
  EXPECT_EQ(testing::count_of(text, ">neutral periodic motion (a multiplier on the unit circle)<"),
            1);
  EXPECT_GE(testing::count_of(text, "stroke-linecap:round"), 2);  // the line and its swatch
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

// A branch made by hand: φ̇ at the section along Ω, stable throughout.
OrbitBranch hand_branch(const std::vector<std::pair<double, PhasePoint>>& points) {
  OrbitBranch b;
  for (const auto& [value, state] : points) b.points.push_back({value, {state}, {}, true, 1.0});
  return b;
}

std::string svg_of(const OrbitBranch& branch, const ContinuationSpec& spec) {
  FigureSpec figure;
  figure.plots = {BranchPlot{}};
  const RenderResult r = render_figure(figure, impact_oscillator(6.0), RunResult{},
                                       ImageFormat::svg, {nullptr, std::nullopt, {{branch, spec}}});
  EXPECT_TRUE(r.ok()) << r.error->message;
  return std::string(r.bytes.begin(), r.bytes.end());
}

// Where an impact crosses the section time, the section's φ̇ turns over at the stop (k = 0.8:
// −2.85 after the impact, +3.56 before it): the line is broken there and the legend says why,
// not drawn as a vertical stroke a reader takes for a bifurcation. A turn away from the stop, or
// one that is no rebound, is not a crossing.
TEST(BranchPlot, TheLineBreaksWhereAnImpactCrossesTheSectionTime) {
  const OrbitBranch crossing = hand_branch(
      {{5.0, {0.02, -2.80}}, {5.1, {0.01, -2.85}}, {5.2, {0.01, 3.5625}}, {5.3, {0.03, 3.60}}});
  EXPECT_EQ(render::section_crossings(crossing, impact_oscillator(6.0), 0),
            std::vector<std::size_t>{2});
  const ContinuationSpec spec{"model.pellets[0].Omega", 5.3, 10};
  const std::string text = svg_of(crossing, spec);
  EXPECT_EQ(testing::count_of(text, "an impact crosses t = kT there"), 1);
  const OrbitBranch far = hand_branch({{5.0, {1.5, -2.85}}, {5.1, {1.5, 3.5625}}});
  EXPECT_TRUE(render::section_crossings(far, impact_oscillator(6.0), 0).empty());
  const OrbitBranch no_rebound = hand_branch({{5.0, {0.01, -2.85}}, {5.1, {0.01, 9.0}}});
  EXPECT_TRUE(render::section_crossings(no_rebound, impact_oscillator(6.0), 0).empty());
  EXPECT_EQ(testing::count_of(svg_of(no_rebound, spec), "an impact crosses"), 0);
}

// The legend names only what the plot draws. At a grazing the section's φ̇ passes through zero,
// here from round-off (+8.9e-15) to the impacting motion's −2.8e-6 (issue 34's reproducer 3 as
// it was drawn, its stop at 0.0010478): no impact crosses the section there, and no break is
// drawn or named (a break's open circles lay under the grazing's mark, the legend named it). Nor
// is a break outside the plot's window named: drawn alone the crossing below is, over a sweep
// from 2.5 it is clipped away.
TEST(BranchPlot, TheLegendNamesNoBreakItDoesNotDraw) {
  const OrbitBranch grazing = hand_branch({{3.1320584542, {0.0010477778615, 8.818e-15}},
                                           {3.1320915433, {0.0010477999999, 8.879e-15}},
                                           {3.1323573101, {0.0010477999172, -2.8476405e-6}},
                                           {3.1326230769, {0.0010477996699, -5.6877776e-6}}});
  EXPECT_TRUE(render::section_crossings(grazing, impact_oscillator(6.0), 0).empty());
  const ContinuationSpec near_spec{"model.pellets[0].Omega", 3.1326230769, 10};
  EXPECT_EQ(testing::count_of(svg_of(grazing, near_spec), "an impact crosses"), 0);

  const OrbitBranch crossing = hand_branch(
      {{2.0, {0.01, -2.85}}, {2.1, {0.01, 3.5625}}, {2.6, {0.02, 3.6}}, {2.9, {0.03, 3.7}}});
  const ContinuationSpec spec{"model.pellets[0].Omega", 2.9, 10};
  EXPECT_EQ(testing::count_of(svg_of(crossing, spec), "an impact crosses"), 1);
  SweepSpec sweep;
  sweep.axis = {"model.pellets[0].Omega", 2.5, 3.0, 2};
  FigureSpec figure;
  figure.plots = {SweepPlot{}};
  const RenderResult over =
      render_figure(figure, impact_oscillator(6.0), RunResult{}, ImageFormat::svg,
                    {nullptr, {{sweep, SweepResult{}}}, {{crossing, spec}}});
  ASSERT_TRUE(over.ok()) << over.error->message;
  const std::string text(over.bytes.begin(), over.bytes.end());
  EXPECT_EQ(testing::count_of(text, "an impact crosses"), 0);
  EXPECT_EQ(testing::count_of(text, ">stable periodic motion<"), 1);
}

// A fold and a period doubling at one value are a multiplier through infinity: one mark, named
// so. A bifurcation outside the plot's window is named in the legend with its value.
TEST(BranchPlot, AFoldAndADoublingAtOneValueAreOneMarkAndOnesOutsideTheWindowAreSaid) {
  OrbitBranch b = hand_branch({{2.0, {0.5, 1.2}}, {2.5, {0.5, 1.0}}, {3.0, {0.5, 0.9}}});
  b.bifurcations = {{BifurcationKind::fold, 2.000471220735955, {{0.5, 1.2033}}, {}, {}},
                    {BifurcationKind::period_doubling, 2.0004714393322716, {{0.5, 1.2042}}, {}, {}},
                    {BifurcationKind::period_doubling, 2.7, {{0.5, 0.95}}, {}, {}}};
  const auto marked = render::marked_bifurcations(b);
  ASSERT_EQ(marked.size(), 2u);
  EXPECT_FALSE(marked[0].kind.has_value());
  EXPECT_EQ(marked[1].kind, BifurcationKind::period_doubling);
  const ContinuationSpec spec{"model.pellets[0].Omega", 3.0, 10};
  std::string text = svg_of(b, spec);
  EXPECT_EQ(testing::count_of(text, ">F<"), 0);
  EXPECT_EQ(testing::count_of(text, ">PD<"), 1);
  EXPECT_EQ(testing::count_of(text, "a multiplier through"), 1);

  // Over a sweep from 2.5: the one at 2.0005 lies left of the window.
  SweepSpec sweep;
  sweep.axis = {"model.pellets[0].Omega", 2.5, 3.0, 2};
  SweepResult none;
  FigureSpec figure;
  figure.plots = {SweepPlot{}};
  const RenderResult over =
      render_figure(figure, impact_oscillator(6.0), RunResult{}, ImageFormat::svg,
                    {nullptr, {{sweep, none}}, {{b, spec}}});
  ASSERT_TRUE(over.ok()) << over.error->message;
  text.assign(over.bytes.begin(), over.bytes.end());
  EXPECT_EQ(testing::count_of(text, "at 2.0005, outside the plot"), 1) << text.size();
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
