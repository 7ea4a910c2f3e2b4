// Automatic method choice ("auto"), in the spirit of LSODA: an explicit method while the problem
// is non-stiff, RADAU5 while it is stiff, and at loose tolerances DOPRI5 or DOP853, whichever
// costs less on this problem; at tight tolerances (kAutoTaylorRtol, core/integrators/stepper.h)
// the Taylor method, with DOP853 probing for stiffness, and DOP853 alone where the system has no
// jets (OdeSystem::has_taylor_coefficients).
#pragma once

#include <memory>
#include <optional>
#include <string_view>

#include "core/integrators/dop853.h"
#include "core/integrators/dopri5.h"
#include "core/integrators/radau5.h"
#include "core/integrators/stepper.h"
#include "core/integrators/taylor.h"

namespace vibro::integrators {

// Stiffness, chosen by cost as LSODA does: when the explicit method's step size is held by
// stability (ExplicitRk::stability_limited), its cost per unit of time over the next
// kMeasureSteps steps is noted and RADAU5 takes over from the same point with the explicit
// method's step size, on trial: after kTrialSteps steps (the first kTrialWarmupSteps let its step
// size grow) RADAU5's cost per unit of time is compared, and the cheaper method goes on. A trial
// that RADAU5 loses is retried only after kRetrySteps explicit steps, twice as many after each
// loss. When RADAU5's h·‖J‖∞ stays below kNonStiffBound for kNonStiffSteps accepted steps, the
// explicit method takes over again. Cost is counted in right-hand-side evaluations, RADAU5's
// weighted by kImplicitEvalCost for its linear algebra, so the choice is the same on any machine.
//
// The explicit method, where the tolerance does not settle it (auto_weighs_explicit, rtol
// around 1e-6): DOPRI5 starts; after kExplicitMeasureSteps steps DOP853 is tried for
// kExplicitTrialSteps, and goes on if its cost per unit of time after its first
// kExplicitWarmupSteps (the other method's step size settling) is below kExplicitMargin times
// the incumbent's over its whole stretch. A short trial's cost is noisy (on high-frequency
// DOP853 won a trial by 2 % and ran a third of the run at 1.3 times the cost), hence the margin.
// The other method is tried again after kExplicitRetrySteps steps, twice as many after each
// trial that changes nothing. Here a step's cost is its right-hand sides and kStepCost more: at
// rtol 1e-6 DOP853 won on presets where it made more evaluations but half the steps (grazing:
// 1048 evaluations in 66 steps against DOPRI5's 862 in 135; 1.16× faster), and lost where its
// steps are held by the forcing or by events (high-frequency: 1.24× slower).
//
// A switch happens at the beginning of the next step (or start()), so t_prev(), dense() and
// name() always refer to the method that took the last step. The current method is kept across
// start().
class AutoSwitch final : public Stepper {
 public:
  enum class Kind { dopri5, dop853, taylor, radau5 };
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
  static constexpr int kExplicitMeasureSteps = 10;
  static constexpr int kExplicitWarmupSteps = 5;
  static constexpr int kExplicitTrialSteps = 15;
  static constexpr long kExplicitRetrySteps = 100;
  static constexpr double kExplicitMargin = 0.9;
  // The work of an explicit step beyond its right-hand sides (the event search, the watches, the
  // step's bookkeeping), in right-hand sides: fitted to the presets' wall times at rtol 1e-6,
  // which put it between 1.4 (plastic-limiter) and 6.5 (high-frequency).
  static constexpr double kStepCost = 4.0;
  // Where Taylor is the explicit method, DOP853 probes for stiffness (probe_stiffness): first after
  // kExplicitMeasureSteps Taylor steps, then after twice as many each time, kProbeRetrySteps at
  // least, each where the system's stiffness_hint allows stiffness (kStiffnessHint); each probe
  // kProbeSteps long, up to kProbeMaxSteps while DOP853's step is held by stability (kMeasureSteps
  // of them start RADAU5's trial).
  static constexpr int kProbeSteps = 15;
  static constexpr int kProbeMaxSteps = 60;
  static constexpr long kProbeRetrySteps = 100;
  // A probe that is due waits, step after step, while the system's stiffness_hint is at most
  // this: no disturbance then decays much faster than the motion moves, and DOP853's steps
  // would only cost more and err more than Taylor's (the paper scene at rtol 1e-9: 14 % more
  // instructions, 18 times the error). The stiff-friction preset's hint is about 4,500.
  static constexpr double kStiffnessHint = 10.0;

