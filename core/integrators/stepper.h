// One-step integrators with step-size control and dense output (Hairer's codes are the model).
// A Stepper takes accepted steps one at a time; the simulation driver searches each step's
// dense output for events and restarts the stepper after each event.
#pragma once

#include <algorithm>
#include <limits>
#include <memory>
#include <string_view>

#include "core/integrators/ode.h"
#include "core/integrators/step_view.h"

namespace vibro {

enum class Method { dopri5, dop853, radau5, automatic, taylor };

// "dopri5", "dop853", "radau5", "auto", "taylor"
std::string_view method_name(Method m);

// The explicit method `auto` runs while the problem is not stiff: by default the cheaper one for
// the tolerance (auto_explicit_for); the trust check asks for the other one, so that a run and
// its shadow do not share a method's bias. Taylor stands for DOP853 where the system has no
// jets (OdeSystem::has_taylor_coefficients).
enum class AutoExplicit { by_tolerance, dopri5, dop853, taylor };

// The explicit method `auto` starts with: the one `choice` names; by tolerance, DOPRI5 above
// kAutoTaylorRtol (weighed against DOP853 from 5e-6 down: auto_weighs_explicit), Taylor from there
// down.
AutoExplicit auto_explicit_for(double rtol, AutoExplicit choice = AutoExplicit::by_tolerance);

// From this rtol down `auto` runs the Taylor method where the system has jets (DOP853 probing
// for stiffness, core/integrators/auto_switch.h): at and below it Taylor costs less than DOP853
// and DOPRI5 on every non-stiff preset. Measured by the instructions of whole runs
// (deterministic, unlike times on the shared machine; `bench/auto_cost.sh`, atol = rtol/100, the
// check off) on the eleven non-stiff presets, Taylor against the cheaper of DOP853 and DOPRI5:
// at rtol 1e-7 0.35 (impact-oscillator) to 0.58 (mass-ratio), at 1e-8 0.33 to 0.58 (the same),
// at 1e-10 0.27 to 0.56 (the same), at 1e-12 0.21 to 0.51 (the same). (Grazing at 1e-7 and 1e-9
// is left out: DOP853 lists 2 of its 7 events there.) Above it `auto` weighs DOPRI5 against
// DOP853 over stretches of the run, where Taylor measured 0.30 (rest-in-cone) to 0.59 (loop) of
// the cheaper at 1e-6 and up to 0.75 (loop) at 1e-3; the same kind of weighing chose
// DOP853 on the paper scene at 1e-9, where Taylor is the cheaper over the whole run (its cost per
// unit of time over its first, event-dense 0.53 s was 1.6 times DOP853's over the next 0.63 s).
inline constexpr double kAutoTaylorRtol = 5e-7;

// True where `auto` weighs DOPRI5 against DOP853 by their cost on the problem
// (core/integrators/auto_switch.h): rtol from 5e-6 down to above kAutoTaylorRtol with the method
// left to it, where each is the cheaper on some preset (at 1e-6 DOPRI5 by 1.27× on
// high-frequency, DOP853 by 1.18× on plastic-limiter). Below, DOP853 is the cheaper on every
// preset (at 1e-9 the faster everywhere but mass-ratio, by 1.13×; docs/PERFORMANCE.md), and
// Taylor cheaper still (kAutoTaylorRtol); above 5e-6 DOPRI5 is
// (Hairer's advice; the paper scene at rtol 1e-4: 0.32 ms against DOP853's 0.39 ms), and a
// trial of DOP853 there, measured over a stretch of another phase of the motion, chose it.
bool auto_weighs_explicit(double rtol, AutoExplicit choice);

struct StepperOptions {
  double rtol = 1e-9;   // relative tolerance per component
  double atol = 1e-12;  // absolute tolerance per component
  double h_max = std::numeric_limits<double>::infinity();
  AutoExplicit auto_explicit = AutoExplicit::by_tolerance;
};

struct StepperStats {
  long steps = 0;           // accepted steps
  long rejected = 0;        // rejected step attempts
  long rhs_evals = 0;       // evaluations of f
  long jac_evals = 0;       // Jacobian evaluations (implicit method only)
  long lu_decomps = 0;      // LU factorisations (implicit method only)
  long stiff_switches = 0;  // method switches made by "auto"
  // "auto": the accepted steps each explicit method took, where it weighs one against the other.
  long dopri5_steps = 0, dop853_steps = 0, taylor_steps = 0;
};

enum class StepStatus {
  ok,
  step_underflow,  // the step size fell below round-off of t
  non_finite,      // f returned NaN/Inf, or the state became non-finite
  solver_failure,  // the implicit method's Newton iteration or factorisation failed repeatedly
};

// A Stepper is the StepView of its last accepted step (t_prev(), t(), dense()).
class Stepper : public StepView {
 public:
  // Name of the method that took the last step ("dopri5", "dop853", "radau5").
  virtual std::string_view name() const = 0;

  // Starts, or restarts after a discontinuity, at (t0, y0). The system must outlive the stepper's
  // use of it. The step size of the previous segment, if any, is kept as a hint for the first step.
  virtual void start(const OdeSystem& sys, double t0, const Vec& y0) = 0;

  // Restarts at (t0, y0) where the state went on continuously and the motion on the far side is
  // as smooth as before (a sliding body's speed passing through zero: its friction changes sign,
  // nothing else). The previous proposal is the first step: HINIT, which start() bounds it by,
  // guesses a thousand times too short where the speed is zero (its weight there is atol), and
  // the controller takes four steps to grow back. After an impact or a change of mode, start().
  // RADAU5 keeps start() here too: with the proposal it listed a reversal and seven impacts
  // more than the reference in a chatter at 1e-6 rad/s (tests/reference/corpus,
  // body-slides-through-its-limiter).
  virtual void continue_smoothly(const OdeSystem& sys, double t0, const Vec& y0) {
    start(sys, t0, y0);
  }

  // Takes one accepted step, never beyond t_limit (> t()). Rejected attempts are retried inside.
  // On anything but ok, t() and y() are left at the last accepted point.
  virtual StepStatus step(double t_limit) = 0;
  // Takes one step as step(t_limit) does, landing on t_land (> t()) too unless the step is a
  // polynomial (StepView::polynomials), whose dense output at t_land is as exact as its end: a
  // caller then reads the state there from dense() (a stroboscopic section's stops).
  virtual StepStatus step_landing(double t_limit, double t_land) {
    return step(std::min(t_limit, t_land));
  }

  // y() is the state at t(), the end of the last accepted step [t_prev(), t()] (StepView).
  virtual const Vec& y() const = 0;

  // The state at t in the last accepted step (or a little past its end), as accurate as a step's
  // end: a step from the last step's start. Every method's dense output is of lower order than
  // its steps (DOPRI5 4 for 5, DOP853 7 for 8, Radau IIA's collocation 3 for 5); event times
  // and states are corrected with this one. A stepper without it answers dense().
  virtual void precise_state(double t, Vec& out) { dense(t, out); }

  virtual const StepperStats& stats() const = 0;
};

// A stepper for the method, with tolerances and the maximum step size.
std::unique_ptr<Stepper> make_stepper(Method method, const StepperOptions& options);

}  // namespace vibro
