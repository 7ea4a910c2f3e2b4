// Chatter: finitely many events, the accumulation time of the geometric series, rest against
// the limiter, release when pulled away; plastic limiter.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/analysis/checked_run.h"
#include "scenes.h"

namespace vibro {
namespace {

TEST(Chatter, EndsInFinitelyManyEventsAtThePredictedAccumulationTime) {
  // No friction: the pellet drops a height d onto a limiter below it; for a small drop the
  // flights are parabolas under a = (g/R) sin(theta), so with the first impact at t1 with
  // speed v1 the impacts accumulate at t* = t1 + 2 k v1 / (a (1 − k)).
  const double theta = 0.3, d = 1e-4, k = 0.5;
  Model m = testing::one_pellet(0.0, theta + d, 0.0);
  m.limiters = {{theta, k, false, -1, {}}};
  const RunResult run = simulate(m, testing::recorded(m, 1.0));
  ASSERT_EQ(run.stats.termination, Termination::completed);
  EXPECT_LT(run.events.size(), 200u);
  auto impacts = testing::events_of(run, EventKind::limiter);
  auto chatter = testing::events_of(run, EventKind::chatter);
  ASSERT_GE(impacts.size(), 2u);
  ASSERT_EQ(chatter.size(), 1u);
  const double a = m.g / m.R * std::sin(theta);
  const double t1 = impacts[0]->t, v1 = std::abs(impacts[0]->dphi_before[0]);
  const double predicted = t1 + 2 * k * v1 / (a * (1 - k));
  EXPECT_NEAR(chatter[0]->t_accumulation, predicted, 1e-3 * (predicted - t1));
  EXPECT_GT(chatter[0]->impacts_resolved, 10);
  EXPECT_EQ(run.summary.final[0].state, PelletState::resting_at_limiter);
  EXPECT_EQ(run.summary.final[0].limiter, 0);
  EXPECT_DOUBLE_EQ(run.summary.final[0].phi, theta);
}

TEST(Chatter, WithFrictionTheRatioIsKTimesSqrtOfTheAccelerations) {
  const Scene scene = testing::preset("chatter");
  const RunResult run = simulate(scene.model, testing::recorded(scene.model, scene.sim.t_end));
  auto impacts = testing::events_of(run, EventKind::limiter);
  ASSERT_GE(impacts.size(), 6u);
  const Model& m = scene.model;
  const double theta = m.limiters[0].angle, k = m.limiters[0].k;
  const double press = m.g / m.R * std::sin(theta), f = m.mu() * m.g / m.R * std::cos(theta);
  const double r = k * std::sqrt((press - f) / (press + f));
  // Late impacts, where the flights are short enough for constant accelerations.
  const std::size_t n = impacts.size();
  const double ratio = std::abs(impacts[n - 1]->dphi_before[0] / impacts[n - 2]->dphi_before[0]);
  EXPECT_NEAR(ratio, r, 1e-3);
  EXPECT_EQ(testing::events_of(run, EventKind::chatter).size(), 1u);
  EXPECT_EQ(run.summary.final[0].state, PelletState::resting_at_limiter);
}

TEST(Chatter, ABodyLeavingItsLimiterHasItsSeriesSummedAtItsAccumulationTime) {
  // Pellet 2 (behind) is pushed by a constant force into pellet 1 and a limiter above them:
  // the two come to bounce on the limiter as one body, each bounce a cascade of impacts at one
  // instant that returns the same fraction of the body's speed. The series is summed from the
  // instant it gets shorter than the chatter time, at t0 + T/(1 − r) with the body's own
  // accelerations: a_away, a_toward = press ± friction, the press of the force on both masses.
  Model m;
  m.g = 9.81;
  m.R = 1.0;
  m.alpha0 = 0.1;
  m.k_c = 0.5;
  const double theta = -0.2, F = 20.0;
  m.limiters = {{theta, 0.9, false, -1, {}}};
  m.pellets = {{1.0, -0.6, 0.0, {}}, {2.0, -0.7, 0.0, {F, 0.0, 0.0}}};
  const RunResult run = simulate(m, testing::recorded(m, 1.0));
  ASSERT_EQ(run.stats.termination, Termination::completed);
  const auto chatter = testing::events_of(run, EventKind::chatter);
  const auto body_chatter = std::find_if(chatter.begin(), chatter.end(),
                                         [](const Event* e) { return e->pellets.size() == 2; });
  ASSERT_NE(body_chatter, chatter.end());
  const Event& c = **body_chatter;
  // The instant it was summed from: the impacts just before it, the body arriving as one.
  const std::size_t at = static_cast<std::size_t>(&c - run.events.data());
  ASSERT_GT(at, 0u);
  const double t0 = run.events[at - 1].t;
  const auto first =
      std::find_if(run.events.begin(), run.events.end(), [&](const Event& e) { return e.t == t0; });
  ASSERT_EQ(first->kind, EventKind::limiter);
  const double v0 = first->dphi_before[0], u = c.dphi_before[0];
  EXPECT_EQ(c.dphi_before[1], u);
  const double press = F / (3.0 * m.R) - m.g / m.R * std::sin(theta);
  const double friction = m.mu() * m.g / m.R * std::cos(theta);
  const double a_away = press + friction, a_toward = press - friction;
  const double r = std::abs(u / v0) * std::sqrt(a_toward / a_away);
  const double T = std::abs(u) / a_away + std::abs(u) / std::sqrt(a_away * a_toward);
  ASSERT_LT(r, 1.0);
  EXPECT_NEAR(c.t_accumulation, t0 + T / (1.0 - r), 1e-9 * T / (1.0 - r));
  for (const FinalState& f : run.summary.final) {
    EXPECT_EQ(f.state, PelletState::resting_at_limiter);
    EXPECT_NEAR(f.phi, theta, 1e-12);
  }
  EXPECT_LT(std::abs(run.stats.energy_defect), 1e-8);
}

TEST(Chatter, RestingPelletIsReleasedWhenTheForcePullsItAway) {
  const double theta = 0.3;
  Model m = testing::one_pellet(0.02, theta + 1e-3, 0.0);
  m.limiters = {{theta, 0.5, false, -1, {}}};
  // Gravity presses it down onto the limiter with (g/R) sin 0.3 ≈ 5.8 rad/s²; a force of
  // 1 N on 0.2 kg at R = 0.5 gives 10 rad/s² away from it at its peak.
  m.pellets[0].force = {1.0, 2.0, M_PI};  // starts pressing, pulls away after a quarter period
  const RunResult run = simulate(m, testing::recorded(m, 2.0));
  ASSERT_FALSE(testing::events_of(run, EventKind::chatter).empty());
  const auto releases = testing::events_of(run, EventKind::release);
  ASSERT_FALSE(releases.empty());
  EXPECT_GT(releases[0]->t, testing::events_of(run, EventKind::chatter)[0]->t);
  // Released, it leaves the limiter upward: the next event is above it.
  const auto next = std::find_if(run.events.begin(), run.events.end(),
                                 [&](const Event& e) { return e.t > releases[0]->t; });
  ASSERT_NE(next, run.events.end());
  EXPECT_GT(next->phi, theta);
}

// A limiter near the top, under the paper law: there the normal force is negative, friction
// pushes the pellet along, flights away are longer than flights back (r = k·sqrt(a_toward /
// a_away) > 1), and the impacts do not shrink. Summed anyway, the series accumulated at
// t* = −3.4 s, before the run began (found by the independent reference simulator).
TEST(Chatter, ASeriesThatDoesNotShrinkIsNotSummed) {
  Model m = testing::one_pellet(0.2, -1.66, -7.45);
  m.R = 0.5;
  m.pellets[0].m = 1.0;
  m.limiters = {{2.55838754912412, 0.9, false, -1, {}}};
  const RunResult run = simulate(m, testing::recorded(m, 3.0));
  ASSERT_FALSE(run.events.empty());
  for (const Event& e : run.events) {
    EXPECT_GE(e.t, 0.0) << event_kind_name(e.kind);
    EXPECT_NE(e.kind, EventKind::chatter) << "at t = " << e.t;
  }
}

TEST(Chatter, PlasticLimiterStopsThePelletAtTheFirstImpact) {
  const Scene scene = testing::preset("plastic-limiter");
  const RunResult run = simulate(scene.model, testing::recorded(scene.model, scene.sim.t_end));
  auto impacts = testing::events_of(run, EventKind::limiter);
  ASSERT_GE(impacts.size(), 1u);
  EXPECT_EQ(impacts[0]->dphi_after[0], 0.0);
  EXPECT_LT(run.events.size(), 50u);
}

}  // namespace
}  // namespace vibro
