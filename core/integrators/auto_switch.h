// Automatic stiffness switching ("auto"), in the spirit of LSODA: DOP853 while the problem is
// non-stiff, RADAU5 while it is stiff.
#pragma once

#include <memory>
#include <string_view>

#include "core/integrators/dop853.h"
#include "core/integrators/dopri5.h"
#include "core/integrators/radau5.h"
#include "core/stepper.h"

namespace vibro::integrators {

// Automatic stiffness switching: an explicit method while the problem is non-stiff, RADAU5 while
// it is stiff, chosen by cost as LSODA does. When the explicit method's step size is held by
// stability (ExplicitRk::stability_limited), its cost per unit of time over the next
// kMeasureSteps steps is noted and RADAU5 takes over from the same point with the explicit
// method's step size, on trial: after kTrialSteps steps (the first kTrialWarmupSteps let its step
// size grow) RADAU5's cost per unit of time is compared, and the cheaper method goes on. A trial
// that RADAU5 loses is retried only after kRetrySteps explicit steps, twice as many after each
// loss. When RADAU5's h·‖J‖∞ stays below kNonStiffBound for kNonStiffSteps accepted steps, the
// explicit method takes over again. Cost is counted in right-hand-side evaluations, RADAU5's
// weighted by kImplicitEvalCost for its linear algebra, so the choice is the same on any machine.
// A switch happens at the beginning of the next step (or start()), so t_prev(), dense() and
// name() always refer to the method that took the last step. The current method is kept across
// start().
class AutoSwitch : public Stepper {
 public:
  // h·‖J‖∞ <= 1 leaves the explicit methods (stability bounds h·ρ ≈ 3.3 and 6.1) room to grow.
  static constexpr double kNonStiffBound = 1.0;
  static constexpr int kNonStiffSteps = 15;
  static constexpr int kMeasureSteps = 10;
  static constexpr int kTrialWarmupSteps = 10;
  static constexpr int kTrialSteps = 20;
  static constexpr long kRetrySteps = 200;
  // A RADAU5 step costs about 2.5 times a DOP853 step per right-hand side it evaluates (its
  // Newton iterations' linear solves; bench/overhead_bench.cpp: 232 against 94 ns per evaluation).
  static constexpr double kImplicitEvalCost = 2.5;

  // True while RADAU5 is (or is about to be) the method.
  virtual bool stiff() const = 0;
};

// `auto` with a given explicit method: DOPRI5 for loose tolerances, DOP853 for tight ones.
template <class Explicit>
class AutoSwitchWith final : public AutoSwitch {
 public:
  explicit AutoSwitchWith(const StepperOptions& options);

  std::string_view name() const override { return active().name(); }
  void start(const OdeSystem& sys, double t0, const Vec& y0) override;
  StepStatus step(double t_limit) override;
  double t_prev() const override { return active().t_prev(); }
  double t() const override { return active().t(); }
  const Vec& y() const override { return active().y(); }
  void dense(double t, Vec& out) const override { active().dense(t, out); }
  void precise_state(double t, Vec& out) override { active().precise_state(t, out); }
  bool dense_is_coarse() const override { return active().dense_is_coarse(); }
  const StepperStats& stats() const override;
  bool stiff() const override { return stiff_ != switch_pending_; }

 private:
  // Work done and time reached: where a measurement of cost per unit of time begins.
  struct Mark {
    double work = 0.0;
    double t = 0.0;
    long steps = 0;
  };

  const Stepper& active() const;
  Stepper& active();
  void switch_method();
  double work() const;
  Mark mark() const;
  double cost_rate(const Mark& from) const;  // work per unit of time since `from`
  void after_explicit_step();
  void after_implicit_step();

  Explicit explicit_;
  Radau5 implicit_;
  const OdeSystem* sys_ = nullptr;
  bool stiff_ = false;           // RADAU5 is the method
  bool switch_pending_ = false;  // the other method takes the next step
  int non_stiff_steps_ = 0;      // consecutive RADAU5 steps with h·‖J‖∞ <= kNonStiffBound
  long switches_ = 0;
  long steps_ = 0;               // accepted steps of either method
  Mark measure_from_;            // where the explicit method's measured stretch began
  double explicit_rate_ = 0.0;   // its cost per unit of time there
  bool trial_ = false;           // RADAU5 is on trial
  Mark trial_from_;
  long retry_after_ = 0;         // explicit steps before the next trial
  long explicit_steps_ = 0;      // since the last lost trial
  mutable StepperStats stats_;
};

// The `auto` stepper for these options (StepperOptions::auto_explicit). At rtol 1e-6 and looser a
// DOPRI5 step (6 stages) buys as much as a DOP853 step (12, and 3 more for its dense output), and
// runs with many events are bound by restarts rather than accuracy: DOPRI5 is then the cheaper
// explicit method (Hairer's own advice; on the presets at 1e-6 at most 1.03× DOP853's time,
// against up to 1.2× the other way). From 5e-7 down DOP853 is (at 1e-7 the two are within 1.18×
// of each other either way; at 1e-9 DOP853 is the faster on every preset; docs/PERFORMANCE.md).
std::unique_ptr<AutoSwitch> make_auto_switch(const StepperOptions& options);

}  // namespace vibro::integrators
