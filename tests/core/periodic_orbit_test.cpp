// Periodic motions (core/analysis/periodic_orbit.h, core/analysis/monodromy.h): the exact Jacobian
// of the map against central differences of plain runs, across every kind of event; period-1 and
// period-2 motions of the impact oscillator found, stable and unstable, and reached by long runs;
// bad requests refused with the field named.
#include "core/analysis/periodic_orbit.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <atomic>
#include <chrono>
#include <cmath>
#include <complex>
#include <map>
#include <string>

#include "core/analysis/checked_run.h"
#include "core/analysis/monodromy.h"
#include "core/analysis/orbit_continuation.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

using testing::impact_oscillator;

SimOptions tight() {
  SimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  o.check = false;
  return o;
}

Vec start_of(const Model& m) {
  Vec x(2 * m.size());
  for (int i = 0; i < m.size(); ++i) x.segment(2 * i, 2) << m.pellets[i].phi0, m.pellets[i].dphi0;
  return x;
}

// The state after t_end from x, by a plain run: the reference the Jacobian is differenced from.
Vec end_state(Model m, const Vec& x, double t_end) {
  for (int i = 0; i < m.size(); ++i) {
    m.pellets[i].phi0 = x[2 * i];
    m.pellets[i].dphi0 = x[2 * i + 1];
  }
  SimOptions o = tight();
  o.t_end = t_end;
  const RunResult r = simulate(m, o);
  EXPECT_EQ(r.stats.termination, Termination::completed);
  Vec y(2 * m.size());
  for (int i = 0; i < m.size(); ++i)
    y.segment(2 * i, 2) << r.summary.final[i].phi, r.summary.final[i].dphi;
  return y;
}

Mat central_differences(const Model& m, const Vec& x, double t_end, double h = 1e-5) {
  Mat J(x.size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Vec xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    J.col(k) = (end_state(m, xp, t_end) - end_state(m, xm, t_end)) / (2.0 * h);
  }
  return J;
}

std::map<EventKind, int> kinds(const std::vector<Event>& events) {
  std::map<EventKind, int> k;
  for (const Event& e : events) ++k[e.kind];
  return k;
}

// The map's Jacobian over two forcing periods from the scene's start, exact and differenced.
void expect_jacobian_matches_differences(const Model& m, std::vector<EventKind> must_see) {
  const MapPoint p = stroboscopic_map(m, tight(), 2, start_of(m));
  ASSERT_TRUE(p.ok) << p.run.stats.message;
  ASSERT_TRUE(p.exact) << p.jacobian_note;
  const std::map<EventKind, int> seen = kinds(p.run.events);
  for (EventKind k : must_see)
    EXPECT_TRUE(seen.count(k)) << event_kind_name(k) << " not in the run";
  const Mat fd = central_differences(m, start_of(m), 2 * forcing_period(m));
  const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
  EXPECT_LT((p.jacobian - fd).cwiseAbs().maxCoeff(), 1e-5 * scale)
      << "exact\n"
      << p.jacobian << "\ndifferenced\n"
      << fd;
}

// The saltations along a long path are not under the run's deadline unless given it: an orbit
// search on a circle of 1e-9 m, 20,000 impacts a period, answered 0.4 s past its deadline.
TEST(MapJacobian, GivesUpOnceTheDeadlineHasPassed) {
  const Model m = impact_oscillator(5.0);
  SimOptions o = tight();
  o.t_end = 2 * forcing_period(m);
  o.keep_path = true;
  o.check = false;
  const RunResult run = simulate(m, o);
  ASSERT_GT(run.path.size(), 2u);
  const PathJacobian late = path_jacobian(m, run.path, o.rtol, Deadline::in_ms(-1000.0));
  EXPECT_TRUE(late.out_of_time);
  EXPECT_NE(late.unsupported.find("deadline"), std::string::npos) << late.unsupported;
  const PathJacobian in_time = path_jacobian(m, run.path, o.rtol);
  EXPECT_FALSE(in_time.out_of_time);
  EXPECT_TRUE(in_time.unsupported.empty()) << in_time.unsupported;
  SimOptions spent = tight();
  spent.deadline_ms = 0.0;
  const MapPoint p = stroboscopic_map(m, spent, 1, start_of(m));
  EXPECT_FALSE(p.ok);
}

