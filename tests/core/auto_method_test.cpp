// `auto` picks the cheaper method by cost: RADAU5 wherever it is cheaper (the stiff-friction
// preset, at every tolerance, also where DOP853's step is held by accuracy rather than by
// stability), and no trial of it on the non-stiff presets; at loose tolerances DOPRI5 or DOP853,
// whichever is the cheaper on the preset, and at tight ones Taylor. Work is counted in
// right-hand sides and steps, which is deterministic, rather than timed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "core/analysis/checked_run.h"
#include "core/integrators/auto_switch.h"
#include "core/integrators/stepper.h"
#include "scenes.h"

namespace vibro {
namespace {

RunResult run_preset(const std::string& name, Method method, double rtol) {
  const Scene scene = testing::preset(name);
  SimOptions o = scene.sim;
  o.method = method;
  o.rtol = rtol;
  o.atol = rtol / 100;
  o.check = false;
  const RunResult run = simulate(scene.model, o);
  EXPECT_EQ(run.stats.termination, Termination::completed) << name << ": " << run.stats.message;
  return run;
}

TEST(AutoMethod, IsAsCheapAsRadau5WhereTheProblemIsStiff) {
  for (double rtol : {1e-6, 1e-9, 1e-12}) {
    SCOPED_TRACE(rtol);
    const RunResult radau = run_preset("stiff-friction", Method::radau5, rtol);
    const RunResult dop853 = run_preset("stiff-friction", Method::dop853, rtol);
    const RunResult automatic = run_preset("stiff-friction", Method::automatic, rtol);
    // At rtol 1e-12 DOP853's h·ρ stays at a fifth of its stability boundary, yet it needs 18
    // times RADAU5's right-hand sides: only a cost comparison sees it.
    EXPECT_GT(dop853.stats.rhs_evals, 8 * radau.stats.rhs_evals);
    EXPECT_GE(automatic.stats.stiff_switches, 1);
    EXPECT_LT(automatic.stats.rhs_evals, 1.2 * static_cast<double>(radau.stats.rhs_evals));
  }
}

// Work as `auto` weighs its explicit methods: right-hand sides and a step's own cost.
double explicit_work(const RunResult& run) {
  return static_cast<double>(run.stats.rhs_evals) +
         integrators::AutoSwitch::kStepCost *
             static_cast<double>(run.stats.steps + run.stats.rejected);
}

// No trial of RADAU5 on the non-stiff presets. From kAutoTaylorRtol down `auto` is Taylor step
// for step (no probe for stiffness); above, it weighs DOPRI5 against DOP853 and is about as cheap
// as the cheaper of the two.
TEST(AutoMethod, StaysExplicitOnTheNonStiffPresets) {
  for (const char* name : {"paper", "chatter", "frictionless-elastic", "grazing", "high-frequency",
                           "impact-oscillator", "loop", "mass-ratio", "plastic-limiter",
                           "rest-in-cone", "tiny-radius"}) {
    for (double rtol : {1e-6, 1e-9, 1e-12}) {
      SCOPED_TRACE(std::string(name) + " at rtol " + std::to_string(rtol));
      const RunResult automatic = run_preset(name, Method::automatic, rtol);
      EXPECT_EQ(automatic.stats.stiff_switches, 0);
      EXPECT_EQ(automatic.stats.dopri5_steps + automatic.stats.dop853_steps +
                    automatic.stats.taylor_steps,
                automatic.stats.steps);
      if (auto_explicit_for(rtol) == AutoExplicit::taylor) {
        // No probe for stiffness where no disturbance decays fast (stiffness_hint): Taylor's
        // run, step for step.
        const RunResult taylor = run_preset(name, Method::taylor, rtol);
        EXPECT_EQ(automatic.stats.dop853_steps, 0);
        EXPECT_EQ(automatic.stats.taylor_steps, taylor.stats.steps);
        continue;
      }
      const RunResult dop853 = run_preset(name, Method::dop853, rtol);
      if (!auto_weighs_explicit(rtol, AutoExplicit::by_tolerance)) {
        EXPECT_EQ(automatic.stats.rhs_evals, dop853.stats.rhs_evals);
        continue;
      }
      const RunResult dopri5 = run_preset(name, Method::dopri5, rtol);
      EXPECT_LT(explicit_work(automatic),
                1.15 * std::min(explicit_work(dopri5), explicit_work(dop853)));
    }
  }
}

// Where one explicit method is the cheaper at rtol 1e-6, `auto` runs it: DOPRI5 where a light
// pellet's collisions keep every interval short (mass-ratio: 1.6 times cheaper than DOP853) or
// where events come every few steps (high-frequency: each event's precise state costs DOP853
// twelve right-hand sides, DOPRI5 six), DOP853 on forced and smooth flights (1.2 to 2 times
// cheaper than DOPRI5).
TEST(AutoMethod, WeighsItsExplicitMethodsByCost) {
  for (const char* name : {"mass-ratio", "high-frequency"}) {
    const RunResult busy = run_preset(name, Method::automatic, 1e-6);
    EXPECT_GT(busy.stats.dopri5_steps, 5 * busy.stats.dop853_steps) << name;
  }
  for (const char* name : {"impact-oscillator", "grazing", "plastic-limiter"}) {
    const RunResult flight = run_preset(name, Method::automatic, 1e-6);
    EXPECT_GT(flight.stats.dop853_steps, flight.stats.dopri5_steps) << name;
  }
}

// At tight tolerances `auto` runs Taylor, and its events are DOP853's.
TEST(AutoMethod, RunsTaylorAtTightTolerancesWithDop853sEvents) {
  for (const char* name : {"impact-oscillator", "paper", "frictionless-elastic", "chatter"}) {
    for (double rtol : {1e-9, 1e-12}) {
      SCOPED_TRACE(std::string(name) + " at rtol " + std::to_string(rtol));
      const RunResult automatic = run_preset(name, Method::automatic, rtol);
      EXPECT_GT(automatic.stats.taylor_steps, 2 * automatic.stats.dop853_steps);
      const RunResult dop853 = run_preset(name, Method::dop853, rtol);
      ASSERT_EQ(automatic.events.size(), dop853.events.size());
      for (std::size_t k = 0; k < dop853.events.size(); ++k) {
        EXPECT_EQ(automatic.events[k].kind, dop853.events[k].kind) << "event " << k;
        EXPECT_EQ(automatic.events[k].pellets, dop853.events[k].pellets) << "event " << k;
        EXPECT_NEAR(automatic.events[k].t, dop853.events[k].t, 1e3 * rtol) << "event " << k;
      }
    }
  }
}

// An overdamped pendulum (c = 2000 1/s, against sqrt(g/R) ≈ 4.4 1/s) creeps down at a rate of
// g/(R·c) ≈ 0.01 1/s while disturbances of its speed die at 2000 1/s: stiff through its damper
// alone, with no friction. At tight tolerances `auto` probes from Taylor (the damper is in the
// stiffness hint) and hands over to RADAU5, which takes far fewer steps.
TEST(AutoMethod, FindsStiffnessThroughAStrongDamper) {
  Model m;
  m.R = 0.5;
  m.pellets = {{0.1, 1.0, 0.0, {}}};
  m.pellets[0].c = 2000.0;
  SimOptions o;
  o.t_end = 2.0;
  o.rtol = 1e-9;
  o.atol = 1e-11;
  o.check = false;
  o.method = Method::taylor;
  const RunResult taylor = simulate(m, o);
  o.method = Method::automatic;
  const RunResult automatic = simulate(m, o);
  ASSERT_EQ(automatic.stats.termination, Termination::completed) << automatic.stats.message;
  EXPECT_GE(automatic.stats.stiff_switches, 1);
  EXPECT_LT(automatic.stats.steps, taylor.stats.steps / 2);
  EXPECT_NEAR(automatic.summary.final[0].phi, taylor.summary.final[0].phi, 1e-7);
}

// A harmonic oscillator with no jets (as the variational equations that monodromy integrates).
struct NoJets final : OdeSystem {
  int dimension() const override { return 2; }
  void rhs(double, const Vec& y, Vec& dydt) const override {
    dydt[0] = y[1];
    dydt[1] = -y[0];
  }
  void jacobian(double, const Vec&, Mat& dfdy, Vec& dfdt) const override {
    dfdy = (Mat(2, 2) << 0.0, 1.0, -1.0, 0.0).finished();
    dfdt = Vec::Zero(2);
  }
};

// Without jets `auto` runs DOP853 alone where it would run Taylor.
TEST(AutoMethod, RunsDop853WhereTheSystemHasNoJets) {
  NoJets sys;
  auto automatic = make_stepper(Method::automatic, StepperOptions{1e-10, 1e-12});
  automatic->start(sys, 0.0, (Vec(2) << 1.0, 0.0).finished());
  while (automatic->t() < 20.0) ASSERT_EQ(automatic->step(20.0), StepStatus::ok);
  EXPECT_EQ(automatic->name(), "dop853");
  EXPECT_EQ(automatic->stats().dop853_steps, automatic->stats().steps);
  EXPECT_NEAR(automatic->y()[0], std::cos(20.0), 1e-8);
}

}  // namespace
}  // namespace vibro
