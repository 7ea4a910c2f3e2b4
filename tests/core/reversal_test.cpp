// A sliding body's reversal is an event (its friction changes sign), but the motion goes on as
// smoothly as before: the stepper keeps its step size there instead of starting afresh.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "core/analysis/checked_run.h"
#include "core/integrators/stepper.h"
#include "core/model/dynamics.h"

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
// guess there (a thousand times too short where the speed is zero) took three or four. `auto` is
// taken at rtol 1e-6, where it runs an explicit Runge–Kutta method: at 5e-7 and tighter it runs
// Taylor, which the plain pendulum here (without jets) cannot.
TEST(Reversal, ASwingsReversalsCostOneStepEach) {
  Model model;
  model.pellets.push_back(Pellet{.m = 0.1, .phi0 = 1.0, .dphi0 = 0.0, .force = {}});
  for (Method method : {Method::dopri5, Method::dop853, Method::automatic}) {
    SCOPED_TRACE(method_name(method));
    SimOptions o;
    o.method = method;
    o.rtol = method == Method::automatic ? 1e-6 : 1e-9;
    o.atol = method == Method::automatic ? 1e-9 : 1e-12;
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

// Two pellets at the bottom collide and swing apart; small swings take the same time whatever
// their amplitude, so both turn back together. Every method at every tolerance lists both
// reversals at one instant, with atol a thousandth of rtol as a user would set it.
void expect_both_turn_back_together(const Model& model, double t_end) {
  for (Method method : {Method::dopri5, Method::dop853, Method::radau5, Method::automatic}) {
    for (double rtol : {1e-6, 1e-8, 1e-10, 1e-12}) {
      SCOPED_TRACE(std::string(method_name(method)) + " at rtol " + std::to_string(rtol));
      SimOptions o;
      o.method = method;
      o.rtol = rtol;
      o.atol = 1e-3 * rtol;
      o.t_end = t_end;
      o.check = false;
      const RunResult run = simulate(model, o);
      ASSERT_EQ(run.stats.termination, Termination::completed);
      ASSERT_EQ(run.events.size(), 3u);
      EXPECT_EQ(run.events[0].kind, EventKind::collision);
      for (int i : {0, 1}) {
        const Event& e = run.events[1 + i];
        EXPECT_EQ(e.kind, EventKind::reversal);
        EXPECT_EQ(e.pellets, std::vector<int>{i});
        EXPECT_EQ(e.t, run.events[1].t);
        EXPECT_EQ(e.dphi_after, std::vector<double>{0.0});
      }
    }
  }
}

// On a small circle they turn back 6e-11 s apart. The first reversal found the other pellet at
// 1.6e-13 rad/s, within the speeds taken as zero: it turned back there too, but only the
// reversal whose root came first was listed, which the step sequence decided (trust scan, seed
// 13, scene 680: every method and tolerance listed either).
TEST(Reversal, PelletsTurningBackAtOneInstantAreAllListed) {
  Model model;
  model.R = 0.0016574064175314982;
  model.k_c = 0.8842964172363281;
  const double bottom = -2.0 * std::acos(-1.0);
  model.pellets.resize(2);
  model.pellets[0].m = 0.528761621646652;
  model.pellets[0].phi0 = bottom;
  model.pellets[1].m = 0.1617524474373409;
  model.pellets[1].phi0 = bottom + 1e-6;
  expect_both_turn_back_together(model, 0.05);
}

// Where the other pellet's root comes just before the instant, it has turned already (a speed
// within v_eps, of its new sign) and goes on its new way: that too is a reversal. Radau IIA at
// rtol 1e-8 put pellet 2's reversal 6e-8 s late, past pellet 1's root, and listed pellet 1's
// turn nowhere (trust scan, seed 30, scene 433).
TEST(Reversal, APelletThatTurnedJustBeforeTheInstantIsListed) {
  Model model;
  model.R = 0.46296720899680927;
  model.alpha0 = 0.0;  // no friction
  model.k_c = 0.34143924713134766;
  const double bottom = 2.0 * std::acos(-1.0);
  model.pellets.resize(2);
  model.pellets[0].m = 0.28446703378046595;
  model.pellets[0].phi0 = bottom;
  model.pellets[1].m = 5.968452475733748;
  model.pellets[1].phi0 = bottom + 1e-6;
  expect_both_turn_back_together(model, 0.8);
}

}  // namespace
}  // namespace vibro
