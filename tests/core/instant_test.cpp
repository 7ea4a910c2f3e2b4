// The phases of one event instant on hand-made contacts, each checked against values derived by
// hand: the snap onto a limiter's angle and onto one place, Newton's restitution law with
// momentum, the plastic limit of an endless cascade, the chatter series' closed-form sum, the
// plastic merge of touching pellets, and the modes and events a body leaves in.
#include "core/events/instant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/events/chatter.h"
#include "scenes.h"

namespace vibro {
namespace {

// n pellets of 0.2 kg on R = 0.5 m, g = 9.81, no friction; pellet i starts at (phi, dphi)[i].
Model pellets_at(const std::vector<std::pair<double, double>>& starts) {
  Model m = testing::one_pellet(0.0, 0.0, 0.0);
  m.pellets.clear();
  for (const auto& [phi, dphi] : starts) m.pellets.push_back({0.2, phi, dphi, {}});
  return m;
}

Vec state(const Model& m) {
  Vec y = Vec::Zero(3 * m.size());
  for (int i = 0; i < m.size(); ++i) {
    y[phi_index(i)] = m.pellets[i].phi0;
    y[dphi_index(i)] = m.pellets[i].dphi0;
  }
  return y;
}

InstantContacts no_contacts(const Model& m) {
  InstantContacts c;
  c.pellets.assign(m.size(), {});
  return c;
}

// J: ½ m R² v².
double kinetic(const Model& m, int i, double v) { return 0.5 * m.pellets[i].m * m.R * m.R * v * v; }

// ---- Phase 1: snap -----------------------------------------------------------------------------

int watch_of(const MotionInterval& interval, WatchKind kind, int pellet) {
  for (int k = 0; k < static_cast<int>(interval.watches().size()); ++k)
    if (interval.watches()[k].kind == kind && interval.watches()[k].pellet == pellet) return k;
  ADD_FAILURE() << "no such watch";
  return 0;
}

TEST(InstantSnap, ABodyArrivingAtALimiterLandsOnItsAngleAndTouchesItFromBelow) {
  const double theta = 0.5;
  Model m = pellets_at({{0.2, 1.0}});
  m.limiters = {{theta, 0.6, false, -1, {}}};
  const EventTolerances tol = event_tolerances(m);
  const std::vector<bool> armed = {true};
  Vec y = state(m);
  const MotionInterval interval(m, initial_bodies(m, y), armed, {}, 0.0, y, tol);
  const int w = watch_of(interval, WatchKind::limiter, 0);
  y[phi_index(0)] = theta - 1e-13;  // where the root finder put the crossing
  const InstantContacts c = snap(m, tol, interval, {{w, 0.3}}, {}, armed, y);
  EXPECT_EQ(y[phi_index(0)], theta);
  EXPECT_EQ(y[dphi_index(0)], 1.0);  // the snap moves angles, not speeds
  ASSERT_EQ(c.limiters.size(), 1u);
  EXPECT_EQ(c.limiters[0], (LimiterContact{0, 0, -1}));  // sliding up (s = +1): from below
  EXPECT_TRUE(c.pairs.empty());
}

TEST(InstantSnap, TwoPelletsMeetingAwayFromLimitersMeetHalfway) {
  Model m = pellets_at({{0.2, 1.0}, {0.4, -1.0}});
  const EventTolerances tol = event_tolerances(m);
  Vec y = state(m);
  const std::vector<Neighbours> nb = circular_neighbours(y, m.size());
  const MotionInterval interval(m, initial_bodies(m, y), {}, nb, 0.0, y, tol);
  const int w = watch_of(interval, WatchKind::gap, 0);
  y[phi_index(0)] = 0.3 - 1e-13;
  y[phi_index(1)] = 0.3 + 3e-13;
  const InstantContacts c = snap(m, tol, interval, {{w, 0.1}}, nb, {}, y);
  EXPECT_EQ(y[phi_index(0)], y[phi_index(1)]);
  EXPECT_NEAR(y[phi_index(0)], 0.3 + 1e-13, 4e-16);  // the midpoint
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs[0], (PairContact{0, 1}));
  EXPECT_TRUE(c.limiters.empty());
}

TEST(InstantSnap, APelletMeetingOneRestingOnALimiterComesOntoTheLimitersAngle) {
  const double theta = 0.3;
  Model m = pellets_at({{theta, 0.0}, {theta + 0.1, -1.0}});
  m.limiters = {{theta, 0.6, false, -1, {}}};
  const EventTolerances tol = event_tolerances(m);
  const std::vector<bool> armed = {true};
  Vec y = state(m);
  std::vector<Body> bodies = initial_bodies(m, y);
  bodies[0].mode = Mode::resting;  // on the limiter from above, where gravity presses it
  bodies[0].limiter = 0;
  bodies[0].side = 1;
  const std::vector<Neighbours> nb = circular_neighbours(y, m.size());
  const MotionInterval interval(m, bodies, armed, nb, 0.0, y, tol);
  const int w = watch_of(interval, WatchKind::gap, 0);
  y[phi_index(1)] = theta + 2e-13;
  const InstantContacts c = snap(m, tol, interval, {{w, 0.1}}, nb, armed, y);
  EXPECT_EQ(y[phi_index(0)], theta);  // it stays put
  EXPECT_EQ(y[phi_index(1)], theta);
  ASSERT_EQ(c.limiters.size(), 1u);
  EXPECT_EQ(c.limiters[0], (LimiterContact{0, 0, 1}));
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs[0], (PairContact{0, 1}));
}

