// The mechanism panel on the paper scene: pellets drawn where the run had them (against the exact
// state the simulator keeps at a stop, not the samples the panel reads), a resting pellet at its
// limiter, labels as SVG text, the mobile limiter told apart, the force arrow as long as |F| and
// turned by its sign, and a time outside the run refused.
#include "render/mechanism_panel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/analysis/checked_run.h"
#include "paper_scene.h"
#include "png_decode.h"
#include "render/figure.h"
#include "render/layout.h"
#include "svg_check.h"

namespace vibro {
namespace {

constexpr std::uint32_t kPellet1 = 0x0072B2;  // series colour 0
constexpr std::uint32_t kPellet2 = 0xD55E00;  // series colour 1
constexpr double kPi = std::numbers::pi;

FigureSpec mechanism_at(double t, int width = 900, int height = 700) {
  MechanismPlot plot;
  plot.t = t;
  return {{plot}, width, height};
}

// The paper scene to 9 s: pellet 1 chatters into limiter 2 at 7.26 s and rests there.
class MechanismPanel : public ::testing::Test {
 protected:
  static SimOptions options(std::vector<double> stops = {}) {
    SimOptions o = testing::paper_options();
    o.t_end = 9.0;
    o.check = false;
    o.stops = std::move(stops);
    return o;
  }

  testing::Decoded png(const FigureSpec& figure) {
    const RenderResult r = render_figure(figure, model, run, ImageFormat::png);
    EXPECT_TRUE(r.ok()) << r.error->field << ": " << r.error->message;
    return testing::decode_png(r.bytes);
  }

  // Where the panel draws a point of the circle at angle φ, in image pixels.
  render::Point pixel_at(const FigureSpec& figure, double phi) const {
    const render::Transform frame =
        render::mechanism_frame(render::figure_layout(figure)[0].plots[0], model.R);
    return frame.to_pixel(model.R * std::sin(phi), -model.R * std::cos(phi));
  }

  // Pixels of a colour in the column `half` px either side of x, above and below the row y
  // (farther than `gap` px from it).
  static std::pair<int, int> above_and_below(const testing::Decoded& image, render::Point at,
                                             int half, int gap, std::uint32_t rgb) {
    int above = 0, below = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = static_cast<int>(at.x) - half; x <= static_cast<int>(at.x) + half; ++x)
        if (std::abs(y - at.y) > gap && testing::near_colour(image.at(x, y), rgb, 6))
          (y < at.y ? above : below)++;
    return {above, below};
  }

  static bool colour_at(const testing::Decoded& image, render::Point p, std::uint32_t rgb) {
    return testing::near_colour(image.at(static_cast<int>(p.x), static_cast<int>(p.y)), rgb, 6);
  }