TEST(MapJacobian, LimiterImpactsMatchDifferences) {
  expect_jacobian_matches_differences(impact_oscillator(5.0), {EventKind::limiter});
}

TEST(MapJacobian, StickAndReleaseMatchDifferences) {
  Model m;
  m.alpha0 = 0.3;
  m.pellets = {{0.1, 0.2, 0.0, {0.25, 3.0, 0.0}}};
  m.limiters = {{1.0, 0.7, false, -1, {}}, {-1.0, 0.7, false, -1, {}}};
  expect_jacobian_matches_differences(m, {EventKind::stick, EventKind::release});
}

TEST(MapJacobian, CollisionsReversalsAndFrictionMatchDifferences) {
  Model m;
  m.alpha0 = 0.05;
  m.k_c = 0.7;
  m.pellets = {{0.2, 0.3, 2.0, {1.0, 4.0, 0.3}}, {0.3, -0.3, 0.5, {}}};
  m.limiters = {{M_PI / 4, 0.6, false, -1, {}}, {-M_PI / 4, 0.6, false, -1, {}}};
  expect_jacobian_matches_differences(
      m, {EventKind::collision, EventKind::reversal, EventKind::limiter});
}

TEST(MapJacobian, ChatterToRestAndReleaseMatchDifferences) {
  Model m;
  m.alpha0 = 0.1;
  m.pellets = {{0.1, 0.3, 1.0, {0.6, 2.0, 0.0}}};
  m.limiters = {{0.0, 0.5, false, -1, {}}};
  expect_jacobian_matches_differences(m, {EventKind::chatter, EventKind::release});
}

TEST(MapJacobian, BilateralNormalForceZerosMatchDifferences) {
  Model m;
  m.alpha0 = 0.1;
  m.friction = FrictionLaw::bilateral;
  m.pellets = {{0.1, 0.0, 12.0, {0.5, 3.0, 0.0}}};
  expect_jacobian_matches_differences(m, {EventKind::reversal});
}

OrbitSpec from_guess(double phi, double dphi, int periods = 1) {
  OrbitSpec s;
  s.periods = periods;
  s.guess = {{phi, dphi}};
  return s;
}

TEST(PeriodicOrbit, FoundFromANearbyGuessIsWhereALongRunSettles) {
  const Model m = impact_oscillator(6.0);
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(), from_guess(0.15, 0.1));
  ASSERT_TRUE(orbit.converged) << orbit.message;
  EXPECT_TRUE(orbit.admissible) << orbit.message;
  EXPECT_TRUE(orbit.stable);
  EXPECT_GT(orbit.iterations, 1);
  EXPECT_LT(orbit.residual, 1e-9);
  EXPECT_EQ(orbit.impacts_per_period, 1.0);
  // The run from the scene's own start settles onto it: after 400 periods it is on the orbit.
  SimOptions o = tight();
  o.t_end = 400 * forcing_period(m);
  const RunResult settled = simulate(m, o);
  EXPECT_NEAR(wrap_angle(settled.summary.final[0].phi - orbit.state[0].phi), 0.0, 1e-8);
  EXPECT_NEAR(settled.summary.final[0].dphi, orbit.state[0].dphi, 1e-8);
}

TEST(PeriodicOrbit, MultipliersMatchThoseOfTheDifferencedMap) {
  const Model m = impact_oscillator(6.0);
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(), from_guess(0.15, 0.1));
  ASSERT_TRUE(orbit.converged) << orbit.message;
  Vec x(2);
  x << orbit.state[0].phi, orbit.state[0].dphi;
  const Eigen::EigenSolver<Mat> fd(central_differences(m, x, forcing_period(m)), false);
  ASSERT_EQ(orbit.multipliers.size(), 2u);
  for (const std::complex<double>& mu : orbit.multipliers) {
    double nearest = INFINITY;
    for (Eigen::Index k = 0; k < 2; ++k)
      nearest = std::min(nearest, std::abs(mu - fd.eigenvalues()[k]));
    EXPECT_LT(nearest, 1e-5) << mu;
  }
  // Frictionless between impacts, the flow keeps areas; each impact scales them by k²: the
  // multipliers' product is k² per period.
  EXPECT_NEAR(std::abs(orbit.multipliers[0] * orbit.multipliers[1]), 0.64, 1e-8);
}

