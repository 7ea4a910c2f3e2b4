// Continuation near grazing (issue 34 item 3, MODEL.md "A fixed point never crosses a limiter"):
// the three reproducers of the issue, on the small-angle forced pendulum with a stop just past
// its swing. Frictionless and non-impacting, the motion is the linear oscillator's
// φ = A cos(Ωt + ψ) (up to sign) with A = f/|ω0² − Ω²| (ω0² = g/R, f = F0/(mR)); it grazes the
// stop at δ where A = δ: Ω_g² = ω0² ± f/δ (O(δ²) relative from the pendulum's own nonlinearity).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "core/analysis/orbit_continuation.h"
#include "core/analysis/periodic_orbit.h"

namespace vibro {
namespace {

constexpr double kG = 9.81, kR = 0.5, kMass = 0.1;

SimOptions tight() {
  SimOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-16;
  o.check = false;
  o.t_end = 10.0;
  return o;
}

struct Reproducer {
  Model model;
  PhasePoint guess;
  double to;
  double delta() const { return model.limiters[0].angle; }
  double f() const { return model.pellets[0].force.F0 / (kMass * kR); }
};

Model stop_scene(double F0, double Omega, double psi, double phi0, double dphi0, double delta,
                 double k) {
  Model m;
  m.g = kG;
  m.R = kR;
  m.pellets = {{kMass, phi0, dphi0, {F0, Omega, psi}}};
  m.limiters = {{delta, k, false, -1, {}}};
  return m;
}

OrbitBranch follow(const Reproducer& r) {
  OrbitSpec spec;
  spec.transient = 0;
  spec.guess = {r.guess};
  const PeriodicOrbit start = find_periodic_orbit(r.model, tight(), spec);
  EXPECT_TRUE(start.converged) << start.message;
  ContinuationSpec c;
  c.parameter = "model.pellets[0].Omega";
  c.to = r.to;
  c.max_points = 300;
  return continue_orbit(r.model, tight(), start, c);
}

std::vector<double> grazings(const OrbitBranch& b) {
  std::vector<double> out;
  for (const Bifurcation& x : b.bifurcations)
    if (x.kind == BifurcationKind::grazing) out.push_back(x.value);
  return out;
}

// Reproducer 1: above resonance, section at phase π/2. The non-impacting branch is frictionless:
// its map keeps areas and its multipliers stay on the unit circle. No Neimark–Sacker there, and
// `stable` does not flip with round-off; the grazing is where A = δ.
TEST(OrbitGrazing, AnAreaPreservingBranchStaysNeutralUpToItsGrazing) {
  const double Omega = 15.06011952143807;
  const Reproducer r{
      stop_scene(0.01035936, Omega, M_PI / 2, 0.0, 0.01506011952143807, 0.001056, 0.7),
      {0.0, 0.01506011952143807},
      13.288340754210061};
  const OrbitBranch b = follow(r);
  for (const Bifurcation& x : b.bifurcations)
    EXPECT_NE(x.kind, BifurcationKind::neimark_sacker) << "at Ω = " << x.value;
  int neutral = 0;
  for (const BranchPoint& p : b.points) {
    if (p.impacts_per_period != 0.0) continue;
    ++neutral;
    EXPECT_FALSE(p.stable) << "at Ω = " << p.value;
    for (const auto& mu : p.multipliers) EXPECT_NEAR(std::abs(mu), 1.0, 1e-10);
  }
  EXPECT_GE(neutral, 5);
  const double grazing = std::sqrt(kG / kR + r.f() / r.delta());
  const std::vector<double> g = grazings(b);
  ASSERT_FALSE(g.empty()) << b.message;
  EXPECT_NEAR(g.front(), grazing, 1e-5);
}

// Reproducer 2: the same scene with the section at phase π, where the swing's far end lies on
// the section. Past the grazing the branch must not go on with a motion on the far side of the
// stop (the pellet starts below it and never gets past it), and the grazing is where A = δ.
TEST(OrbitGrazing, NoBranchPointLiesOnTheFarSideOfTheStop) {
  const Reproducer r{stop_scene(0.01035936, 15.06011952143807, M_PI, 0.001, 0.0, 0.001056, 0.7),
                     {0.001, 0.0},
                     13.288340754210061};
  const OrbitBranch b = follow(r);
  ASSERT_FALSE(b.points.empty());
  for (const BranchPoint& p : b.points)
    EXPECT_LE(p.state[0].phi, r.delta() * (1.0 + 1e-9)) << "at Ω = " << p.value;
  const double grazing = std::sqrt(kG / kR + r.f() / r.delta());
  const std::vector<double> g = grazings(b);
  ASSERT_FALSE(g.empty()) << b.message;
  EXPECT_NEAR(g.front(), grazing, 1e-5);
}

// Reproducer 3: below resonance, section at phase 0 (the swing's far end again on the section).
// The branch must not jump to a pellet "resting" on the stop from its far side (the force never
// presses it there: gravity pulls it back harder), and must report the grazing, where A = δ.
TEST(OrbitGrazing, NoRestOnTheStopFromItsFarSideAndTheGrazingIsReported) {
  const Reproducer r{stop_scene(0.0005139459, 3.0563183734683137, 0.0, 0.001, 0.0, 0.0010478, 0.8),
                     {0.001, 0.0},
                     3.3220851885525153};
  const OrbitBranch b = follow(r);
  ASSERT_FALSE(b.points.empty());
  for (const BranchPoint& p : b.points) {
    const bool rests_on_stop = std::abs(p.state[0].phi - r.delta()) < 1e-9 &&
                               p.state[0].dphi == 0.0 && std::abs(p.multipliers[0]) < 1e-6;
    EXPECT_FALSE(rests_on_stop) << "at Ω = " << p.value;
  }
  const double grazing = std::sqrt(kG / kR - r.f() / r.delta());
  const std::vector<double> g = grazings(b);
  ASSERT_FALSE(g.empty()) << b.message;
  EXPECT_NEAR(g.front(), grazing, 1e-5);
}

// From the impacting side the branch used to creep toward the grazing (a multiplier running to
// −∞, steps shrinking: the square root of Nordmark's map) and stop short of it. Now it crosses:
// the grazing is reported where A = δ, and the branch goes on with non-impacting motions to `to`.
// The scenes of reproducers 1 and 3 from their impacting ends, each started on the impacting
// motion a 400-period run settles on.
TEST(OrbitGrazing, TheBranchCrossesTheGrazingFromTheImpactingSide) {
  struct Case {
    Model model;
    double to, sign;
  };
  const Case cases[] = {
      {stop_scene(0.01035936, 13.288340754210061, M_PI / 2, 0.000528, 0.0, 0.001056, 0.7),
       15.06011952143807, 1.0},
      {stop_scene(0.0005139459, 3.3220851885525153, 0.0, 0.0005239, 0.0, 0.0010478, 0.8),
       3.0563183734683137, -1.0}};
  for (const Case& c : cases) {
    const Reproducer r{c.model, {}, c.to};
    const double grazing = std::sqrt(kG / kR + c.sign * r.f() / r.delta());
    OrbitSpec spec;
    spec.transient = 400;
    const PeriodicOrbit start = find_periodic_orbit(c.model, tight(), spec);
    ASSERT_TRUE(start.converged) << start.message;
    ASSERT_EQ(start.impacts_per_period, 1.0);
    ContinuationSpec cs;
    cs.parameter = "model.pellets[0].Omega";
    cs.to = c.to;
    cs.max_points = 300;
    const OrbitBranch b = continue_orbit(c.model, tight(), start, cs);
    const std::vector<double> g = grazings(b);
    ASSERT_FALSE(g.empty()) << b.message;
    EXPECT_NEAR(g.front(), grazing, 1e-5);
    EXPECT_TRUE(b.reached) << b.message;
    ASSERT_FALSE(b.points.empty());
    EXPECT_EQ(b.points.front().impacts_per_period, 1.0);
    EXPECT_EQ(b.points.back().impacts_per_period, 0.0);
  }
}

}  // namespace
}  // namespace vibro
