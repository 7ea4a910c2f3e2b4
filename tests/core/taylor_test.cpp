// The Taylor-series method (core/integrators/taylor.h) on the equations of motion: its accuracy
// as the tolerance tightens, its step counts against DOP853, its step as polynomials, and an
// event whose two crossings fall inside one of its steps.
#include "core/integrators/taylor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "core/analysis/checked_run.h"
#include "core/analysis/periodic_orbit.h"
#include "core/integrators/stepper.h"
#include "core/model/dynamics.h"
#include "core/run/observers.h"
#include "core/run/simulate.h"
#include "impact_oscillator.h"
#include "scenes.h"

namespace vibro {
namespace {

// A forced pendulum with friction, sliding alone.
struct ForcedPendulum {
  Model model = [] {
    Model m = testing::one_pellet(0.1, 0.4, 2.0);
    m.pellets[0].force = {0.5, 4.0, 0.2};
    return m;
  }();
  std::vector<Body> bodies = {Body{.members = {0}, .mode = Mode::sliding, .s = 1}};
  Vec y0 = (Vec(3) << 0.4, 2.0, 0.0).finished();
  SegmentDynamics sys{model, bodies, y0};
};

Vec solve(Stepper& stepper, const OdeSystem& sys, const Vec& y0, double t_end, long* steps) {
  stepper.start(sys, 0.0, y0);
  while (stepper.t() < t_end)
    if (stepper.step(t_end) != StepStatus::ok) return Vec::Constant(3, NAN);
  if (steps) *steps = stepper.stats().steps;
  return stepper.y();
}

TEST(Taylor, TheOrderFollowsTheTolerance) {
  EXPECT_EQ(integrators::Taylor::jorba_zou_order(1e-12), 15);  // ⌈13.8 + 1⌉
  EXPECT_EQ(integrators::Taylor::jorba_zou_order(1e-9), 12);
  EXPECT_EQ(integrators::Taylor::jorba_zou_order(1e-14), 18);
  EXPECT_EQ(integrators::Taylor::jorba_zou_order(0.1), 3);
  EXPECT_EQ(integrators::Taylor::order_for(1e-12), 18);  // three above
  EXPECT_EQ(integrators::Taylor::order_for(1e-14), 21);
  EXPECT_EQ(integrators::Taylor::order_for(0.1), 6);
}

// At Jorba and Zou's order the step is theirs, ρ_m/e²; above it, the step at which the last term
// (h/ρ)^p is as small as theirs, e^(−2·p_JZ), but for the safety factor ρ_m.
TEST(Taylor, ItsStepKeepsJorbaAndZousLastTerm) {
  const double e2 = std::exp(-2.0);
  for (double rtol : {1e-6, 1e-9, 1e-12, 1e-14}) {
    const int p_jz = integrators::Taylor::jorba_zou_order(rtol);
    EXPECT_DOUBLE_EQ(integrators::Taylor::safety_for(rtol, p_jz), std::exp(-0.7 / (p_jz - 1)) * e2);
    const int p = integrators::Taylor::order_for(rtol);
    const double x = integrators::Taylor::safety_for(rtol, p) / std::exp(-0.7 / (p - 1));
    EXPECT_NEAR(std::pow(x, p), std::exp(-2.0 * p_jz), 1e-12 * std::exp(-2.0 * p_jz));
    EXPECT_GT(x, e2);  // a longer step
  }
}

// The state's error after 0.3 s is within ten times the tolerance at every tolerance, and falls
// as it tightens down to round-off (1e-14, some twenty units in the last place of the state). (The
// friction's direction s is fixed, so the equations stay smooth where the speed changes sign: the
// test is of the integrator alone.)
TEST(Taylor, ItsErrorFollowsTheTolerance) {
  ForcedPendulum p;
  auto reference = make_stepper(Method::dop853, StepperOptions{1e-14, 1e-16});
  const Vec exact = solve(*reference, p.sys, p.y0, 0.3, nullptr);
  double previous = INFINITY;
  for (double rtol : {1e-6, 1e-8, 1e-10, 1e-12}) {
    auto taylor = make_stepper(Method::taylor, StepperOptions{rtol, 1e-3 * rtol});
    const Vec y = solve(*taylor, p.sys, p.y0, 0.3, nullptr);
    const double error = (y - exact).head<2>().cwiseAbs().maxCoeff();
    EXPECT_LT(error, 10.0 * rtol) << "rtol " << rtol;
    EXPECT_LT(error, previous) << "rtol " << rtol;
    previous = std::max(error, 1e-14);
  }
}

TEST(Taylor, ItsStepIsItsPolynomialsAndItsDenseOutputEvaluatesThem) {
  ForcedPendulum p;
  integrators::Taylor taylor(StepperOptions{1e-10, 1e-13});
  taylor.start(p.sys, 0.0, p.y0);
  EXPECT_EQ(taylor.polynomials(), nullptr);  // no step yet
  ASSERT_EQ(taylor.step(1.0), StepStatus::ok);
  const StepPolynomials* poly = taylor.polynomials();
  ASSERT_NE(poly, nullptr);
  EXPECT_EQ(poly->t0, 0.0);
  EXPECT_EQ(poly->degree, taylor.order());
  Vec y;
  taylor.dense(taylor.t_prev(), y);
  EXPECT_EQ(y, p.y0);
  taylor.dense(taylor.t(), y);
  EXPECT_EQ(y, taylor.y());
  for (int i = 0; i < 3; ++i) EXPECT_EQ(poly->component(i)[0], p.y0[i]);
}

// OdeSystem without jets: the stepper says so rather than stepping.
class NoJets final : public OdeSystem {
 public:
  int dimension() const override { return 1; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt[0] = -y[0]; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy(0, 0) = -1.0;
    dfdt[0] = 0.0;
  }
};

TEST(Taylor, ASystemWithoutJetsFailsItsFirstStep) {
  NoJets sys;
  integrators::Taylor taylor(StepperOptions{1e-10, 1e-13});
  taylor.start(sys, 0.0, Vec::Ones(1));
  EXPECT_EQ(taylor.step(1.0), StepStatus::solver_failure);
  EXPECT_EQ(taylor.t(), 0.0);
}

// y' = −y, two components, whose jets put `bad` (NaN or an infinity) at coefficient k of
// component 1.
class BadJets final : public OdeSystem {
 public:
  BadJets(double bad, int k) : bad_(bad), k_(k) {}
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override { dydt = -y; }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy = -Mat::Identity(2, 2);
    dfdt.setZero();
  }
  bool taylor_coefficients(double, const Vec& y0, int order, std::span<double> out) const override {
    for (int i = 0; i < 2; ++i) {
      double c = y0[i];
      for (int k = 0; k <= order; ++k, c /= -k)
        out[static_cast<std::size_t>(i) * (order + 1) + k] = c;
    }
    out[static_cast<std::size_t>(order + 1) + k_] = bad_;
    return true;
  }
  bool has_taylor_coefficients() const override { return true; }