TEST(InstantSnap, AReversalPutsTheBodysSpeedToZeroAndMarksItsPellets) {
  Model m = pellets_at({{0.2, 1.0}});
  const EventTolerances tol = event_tolerances(m);
  Vec y = state(m);
  const MotionInterval interval(m, initial_bodies(m, y), {}, {}, 0.0, y, tol);
  const int w = watch_of(interval, WatchKind::reversal, 0);
  y[dphi_index(0)] = 1e-15;
  const InstantContacts c = snap(m, tol, interval, {{w, 0.1}}, {}, {}, y);
  EXPECT_EQ(y[dphi_index(0)], 0.0);
  EXPECT_TRUE(c.pellets[0].reversed);
  EXPECT_FALSE(c.pellets[0].released);
}

// ---- Phase 2: impacts --------------------------------------------------------------------------

TEST(InstantImpacts, TwoPelletsTouchingObeyNewtonsLawAndKeepTheirMomentum) {
  // m = 0.2 and 0.3 kg at 2 and −1 rad/s, k_c = 0.5: momentum 0.1 kg·rad/s, so the centre of
  // mass moves at 0.2 rad/s; the relative speed −3 becomes +1.5, shared 0.6 : 0.4 by the
  // masses' ratios: −0.7 and 0.8 rad/s.
  Model m = pellets_at({{0.3, 2.0}, {0.3, -1.0}});
  m.pellets[1].m = 0.3;
  m.k_c = 0.5;
  Vec y = state(m);
  std::vector<bool> armed;
  InstantContacts c = no_contacts(m);
  c.pairs = {{0, 1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 1.0, initial_bodies(m, y), c, y, armed);
  ASSERT_EQ(out.events.size(), 1u);
  const Event& e = out.events[0];
  EXPECT_EQ(e.kind, EventKind::collision);
  EXPECT_EQ(e.t, 1.0);
  EXPECT_EQ(e.phi, 0.3);
  EXPECT_NEAR(e.dphi_after[0], -0.7, 1e-15);
  EXPECT_NEAR(e.dphi_after[1], 0.8, 1e-15);
  EXPECT_NEAR(y[dphi_index(0)], -0.7, 1e-15);
  EXPECT_NEAR(y[dphi_index(1)], 0.8, 1e-15);
  const double lost = kinetic(m, 0, 2.0) + kinetic(m, 1, -1.0) - kinetic(m, 0, -0.7) -
                      kinetic(m, 1, 0.8);  // 0.10125 J
  EXPECT_NEAR(out.kinetic_change, -lost, 1e-15);
  // Parting at 1.5 rad/s with nothing pressing them: two bodies, each its own way.
  ASSERT_EQ(out.bodies.size(), 2u);
  EXPECT_EQ(out.bodies[0].mode, Mode::sliding);
  EXPECT_EQ(out.bodies[0].s, -1);
  EXPECT_EQ(out.bodies[1].s, 1);
  EXPECT_EQ(out.touched, (std::vector<bool>{true, true}));
  EXPECT_EQ(out.unordered, -1);
}

TEST(InstantImpacts, APelletAtALimiterReboundsWithItsRestitution) {
  // 3 rad/s up into a limiter of k = 0.6: 1.8 rad/s back down, where gravity carries it off.
  const double theta = 0.5;
  Model m = pellets_at({{theta, 3.0}});
  m.limiters = {{theta, 0.6, false, -1, {}}};
  Vec y = state(m);
  std::vector<bool> armed = {true};
  InstantContacts c = no_contacts(m);
  c.limiters = {{0, 0, -1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 0.5, initial_bodies(m, y), c, y, armed);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(out.events[0].kind, EventKind::limiter);
  EXPECT_EQ(out.events[0].limiter, 0);
  EXPECT_DOUBLE_EQ(out.events[0].dphi_after[0], -1.8);
  EXPECT_DOUBLE_EQ(y[dphi_index(0)], -1.8);
  EXPECT_NEAR(out.kinetic_change, kinetic(m, 0, 1.8) - kinetic(m, 0, 3.0), 1e-15);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].mode, Mode::sliding);
  EXPECT_EQ(out.bodies[0].s, -1);
  EXPECT_TRUE(armed[0]);  // a fixed limiter stays armed
}

