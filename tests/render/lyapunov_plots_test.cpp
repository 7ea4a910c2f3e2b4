// The Lyapunov plots of a sweep: the map colours its cells in the diverging scale (blue below 0,
// red above) with a colour bar beside it, and names the cells it has no colour for (no value,
// −∞); the line plot draws each direction of continuation; the SVG keeps the colour bar's label
// as text; and a sweep that computed no exponents is refused, naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "png_decode.h"
#include "render/colour_bar.h"
#include "render/figure.h"
#include "render/layout.h"
#include "svg_check.h"
#include "swept.h"

namespace vibro {
namespace {

constexpr const char* kLabel = "largest Lyapunov exponent [1/s]";
constexpr std::uint32_t kMostNegative = 0x313695, kMostPositive = 0xa50026;  // the scale's ends

using testing::draw;
using testing::figure_of;
using testing::Swept;

// A 2-D grid whose exponents rise from −0.4 on the left to +0.4 on the right; in the bottom row
// one cell has no exponent, one has −∞ and one is not trusted.
Swept grid() {
  Swept s;
  s.spec.axis = {"model.pellets[0].Omega", 3.0, 8.0, 24};
  s.spec.axis2 = SweepAxis{"model.pellets[0].F0", 0.1, 0.5, 12};
  s.spec.lyapunov = true;
  for (int j = 0; j < s.spec.axis2->count; ++j)
    for (int i = 0; i < s.spec.axis.count; ++i) {
      SweepRun run;
      run.value = s.spec.axis.value(i);
      run.value2 = s.spec.axis2->value(j);
      if (j > 0 || i > 1) run.lyapunov = -0.4 + 0.8 * i / (s.spec.axis.count - 1);
      if (j == 0 && i == 1) run.lyapunov = -std::numeric_limits<double>::infinity();
      run.trusted = !(j == 0 && i == 2);
      s.result.runs.push_back(run);
    }
  return s;
}

// A 1-D sweep up and down whose exponent changes sign, with one −∞ and one run without it.
Swept line() {
  Swept s;
  s.spec.axis = {"model.pellets[0].Omega", 3.0, 9.0, 40};
  s.spec.continuation = Continuation::both;
  s.spec.lyapunov = true;
  for (int direction : {1, -1})
    for (int i = 0; i < s.spec.axis.count; ++i) {
      SweepRun run;
      run.value = s.spec.axis.value(i);
      run.direction = direction;
      run.lyapunov = 0.3 * std::sin(run.value * direction);
      if (i == 5) run.lyapunov = -std::numeric_limits<double>::infinity();
      if (i == 9) run.lyapunov.reset();
      run.trusted = i < 30;
      s.result.runs.push_back(run);
    }
  return s;
}

// A plot drawn as PNG, and where its plot area is.
struct Drawn {
  testing::Decoded image;
  render::Rect area;
  int left = 0, right = 0;  // the area's columns, 2 px in from its frame