// Past the period doubling near Ω = 5.6 rad/s, the period-1 motion lives on, unstable, with a
// multiplier below −1; beside it the period-2 motion it shed is stable.
TEST(PeriodicOrbit, UnstableMotionPastAPeriodDoublingAndTheStablePeriodTwoBesideIt) {
  const Model m = impact_oscillator(5.5);
  const PeriodicOrbit one = find_periodic_orbit(m, tight(), from_guess(0.12, 0.15));
  ASSERT_TRUE(one.converged) << one.message;
  EXPECT_FALSE(one.stable);
  EXPECT_LT(one.multipliers[0].real(), -1.0);
  EXPECT_NEAR(one.multipliers[0].imag(), 0.0, 1e-12);
  // A long run does not stay on it: it settles onto the period-2 motion.
  OrbitSpec spec;
  spec.periods = 2;
  spec.transient = 300;
  const PeriodicOrbit two = find_periodic_orbit(m, tight(), spec);
  ASSERT_TRUE(two.converged) << two.message;
  EXPECT_TRUE(two.stable);
  EXPECT_TRUE(two.admissible) << two.message;
  EXPECT_GT(std::abs(wrap_angle(two.state[0].phi - one.state[0].phi)), 1e-3);
  // Over two periods its state is not the period-1 one: the map of one period moves it.
  const MapPoint half = stroboscopic_map(m, tight(), 1, Vec::Map(&two.state[0].phi, 2));
  EXPECT_GT(residual_norm(m, orbit_residual(half)), 1e-3);
}

TEST(PeriodicOrbit, TwoReturnsOfAPeriodOneMotionSquareItsMultipliers) {
  const Model m = impact_oscillator(6.5);
  const PeriodicOrbit one = find_periodic_orbit(m, tight(), from_guess(0.2, 0.2));
  const PeriodicOrbit two = find_periodic_orbit(m, tight(), from_guess(0.2, 0.2, 2));
  ASSERT_TRUE(one.converged && two.converged);
  EXPECT_NEAR(two.state[0].phi, one.state[0].phi, 1e-9);
  for (const auto& mu : one.multipliers) {
    double nearest = INFINITY;
    for (const auto& nu : two.multipliers) nearest = std::min(nearest, std::abs(mu * mu - nu));
    EXPECT_LT(nearest, 1e-8);
  }
}

// The run's deadline bounds the whole search, not each of its runs.
TEST(PeriodicOrbit, TheDeadlineBoundsTheWholeSearch) {
  SimOptions o = tight();
  o.deadline_ms = 1e-3;
  const PeriodicOrbit orbit =
      find_periodic_orbit(impact_oscillator(5.5), o, from_guess(0.12, 0.15));
  EXPECT_FALSE(orbit.converged);
  EXPECT_NE(orbit.message.find("deadline"), std::string::npos) << orbit.message;
}

TEST(PeriodicOrbit, BadRequestsNameTheirField) {
  Model unforced = impact_oscillator(5.0);
  unforced.pellets[0].force = {};
  EXPECT_EQ(validate_orbit(unforced, {})->field, "model.pellets");
  OrbitSpec zero;
  zero.periods = 0;
  EXPECT_EQ(validate_orbit(impact_oscillator(5.0), zero)->field, "periodic_orbit.periods");
  OrbitSpec two_pellets;
  two_pellets.guess = {{0.1, 0.0}, {0.2, 0.0}};
  const auto wrong = validate_orbit(impact_oscillator(5.0), two_pellets);
  ASSERT_TRUE(wrong);
  EXPECT_EQ(wrong->field, "periodic_orbit.guess");
  EXPECT_NE(wrong->message.find("got 2"), std::string::npos);
  Model incommensurate = impact_oscillator(5.0);
  incommensurate.pellets.push_back({0.1, 1.0, 0.0, {0.2, 7.3, 0.0}});
  EXPECT_EQ(validate_orbit(incommensurate, {})->field, "model.pellets[1].Omega");
  EXPECT_FALSE(validate_orbit(impact_oscillator(5.0), {}));
}

