#include "render/ticks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace vibro::render {
namespace {

constexpr double kPi = std::numbers::pi;

// The mantissa of a 1-2-5 step: 1, 2 or 5.
double mantissa(double step) { return step / std::pow(10.0, std::floor(std::log10(step) + 1e-9)); }

TEST(NiceStep, IsOneTwoOrFiveTimesAPowerOfTen) {
  for (double span : {0.013, 0.7, 1.0, 3.3, 12.0, 47.0, 99.0, 1234.5, 8e6}) {
    for (double intervals : {2.0, 4.0, 7.0, 10.0}) {
      const double m = mantissa(nice_step(span, intervals));
      EXPECT_TRUE(std::abs(m - 1) < 1e-9 || std::abs(m - 2) < 1e-9 || std::abs(m - 5) < 1e-9)
          << "span " << span << " intervals " << intervals << " mantissa " << m;
    }
  }
}

TEST(NiceTicks, CoverTheRangeAboutOnePerSpacing) {
  const Range r{-3.7, 41.2};
  const auto ticks = nice_ticks(r, 600.0, 120.0);
  ASSERT_GE(ticks.size(), 3u);
  const double step = ticks[1].value - ticks[0].value;
  EXPECT_NEAR(mantissa(step), std::round(mantissa(step)), 1e-9);
  for (std::size_t i = 1; i < ticks.size(); ++i)
    EXPECT_NEAR(ticks[i].value - ticks[i - 1].value, step, 1e-9 * step);
  EXPECT_GE(ticks.front().value, r.lo);
  EXPECT_LT(ticks.front().value - step, r.lo);  // no room for one more below
  EXPECT_LE(ticks.back().value, r.hi);
  EXPECT_GT(ticks.back().value + step, r.hi);
  const double spacing_px = step / r.span() * 600.0;
  EXPECT_GT(spacing_px, 60.0);
  EXPECT_LT(spacing_px, 300.0);
}

TEST(NiceTicks, LabelsUseTheMinusSignAndEnoughDecimals) {
  const auto ticks = nice_ticks({-0.5, 0.5}, 500.0, 100.0);
  ASSERT_FALSE(ticks.empty());
  EXPECT_EQ(ticks.front().label, "\u22120.4");
  bool zero = false;
  for (const Tick& t : ticks) zero |= t.label == "0";
  EXPECT_TRUE(zero);
  EXPECT_EQ(format_tick(2.5, 0.5), "2.5");
  EXPECT_EQ(format_tick(-20.0, 10.0), "\u221220");
  EXPECT_EQ(format_tick(0.025, 0.005), "0.025");
}

TEST(PiLabel, ReducesQuarters) {
  EXPECT_EQ(pi_label(0), "0");
  EXPECT_EQ(pi_label(1), "\u03c0/4");
  EXPECT_EQ(pi_label(2), "\u03c0/2");
  EXPECT_EQ(pi_label(3), "3\u03c0/4");
  EXPECT_EQ(pi_label(4), "\u03c0");
  EXPECT_EQ(pi_label(5), "5\u03c0/4");
  EXPECT_EQ(pi_label(6), "3\u03c0/2");
  EXPECT_EQ(pi_label(8), "2\u03c0");
  EXPECT_EQ(pi_label(-1), "\u2212\u03c0/4");
  EXPECT_EQ(pi_label(-6), "\u22123\u03c0/2");
}

TEST(AngleTicks, QuartersOfPiOnAFewPiRange) {
  const auto ticks = axis_ticks({-0.3, 1.9 * kPi}, 900.0, true);
  ASSERT_GE(ticks.size(), 5u);
  EXPECT_EQ(ticks[0].label, "0");
  EXPECT_EQ(ticks[1].label, "\u03c0/4");
  EXPECT_NEAR(ticks[1].value, kPi / 4, 1e-12);
  EXPECT_EQ(ticks[4].label, "\u03c0");
}

TEST(AngleTicks, CoarserStepsWhenTheAxisIsShort) {
  const auto ticks = angle_ticks({-2.0 * kPi, 2.0 * kPi}, 300.0);
  ASSERT_GE(ticks.size(), 3u);
  EXPECT_NEAR(ticks[1].value - ticks[0].value, kPi, 1e-12);
  EXPECT_EQ(ticks.front().label, "\u22122\u03c0");
}

TEST(AngleTicks, FallBackToNiceTicksWhereThoseReadBetter) {
  // Too narrow for three multiples of π/4.
  EXPECT_TRUE(angle_ticks({0.1, 0.9}, 800.0).empty());
  const auto narrow = axis_ticks({0.1, 0.9}, 800.0, true);
  ASSERT_FALSE(narrow.empty());
  EXPECT_EQ(narrow.front().label.find("\u03c0"), std::string::npos);
  // Too wide: steps above 2π.
  EXPECT_TRUE(angle_ticks({0.0, 200.0}, 400.0).empty());
  // Not an angle axis.
  EXPECT_EQ(axis_ticks({-0.3, 1.9 * kPi}, 900.0, false).front().label.find("\u03c0"),
            std::string::npos);
}

}  // namespace
}  // namespace vibro::render

namespace vibro::render {
namespace {

// A small figure's axes (600×400: plots about 110 px tall) keep at least three labelled ticks,
// never closer than a label's height: "0" alone told a reader nothing (issue 13).
TEST(SmallAxes, AVerticalAxisKeepsThreeTicksALabelHeightApart) {
  for (const Range r : {Range{-18.0, 9.0}, Range{-21.0, 52.0}, Range{0.3, 0.9}, Range{5.6, 6.05}}) {
    const double length = 110.0;
    const auto ticks = axis_ticks(r, length, false, true);
    ASSERT_GE(ticks.size(), 3u) << r.lo << " " << r.hi;
    const double gap = (ticks[1].value - ticks[0].value) / r.span() * length;
    EXPECT_GE(gap, 18.0) << r.lo << " " << r.hi;
  }
  // φ(t) from −2 to 5 rad: multiples of π/2, not "0" and "5".
  const auto angles = axis_ticks({-2.0, 5.0}, 110.0, true, true);
  ASSERT_GE(angles.size(), 3u);
  EXPECT_EQ(angles[1].label, "0");
  EXPECT_EQ(angles[2].label, "\u03c0/2");
}

TEST(SmallAxes, AHorizontalAxisKeepsItsLabelsAWidthApart) {  // "−0.2" is some 25 px wide
  const auto ticks = axis_ticks({-0.3, 0.35}, 120.0, false, false);
  ASSERT_GE(ticks.size(), 2u);
  EXPECT_GE((ticks[1].value - ticks[0].value) / 0.65 * 120.0, 35.0);
}

}  // namespace
}  // namespace vibro::render
