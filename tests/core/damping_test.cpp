// Viscous damping (MODEL.md, third round) against the closed forms of the damped linear
// oscillator x'' + c x' + ω0² x = f cos Ωt (ω0² = g/R, f = F0/(mR)), which a pellet on a
// frictionless circle (alpha0 = 0) with no limiter follows at small angles up to O(amplitude²):
// free decay by exp(−c T_d/2) a period at ω_d = sqrt(ω0² − c²/4); forced steady amplitude
// f/sqrt((ω0² − Ω²)² + (cΩ)²); Floquet multipliers exp(−cT/2)·e^{±iω_d T}. Also: the energy
// balance closing with the damper's work, the Jacobians against central differences, and the
// field checked and echoed.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "core/analysis/checked_run.h"
#include "core/analysis/periodic_orbit.h"
#include "core/events/watch.h"
#include "core/model/dynamics.h"
#include "core/model/parameter.h"
#include "core/run/validate.h"
#include "tests/core/impact_oscillator.h"

namespace vibro {
namespace {

constexpr double kG = 9.81, kR = 0.5, kMass = 0.1;

SimOptions tight(double t_end) {
  SimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-16;
  o.check = false;
  o.t_end = t_end;
  return o;
}

// A damped pellet on a frictionless circle with no limiter, from phi0 at rest.
Model damped_pendulum(double c, double phi0, double F0 = 0.0, double Omega = 0.0) {
  Model m;
  m.g = kG;
  m.R = kR;
  m.pellets = {{kMass, phi0, 0.0, {F0, Omega, 0.0}}};
  m.pellets[0].c = c;
  return m;
}

double omega0() { return std::sqrt(kG / kR); }

// The turning points of pellet 0: reversals, at the extremes of the swing.
std::vector<Event> reversals(const RunResult& r) {
  std::vector<Event> out;
  for (const Event& e : r.events)
    if (e.kind == EventKind::reversal) out.push_back(e);
  return out;
}

// Free decay: the turning points come every half damped period, each swing exp(−c T_d/4) of
// the one before (1e-4 rad: the pendulum's own frequency shift, ω0·A²/16, is 6e-10 of it).
TEST(Damping, FreeDecayKeepsTheDampedPeriodAndRatio) {
  const double c = 0.8, A = 1e-4;
  const RunResult r = simulate(damped_pendulum(c, A), tight(6.0));
  ASSERT_EQ(r.stats.termination, Termination::completed) << r.stats.message;
  const std::vector<Event> turns = reversals(r);
  ASSERT_GE(turns.size(), 8u);
  const double wd = std::sqrt(omega0() * omega0() - c * c / 4.0);
  const double Td = 2.0 * M_PI / wd;
  // x(t) = A e^{−ct/2}(cos ω_d t + c/(2ω_d) sin ω_d t): x' = 0 at t = kπ/ω_d.
  for (std::size_t k = 0; k < turns.size(); ++k) {
    const double t = (k + 1) * Td / 2.0;
    EXPECT_NEAR(turns[k].t, t, 1e-9 * Td) << "turn " << k;
    const double amplitude = A * std::exp(-c * t / 2.0);
    EXPECT_NEAR(std::abs(turns[k].phi), amplitude, 1e-8 * A) << "turn " << k;
  }
  const double ratio = turns[2].phi / turns[0].phi;  // one damped period apart
  EXPECT_NEAR(ratio, std::exp(-c * Td / 2.0), 1e-8);
}

// The steady state of the forced damped oscillator, and the Floquet multipliers of that
// periodic motion: those of the linear flow over a forcing period T, exp((−c/2 ± iω_d)T).
TEST(Damping, ForcedSteadyStateAmplitudeAndFloquetMultipliers) {
  const double c = 0.6, Omega = 3.7, f = 1e-4 * omega0() * omega0();  // about 1e-4 rad
  Model m = damped_pendulum(c, 0.0, f * kMass * kR, Omega);
  const double w0 = omega0();
  const double amplitude = f / std::hypot(w0 * w0 - Omega * Omega, c * Omega);
  // A plain run settles onto it: after 70 s the transient is exp(−21) of it.
  const RunResult r = simulate(m, tight(70.0));
  ASSERT_EQ(r.stats.termination, Termination::completed) << r.stats.message;
  const FinalState& end = r.summary.final[0];
  EXPECT_NEAR(std::hypot(end.phi, end.dphi / Omega), amplitude, 1e-7 * amplitude);

  OrbitSpec spec;
  spec.transient = 0;
  spec.guess = {{0.0, 0.0}};
  SimOptions o = tight(10.0);
  const PeriodicOrbit orbit = find_periodic_orbit(m, o, spec);
  ASSERT_TRUE(orbit.converged) << orbit.message;
  EXPECT_TRUE(orbit.stable);
  EXPECT_NEAR(std::hypot(orbit.state[0].phi, orbit.state[0].dphi / Omega), amplitude,
              1e-7 * amplitude);
  const double T = 2.0 * M_PI / Omega;
  const double wd = std::sqrt(w0 * w0 - c * c / 4.0);
  ASSERT_EQ(orbit.multipliers.size(), 2u);
  const std::complex<double> expected = std::exp(std::complex<double>(-c * T / 2.0, wd * T));
  for (const std::complex<double>& mu : orbit.multipliers) {
    const double off = std::min(std::abs(mu - expected), std::abs(mu - std::conj(expected)));
    EXPECT_LT(off, 1e-7) << mu << " against " << expected;
  }
  EXPECT_NEAR(std::abs(orbit.multipliers[0] * orbit.multipliers[1]), std::exp(-c * T), 1e-8);
}

// Unforced and frictionless, the work component holds the damper's work alone: at every
// instant the energy lost equals ∫ m R² c dphi² dt, and the balance closes to round-off.
TEST(Damping, EnergyBalanceClosesWithTheDampersWork) {
  const Model m = damped_pendulum(0.5, 1.2);
  SimOptions o = tight(8.0);
  o.keep_path = true;
  const RunResult r = simulate(m, o);
  ASSERT_EQ(r.stats.termination, Termination::completed) << r.stats.message;
  ASSERT_GE(r.path.size(), 4u);
  const double E0 = energy(m, 0, m.pellets[0].phi0, 0.0);
  for (const PathSegment& s : r.path) {
    const double lost = E0 - energy(m, 0, s.y[phi_index(0)], s.y[dphi_index(0)]);
    const double damper = -s.y[work_index(0)];
    if (s.t > 0.0) {
      EXPECT_GT(lost, 1e-3 * std::abs(E0));
    }
    EXPECT_NEAR(damper, lost, 1e-10 * std::abs(E0)) << "at t = " << s.t;
  }
  EXPECT_LT(r.stats.energy_defect, 1e-10);
}

// Forced, with friction and a limiter, the balance closes with the damper's term among the rest.
TEST(Damping, EnergyBalanceClosesOnAForcedImpactingRunWithFriction) {
  Model m = testing::impact_oscillator(5.0);
  m.alpha0 = 0.05;
  m.pellets[0].c = 0.7;
  const RunResult r = simulate(m, tight(10.0));
  ASSERT_EQ(r.stats.termination, Termination::completed) << r.stats.message;
  EXPECT_LT(r.stats.energy_defect, 1e-9);
}

// The right-hand side's Jacobian (RADAU5's) and the motion's (the variational equations') with
// damping, against central differences of the right-hand side, for a lone pellet and for a
// body of two pellets damped differently (its damping the mass-weighted mean).
void expect_jacobians_match(const Model& m, const std::vector<Body>& bodies, const Vec& y) {
  const SegmentDynamics d(m, bodies, y);
  const int n = d.dimension();
  Mat J(n, n), motion(2 * m.size(), 2 * m.size());
  Vec dfdt(n), f(n), fp(n), fm(n);
  d.jacobian(0.3, y, J, dfdt);
  d.rhs_and_motion_jacobian(0.3, y, f, motion);
  for (int k = 0; k < n; ++k) {
    Vec yp = y, ym = y;
    const double h = 1e-6;
    yp[k] += h;
    ym[k] -= h;
    d.rhs(0.3, yp, fp);
    d.rhs(0.3, ym, fm);
    const Vec col = (fp - fm) / (2.0 * h);
    for (int r = 0; r < n; ++r) EXPECT_NEAR(J(r, k), col[r], 1e-6) << "row " << r << " col " << k;
    if (k % 3 == 2) continue;  // the work does not act on the motion
    for (int i = 0; i < m.size(); ++i) {
      const int mk = 2 * (k / 3) + k % 3;
      EXPECT_NEAR(motion(2 * i + 1, mk), col[dphi_index(i)], 1e-6) << i << ", " << k;
    }
  }
}

TEST(Damping, JacobiansMatchCentralDifferences) {
  Model m = testing::impact_oscillator(5.0);
  m.alpha0 = 0.1;
  m.pellets[0].c = 1.3;
  Body lone;
  lone.members = {0};
  lone.s = 1;
  Vec y(3);
  y << 0.4, 1.1, 0.0;
  expect_jacobians_match(m, {lone}, y);

  m.pellets.push_back({0.3, 0.41, 1.1, {0.2, 2.0, 0.1}});
  m.pellets[1].c = 0.2;
  Body pair;
  pair.members = {0, 1};
  pair.s = 1;
  Vec y2(6);
  y2 << 0.4, 1.1, 0.0, 0.4, 1.1, 0.0;
  expect_jacobians_match(m, {pair}, y2);
  Vec dydt(6);
  SegmentDynamics(m, {pair}, y2).rhs(0.3, y2, dydt);
  Vec dydt_undamped(6);
  Model undamped = m;
  undamped.pellets[0].c = undamped.pellets[1].c = 0.0;
  SegmentDynamics(undamped, {pair}, y2).rhs(0.3, y2, dydt_undamped);
  const double mean = (0.1 * 1.3 + 0.3 * 0.2) / 0.4;
  EXPECT_NEAR(dydt[dphi_index(0)], dydt_undamped[dphi_index(0)] - mean * 1.1, 1e-12);
  EXPECT_EQ(body_damping(m, pair), mean);
}

// body_load, which the rates of speeds take at every sample, is the three functions to the bit.
TEST(Damping, BodyLoadIsForceMassAndDampingToTheBit) {
  Model m = testing::impact_oscillator(5.0);
  m.pellets[0].c = 1.3;
  m.pellets.push_back({0.3, 0.41, 1.1, {0.2, 2.0, 0.1}});
  m.pellets[1].c = 0.2;
  Body lone, pair;
  lone.members = {1};
  pair.members = {0, 1};
  for (const Body& b : {lone, pair})
    for (double t : {0.0, 0.37, 2.9}) {
      const BodyLoad load = body_load(m, b, t);
      EXPECT_EQ(load.F, body_force(m, b, t));
      EXPECT_EQ(load.M, body_mass(m, b));
      EXPECT_EQ(load.C, body_damping(m, b));
    }
}

// The map's Jacobian of a damped impacting, sticking run, exact and by central differences of
// plain runs.
TEST(Damping, MapJacobianMatchesDifferences) {
  Model m;
  m.alpha0 = 0.3;
  m.pellets = {{0.1, 0.2, 0.0, {0.25, 3.0, 0.0}}};
  m.pellets[0].c = 0.9;
  m.limiters = {{1.0, 0.7, false, -1, {}}, {-1.0, 0.7, false, -1, {}}};
  SimOptions o = tight(0.0);
  o.atol = 1e-15;
  Vec x(2);
  x << 0.2, 0.0;
  const double T = 2 * forcing_period(m);
  const MapPoint p = stroboscopic_map(m, o, 2, x);
  ASSERT_TRUE(p.ok) << p.run.stats.message;
  ASSERT_TRUE(p.exact) << p.jacobian_note;
  Mat fd(2, 2);
  for (int k = 0; k < 2; ++k) {
    Vec xp = x, xm = x;
    xp[k] += 1e-5;
    xm[k] -= 1e-5;
    Vec ends[2];
    for (int side = 0; side < 2; ++side) {
      Model s = m;
      s.pellets[0].phi0 = (side ? xm : xp)[0];
      s.pellets[0].dphi0 = (side ? xm : xp)[1];
      const RunResult r = simulate(s, tight(T));
      ends[side] = Vec(2);
      ends[side] << r.summary.final[0].phi, r.summary.final[0].dphi;
    }
    fd.col(k) = (ends[0] - ends[1]) / 2e-5;
  }
  EXPECT_LT((p.jacobian - fd).cwiseAbs().maxCoeff(), 1e-5 * std::max(1.0, fd.cwiseAbs().maxCoeff()))
      << p.jacobian << "\n"
      << fd;
}

// Two pellets sliding as one part where the one behind, force less damper per unit mass, no
// longer pushes the one ahead: the separation watch carries −R·dphi·(c_behind − c_ahead), and
// follows the speed (no watch of time alone) only where the parts are damped differently.
TEST(Damping, PelletsDampedDifferentlyPartOnForceLessDamper) {
  Model m;
  m.R = kR;
  m.pellets = {{0.1, 0.3, 0.0, {0.2, 0.0, 0.0}}, {0.3, 0.3 + 1e-6, 0.0, {0.3, 0.0, 0.0}}};
  m.pellets[0].c = 2.0;
  m.pellets[1].c = 0.5;
  Body pair;
  pair.members = {0, 1};
  pair.s = 1;
  Watch w{WatchKind::separation, 0, 0};
  w.split = 1;
  Vec y(6);
  y << 0.3, 0.7, 0.0, 0.3, 0.7, 0.0;
  const double forces = 0.2 / 0.1 - 0.3 / 0.3;
  EXPECT_NEAR(raw_value(w, m, {pair}, 0.0, y), forces - kR * 0.7 * (2.0 - 0.5), 1e-15);
  EXPECT_FALSE(depends_on_time_alone(w, m, {pair}));
  m.pellets[1].c = 2.0;
  EXPECT_NEAR(raw_value(w, m, {pair}, 0.0, y), forces, 1e-15);
  EXPECT_TRUE(depends_on_time_alone(w, m, {pair}));
}

TEST(Damping, NegativeOrNonFiniteDampingIsRefusedByName) {
  Model m = damped_pendulum(-0.1, 0.1);
  m.pellets.push_back({0.1, 1.0, 0.0, {}});
  std::optional<FieldError> e = validate_model(m);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "model.pellets[0].c");
  m.pellets[0].c = 0.0;
  m.pellets[1].c = NAN;
  e = validate_model(m);
  ASSERT_TRUE(e);
  EXPECT_EQ(e->field, "model.pellets[1].c");
  EXPECT_FALSE(set_parameter(m, "model.pellets[1].c", 2.5));
  EXPECT_EQ(m.pellets[1].c, 2.5);
  EXPECT_FALSE(validate_model(m));
}

}  // namespace
}  // namespace vibro