// A force with Omega = 0 is the constant F0 cos(psi): it repeats with every period, so a pellet
// pushed by one leaves the scene's orbits to seek. Forces that do not repeat are refused.
TEST(PeriodicOrbit, AConstantForceRepeatsWithEveryPeriod) {
  Model m = impact_oscillator(5.0);
  m.pellets.push_back({0.1, 2.0, 0.0, {0.05, 0.0, 0.0}});
  EXPECT_FALSE(validate_orbit(m, {}));
  m.pellets[1].force.Omega = 2.5;  // half the first force's frequency: it does not repeat
  EXPECT_EQ(validate_orbit(m, {})->field, "model.pellets[1].Omega");
  m.pellets[1].force.Omega = -5.0;  // periodic forces turn forward (Omega > 0)
  EXPECT_EQ(validate_orbit(m, {})->field, "model.pellets[1].Omega");
}

// A guess is a starting state and is bounded as phi0 and dphi0 are: far past them an angle keeps
// no digits below the turn (a guess of 1e17 rad once hung the search).
TEST(PeriodicOrbit, GuessesAreBoundedLikeStartingStates) {
  const Model m = impact_oscillator(5.0);
  EXPECT_EQ(validate_orbit(m, from_guess(1e17, 1.0))->field, "periodic_orbit.guess[0].phi");
  EXPECT_EQ(validate_orbit(m, from_guess(-1e4 - 1.0, 0.0))->field, "periodic_orbit.guess[0].phi");
  EXPECT_EQ(validate_orbit(m, from_guess(0.1, 2e7))->field, "periodic_orbit.guess[0].dphi");
  EXPECT_EQ(validate_orbit(m, from_guess(0.1, NAN))->field, "periodic_orbit.guess[0].dphi");
  Model free = m;
  free.limiters.clear();
  EXPECT_FALSE(validate_orbit(free, from_guess(1e4, -1e7)));
}

// A guess beyond a fixed limiter from the pellet's start (MODEL.md, "A fixed point never crosses
// a limiter") is refused: the stop at 0 holds the pellet that starts at 0.1 in (0, 2π).
TEST(PeriodicOrbit, AGuessBeyondAStopFromTheStartIsRefused) {
  const Model m = impact_oscillator(5.0);
  EXPECT_FALSE(validate_orbit(m, from_guess(0.0, 0.3)));
  EXPECT_FALSE(validate_orbit(m, from_guess(6.2, -0.3)));
  const std::optional<FieldError> e = validate_orbit(m, from_guess(-0.05, 0.3));
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "periodic_orbit.guess[0].phi");
  EXPECT_NE(e->message.find("beyond limiter 1"), std::string::npos) << e->message;
  EXPECT_EQ(validate_orbit(m, from_guess(0.1 + kTwoPi, 0.0))->field, "periodic_orbit.guess[0].phi");
}

}  // namespace
}  // namespace vibro

