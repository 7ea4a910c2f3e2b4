// A sliding body's reversal is an event (its friction changes sign), but the motion goes on as
// smoothly as before: the stepper keeps its step size there instead of starting afresh.
#include <gtest/gtest.h>

#include <cmath>

#include "core/dynamics.h"
#include "core/simulate.h"
#include "core/stepper.h"

namespace vibro {
namespace {

// The frictionless pendulum φ'' = −(g/R) sin φ, integrated without events.
class Pendulum final : public OdeSystem {
 public:
  explicit Pendulum(double w2) : w2_(w2) {}
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -w2_ * std::sin(y[0]);
  }
  void jacobian(double, const Vec& y, Mat& dfdy, Vec& dfdt) const override {
    dfdy << 0.0, 1.0, -w2_ * std::cos(y[0]), 0.0;
    dfdt.setZero();
  }

 private:
  double w2_;
};

// Each reversal cuts one step short and costs one step more, no more: restarting with HINIT's
// guess there (a thousand times too short where the speed is zero) took three or four.
TEST(Reversal, ASwingsReversalsCostOneStepEach) {
  Model model;
  model.pellets.push_back(Pellet{.m = 0.1, .phi0 = 1.0, .dphi0 = 0.0});
  for (Method method : {Method::dopri5, Method::dop853, Method::automatic}) {
    SCOPED_TRACE(method_name(method));
    SimOptions o;
    o.method = method;
    o.rtol = 1e-9;
    o.atol = 1e-12;
    o.t_end = 20.0;
    o.check = false;
    const RunResult run = simulate(model, o);
    ASSERT_EQ(run.stats.termination, Termination::completed);
    ASSERT_GE(run.events.size(), 20u);
    for (const Event& e : run.events) ASSERT_EQ(e.kind, EventKind::reversal);

    const Pendulum pendulum(model.g / model.R);
    auto plain = make_stepper(method, StepperOptions{o.rtol, o.atol, longest_step(model)});
    Vec y(2);
    y << 1.0, 0.0;
    plain->start(pendulum, 0.0, y);
    while (plain->t() < o.t_end) ASSERT_EQ(plain->step(o.t_end), StepStatus::ok);
    EXPECT_LE(run.stats.steps, plain->stats().steps + static_cast<long>(run.events.size()));
  }
}

}  // namespace
}  // namespace vibro
