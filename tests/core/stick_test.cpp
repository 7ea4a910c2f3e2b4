// The stick test at reversals and at t = 0, on both sides of its threshold, and release under
// forcing at the predicted time.
#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

// At rest without forcing, a pellet holds where tan|phi| <= mu_s, i.e. |phi| <= alpha0.
TEST(Stick, AtRestInsideTheFrictionConeStaysAndOutsideSlides) {
  const double alpha0 = 0.05;
  for (double side : {1.0, -1.0}) {
    Model inside = testing::one_pellet(alpha0, side * (alpha0 - 1e-6), 0.0);
    RunResult run = simulate(inside, testing::recorded(inside, 2.0));
    EXPECT_EQ(run.summary.final[0].state, PelletState::stuck);
    EXPECT_DOUBLE_EQ(run.summary.final[0].phi, inside.pellets[0].phi0);
    EXPECT_TRUE(run.events.empty());

    Model outside = testing::one_pellet(alpha0, side * (alpha0 + 1e-6), 0.0);
    run = simulate(outside, testing::recorded(outside, 2.0));
    EXPECT_NE(run.summary.final[0].phi, outside.pellets[0].phi0);
    // It slides toward the bottom and comes to rest inside the cone.
    EXPECT_EQ(run.summary.final[0].state, PelletState::stuck);
    EXPECT_LE(std::abs(run.summary.final[0].phi), alpha0 + 1e-12);
  }
}

TEST(Stick, AReversalInsideTheConeSticksAndOutsideReverses) {
  // Slow start at the bottom: it rises to about 0.0226 rad < alpha0 and sticks there.
  Model slow = testing::one_pellet(0.05, 0.0, 0.1);
  RunResult run = simulate(slow, testing::recorded(slow, 2.0));
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(run.events[0].kind, EventKind::stick);
  EXPECT_EQ(run.summary.final[0].state, PelletState::stuck);
  EXPECT_EQ(run.summary.final[0].phi, run.events[0].phi);
  // Faster: the reversal is outside the cone, so it slides back and oscillates.
  Model fast = testing::one_pellet(0.05, 0.0, 1.0);
  run = simulate(fast, testing::recorded(fast, 2.0));
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(run.events[0].kind, EventKind::reversal);
  EXPECT_GT(std::abs(run.events[0].phi), 0.05);
}

TEST(Stick, ForcingReleasesAStuckPelletWhenItBeatsStaticFriction) {
  // At phi = 0, F = −F0 sin(Omega t): |a_free| = F0 |sin Omega t| / (m R) exceeds mu g / R at
  // t = asin(mu m g / F0) / Omega.
  Model m = testing::one_pellet(0.05, 0.0, 0.0);
  m.pellets[0].force = {0.5, 3.0, M_PI / 2};
  const RunResult run = simulate(m, testing::recorded(m, 1.0));
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(run.events[0].kind, EventKind::release);
  const double expected = std::asin(m.mu() * m.pellets[0].m * m.g / 0.5) / 3.0;
  EXPECT_NEAR(run.events[0].t, expected, 1e-10);
  // The force first pulls toward negative angles: the pellet leaves that way.
  ASSERT_GE(run.events.size(), 2u);
  EXPECT_LT(run.events[1].phi, 0.0);
}

// The force beats static friction by 1e-8 of its capacity at its peak: for 1e-4 s of each 2 s
// period, far shorter than the integrator's step (the pellet is held, nothing limits the step).
// The release is a root of a function of time alone, found without relying on the steps.
TEST(Stick, AForceThatBarelyBeatsFrictionForAnInstantReleases) {
  Model m = testing::one_pellet(0.05, 0.0, 0.0);
  const double capacity = m.mu() * m.g / m.R;  // at phi = 0
  const double F0 = capacity * m.pellets[0].m * m.R * (1.0 + 1e-8);
  m.pellets[0].force = {F0, 3.0, M_PI / 2};  // F = −F0 sin(3t): the first peak at t = π/6
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    const RunResult run = simulate(m, testing::recorded(m, 1.0, method));
    ASSERT_FALSE(run.events.empty()) << method_name(method);
    EXPECT_EQ(run.events[0].kind, EventKind::release) << method_name(method);
    const double expected = std::asin(capacity * m.pellets[0].m * m.R / F0) / 3.0;
    EXPECT_NEAR(run.events[0].t, expected, 1e-10) << method_name(method);
  }
}

// A frictionless pellet whose force balances gravity exactly at the start (a random scene's
// "at rest on the cone's edge", tests/differential): the stick test holds it there, within
// round-off, and the force's turn lets it go at once. Its release watch starts within the same
// round-off of the threshold, so it is released then; measured from the bare capacity, 0, the
// watch started on its root, never armed, and the pellet stayed put until another body's event.
TEST(Stick, APelletHeldExactlyAtItsThresholdIsLetGoAsTheForceTurns) {
  Model model;
  model.R = 0.001;
  model.pellets = {Pellet{.m = 0.01,
                          .phi0 = 1.463431595396416e-05,
                          .dphi0 = 0.0,
                          .force = {4.77132797241211e-06, 13.425004152725975, 1.2651746232584933}}};
  SimOptions o;
  o.t_end = 0.03;
  o.check = false;
  const RunResult run = simulate(model, o);
  const auto releases = testing::events_of(run, EventKind::release);
  ASSERT_EQ(releases.size(), 1u);
  EXPECT_LT(releases[0]->t, 1e-9);
  EXPECT_EQ(run.summary.final[0].state, PelletState::sliding);
  EXPECT_GT(std::abs(run.summary.final[0].phi - model.pellets[0].phi0), 1e-6);
}

TEST(Stick, AStaticCoefficientAboveMuHoldsWhereMuAloneWouldNot) {
  Model m = testing::one_pellet(0.05, 0.07, 0.0);  // outside the kinetic cone
  m.mu_s = 0.08;                                   // tan(0.07) ≈ 0.0701 < 0.08
  const RunResult run = simulate(m, testing::recorded(m, 1.0));
  EXPECT_EQ(run.summary.final[0].state, PelletState::stuck);
  EXPECT_DOUBLE_EQ(run.summary.final[0].phi, 0.07);
}

}  // namespace
}  // namespace vibro
