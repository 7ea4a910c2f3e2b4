// Lyapunov exponents (core/analysis/lyapunov.h): on a stable periodic motion they are
// log|multiplier| per period; in a chaotic window the largest is positive and matches the
// divergence of two nearby runs; frictionless, their sum is fixed by the impacts alone (each scales
// areas by k²); a sweep reports the largest per value.
#include "core/analysis/lyapunov.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/analysis/checked_run.h"
#include "core/analysis/periodic_orbit.h"
#include "core/analysis/sweep.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

using testing::impact_oscillator;

SimOptions tight(double t_end) {
  SimOptions o;
  o.rtol = 1e-11;
  o.atol = 1e-14;
  o.check = false;
  o.t_end = t_end;
  return o;
}

// The spectrum over `periods` after a transient of 100.
LyapunovSpectrum spectrum(const Model& m, int periods) {
  const double T = forcing_period(m);
  SimOptions o = tight((100 + periods) * T);
  o.lyapunov = true;
  o.keep_events_from = 100 * T;
  const RunResult r = simulate(m, o);
  EXPECT_EQ(r.stats.termination, Termination::completed);
  EXPECT_TRUE(r.path.empty());  // not asked for: used and dropped
  EXPECT_TRUE(r.lyapunov);
  LyapunovSpectrum L = r.lyapunov.value_or(LyapunovSpectrum{});
  EXPECT_TRUE(L.unsupported.empty()) << L.unsupported;
  EXPECT_EQ(L.exponents.size(), 2u);
  return L;
}

TEST(Lyapunov, OfAStablePeriodicMotionIsTheLogOfItsMultipliersPerPeriod) {
  const Model m = impact_oscillator(6.0);
  OrbitSpec spec;
  spec.guess = {{0.15, 0.1}};
  const PeriodicOrbit orbit = find_periodic_orbit(m, tight(1.0), spec);
  ASSERT_TRUE(orbit.converged) << orbit.message;
  const double expected = std::log(std::abs(orbit.multipliers.front())) / orbit.period;
  const LyapunovSpectrum L = spectrum(m, 800);
  // A complex pair: both exponents tend to it, oscillating about it as 1/time.
  for (double lambda : L.exponents) EXPECT_NEAR(lambda, expected, 0.01 * std::abs(expected));
  EXPECT_LT(L.exponents.front(), 0.0);
}

// The spectrum's span starts at the instant that opens the interval reaching past the transient,
// which may be an impact before it: the impacts are counted from there, in the same run with
// every event kept.
TEST(Lyapunov, FrictionlessTheirSumIsTheImpactsLossOfArea) {
  const Model m = impact_oscillator(3.25);
  const LyapunovSpectrum L = spectrum(m, 200);
  SimOptions o = tight(300 * forcing_period(m));
  const RunResult run = simulate(m, o);
  const double from = o.t_end - L.span;
  int impacts = 0;
  for (const Event& e : run.events) impacts += e.kind == EventKind::limiter && e.t >= from;
  EXPECT_NEAR(L.exponents[0] + L.exponents[1], impacts * std::log(0.8 * 0.8) / L.span, 1e-9);
}

// At Ω = 3.25 rad/s the impact oscillator is chaotic (no period-1 or period-2 motion attracts).
TEST(Lyapunov, PositiveInAChaoticWindowAsNearbyRunsDiverge) {
  const Model m = impact_oscillator(3.25);
  const LyapunovSpectrum L = spectrum(m, 400);
  EXPECT_GT(L.exponents[0], 0.1);
  // Independently: two runs 1e-10 rad apart, from a state on the attractor, part at that rate
  // until their distance nears the attractor's size.
  const double T = forcing_period(m);
  const RunResult settled = simulate(m, tight(100 * T));
  Model a = m;
  a.pellets[0].phi0 = settled.summary.final[0].phi;
  a.pellets[0].dphi0 = settled.summary.final[0].dphi;
  Model b = a;
  b.pellets[0].phi0 += 1e-10;
  const double t = 60.0;
  const RunResult ra = simulate(a, tight(t)), rb = simulate(b, tight(t));
  const double apart =
      std::hypot(ra.summary.final[0].phi - rb.summary.final[0].phi,
                 (ra.summary.final[0].dphi - rb.summary.final[0].dphi) * std::sqrt(m.R / m.g));
  EXPECT_NEAR(std::log(apart / 1e-10) / t, L.exponents[0], 0.3 * L.exponents[0]);
}

TEST(Lyapunov, ASweepReportsTheLargestPerValue) {
  SweepSpec spec;
  spec.axis = {"model.pellets[0].Omega", 3.25, 6.0, 2};
  spec.transient = 100;
  spec.record = 200;
  spec.lyapunov = true;
  ASSERT_FALSE(validate_sweep(impact_oscillator(3.25), spec));
  const SweepResult r = run_sweep(impact_oscillator(3.25), tight(1.0), spec, {});
  ASSERT_EQ(r.runs.size(), 2u);
  ASSERT_TRUE(r.runs[0].lyapunov && r.runs[1].lyapunov);
  EXPECT_GT(*r.runs[0].lyapunov, 0.1);
  EXPECT_NEAR(*r.runs[1].lyapunov, std::log(0.8) / forcing_period(impact_oscillator(6.0)), 0.01);
  spec.lyapunov = false;
  EXPECT_FALSE(run_sweep(impact_oscillator(3.25), tight(1.0), spec, {}).runs[0].lyapunov);
}

}  // namespace
}  // namespace vibro