TEST(InstantImpacts, ACascadeThatDoesNotSettleEndsAtItsPlasticLimitAgainstTheLimiter) {
  // A light pellet (1e-4 kg) between a heavy one (1 kg) and a limiter, all elastic, both at
  // −2 rad/s into it: the cascade would take some π·sqrt(1e4) impacts. Its limit is one plastic
  // impact of the group: its momentum drives it into the limiter, which stops it; gravity
  // presses it there, so it rests on the limiter, and all its kinetic energy is lost.
  const double theta = 0.5;
  Model m = pellets_at({{theta, -2.0}, {theta, -2.0}});
  m.pellets[0].m = 1e-4;
  m.pellets[1].m = 1.0;
  m.k_c = 1.0;
  m.limiters = {{theta, 1.0, false, -1, {}}};
  Vec y = state(m);
  std::vector<bool> armed = {true};
  InstantContacts c = no_contacts(m);
  c.limiters = {{0, 0, 1}};
  c.pairs = {{0, 1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 0.0, initial_bodies(m, y), c, y, armed);
  ASSERT_EQ(out.events.size(), 1u);
  const Event& e = out.events[0];
  EXPECT_EQ(e.kind, EventKind::collision);
  EXPECT_EQ(e.pellets, (std::vector<int>{0, 1}));
  EXPECT_EQ(e.limiter, 0);
  EXPECT_EQ(e.dphi_after, (std::vector<double>{0.0, 0.0}));
  EXPECT_GT(e.impacts_resolved, 0);
  EXPECT_EQ(y[dphi_index(0)], 0.0);
  EXPECT_EQ(y[dphi_index(1)], 0.0);
  EXPECT_NEAR(out.kinetic_change, -(kinetic(m, 0, 2.0) + kinetic(m, 1, 2.0)), 1e-15);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].members, (std::vector<int>{0, 1}));
  EXPECT_EQ(out.bodies[0].mode, Mode::resting);
  EXPECT_EQ(out.bodies[0].limiter, 0);
  EXPECT_EQ(out.bodies[0].side, 1);
  EXPECT_EQ(out.unordered, -1);  // at the plastic limit no order matters
}

// ---- Phase 4: chatter --------------------------------------------------------------------------

TEST(InstantChatter, AShortSeriesIsSummedToItsAccumulationTimeAndLeavesThePelletAtRest) {
  // No friction: leaving the limiter at u = k·v1, pressed back at a = (g/R)·sin θ, each flight
  // lasts 2u/a and the next leaves at k times the speed: the flights sum to 2u/(a(1 − k)).
  const double theta = 0.3, k = 0.5, v1 = 1e-6, t = 2.0;
  Model m = pellets_at({{theta, -v1}});
  m.limiters = {{theta, k, false, -1, {}}};
  const EventTolerances tol = event_tolerances(m);
  Vec y = state(m);
  std::vector<bool> armed = {true};
  InstantContacts c = no_contacts(m);
  c.limiters = {{0, 0, 1}};
  const InstantOutcome out = resolve_instant(m, tol, t, initial_bodies(m, y), c, y, armed);
  const double a = m.g / m.R * std::sin(theta), u = k * v1;
  const double sum = 2.0 * u / (a * (1.0 - k));
  ASSERT_LT(sum, tol.chatter_time);  // short enough to be summed
  ASSERT_EQ(out.events.size(), 2u);
  EXPECT_EQ(out.events[0].kind, EventKind::limiter);
  EXPECT_DOUBLE_EQ(out.events[0].dphi_after[0], u);
  const Event& e = out.events[1];
  EXPECT_EQ(e.kind, EventKind::chatter);
  EXPECT_EQ(e.limiter, 0);
  EXPECT_DOUBLE_EQ(e.dphi_before[0], u);
  EXPECT_EQ(e.dphi_after[0], 0.0);
  EXPECT_NEAR(e.t_accumulation, t + sum, 1e-12 * sum);
  EXPECT_EQ(e.t, e.t_accumulation);
  // Speeds fall by k = 1/2 per impact: 52 halvings take one below an ulp of the first.
  EXPECT_GE(e.impacts_resolved, 52);
  EXPECT_LE(e.impacts_resolved, 53);
  EXPECT_EQ(y[dphi_index(0)], 0.0);
  EXPECT_NEAR(out.kinetic_change, -kinetic(m, 0, v1), 1e-12 * kinetic(m, 0, v1));
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].mode, Mode::resting);
  EXPECT_EQ(out.bodies[0].side, 1);
}