  Model model = testing::paper_model();
  RunResult run = simulate(model, options());
};

TEST_F(MechanismPanel, DrawsEachPelletInItsColourWhereTheRunHadIt) {
  const double t = 2.0;
  const RunResult exact = simulate(model, options({t}));
  ASSERT_EQ(exact.stops.size(), 1u);
  const FigureSpec figure = mechanism_at(t);
  const auto image = png(figure);
  const render::Point p1 = pixel_at(figure, exact.stops[0].pellets[0].phi);
  const render::Point p2 = pixel_at(figure, exact.stops[0].pellets[1].phi);
  ASSERT_GT(std::hypot(p1.x - p2.x, p1.y - p2.y), 30.0)
      << "the pellets should stand apart at t = 2 s";
  EXPECT_TRUE(colour_at(image, p1, kPellet1));
  EXPECT_TRUE(colour_at(image, p2, kPellet2));
  // Where the other pellet would be had the panel swapped them, or drawn them at t = 0.
  EXPECT_FALSE(colour_at(image, p2, kPellet1));
  EXPECT_FALSE(colour_at(image, pixel_at(figure, model.pellets[1].phi0), kPellet2));
}

TEST_F(MechanismPanel, DrawsARestingPelletAtItsLimiter) {
  ASSERT_EQ(run.summary.final[0].state, PelletState::resting_at_limiter);
  const FigureSpec figure = mechanism_at(8.5);
  // Limiter 2 at −π/2, which pellet 1 reaches over the top at 3π/2: the left of the circle.
  EXPECT_TRUE(colour_at(png(figure), pixel_at(figure, model.limiters[1].angle), kPellet1));
}

TEST_F(MechanismPanel, SvgIsWellFormedWithItsLabelsAsText) {
  const RenderResult r = render_figure(mechanism_at(2.0), model, run, ImageFormat::svg);
  ASSERT_TRUE(r.ok()) << r.error->message;
  const std::string svg(r.bytes.begin(), r.bytes.end());
  EXPECT_EQ(testing::xml_balance_error(svg), "");
  for (const char* label : {">Mechanism at t = 2 s<", ">1<", ">2<", ">limiter 1 (mobile)<",
                            ">limiter 2<", ">R = 0.5 m<", ">g<", ">\u03c6 = 0<", ">F\u2081 = "})
    EXPECT_EQ(testing::count_of(svg, label), 1) << label;
  EXPECT_GE(testing::count_of(svg, "<text"), 12);
  const RenderResult pdf = render_figure(mechanism_at(2.0), model, run, ImageFormat::pdf);
  ASSERT_TRUE(pdf.ok());
  EXPECT_EQ(std::string(pdf.bytes.begin(), pdf.bytes.begin() + 5), "%PDF-");
}

TEST_F(MechanismPanel, DrawsTheMobileLimiterDashed) {
  const auto svg_of = [&](const Model& m) {
    const RenderResult r = render_figure(mechanism_at(0.0), m, run, ImageFormat::svg);
    EXPECT_TRUE(r.ok());
    return std::string(r.bytes.begin(), r.bytes.end());
  };
  Model fixed = model;
  fixed.limiters[0].mobile = false;
  const std::string mobile_svg = svg_of(model), fixed_svg = svg_of(fixed);
  EXPECT_GT(testing::count_of(mobile_svg, "stroke-dasharray"),
            testing::count_of(fixed_svg, "stroke-dasharray"));
  EXPECT_EQ(testing::count_of(fixed_svg, "(mobile)"), 0);
}

// Pellet 1 rests at the left of the circle from 7.26 s while F₁ = 1.2 cos(3.3 t) N turns: at
// 2π·4/3.3 s it is +1.2 N, at 8 s +0.36 N, at 2π·4.5/3.3 s −1.2 N. There +φ points down.
TEST_F(MechanismPanel, TheForceArrowIsAsLongAsTheForceAndTurnsWithItsSign) {
  const double strongest = 2.0 * kPi * 4.0 / 3.3, weaker = 8.0, reversed = 2.0 * kPi * 4.5 / 3.3;
  const auto pellet_1 = [&](double t) {
    const FigureSpec figure = mechanism_at(t);
    return above_and_below(png(figure), pixel_at(figure, 1.5 * kPi), 3, 12, kPellet1);
  };
  const auto [strong_above, strong_below] = pellet_1(strongest);
  const auto [weak_above, weak_below] = pellet_1(weaker);
  const auto [reversed_above, reversed_below] = pellet_1(reversed);
  EXPECT_GT(strong_below, weak_below + 40);  // a longer arrow down
  EXPECT_GT(weak_below, 20);
  EXPECT_LT(strong_above, 10);
  EXPECT_GT(reversed_above, weak_below + 40);  // as long as the strongest, up
  EXPECT_LT(reversed_below, 10);
}

TEST_F(MechanismPanel, RefusesATimeOutsideTheRun) {
  for (double t : {-1.0, std::numeric_limits<double>::quiet_NaN(), 9.5}) {
    const RenderResult r = render_figure(mechanism_at(t), model, run, ImageFormat::png);
    ASSERT_FALSE(r.ok()) << t;
    EXPECT_EQ(r.error->field, "plots[0].t") << t;
    EXPECT_TRUE(r.bytes.empty());
  }
  EXPECT_EQ(validate_figure(mechanism_at(-1.0), model, ImageFormat::svg)->field, "plots[0].t");
  EXPECT_FALSE(validate_figure(mechanism_at(9.0), model, ImageFormat::svg));
}

}  // namespace
}  // namespace vibro