 private:
  double bad_;
  int k_;
};

// A coefficient that is not finite, wherever it is (the step size's orders or the others), fails
// the step as non-finite and leaves the state where it was.
TEST(Taylor, ACoefficientThatIsNotFiniteFailsTheStepAsNonFinite) {
  const double inf = std::numeric_limits<double>::infinity();
  for (double bad : {std::nan(""), inf, -inf}) {
    for (int k : {1, 5, 12, 13}) {
      const BadJets sys(bad, k);
      integrators::Taylor taylor(StepperOptions{1e-10, 1e-13});  // order 13
      taylor.start(sys, 0.0, Vec::Ones(2));
      EXPECT_EQ(taylor.step(1.0), StepStatus::non_finite) << "bad " << bad << ", k " << k;
      EXPECT_EQ(taylor.t(), 0.0);
      EXPECT_EQ(taylor.y()[1], 1.0);
      EXPECT_EQ(taylor.polynomials(), nullptr);
    }
  }
}

// Issue 33's figure: on the impact oscillator (Ω = 7, 70 periods) at rtol 1e-12, at most half
// DOP853's steps, with the same events.
TEST(Taylor, TakesAtMostHalfDop853sStepsOnTheImpactOscillatorAtTightTolerance) {
  const Model model = testing::impact_oscillator(7.0);
  SimOptions o;
  o.t_end = 70.0 * kTwoPi / 7.0;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  o.check = false;
  o.method = Method::dop853;
  const RunResult dop853 = simulate(model, o);
  o.method = Method::taylor;
  const RunResult taylor = simulate(model, o);
  EXPECT_LE(2 * taylor.stats.steps, dop853.stats.steps)
      << taylor.stats.steps << " steps against " << dop853.stats.steps;
  ASSERT_EQ(taylor.events.size(), dop853.events.size());
  for (std::size_t k = 0; k < taylor.events.size(); ++k) {
    EXPECT_EQ(taylor.events[k].kind, dop853.events[k].kind) << "event " << k;
    EXPECT_NEAR(taylor.events[k].t, dop853.events[k].t, 1e-8) << "event " << k;
  }
}

// A Taylor stepper that lands on the stops as the Runge–Kutta methods do (Stepper's own
// step_landing): the reference for stops read from the polynomial inside a step.
class LandingTaylor final : public Stepper {
 public:
  explicit LandingTaylor(const StepperOptions& options) : taylor_(options) {}
  std::string_view name() const override { return taylor_.name(); }
  void start(const OdeSystem& sys, double t0, const Vec& y0) override {
    taylor_.start(sys, t0, y0);
  }
  StepStatus step(double t_limit) override { return taylor_.step(t_limit); }
  const Vec& y() const override { return taylor_.y(); }
  double t_prev() const override { return taylor_.t_prev(); }
  double t() const override { return taylor_.t(); }
  void dense(double t, Vec& out) const override { taylor_.dense(t, out); }
  const StepPolynomials* polynomials() const override { return taylor_.polynomials(); }
  const StepperStats& stats() const override { return taylor_.stats(); }