TEST(InstantChatter, WithFrictionTheSeriesSumsTheFlightsOfItsKinematics) {
  // Above a limiter at θ, a pellet leaving at u is slowed by gravity and friction together,
  // a_away = (g/R)(sin θ + μ cos θ), rises u²/(2 a_away) and falls back under
  // a_toward = (g/R)(sin θ − μ cos θ); it strikes at sqrt(2 h a_toward) and leaves at k times
  // that. The flights, summed one by one, add up to the series' closed form.
  Model m = testing::one_pellet(0.1, 0.0, 0.0);
  const double theta = 0.3, k = 0.7, u0 = 0.01, t = 1.0;
  const double g_r = m.g / m.R, mu = std::tan(0.1);
  const double a_away = g_r * (std::sin(theta) + mu * std::cos(theta));
  const double a_toward = g_r * (std::sin(theta) - mu * std::cos(theta));
  double flights = 0.0, u = u0, ratio = 0.0;
  for (int n = 0; n < 400; ++n) {
    const double h = u * u / (2.0 * a_away);
    flights += u / a_away + std::sqrt(2.0 * h / a_toward);
    const double next = k * std::sqrt(2.0 * h * a_toward);
    ratio = next / u;
    u = next;
  }
  const auto series = chatter_series(m, t, theta, 1, u0, k, -g_r * std::sin(theta));
  ASSERT_TRUE(series.has_value());
  EXPECT_NEAR(series->r, ratio, 1e-14);
  EXPECT_NEAR(series->t_star - t, flights, 1e-12 * flights);
  const double first = u0 / a_away + std::sqrt(u0 * u0 / (a_away * a_toward));
  EXPECT_NEAR(series->t_next, first, 1e-15);
}

// ---- Phase 3: joining bodies -------------------------------------------------------------------

TEST(InstantJoin, TouchingPelletsPartingBelowTheMergeSpeedMoveOnAsOneWithTheirMomentumsSpeed) {
  // 0.2 kg at 1 rad/s and 0.3 kg at 1 + 1e-9 rad/s (below v_merge, 1e-9 of the speed scale
  // sqrt(g/R) = 4.4 rad/s): one body at (0.2·1 + 0.3·(1 + 1e-9)) / 0.5 rad/s, no event.
  Model m = pellets_at({{0.3, 1.0}, {0.3, 1.0 + 1e-9}});
  m.pellets[1].m = 0.3;
  Vec y = state(m);
  std::vector<bool> armed;
  InstantContacts c = no_contacts(m);
  c.pairs = {{0, 1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 0.0, initial_bodies(m, y), c, y, armed);
  EXPECT_TRUE(out.events.empty());
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].members, (std::vector<int>{0, 1}));
  EXPECT_EQ(out.bodies[0].mode, Mode::sliding);
  const double V = (0.2 * 1.0 + 0.3 * (1.0 + 1e-9)) / 0.5;
  EXPECT_NEAR(y[dphi_index(0)], V, 1e-15);
  EXPECT_EQ(y[dphi_index(1)], y[dphi_index(0)]);
}