namespace vibro {
namespace {

OrbitBranch follow(double from, double to, double phi, double dphi, int max_points = 400) {
  const Model m = impact_oscillator(from);
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(), from_guess(phi, dphi));
  EXPECT_TRUE(orbit.converged) << orbit.message;
  const ContinuationSpec spec{"model.pellets[0].Omega", to, max_points};
  EXPECT_FALSE(validate_continuation(m, spec));
  return continue_orbit(m, tight(), orbit, spec);
}

std::vector<Bifurcation> of_kind(const OrbitBranch& b, BifurcationKind kind) {
  std::vector<Bifurcation> out;
  for (const Bifurcation& x : b.bifurcations)
    if (x.kind == kind) out.push_back(x);
  return out;
}

// The largest multiplier of the period-1 motion near `state` at this Ω, found afresh.
std::complex<double> leading_multiplier(double Omega, const std::vector<PhasePoint>& state) {
  const PeriodicOrbit o = find_periodic_orbit(impact_oscillator(Omega), tight(),
                                              from_guess(state[0].phi, state[0].dphi));
  EXPECT_TRUE(o.converged) << o.message;
  return o.multipliers.front();
}

TEST(OrbitContinuation, LocatesThePeriodDoublingWhereAMultiplierPassesMinusOne) {
  const OrbitBranch b = follow(6.0, 5.0, 0.15, 0.1);
  ASSERT_TRUE(b.reached) << b.message;
  const auto pd = of_kind(b, BifurcationKind::period_doubling);
  ASSERT_EQ(pd.size(), 1u);
  EXPECT_NEAR(pd[0].value, 5.557, 0.005);
  // Independently, by Newton's method on either side: stable above, a multiplier below −1 below.
  const auto above = leading_multiplier(pd[0].value + 1e-3, pd[0].state);
  const auto below = leading_multiplier(pd[0].value - 1e-3, pd[0].state);
  EXPECT_LT(std::abs(above), 1.0);
  EXPECT_LT(below.real(), -1.0);
  EXPECT_LT(std::abs(below + 1.0), 0.05);
  // The doubled motion it offers is a stable period-2 motion past the doubling, which one period
  // does not return.
  ASSERT_TRUE(pd[0].doubled_value);
  EXPECT_LT(*pd[0].doubled_value, pd[0].value);
  const Model past = impact_oscillator(*pd[0].doubled_value);
  const PeriodicOrbit doubled = find_periodic_orbit(
      past, tight(), from_guess(pd[0].doubled_state[0].phi, pd[0].doubled_state[0].dphi, 2));
  ASSERT_TRUE(doubled.converged) << doubled.message;
  EXPECT_EQ(doubled.iterations, 0);
  EXPECT_TRUE(doubled.stable);
  const MapPoint once = stroboscopic_map(past, tight(), 1, Vec::Map(&doubled.state[0].phi, 2));
  EXPECT_GT(residual_norm(past, orbit_residual(once)), 1e-4);
  // Stability along the branch follows the multipliers.
  for (const BranchPoint& p : b.points) EXPECT_EQ(p.stable, p.value > pd[0].value) << p.value;
}

TEST(OrbitContinuation, PassesAndLocatesTheFoldWhereTheLowMotionEnds) {
  // The branch goes on to a second fold near 2 rad/s and back up: 30 points see the first.
  const OrbitBranch b = follow(7.0, 9.0, 0.30, 0.23, 30);
  EXPECT_FALSE(b.reached);
  EXPECT_NE(b.message.find("max_points"), std::string::npos) << b.message;
  const auto folds = of_kind(b, BifurcationKind::fold);
  ASSERT_GE(folds.size(), 1u);
  EXPECT_NEAR(folds[0].value, 7.807, 0.005);
  // A multiplier is +1 there, by the map's Jacobian at the located state.
  const MapPoint at = stroboscopic_map(impact_oscillator(folds[0].value), tight(), 1,
                                       Vec::Map(&folds[0].state[0].phi, 2));
  const Eigen::EigenSolver<Mat> eig(at.jacobian, false);
  double nearest = INFINITY;
  for (Eigen::Index k = 0; k < 2; ++k)
    nearest = std::min(nearest, std::abs(eig.eigenvalues()[k] - 1.0));
  EXPECT_LT(nearest, 1e-3);
  // The branch turns back: values below the fold on both its sides, the second unstable.
  bool turned = false;
  for (std::size_t k = 1; k < b.points.size(); ++k)
    if (b.points[k].value < b.points[k - 1].value && b.points[k].value < 7.7) {
      turned = true;
      EXPECT_FALSE(b.points[k].stable);
      break;
    }
  EXPECT_TRUE(turned);
}

TEST(OrbitContinuation, LocatesTheGrazingWhereASecondImpactAppears) {
  const OrbitBranch b = follow(4.6, 4.3, 0.03, 0.2);
  ASSERT_TRUE(b.reached) << b.message;
  const auto grazings = of_kind(b, BifurcationKind::grazing);
  ASSERT_EQ(grazings.size(), 1u);
  EXPECT_NEAR(grazings[0].value, 4.4355, 1e-3);
  for (const BranchPoint& p : b.points) {
    if (std::abs(p.value - grazings[0].value) <= 1e-3) continue;
    EXPECT_EQ(p.impacts_per_period, p.value > grazings[0].value ? 1.0 : 2.0) << p.value;
  }
}

// Where the branch is stable, a long run from the scene's start settles onto it: the branch and
// the brute-force diagram agree.
TEST(OrbitContinuation, StablePartAgreesWithLongRuns) {
  const OrbitBranch b = follow(6.5, 5.6, 0.2, 0.2);
  ASSERT_TRUE(b.reached) << b.message;
  int compared = 0;
  for (std::size_t k = 0; k < b.points.size(); k += 3) {
    const BranchPoint& p = b.points[k];
    ASSERT_TRUE(p.stable) << p.value;
    const Model m = impact_oscillator(p.value);
    SimOptions o = tight();
    o.t_end = 400 * forcing_period(m);
    const RunResult run = simulate(m, o);
    EXPECT_NEAR(wrap_angle(run.summary.final[0].phi - p.state[0].phi), 0.0, 1e-6) << p.value;
    EXPECT_NEAR(run.summary.final[0].dphi, p.state[0].dphi, 1e-6) << p.value;
    ++compared;
  }
  EXPECT_GE(compared, 3);
}

TEST(OrbitContinuation, BadSpecsNameTheirField) {
  const Model m = impact_oscillator(5.0);
  EXPECT_EQ(validate_continuation(m, {"model.pellets[3].Omega", 6.0, 10})->field,
            "periodic_orbit.continuation.parameter");
  EXPECT_EQ(validate_continuation(m, {"model.pellets[0].Omega", 5.0, 10})->field,
            "periodic_orbit.continuation.to");
  EXPECT_EQ(validate_continuation(m, {"model.pellets[0].F0", 0.0, 10})->field,
            "periodic_orbit.continuation.to");
  EXPECT_EQ(validate_continuation(m, {"model.pellets[0].Omega", 6.0, 1})->field,
            "periodic_orbit.continuation.max_points");
}

// Every point of a branch is a valid model: the continuation checks the model at each value, not
// the model seen from its section's phase (whose psi is shifted by Omega times the phase). From
// psi at its bound of -1e4 the branch turns the other way first.
// A cancel reaches the map's every evaluation, not only the walk's next step: a cancelled walk
// evaluates nothing more and says so.
TEST(OrbitContinuation, ACancelStopsEveryEvaluation) {
  const Model m = impact_oscillator(6.0);
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(), from_guess(0.15, 0.1));
  ASSERT_TRUE(orbit.converged) << orbit.message;
  std::atomic<bool> cancel{true};
  const OrbitBranch b =
      continue_orbit(m, tight(), orbit, {"model.pellets[0].Omega", 5.0, 300}, {}, &cancel);
  EXPECT_EQ(b.message, "cancelled");
  EXPECT_TRUE(b.points.empty());
  // Cancelled after its first point, inside the walk.
  cancel = false;
  const OrbitBranch c = continue_orbit(
      m, tight(), orbit, {"model.pellets[0].Omega", 5.0, 300}, [&](double) { cancel = true; },
      &cancel);
  EXPECT_EQ(c.message, "cancelled");
  EXPECT_LE(c.points.size(), 2u);
}