 private:
  integrators::Taylor taylor_;
};

// The runs' stops are at the same times, their pellet's angles within tol and speeds within
// 10·tol.
void expect_same_stops(const RunResult& a, const RunResult& b, double tol) {
  ASSERT_EQ(a.stops.size(), b.stops.size());
  for (std::size_t k = 0; k < a.stops.size(); ++k) {
    EXPECT_EQ(a.stops[k].t, b.stops[k].t);
    EXPECT_NEAR(a.stops[k].pellets[0].phi, b.stops[k].pellets[0].phi, tol) << k;
    EXPECT_NEAR(a.stops[k].pellets[0].dphi, b.stops[k].pellets[0].dphi, 10 * tol) << k;
  }
}

// A stroboscopic section's stops fall inside Taylor steps, whose polynomial gives the state there
// as exactly as a step's end: the steps pass them. The stops agree with a run that lands on each
// (whose steps before a stop are split to reach it evenly), with about a step fewer per stop.
TEST(Taylor, StopsInsideAStepAreReadFromItsPolynomialInsteadOfLandedOn) {
  const Model model = testing::impact_oscillator(7.0);
  const double T = kTwoPi / 7.0;
  SimOptions o;
  o.t_end = 70.0 * T;
  for (int k = 1; k <= 70; ++k) o.stops.push_back(k * T);
  o.rtol = 1e-10;
  o.atol = 1e-12;
  o.check = false;
  o.method = Method::taylor;
  const RunResult passed = simulate(model, o);
  LandingTaylor landing({o.rtol, o.atol});
  StandardOutputs outputs(model, o);
  const RunResult landed =
      simulate(model, static_cast<const SolverOptions&>(o), landing, outputs.list());
  ASSERT_EQ(passed.stops.size(), 70u);
  expect_same_stops(passed, landed, 1e-9);
  EXPECT_EQ(passed.events.size(), landed.events.size());
  // The last stop is t_end, where both land.
  EXPECT_LE(passed.stats.steps + 60, landed.stats.steps)
      << passed.stats.steps << " steps against " << landed.stats.steps;
}

// A free swing sampled every 5 ms: each Taylor step passes several stops, each settled in turn
// from the step's polynomial; they agree with DOP853's, which lands on each.
TEST(Taylor, ManyStopsInsideOneStepAreEachReadFromItsPolynomial) {
  const Model model = testing::one_pellet(0.0, 1.0, 3.0);
  SimOptions o;
  o.t_end = 2.0;
  for (int k = 1; k <= 400; ++k) o.stops.push_back(k * 0.005);
  o.rtol = 1e-12;
  o.atol = 1e-14;
  o.check = false;
  o.method = Method::taylor;
  const RunResult taylor = simulate(model, o);
  o.method = Method::dop853;
  const RunResult dop853 = simulate(model, o);
  ASSERT_EQ(taylor.stops.size(), 400u);
  expect_same_stops(taylor, dop853, 1e-10);
  EXPECT_EQ(taylor.events.size(), dop853.events.size());
  EXPECT_LT(4 * taylor.stats.steps, 400) << taylor.stats.steps << " steps";
}

// A pendulum that turns 1e-7 rad past a stop: the way to the stop falls through zero and rises
// again within 3e-4 s, inside one Taylor step of about 0.05 s. The strike is found, at the time
// the energy gives.
TEST(Taylor, FindsAStrikeWhoseTwoCrossingsFallInsideOneStep) {
  const double g = 9.81, R = 0.5, phi0 = 0.2, stop = 1.0, overshoot = 1e-7;
  const double turn = stop + overshoot;
  Model model = testing::one_pellet(0.0, phi0, 0.0);
  model.pellets[0].dphi0 = std::sqrt(2.0 * g / R * (std::cos(phi0) - std::cos(turn)));
  model.limiters = {Limiter{.angle = stop, .k = 0.5}};
  const std::vector<Body> bodies = {Body{.members = {0}, .mode = Mode::sliding, .s = 1}};
  const Vec y0 = (Vec(3) << phi0, model.pellets[0].dphi0, 0.0).finished();
  const SegmentDynamics sys(model, bodies, y0);

  // The free motion, not stopped: the step that crosses the stop also comes back across it.
  integrators::Taylor taylor(StepperOptions{1e-10, 1e-13});
  taylor.start(sys, 0.0, y0);
  while (taylor.y()[1] > 0.0) ASSERT_EQ(taylor.step(10.0), StepStatus::ok);
  Vec start_of_step;
  taylor.dense(taylor.t_prev(), start_of_step);
  EXPECT_LT(start_of_step[0], stop) << "the step starts past the stop";
  EXPECT_LT(taylor.y()[0], stop) << "the step ends before the return across the stop";

  SimOptions o;
  o.t_end = 1.0;
  o.method = Method::taylor;
  o.rtol = 1e-10;
  o.atol = 1e-13;
  const RunResult run = simulate(model, o);
  ASSERT_FALSE(run.events.empty());
  EXPECT_EQ(run.events[0].kind, EventKind::limiter);
  EXPECT_NEAR(run.events[0].phi, stop, 1e-12);
  // Striking speed from the energy: φ'² = 2(g/R)(cos stop − cos turn), about 1.8e-3 rad/s.
  const double speed = std::sqrt(2.0 * g / R * (std::cos(stop) - std::cos(turn)));
  EXPECT_NEAR(run.events[0].dphi_before[0], speed, 1e-3 * speed);
}

// The analyses run on any method's runs: the impact oscillator's periodic orbit and its Floquet
// multipliers, and the Lyapunov exponents of a run, under Taylor as under DOP853.
TEST(Taylor, PeriodicOrbitsAndLyapunovExponentsAgreeWithDop853s) {
  const Model model = testing::impact_oscillator(6.0);
  SimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-15;
  o.check = false;
  OrbitSpec spec;
  spec.guess = {{0.15, 0.1}};
  o.method = Method::dop853;
  const PeriodicOrbit dop853 = find_periodic_orbit(model, o, spec);
  o.method = Method::taylor;
  const PeriodicOrbit taylor = find_periodic_orbit(model, o, spec);
  ASSERT_TRUE(dop853.converged) << dop853.message;
  ASSERT_TRUE(taylor.converged) << taylor.message;
  EXPECT_NEAR(taylor.state[0].phi, dop853.state[0].phi, 1e-9);
  EXPECT_NEAR(taylor.state[0].dphi, dop853.state[0].dphi, 1e-9);
  ASSERT_EQ(taylor.multipliers.size(), dop853.multipliers.size());
  for (std::size_t k = 0; k < taylor.multipliers.size(); ++k)
    EXPECT_NEAR(std::abs(taylor.multipliers[k] - dop853.multipliers[k]), 0.0, 1e-7);

  o.t_end = 60.0;
  o.lyapunov = true;
  o.method = Method::dop853;
  const RunResult a = simulate(model, o);
  o.method = Method::taylor;
  const RunResult b = simulate(model, o);
  ASSERT_TRUE(a.lyapunov && b.lyapunov);
  ASSERT_EQ(a.lyapunov->exponents.size(), b.lyapunov->exponents.size());
  for (std::size_t k = 0; k < a.lyapunov->exponents.size(); ++k)
    EXPECT_NEAR(b.lyapunov->exponents[k], a.lyapunov->exponents[k],
                1e-6 * (1.0 + std::abs(a.lyapunov->exponents[k])));
}

}  // namespace
}  // namespace vibro
