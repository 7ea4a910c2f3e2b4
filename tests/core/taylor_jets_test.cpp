// The jets of the equations of motion (SegmentDynamics::taylor_coefficients,
// core/model/dynamics_jets.cpp), with forcing, both friction laws and damping, against what they
// must equal: the forcing's closed form, the right-hand side and its exact time derivative (the
// Jacobian), a tight DOP853 solution, the free pendulum's energy, and the truncation error's order.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/integrators/series.h"
#include "core/integrators/stepper.h"
#include "core/model/dynamics.h"
#include "core/model/model.h"
#include "core/model/motion.h"

namespace vibro {
namespace {

// Three pellets under forcing and viscous damping: pellets 0 and 1 slide together as one body
// (damped at Σ m_i c_i / M), pellet 2 is stuck.
Model forced_model(FrictionLaw law) {
  Model m;
  m.R = 0.5;
  m.alpha0 = 0.2;
  m.friction = law;
  m.pellets = {{0.1, 0.3, 1.2, {0.4, 6.0, 0.3}, 0.7},
               {0.3, 0.35, 1.2, {0.2, 3.5, -1.0}, 0.2},
               {0.2, -1.0, 0.0, {0.1, 2.0, 0.0}, 0.5}};
  return m;
}

std::vector<Body> forced_bodies() {
  return {Body{.members = {0, 1}, .mode = Mode::sliding, .s = 1},
          Body{.members = {2}, .mode = Mode::stuck, .s = 1}};
}

Vec forced_state() {
  Vec y(9);
  y << 0.3, 1.2, 0.05, 0.35, 1.2, -0.02, -1.0, 0.0, 0.4;
  return y;
}

std::vector<double> jets(const OdeSystem& sys, double t0, const Vec& y0, int order) {
  std::vector<double> c(static_cast<std::size_t>(sys.dimension()) * (order + 1));
  EXPECT_TRUE(sys.taylor_coefficients(t0, y0, order, c));
  return c;
}

Vec series_at(const std::vector<double>& c, int n, int order, double tau) {
  Vec y(n);
  for (int i = 0; i < n; ++i) {
    double p = 0.0;
    for (int k = order; k >= 0; --k) p = p * tau + c[static_cast<std::size_t>(i) * (order + 1) + k];
    y[i] = p;
  }
  return y;
}

// The recursions multiply by 1/k from a table: each entry is the double nearest 1/k, and past
// the table the reciprocal is the division itself.
TEST(TaylorJets, TheReciprocalsAreTheNearestDoubles) {
  for (int k = 1; k < integrators::kReciprocals; ++k) {
    EXPECT_EQ(integrators::kReciprocal[k], 1.0 / k) << "k = " << k;
    EXPECT_EQ(integrators::reciprocal(k), 1.0 / k) << "k = " << k;
  }
  for (int k : {integrators::kReciprocals, 100, 1000})
    EXPECT_EQ(integrators::reciprocal(k), 1.0 / k);
}

TEST(TaylorJets, TheForcingSeriesIsItsClosedForm) {
  const double F0 = 0.7, Omega = 9.0, psi = 0.4, t0 = 1.3;
  const int order = 30;
  std::vector<double> c(order + 1, 0.0);
  integrators::add_cosine_series(F0, Omega, Omega * t0 + psi, order, c);
  for (int k = 0; k <= 4; ++k) {  // the derivatives of the cosine, over k!
    const double d =
        F0 * std::pow(Omega, k) * std::cos(Omega * t0 + psi + k * std::numbers::pi / 2);
    EXPECT_NEAR(c[k] * std::tgamma(k + 1.0), d, 1e-13 * std::pow(Omega, k)) << "k = " << k;
  }
  for (double tau : {-0.1, 0.05, 0.11}) {
    double p = 0.0;
    for (int k = order; k >= 0; --k) p = p * tau + c[k];
    EXPECT_NEAR(p, F0 * std::cos(Omega * (t0 + tau) + psi), 1e-14);
  }
}

// The series from factors taken once (cosine_series_factors) and a phase per step is the one-call
// form's, bit for bit, at every order's remainder of the kπ/2 cycle.
TEST(TaylorJets, TheForcingSeriesFromItsFactorsIsTheOneCallForm) {
  const double F0 = 0.7, Omega = 9.0, phase = 1.3 * 9.0 + 0.4;
  for (int order : {0, 1, 2, 3, 4, 13, 30}) {
    std::vector<double> once(order + 1, 0.25), split(order + 1, 0.25), factors(order + 1);
    integrators::add_cosine_series(F0, Omega, phase, order, once);
    integrators::cosine_series_factors(F0, Omega, factors);
    integrators::add_cosine_series(factors, phase, split);
    for (int k = 0; k <= order; ++k)
      EXPECT_EQ(split[k], once[k]) << "order " << order << ", k = " << k;
  }
}

// Coefficient 1 is the right-hand side; coefficient 2 half its time derivative along the
// solution, (∂f/∂y·f + ∂f/∂t)/2, from the exact Jacobian.
TEST(TaylorJets, TheFirstTwoCoefficientsAreTheRightHandSideAndItsDerivative) {
  for (FrictionLaw law : {FrictionLaw::paper, FrictionLaw::bilateral}) {
    SCOPED_TRACE(law == FrictionLaw::paper ? "paper" : "bilateral");
    const Model model = forced_model(law);
    const std::vector<Body> bodies = forced_bodies();
    const Vec y = forced_state();
    const SegmentDynamics sys(model, bodies, y);
    const int order = 12, n = sys.dimension();
    const double t0 = 0.7;
    const std::vector<double> c = jets(sys, t0, y, order);
    Vec f(n), dfdt(n);
    Mat J(n, n);
    sys.rhs(t0, y, f);
    sys.jacobian(t0, y, J, dfdt);
    const Vec second = 0.5 * (J * f + dfdt);
    for (int i = 0; i < n; ++i) {
      const std::size_t at = static_cast<std::size_t>(i) * (order + 1);
      EXPECT_EQ(c[at], y[i]);
      EXPECT_NEAR(c[at + 1], f[i], 1e-14 * (1.0 + std::abs(f[i]))) << "component " << i;
      EXPECT_NEAR(c[at + 2], second[i], 1e-13 * (1.0 + std::abs(second[i]))) << "component " << i;
    }
  }
}

// Coefficient 1 is the right-hand side to the bit, for every friction law, with and without
// damping and forcing, one member or several: the event code reads a watch's start from the
// right-hand side (its rate, whether it starts flat) and its series from the jets, and a release
// on the edge of friction's capacity is decided by that agreement.
TEST(TaylorJets, TheFirstCoefficientIsTheRightHandSideBitForBit) {
  for (FrictionLaw law : {FrictionLaw::paper, FrictionLaw::bilateral}) {
    for (bool damped : {false, true}) {
      for (bool frictionless : {false, true}) {
        Model model = forced_model(law);
        if (frictionless) model.alpha0 = 0.0;
        for (Pellet& p : model.pellets) p.c = damped ? p.c : 0.0;
        for (const std::vector<Body>& bodies :
             {forced_bodies(),
              std::vector<Body>{Body{.members = {0}, .mode = Mode::sliding, .s = -1},
                                Body{.members = {1}, .mode = Mode::sliding, .s = 1},
                                Body{.members = {2}, .mode = Mode::stuck, .s = 1}}}) {
          const Vec y = forced_state();
          const SegmentDynamics sys(model, bodies, y);
          const int order = 13, n = sys.dimension();
          for (int step = 0; step < 200; ++step) {
            const double t0 = 0.0137 * step;
            const std::vector<double> c = jets(sys, t0, y, order);
            Vec f(n);
            sys.rhs(t0, y, f);
            for (int i = 0; i < n; ++i)
              EXPECT_EQ(c[static_cast<std::size_t>(i) * (order + 1) + 1], f[i])
                  << "law " << static_cast<int>(law) << ", damped " << damped << ", frictionless "
                  << frictionless << ", bodies " << bodies.size() << ", t0 " << t0 << ", component "
                  << i;
          }
        }
      }
    }
  }
}

// The series over a short span against DOP853 at rtol 1e-13 from the same state: every
// coefficient is checked, where the first two alone are above.
TEST(TaylorJets, TheSeriesFollowsATightSolutionOfTheRightHandSide) {
  for (FrictionLaw law : {FrictionLaw::paper, FrictionLaw::bilateral}) {
    SCOPED_TRACE(law == FrictionLaw::paper ? "paper" : "bilateral");
    const Model model = forced_model(law);
    const std::vector<Body> bodies = forced_bodies();
    const Vec y0 = forced_state();
    const SegmentDynamics sys(model, bodies, y0);
    const int order = 24, n = sys.dimension();
    const double t0 = 0.2, span = 0.05;
    const std::vector<double> c = jets(sys, t0, y0, order);
    auto dop853 = make_stepper(Method::dop853, StepperOptions{1e-13, 1e-15});
    dop853->start(sys, t0, y0);
    while (dop853->t() < t0 + span) ASSERT_EQ(dop853->step(t0 + span), StepStatus::ok);
    const Vec series = series_at(c, n, order, span);
    for (int i = 0; i < n; ++i)
      EXPECT_NEAR(series[i], dop853->y()[i], 1e-11 * (1.0 + std::abs(y0[i]))) << "component " << i;
  }
}

// The free pendulum (no friction, no forcing) keeps its energy ½R²φ'² − gR cos φ: along the
// polynomial of a step within its radius, to round-off.
TEST(TaylorJets, TheFreePendulumKeepsItsEnergyAlongThePolynomial) {
  Model model;
  model.R = 0.5;
  model.pellets = {{0.1, 2.0, 1.5, {}}};
  const std::vector<Body> bodies = {Body{.members = {0}, .mode = Mode::sliding, .s = 1}};
  Vec y0(3);
  y0 << 2.0, 1.5, 0.0;
  const SegmentDynamics sys(model, bodies, y0);
  const int order = 20;
  const std::vector<double> c = jets(sys, 0.0, y0, order);
  const double e0 = energy(model, 0, y0[0], y0[1]);
  for (double tau = 0.0; tau <= 0.1; tau += 0.01) {
    const Vec y = series_at(c, 3, order, tau);
    EXPECT_NEAR(energy(model, 0, y[0], y[1]), e0, 1e-14 * std::abs(e0)) << "tau = " << tau;
    EXPECT_EQ(y[2], 0.0);  // no force, no friction: no work
  }
}

// The series truncated at order p errs by O(h^(p+1)): halving the span divides the error by
// about 2^(p+1), against the series of order 30 as the reference.
TEST(TaylorJets, TheTruncationErrorHasTheSeriesOrder) {
  const Model model = forced_model(FrictionLaw::paper);
  const std::vector<Body> bodies = forced_bodies();
  const Vec y0 = forced_state();
  const SegmentDynamics sys(model, bodies, y0);
  const int n = sys.dimension();
  const std::vector<double> reference = jets(sys, 0.0, y0, 30);
  for (int p : {4, 6, 8}) {
    const std::vector<double> c = jets(sys, 0.0, y0, p);
    auto error = [&](double h) {
      return std::abs(series_at(c, n, p, h)[dphi_index(0)] -
                      series_at(reference, n, 30, h)[dphi_index(0)]);
    };
    const double ratio = error(0.1) / error(0.05);
    const double expected = std::pow(2.0, p + 1);
    EXPECT_GT(ratio, 0.6 * expected) << "p = " << p;
    EXPECT_LT(ratio, 1.6 * expected) << "p = " << p;
  }
}

// Coefficient k depends on the series up to k alone: a long series (past the orders the jets keep
// on the stack, so in their heap scratch) begins with the short one, bit for bit. Every short
// order from 2 to 22 (those whose jets are written out, 8 to 21, and those that loop), with and
// without friction and damping, for a body of two members and one alone.
TEST(TaylorJets, ALongSeriesBeginsWithTheShortOne) {
  struct Case {
    FrictionLaw law;
    double alpha0;  // 0: frictionless
    bool damped;
  };
  for (const Case& c :
       {Case{FrictionLaw::paper, 0.2, true}, Case{FrictionLaw::bilateral, 0.2, true},
        Case{FrictionLaw::paper, 0.0, true}, Case{FrictionLaw::paper, 0.0, false}}) {
    Model model = forced_model(c.law);
    model.alpha0 = c.alpha0;
    if (!c.damped)
      for (Pellet& p : model.pellets) p.c = 0.0;
    const std::vector<Body> bodies = {Body{.members = {0, 1}, .mode = Mode::sliding, .s = 1},
                                      Body{.members = {2}, .mode = Mode::sliding, .s = -1}};
    const Vec y0 = forced_state();
    const SegmentDynamics sys(model, bodies, y0);
    const int long_order = 40;
    const std::vector<double> b = jets(sys, 0.7, y0, long_order);
    for (int short_order = 2; short_order <= 22; ++short_order) {
      const std::vector<double> a = jets(sys, 0.7, y0, short_order);
      for (int i = 0; i < sys.dimension(); ++i)
        for (int k = 0; k <= short_order; ++k)
          EXPECT_EQ(a[static_cast<std::size_t>(i) * (short_order + 1) + k],
                    b[static_cast<std::size_t>(i) * (long_order + 1) + k])
              << "alpha0 " << c.alpha0 << ", damped " << c.damped << ", order " << short_order
              << ", component " << i << ", k = " << k;
    }
  }
}

}  // namespace
}  // namespace vibro