TEST(InstantJoin, AMergeDrivingABodyIntoALimiterHoldingAMemberStopsItThere) {
  // Pellet 0 is pushed up (2 N: 20 rad/s² against gravity's 9.4 at 0.5 rad) into a limiter that
  // acts on it alone; pellet 1, at its place, parts upward at w = 1e-5 rad/s, pressed back at
  // 9.4 rad/s²: their chatter would last 2w/(9.4·(1 − 0.5)) = 4e-6 s, below the chatter time,
  // so they join. Their momentum's speed, w/2 upward, would drag pellet 0 through its limiter:
  // the limiter takes it, and the body rests there (the push, 10 rad/s² on both, beats gravity).
  const double theta = 0.5, w = 1e-5;
  Model m = pellets_at({{theta, 0.0}, {theta, w}});
  m.pellets[0].force = {2.0, 0.0, 0.0};
  m.k_c = 0.5;
  m.limiters = {{theta, 0.5, false, -1, {0}}};
  Vec y = state(m);
  std::vector<bool> armed = {true};
  InstantContacts c = no_contacts(m);
  c.limiters = {{0, 0, -1}};
  c.pairs = {{0, 1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 0.0, initial_bodies(m, y), c, y, armed);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].members, (std::vector<int>{0, 1}));
  EXPECT_EQ(out.bodies[0].mode, Mode::resting);
  EXPECT_EQ(out.bodies[0].limiter, 0);
  EXPECT_EQ(out.bodies[0].side, -1);
  EXPECT_EQ(y[dphi_index(0)], 0.0);
  EXPECT_EQ(y[dphi_index(1)], 0.0);
  EXPECT_NEAR(out.kinetic_change, -kinetic(m, 1, w), 1e-12 * kinetic(m, 1, w));
}

TEST(InstantJoin, APairAPartingWatchSeparatedStaysApart) {
  Model m = pellets_at({{0.3, 1.0}, {0.3, 1.0}});
  Vec y = state(m);
  std::vector<bool> armed;
  InstantContacts c = no_contacts(m);
  c.pairs = {{0, 1}};
  c.parting = {{0, 1}};
  const InstantOutcome out =
      resolve_instant(m, event_tolerances(m), 0.0, initial_bodies(m, y), c, y, armed);
  EXPECT_EQ(out.bodies.size(), 2u);
}

// ---- Phase 5: modes ----------------------------------------------------------------------------

// One pellet that was sliding up, at zero speed at phi: its outcome.
InstantOutcome turned_at(double phi, Vec& y) {
  Model m = testing::one_pellet(0.3, phi, 0.0);  // μ = tan 0.3
  y = state(m);
  std::vector<Body> before = initial_bodies(m, y);
  before[0].mode = Mode::sliding;
  before[0].s = 1;
  InstantContacts c = no_contacts(m);
  c.pellets[0].reversed = true;
  std::vector<bool> armed;
  return resolve_instant(m, event_tolerances(m), 1.0, before, c, y, armed);
}

TEST(InstantModes, ATurnInsideTheFrictionConeSticks) {
  // At 0.1 rad gravity pulls at (g/R)·sin 0.1 = 1.96 rad/s², below μ(g/R)·cos 0.1 = 6.0.
  Vec y;
  const InstantOutcome out = turned_at(0.1, y);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].mode, Mode::stuck);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(out.events[0].kind, EventKind::stick);
  EXPECT_EQ(out.events[0].limiter, -1);
  EXPECT_EQ(out.touched[0], true);
}

TEST(InstantModes, ATurnOutsideTheFrictionConeSlidesBack) {
  // At 1.2 rad gravity pulls at 18.3 rad/s², above μ(g/R)·cos 1.2 = 2.2: it slides down.
  Vec y;
  const InstantOutcome out = turned_at(1.2, y);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].mode, Mode::sliding);
  EXPECT_EQ(out.bodies[0].s, -1);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(out.events[0].kind, EventKind::reversal);
  EXPECT_EQ(out.events[0].dphi_after[0], 0.0);
}

TEST(InstantModes, APelletPulledFreeSlidesTheWayTheCrossingSaidWhateverTheStickTest) {
  // Stuck at the bottom, where the stick test holds it: the release crossing decided at its
  // root that it goes up (+1), and it does.
  Model m = testing::one_pellet(0.3, 0.0, 0.0);
  Vec y = state(m);
  std::vector<Body> before = initial_bodies(m, y);
  ASSERT_EQ(before[0].mode, Mode::stuck);
  InstantContacts c = no_contacts(m);
  c.pellets[0] = {.reversed = false, .released = true, .pulled = 1};
  std::vector<bool> armed;
  const InstantOutcome out = resolve_instant(m, event_tolerances(m), 1.0, before, c, y, armed);
  ASSERT_EQ(out.bodies.size(), 1u);
  EXPECT_EQ(out.bodies[0].mode, Mode::sliding);
  EXPECT_EQ(out.bodies[0].s, 1);
  ASSERT_EQ(out.events.size(), 1u);
  EXPECT_EQ(out.events[0].kind, EventKind::release);
  EXPECT_EQ(out.events[0].limiter, -1);
}

}  // namespace
}  // namespace vibro