  // Pixels within `tolerance` of the colour in the columns [x0, x1) of the plot area's rows.
  long count_near(int x0, int x1, std::uint32_t rgb, int tolerance) const {
    long n = 0;
    for (int y = static_cast<int>(area.y) + 1; y < static_cast<int>(area.bottom()) - 1; ++y)
      for (int x = x0; x < x1; ++x)
        n += testing::near_colour(image.at(x, y), rgb, tolerance) ? 1 : 0;
    return n;
  }
};

Drawn draw_png(SweepView kind, const Swept& s) {
  const RenderResult png = draw(kind, s, ImageFormat::png);
  EXPECT_TRUE(png.ok()) << png.error->message;
  Drawn d{testing::decode_png(png.bytes),
          render::figure_layout(figure_of(kind)).front().plots.front()};
  d.left = static_cast<int>(d.area.x) + 2;
  d.right = static_cast<int>(d.area.right()) - 2;
  EXPECT_EQ(d.image.width, 1200);
  return d;
}

// The SVG of a plot, checked well formed.
std::string draw_svg(SweepView kind, const Swept& s) {
  const RenderResult svg = draw(kind, s, ImageFormat::svg);
  EXPECT_TRUE(svg.ok());
  const std::string text(svg.bytes.begin(), svg.bytes.end());
  EXPECT_EQ(testing::xml_balance_error(text), "");
  return text;
}

TEST(LyapunovPlots, TheMapColoursItsCellsAndItsColourBarBlueToRed) {
  const Swept s = grid();
  const Drawn d = draw_png(SweepView::lyapunov_map, s);
  ASSERT_FALSE(d.image.argb.empty());
  const long cell = static_cast<long>(d.area.w / 24) * static_cast<long>(d.area.h / 12);
  // The first and last columns take the scale's ends; the cell without a value is grey, the −∞
  // one white.
  EXPECT_GT(d.count_near(d.left, d.right, kMostNegative, 2), 8 * cell);
  EXPECT_GT(d.count_near(d.left, d.right, kMostPositive, 2), 8 * cell);
  EXPECT_GT(d.count_near(d.left, d.right, 0x999999, 0), cell / 2);
  EXPECT_GT(d.count_near(d.left, d.right, 0xffffff, 0), cell / 2);
  // The colour bar beside the plot runs through both ends and the pale yellow of 0.
  const int bar_from = static_cast<int>(d.area.right()) + 4, bar_to = d.image.width;
  EXPECT_GT(d.count_near(bar_from, bar_to, kMostNegative, 12), 20);
  EXPECT_GT(d.count_near(bar_from, bar_to, kMostPositive, 12), 20);
  EXPECT_GT(d.count_near(bar_from, bar_to, 0xffffbf, 12), 20);

  const std::string text = draw_svg(SweepView::lyapunov_map, s);
  for (const char* label : {kLabel, "no value", "\u2212\u221e: pellets held", "not trusted"})
    EXPECT_EQ(testing::count_of(text, label), 1) << label;
}

TEST(LyapunovPlots, TheLineDrawsEachDirectionAgainstTheParameter) {
  const Swept s = line();
  const Drawn d = draw_png(SweepView::lyapunov, s);
  ASSERT_FALSE(d.image.argb.empty());
  EXPECT_GT(d.count_near(d.left, d.right, 0x0072b2, 24), 500);  // swept up
  EXPECT_GT(d.count_near(d.left, d.right, 0xd55e00, 24), 500);  // swept down

  const std::string text = draw_svg(SweepView::lyapunov, s);
  EXPECT_EQ(testing::count_of(text, kLabel), 1);  // the y axis
  for (const char* entry : {"swept up", "swept down", "not trusted", "\u2212\u221e: pellets held"})
    EXPECT_EQ(testing::count_of(text, entry), 1) << entry;
  // The parameter is where a click on the image names it, as on a bifurcation diagram.
  const auto axis = parameter_axis(figure_of(SweepView::lyapunov), s.spec);
  ASSERT_TRUE(axis);
  EXPECT_LT(axis->from, 3.0);
  EXPECT_GT(axis->to, 9.0);
}

// A few runs far beyond the rest take the scale's ends instead of setting them; a small sweep's
// ends reach its largest magnitude.
TEST(LyapunovPlots, AFewFarValuesDoNotWashOutTheScale) {
  std::vector<double> values(300, -0.27);
  values.push_back(0.9);
  values.push_back(-std::numeric_limits<double>::infinity());  // named in the legend, not scaled
  const render::DivergingScale scale = render::diverging_scale(values);
  EXPECT_DOUBLE_EQ(scale.limit, 0.3);
  EXPECT_TRUE(scale.beyond_high);
  EXPECT_FALSE(scale.beyond_low);
  const render::Colour end = scale.at(0.3), far = scale.at(0.9);
  EXPECT_NEAR(end.r, far.r, 1e-12);
  EXPECT_NEAR(end.g, far.g, 1e-12);
  EXPECT_NEAR(end.b, far.b, 1e-12);
  EXPECT_DOUBLE_EQ(render::diverging_scale({-0.27, 0.9}).limit, 1.0);
  EXPECT_DOUBLE_EQ(render::diverging_scale({}).limit, 1.0);
}

TEST(LyapunovPlots, ASweepWithoutExponentsIsRefusedNamingTheField) {
  for (SweepView kind : {SweepView::lyapunov, SweepView::lyapunov_map}) {
    Swept s = kind == SweepView::lyapunov ? line() : grid();
    s.spec.lyapunov = false;
    const RenderResult r = draw(kind, s, ImageFormat::png);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error->field, "sweep.lyapunov");
    EXPECT_NE(r.error->message.find("no Lyapunov exponents"), std::string::npos);
  }
  // A line of exponents against one parameter cannot draw a 2-D sweep; the map can draw a 1-D one.
  const auto two_d = validate_sweep_plot(SweepView::lyapunov, grid().spec);
  ASSERT_TRUE(two_d);
  EXPECT_EQ(two_d->field, "sweep.parameter2");
  EXPECT_FALSE(validate_sweep_plot(SweepView::lyapunov_map, line().spec));
  EXPECT_TRUE(draw(SweepView::lyapunov_map, line(), ImageFormat::png).ok());
}

}  // namespace
}  // namespace vibro
