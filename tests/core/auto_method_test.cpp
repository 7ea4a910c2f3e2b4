// `auto` picks the cheaper method by cost: RADAU5 wherever it is cheaper (the stiff-friction
// preset, at every tolerance, also where DOP853's step is held by accuracy rather than by
// stability), and no trial of it on the non-stiff presets. Work is counted in right-hand sides,
// which is deterministic, rather than timed.
#include <gtest/gtest.h>

#include "core/simulate.h"
#include "core/stepper.h"
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

TEST(AutoMethod, StaysExplicitOnTheNonStiffPresets) {
  for (const char* name : {"paper", "chatter", "frictionless-elastic", "grazing", "high-frequency",
                           "impact-oscillator", "loop", "mass-ratio", "plastic-limiter",
                           "rest-in-cone", "tiny-radius"}) {
    for (double rtol : {1e-6, 1e-9, 1e-12}) {
      const RunResult automatic = run_preset(name, Method::automatic, rtol);
      const Method explicit_method =
          auto_explicit_for(rtol) == AutoExplicit::dopri5 ? Method::dopri5 : Method::dop853;
      const RunResult alone = run_preset(name, explicit_method, rtol);
      EXPECT_EQ(automatic.stats.stiff_switches, 0) << name << " at rtol " << rtol;
      EXPECT_EQ(automatic.stats.rhs_evals, alone.stats.rhs_evals) << name << " at rtol " << rtol;
    }
  }
}

}  // namespace
}  // namespace vibro