  explicit AutoSwitch(const StepperOptions& options);

  std::string_view name() const override { return active().name(); }
  void start(const OdeSystem& sys, double t0, const Vec& y0) override;
  void continue_smoothly(const OdeSystem& sys, double t0, const Vec& y0) override;
  StepStatus step(double t_limit) override;
  StepStatus step_landing(double t_limit, double t_land) override;
  double t_prev() const override { return active().t_prev(); }
  double t() const override { return active().t(); }
  const Vec& y() const override { return active().y(); }
  void dense(double t, Vec& out) const override { active().dense(t, out); }
  void precise_state(double t, Vec& out) override { active().precise_state(t, out); }
  const StepPolynomials* polynomials() const override { return active().polynomials(); }
  const StepperStats& stats() const override;

  // True while RADAU5 is (or is about to be) the method.
  bool stiff() const { return (pending_ ? *pending_ : active_) == Kind::radau5; }

 private:
  // Work done and time reached: where a measurement of cost per unit of time begins.
  struct Mark {
    double work = 0.0;
    double t = 0.0;
    long steps = 0;
  };

  const Stepper& active() const { return stepper(active_); }
  Stepper& active() { return const_cast<Stepper&>(stepper(active_)); }
  const Stepper& stepper(Kind kind) const;
  void switch_method();  // the pending method resumes where the active one stands
  void take_pending();   // the pending method becomes the active one
  void prepare(const OdeSystem& sys, const Vec& y0);  // before a (re)start
  double work() const;                                // RADAU5 against the explicit methods
  double explicit_work() const;                       // the explicit methods against each other
  Mark mark(double w) const { return {w, active().t(), steps_}; }
  double rate(const Mark& from, double w) const;  // work per unit of time since `from`
  void after_explicit_step();
  void weigh_explicit();
  void after_implicit_step();
  void probe_stiffness();
  // Hands back to Taylor after a probe (its end, or a step DOP853 could not take).
  void end_probe();

  Dopri5 dopri5_;
  Dop853 dop853_;
  Taylor taylor_;
  Radau5 implicit_;
  const OdeSystem* sys_ = nullptr;
  const bool weighs_explicit_;
  Kind explicit_;                // the explicit method that runs while the problem is non-stiff
  bool taylor_home_;             // Taylor is the explicit method, DOP853 its probe
  Kind active_;                  // the method that took the last step
  std::optional<Kind> pending_;  // the method that takes the next step, if another
  int non_stiff_steps_ = 0;      // consecutive RADAU5 steps with h·‖J‖∞ <= kNonStiffBound
  long switches_ = 0;            // between explicit and implicit
  long steps_ = 0;               // accepted steps of any method
  Mark measure_from_;            // where the explicit method's measured stretch began
  double explicit_rate_ = 0.0;   // its cost per unit of time there
  bool trial_ = false;           // RADAU5 is on trial
  Mark trial_from_;
  long retry_after_ = 0;     // explicit steps before the next trial of RADAU5
  long explicit_steps_ = 0;  // since the last lost trial
  // Weighing the explicit methods.
  long weighed_steps_ = 0;  // explicit steps since the last explicit trial ended
  long next_weighing_ = kExplicitMeasureSteps;
  Mark weigh_from_;  // the incumbent's measured stretch, then the challenger's
  double incumbent_rate_ = 0.0;
  bool weighing_ = false;  // the other explicit method is on trial
  // Probing for stiffness.
  bool probing_ = false;  // DOP853 is probing
  long probe_steps_ = 0;  // steps of the method now running since the last hand-over
  long next_probe_ = kExplicitMeasureSteps;
  mutable StepperStats stats_;
};

}  // namespace vibro::integrators