TEST(OrbitContinuation, StaysWhereTheModelIsValid) {
  Model m = impact_oscillator(5.0);
  m.pellets[0].force.psi = -1e4;
  SimOptions o;
  o.rtol = 1e-9;
  o.atol = 1e-12;
  OrbitSpec spec;
  spec.transient = 40;
  const PeriodicOrbit orbit = find_periodic_orbit(m, o, spec);
  ASSERT_TRUE(orbit.converged) << orbit.message;
  const ContinuationSpec to{"model.pellets[0].psi", 1e4, 6};
  ASSERT_FALSE(validate_continuation(m, to));
  const OrbitBranch b = continue_orbit(m, o, orbit, to);
  ASSERT_FALSE(b.points.empty()) << b.message;
  for (const BranchPoint& p : b.points) EXPECT_GE(p.value, -1e4);
}

// A far `to` scales the parameter by the value's own size, not by the span to − p0: the branch is
// followed as far as max_points allows, point for point the branch toward a near `to` whose span
// is that size (Ω from 5 to 10, F0 from 0.3 to 1.3, R from 0.5 to 1.5), its bifurcations the same.
// Scaled by the span, its smallest step was 1e-7 of it (100 rad/s toward 1e9) and the branch
// stopped at its first point.
TEST(OrbitContinuation, AFarToFollowsTheBranchAsANearOneDoes) {
  struct Case {
    std::string parameter;
    double near, far;
  };
  const Case cases[] = {{"model.pellets[0].Omega", 10.0, 1e9},
                        {"model.pellets[0].F0", 1.3, 1e12},
                        {"model.R", 1.5, 1e6}};
  const Model m = impact_oscillator(5.0);
  OrbitSpec spec;
  spec.transient = 150;
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(), spec);
  ASSERT_TRUE(orbit.converged) << orbit.message;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.parameter);
    const ContinuationSpec near{c.parameter, c.near, 30}, far{c.parameter, c.far, 30};
    ASSERT_FALSE(validate_continuation(m, far));
    const OrbitBranch a = continue_orbit(m, tight(), orbit, near);
    const OrbitBranch b = continue_orbit(m, tight(), orbit, far);
    EXPECT_FALSE(b.reached);
    EXPECT_EQ(b.points.size(), 30u);
    EXPECT_NE(b.message.find("max_points"), std::string::npos) << b.message;
    // The near branch's points before its end at `to`, and its bifurcations.
    const std::size_t shared = a.points.size() - (a.reached ? 1 : 0);
    ASSERT_GE(shared, 10u);
    for (std::size_t k = 0; k < shared; ++k) {
      EXPECT_EQ(a.points[k].value, b.points[k].value) << k;
      EXPECT_EQ(a.points[k].state[0].phi, b.points[k].state[0].phi) << k;
      EXPECT_EQ(a.points[k].state[0].dphi, b.points[k].state[0].dphi) << k;
    }
    ASSERT_GE(b.bifurcations.size(), a.bifurcations.size());
    for (std::size_t k = 0; k < a.bifurcations.size(); ++k) {
      EXPECT_EQ(a.bifurcations[k].kind, b.bifurcations[k].kind);
      EXPECT_EQ(a.bifurcations[k].value, b.bifurcations[k].value);
    }
  }
}

// The search holds its simulated time to the run's limit, as a scene's run is: the run to the
// guess (transient periods) and the Newton iterations ((max_iterations + 1) × periods).
TEST(PeriodicOrbit, ItsSimulatedTimeIsHeldToTheLimits) {
  const Model m = impact_oscillator(5.0);  // T = 1.26 s
  Limits limits;
  limits.t_end = 100.0;
  OrbitSpec spec;  // a transient of 100 periods: 126 s
  EXPECT_EQ(validate_orbit(m, spec, limits)->field, "periodic_orbit.transient");
  spec.guess = {{0.1, 0.0}};  // no transient; 41 maps of one period: 52 s
  EXPECT_FALSE(validate_orbit(m, spec, limits));
  spec.max_iterations = 100;  // 101 maps: 127 s
  EXPECT_EQ(validate_orbit(m, spec, limits)->field, "periodic_orbit.max_iterations");
}

}  // namespace
}  // namespace vibro
