// Two-parameter curves (core/analysis/bifurcation_curve.h) against closed forms of the small-angle
// impact oscillator x'' + c x' + ω0² x = f cos(Ωt + ψ) (ω0² = g/R, f = F0/(mR); MODEL.md), each
// to O(amplitude²) from the pendulum's own nonlinearity.
//
// Period doubling, stop at the equilibrium (x ≥ 0), restitution r, c = 0. Between impacts
// x = a cos ω0t + b sin ω0t + P cos(Ωt + θ) with P = f/(ω0² − Ω²); the period-1 motion strikes
// once per T = 2π/Ω, at phase θ with tan θ = −(1 − r) tan(ω0T/2) / ((1 + r) Ω/ω0). Its map on
// the impact surface, (θ, outgoing speed) to the next, keeps the form v dv ∧ dt of the flow and
// scales the speed by −r at the impact: det J = r². The trace gives, with 1 + tr J + det J = 0,
//   cos²(π ω0/Ω) = (1 + r)² / ((1 + r)² (Ω/ω0)² − (1 − r)²),
// in which P (so F0) cancels: the curve in (r, Ω) does not depend on the forcing amplitude.
//
// Grazing, stop at δ > 0 off the equilibrium: the motion that does not strike is the linear
// response of amplitude f / sqrt((ω0² − Ω²)² + (cΩ)²); it grazes where that equals δ:
//   F0 = m R δ sqrt((ω0² − Ω²)² + (cΩ)²),  linear in δ·|ω0² − Ω²| when c = 0.
#include "core/analysis/bifurcation_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"

