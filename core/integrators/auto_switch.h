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
// it is stiff. When the explicit method's stiffness detection fires, the next step is taken by
// RADAU5 from the same point with the explicit method's step size; when RADAU5's h·‖J‖∞ stays
// below kNonStiffBound for kNonStiffSteps accepted steps, the explicit method takes over again. A
// switch happens at the beginning of the next step (or start()), so t_prev(), dense() and name()
// always refer to the method that took the last step. The current method is kept across start().
class AutoSwitch : public Stepper {
 public:
  // h·‖J‖∞ <= 1 leaves the explicit methods (stability bounds h·ρ ≈ 3.3 and 6.1) room to grow.
  static constexpr double kNonStiffBound = 1.0;
  static constexpr int kNonStiffSteps = 15;

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
  const Stepper& active() const;
  Stepper& active();
  void switch_method();

  Explicit explicit_;
  Radau5 implicit_;
  const OdeSystem* sys_ = nullptr;
  bool stiff_ = false;           // RADAU5 is the method
  bool switch_pending_ = false;  // the other method takes the next step
  int non_stiff_steps_ = 0;      // consecutive RADAU5 steps with h·‖J‖∞ <= kNonStiffBound
  long switches_ = 0;
  mutable StepperStats stats_;
};

// The `auto` stepper for these tolerances. Above rtol 1e-7 a DOPRI5 step (6 stages) buys as much
// as a DOP853 step (12, and 3 more for its dense output), and runs with many events are bound by
// restarts rather than accuracy: DOPRI5 is then the cheaper explicit method (Hairer's own advice).
std::unique_ptr<AutoSwitch> make_auto_switch(const StepperOptions& options);

}  // namespace vibro::integrators
