// The watches' values and rates (core/events/watch.h) on hand-made states.
#include "core/events/watch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace vibro {
namespace {

Model two_pellets() {
  Model m;
  m.g = 9.81;
  m.R = 0.5;
  m.pellets = {Pellet{.m = 1.0}, Pellet{.m = 2.0}};
  m.limiters = {Limiter{.angle = 1.0}, Limiter{.angle = -2.0}};
  return m;
}

Vec state(double phi0, double dphi0, double phi1, double dphi1) {
  Vec y(6);
  y << phi0, dphi0, 0.0, phi1, dphi1, 0.0;
  return y;
}

TEST(Watch, TheLinearFormOfAWatchOfTheMotionIsItsValue) {
  const Model model = two_pellets();
  const std::vector<Body> bodies = {Body{.members = {0}, .s = -1}, Body{.members = {1}, .s = 1}};
  const std::vector<Watch> watches = {
      Watch{.kind = WatchKind::reversal, .body = 0, .pellet = 0},
      Watch{.kind = WatchKind::limiter,
            .body = 0,
            .pellet = 0,
            .limiter = 1,
            .target = -2.0,
            .side = -1},
      Watch{.kind = WatchKind::gap, .pellet = 0, .other = 1, .target = 0.25}};
  const Vec y = state(0.3, -1.5, 0.9, 2.5);
  for (const Watch& w : watches) {
    const std::optional<LinearForm> form = linear_form(w, bodies);
    ASSERT_TRUE(form);
    double g = form->constant;
    for (int j = 0; j < form->terms; ++j) g += form->weight[j] * y[form->index[j]];
    EXPECT_DOUBLE_EQ(g, raw_value(w, model, bodies, 0.0, y));  // summed in another order
  }
  EXPECT_FALSE(linear_form(Watch{.kind = WatchKind::release, .body = 0, .pellet = 0}, bodies));
}

TEST(Watch, TheRatesOfAWatchOfTheMotionComeFromTheState) {
  const Model model = two_pellets();
  const SlidingLaw law(model);
  const std::vector<Body> bodies = {Body{.members = {0}, .s = 1}, Body{.members = {1}, .s = 1}};
  const Vec y = state(0.3, 1.5, 0.9, 2.5);
  const Watch limiter{.kind = WatchKind::limiter, .body = 0, .pellet = 0, .target = 1.0, .side = 1};
  const Closing c = closing(limiter, model, law, bodies, 0.0, y);
  EXPECT_DOUBLE_EQ(c.value, 0.7);
  EXPECT_EQ(c.rate, -1.5);
  const Watch gap{.kind = WatchKind::gap, .pellet = 0, .other = 1};
  EXPECT_EQ(closing(gap, model, law, bodies, 0.0, y).rate, 1.0);
}

TEST(Watch, ADeflatedWatchIsItsChangeOverThePowerOfTheTimeSinceItsStart) {
  const Model model = two_pellets();
  const std::vector<Body> bodies = {Body{.members = {0}, .s = 1}, Body{.members = {1}, .s = 1}};
  Watch gap{.kind = WatchKind::gap, .pellet = 0, .other = 1};
  deflate(gap, model, bodies, 1.0, state(0.5, 0.0, 0.5, 0.0), 0.0, 4.0);
  EXPECT_EQ(gap.deflation, 2);
  EXPECT_EQ(evaluate(gap, model, bodies, 1.0, state(0.5, 0.0, 0.5, 0.0)), 2.0);  // its start
  EXPECT_DOUBLE_EQ(evaluate(gap, model, bodies, 1.5, state(0.5, 0.0, 1.0, 0.0)), 2.0);
  deflate(gap, model, bodies, 1.0, state(0.5, 0.0, 0.5, 0.0), 3.0, 0.0);
  EXPECT_EQ(gap.deflation, 1);
  EXPECT_DOUBLE_EQ(evaluate(gap, model, bodies, 1.5, state(0.5, 0.0, 1.0, 0.0)), 1.0);
}

TEST(Watch, AClosingMeetsZeroWithinASpanWhereItsQuadraticDoes) {
  // value 1, closing at 1 rad/s, accelerating toward it at 2 rad/s²: τ² + τ − 1 = 0.
  const Closing c{.value = 1.0, .rate = -1.0, .curvature = -2.0};
  const double tau = (std::sqrt(5.0) - 1.0) / 2.0;
  EXPECT_NEAR(c.time_to_zero(), tau, 1e-15);
  EXPECT_TRUE(c.meets_within(tau * 1.001));
  EXPECT_FALSE(c.meets_within(tau * 0.999));
  // Opening with no curvature, it never meets zero; on its root and not opening, it has.
  EXPECT_EQ((Closing{.value = 1.0, .rate = 1.0}.time_to_zero()),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ((Closing{.value = 0.0, .rate = -1.0}.time_to_zero()), 0.0);
}

TEST(Watch, TheNextLimiterIsTheNearestArmedOneAheadOfTheBody) {
  const Model model = two_pellets();
  const Body body{.members = {0}, .s = 1};
  int limiter = -1;
  double target = 0.0;
  ASSERT_TRUE(next_limiter(model, {true, true}, body, 0.5, 1, 1e-12, limiter, target));
  EXPECT_EQ(limiter, 0);
  EXPECT_DOUBLE_EQ(target, 1.0);
  ASSERT_TRUE(next_limiter(model, {false, true}, body, 0.5, 1, 1e-12, limiter, target));
  EXPECT_EQ(limiter, 1);
  EXPECT_NEAR(target, -2.0 + kTwoPi, 1e-15);
  // Sitting on a limiter, the body watches the next one.
  ASSERT_TRUE(next_limiter(model, {true, true}, body, 1.0, -1, 1e-12, limiter, target));
  EXPECT_EQ(limiter, 1);
  EXPECT_DOUBLE_EQ(target, -2.0);
  EXPECT_TRUE(on_limiter_angle(1.0, 1.0 + kTwoPi, 1e-12));
}

}  // namespace
}  // namespace vibro