namespace vibro {
namespace {

constexpr double kG = 9.81, kR = 0.5, kMass = 0.1;
const double kOmega0 = std::sqrt(kG / kR);

SimOptions tight() {
  SimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-16;
  o.check = false;
  o.t_end = 10.0;
  return o;
}

Model oscillator(double F0, double Omega, double psi, double stop, double k, double c) {
  Model m;
  m.g = kG;
  m.R = kR;
  // Started on the linear response, which the search corrects.
  const std::complex<double> z =
      F0 / (kMass * kR) / std::complex<double>(kOmega0 * kOmega0 - Omega * Omega, c * Omega) *
      std::polar(1.0, psi);
  m.pellets = {{kMass, z.real(), (std::complex<double>(0, Omega) * z).real(), {F0, Omega, psi}, c}};
  m.limiters = {{stop, k, false, -1, {}}};
  return m;
}

struct Followed {
  OrbitBranch branch;
  BifurcationCurve curve;
};

Followed follow(const Model& m, const OrbitSpec& orbit, const ContinuationSpec& c,
                const FollowSpec& f) {
  const PeriodicOrbit start = find_periodic_orbit(m, tight(), orbit);
  EXPECT_TRUE(start.converged) << start.message;
  EXPECT_FALSE(validate_continuation(m, c));
  EXPECT_FALSE(validate_follow(m, c, f));
  Followed out;
  out.branch = continue_orbit(m, tight(), start, c);
  out.curve = follow_bifurcation(m, tight(), orbit.periods, c, out.branch, f);
  return out;
}

OrbitSpec from_start(int transient) {
  OrbitSpec s;
  s.transient = transient;
  return s;
}

// The closed form's residual at (Ω, r): zero on the period-doubling curve.
double doubling_residual(double Omega, double r) {
  const double w = Omega / kOmega0, c = std::cos(M_PI / w);
  return c * c - (1 + r) * (1 + r) / ((1 + r) * (1 + r) * w * w - (1 - r) * (1 - r));
}

// The Ω of the closed-form curve at restitution r, by bisection on [lo, hi].
double doubling_Omega(double r, double lo, double hi) {
  const double sign_lo = doubling_residual(lo, r) > 0;
  for (int k = 0; k < 100; ++k) {
    const double mid = 0.5 * (lo + hi);
    ((doubling_residual(mid, r) > 0) == sign_lo ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(BifurcationCurve, ThePeriodDoublingCurveInRestitutionAndFrequencyIsTheClosedForms) {
  // A stop at the equilibrium, a small forcing (the motion strikes at some 4e-3 rad/s·ω0).
  const Model m = oscillator(0.002, 6.0, 0.0, 0.0, 0.8, 0.0);
  Model started = m;
  started.pellets[0].phi0 = 0.01;
  started.pellets[0].dphi0 = 0.0;
  const Followed f = follow(started, from_start(300), {"model.pellets[0].Omega", 5.0, 60},
                            {BifurcationKind::period_doubling, "model.limiters[0].k", 0.6, 0.95});
  ASSERT_FALSE(f.curve.points.empty()) << f.curve.message;
  EXPECT_TRUE(f.curve.reached_from) << f.curve.message;
  EXPECT_TRUE(f.curve.reached_to) << f.curve.message;
  EXPECT_EQ(f.curve.points.front().value2, 0.6);
  EXPECT_EQ(f.curve.points.back().value2, 0.95);
  EXPECT_GE(f.curve.points.size(), 5u);
  for (const CurvePoint& p : f.curve.points) {
    const double theory = doubling_Omega(p.value2, 5.2, 6.5);
    EXPECT_NEAR(p.value, theory, 1e-4 * theory) << "k = " << p.value2;
  }
}

// The grazing curve in (F0, Ω) of a stop at δ = 0.01 rad, below resonance, with damping c.
void expect_grazing_curve(double c) {
  const double delta = 0.01, Omega = 3.0;
  const Model m = oscillator(0.003, Omega, M_PI / 2, delta, 0.8, c);
  OrbitSpec orbit = from_start(0);
  orbit.guess = {{m.pellets[0].phi0, m.pellets[0].dphi0}};
  const Followed f = follow(m, orbit, {"model.pellets[0].F0", 0.008, 60},
                            {BifurcationKind::grazing, "model.pellets[0].Omega", 2.5, 3.5});
  ASSERT_FALSE(f.curve.points.empty()) << f.curve.message << " / " << f.branch.message;
  EXPECT_TRUE(f.curve.reached_from) << f.curve.message;
  EXPECT_TRUE(f.curve.reached_to) << f.curve.message;
  EXPECT_GE(f.curve.points.size(), 5u);
  for (const CurvePoint& p : f.curve.points) {
    const double w2 = kOmega0 * kOmega0 - p.value2 * p.value2;
    const double theory = kMass * kR * delta * std::hypot(w2, c * p.value2);
    EXPECT_NEAR(p.value, theory, 2e-4 * theory) << "Ω = " << p.value2;
  }
}

TEST(BifurcationCurve, TheGrazingCurveInForceAndFrequencyIsTheLinearResponses) {
  expect_grazing_curve(0.0);
}

TEST(BifurcationCurve, TheGrazingCurveOfADampedOscillatorIsItsLinearResponses) {
  expect_grazing_curve(0.5);
}

TEST(BifurcationCurve, BadFollowsNameTheirField) {
  const Model m = oscillator(0.002, 6.0, 0.0, 0.0, 0.8, 0.0);
  const ContinuationSpec c{"model.pellets[0].Omega", 5.0, 60};
  const auto field = [&](FollowSpec f) {
    const auto e = validate_follow(m, c, f);
    return e ? e->field : std::string();
  };
  const std::string p2 = "periodic_orbit.continuation.parameter2.";
  EXPECT_EQ(field({BifurcationKind::neimark_sacker, "model.limiters[0].k", 0.5, 0.9}),
            "periodic_orbit.continuation.follow");
  EXPECT_EQ(field({BifurcationKind::fold, "model.pellets[0].Omega", 5.0, 7.0}), p2 + "parameter");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[4].k", 0.5, 0.9}), p2 + "parameter");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[0].k", 0.5, 1.5}), p2 + "to");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[0].k", 0.9, 0.5}), p2 + "to");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[0].k", NAN, 0.9}), p2 + "from");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[0].k", 0.85, 0.9}), p2 + "from");
  EXPECT_EQ(field({BifurcationKind::fold, "model.limiters[0].k", 0.5, 0.9}), "");
  Model mobile = m;
  mobile.limiters[0].mobile = true;
  EXPECT_EQ(
      validate_follow(mobile, c, {BifurcationKind::fold, "model.limiters[0].k", 0.5, 0.9})->field,
      "model.limiters[0].mobile");
}

// Without the named bifurcation on the branch there is no curve, and the message says so; a
// cancel stops the walk.
TEST(BifurcationCurve, NoBifurcationOfTheKindNoCurve) {
  const Model m = oscillator(0.002, 6.0, 0.0, 0.0, 0.8, 0.0);
  OrbitBranch none;
  const BifurcationCurve curve =
      follow_bifurcation(m, tight(), 1, {"model.pellets[0].Omega", 5.0, 60}, none,
                         {BifurcationKind::fold, "model.limiters[0].k", 0.5, 0.9});
  EXPECT_TRUE(curve.points.empty());
  EXPECT_NE(curve.message.find("no fold"), std::string::npos) << curve.message;
}

}  // namespace
}  // namespace vibro
