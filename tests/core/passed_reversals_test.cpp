// A frictionless body of one pellet whose reversals are passed (SolverOptions::
// frictionless_reversals false, as a sweep runs) moves as one whose reversals are events: the
// same impacts, collisions, releases and chatter at the same times, the same states at the
// stops, and no reversal listed. Each scene here lists reversals when they are events, so a
// comparison that skipped them could not pass by accident.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/analysis/checked_run.h"
#include "impact_oscillator.h"
#include "scenes.h"

namespace vibro {
namespace {

RunResult run(const Model& model, Method method, bool reversals, double t_end,
              const std::vector<double>& stops = {}) {
  SimOptions o;
  o.t_end = t_end;
  o.method = method;
  o.rtol = 1e-11;
  o.atol = 1e-13;
  o.check = false;
  o.stops = stops;
  o.frictionless_reversals = reversals;
  return simulate(model, o);
}

std::vector<Event> without_reversals(const std::vector<Event>& events) {
  std::vector<Event> kept;
  for (const Event& e : events)
    if (e.kind != EventKind::reversal) kept.push_back(e);
  return kept;
}

// Runs the scene both ways under Taylor and DOP853 and compares them.
void expect_same_motion(const Model& model, double t_end, const std::vector<double>& stops = {}) {
  for (Method method : {Method::taylor, Method::dop853}) {
    SCOPED_TRACE(method_name(method));
    const RunResult listed = run(model, method, true, t_end, stops);
    const RunResult passed = run(model, method, false, t_end, stops);
    ASSERT_EQ(listed.stats.termination, Termination::completed);
    ASSERT_EQ(passed.stats.termination, Termination::completed);
    EXPECT_FALSE(testing::events_of(listed, EventKind::reversal).empty());
    EXPECT_TRUE(testing::events_of(passed, EventKind::reversal).empty());
    const std::vector<Event> expected = without_reversals(listed.events);
    ASSERT_EQ(passed.events.size(), expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      const Event& a = expected[k];
      const Event& b = passed.events[k];
      EXPECT_EQ(a.kind, b.kind) << k;
      EXPECT_EQ(a.limiter, b.limiter) << k;
      EXPECT_EQ(a.pellets, b.pellets) << k;
      EXPECT_NEAR(a.t, b.t, 1e-8) << k;
      EXPECT_NEAR(a.phi, b.phi, 1e-8) << k;
      EXPECT_NEAR(a.dphi_after[0], b.dphi_after[0], 1e-7) << k;
    }
    ASSERT_EQ(passed.stops.size(), listed.stops.size());
    for (std::size_t k = 0; k < stops.size(); ++k)
      for (std::size_t i = 0; i < passed.stops[k].pellets.size(); ++i) {
        EXPECT_NEAR(passed.stops[k].pellets[i].phi, listed.stops[k].pellets[i].phi, 1e-8) << k;
        EXPECT_NEAR(passed.stops[k].pellets[i].dphi, listed.stops[k].pellets[i].dphi, 1e-7) << k;
      }
    for (std::size_t i = 0; i < passed.summary.final.size(); ++i) {
      EXPECT_EQ(passed.summary.final[i].state, listed.summary.final[i].state);
      EXPECT_NEAR(passed.summary.final[i].phi, listed.summary.final[i].phi, 1e-8);
    }
    // Each reversal cut a step short.
    EXPECT_LT(passed.stats.steps, listed.stats.steps);
  }
}

std::vector<double> every(double T, int n) {
  std::vector<double> stops;
  for (int k = 1; k <= n; ++k) stops.push_back(k * T);
  return stops;
}

// The sweep's scene: three reversals to an impact, period 1 at Ω = 6.
TEST(PassedReversals, TheImpactOscillatorStrikesAndSettlesAlike) {
  const double T = kTwoPi / 6.0;
  expect_same_motion(testing::impact_oscillator(6.0), 30 * T, every(T, 30));
}

// Between two stops, damped: swings that turn short of a stop and strikes on both sides.
TEST(PassedReversals, ADampedPelletBetweenTwoStops) {
  Model model = testing::impact_oscillator(4.0);
  model.limiters = {Limiter{.angle = -0.4, .k = 0.7}, Limiter{.angle = 0.5, .k = 0.9}};
  model.pellets[0].c = 0.2;
  model.pellets[0].dphi0 = 3.0;
  expect_same_motion(model, 25.0, every(0.5, 50));
}

// Dropped onto a stop at the bottom: each rebound rises, turns and comes back to the stop it
// left (the limiter behind it, watched deflated from the impact), until the chatter sums the
// rest and it lies there.
TEST(PassedReversals, ABounceReturnsToTheStopItLeft) {
  Model model = testing::one_pellet(0.0, 0.8, 0.0);
  model.limiters = {Limiter{.angle = 0.0, .k = 0.5}};
  expect_same_motion(model, 6.0);
}

// Gravity presses it back onto a stop it strikes at 4.5 rad/s with k = 0.03: each rebound
// returns within a step, found because the stop it left is watched deflated from the impact.
TEST(PassedReversals, AQuickReboundReturnsWithinOneStep) {
  Model model = testing::one_pellet(0.0, -1.2, 0.0);
  model.limiters = {Limiter{.angle = -0.5, .k = 0.03}};
  expect_same_motion(model, 2.0);
}

// Pressed onto a stop by its force until the force turns: let go at rest, it swings away from
// the stop (watched deflated to second order) and comes back to strike it.
TEST(PassedReversals, LetGoFromAStopItSwingsBackOntoIt) {
  Model model = testing::one_pellet(0.0, -0.3, 0.0);
  model.limiters = {Limiter{.angle = -0.3, .k = 0.6}};
  model.pellets[0].m = 0.1;
  model.pellets[0].force = {-0.5, 2.0, 0.0};
  expect_same_motion(model, 8.0);
  EXPECT_FALSE(
      testing::events_of(run(model, Method::taylor, false, 8.0), EventKind::release).empty());
}

// Two pellets that collide: each its own body, each passing its reversals, the collisions found.
TEST(PassedReversals, TwoPelletsCollideAlike) {
  Model model = testing::impact_oscillator(5.0);
  model.pellets.push_back(Pellet{.m = 0.05, .phi0 = -0.6, .dphi0 = 0.0});
  model.limiters = {Limiter{.angle = 1.2, .k = 0.8}};
  model.k_c = 0.9;
  expect_same_motion(model, 10.0);
  EXPECT_FALSE(
      testing::events_of(run(model, Method::taylor, false, 10.0), EventKind::collision).empty());
}

// Friction makes a reversal change the equations: the option changes nothing.
TEST(PassedReversals, ABodyWithFrictionListsItsReversalsAnyway) {
  Model model = testing::impact_oscillator(6.0);
  model.alpha0 = 0.05;
  const RunResult listed = run(model, Method::taylor, true, 10.0);
  const RunResult passed = run(model, Method::taylor, false, 10.0);
  EXPECT_FALSE(testing::events_of(passed, EventKind::reversal).empty());
  ASSERT_EQ(listed.events.size(), passed.events.size());
  for (std::size_t k = 0; k < listed.events.size(); ++k)
    EXPECT_EQ(listed.events[k].t, passed.events[k].t) << k;
  EXPECT_EQ(listed.stats.steps, passed.stats.steps);
}

}  // namespace
}  // namespace vibro
