// Automatic stiffness switching ("auto"), in the spirit of LSODA: DOP853 while the problem is
// non-stiff, RADAU5 while it is stiff.
#pragma once

#include <string_view>

#include "core/integrators/dop853.h"
#include "core/integrators/radau5.h"
#include "core/stepper.h"

namespace vibro::integrators {

// Starts with DOP853. When its stiffness detection fires, the next step is taken by RADAU5 from the
// same point with DOP853's step size; when RADAU5's h·‖J‖∞ stays below kNonStiffBound for
// kNonStiffSteps accepted steps, DOP853 takes over again. A switch happens at the beginning of the
// next step (or start()), so t_prev(), dense() and name() always refer to the method that took the
// last step. The current method is kept across start().
class AutoSwitch final : public Stepper {
 public:
  // h·‖J‖∞ <= 1 leaves DOP853 (stability bound h·ρ ≈ 6.1) room to grow its step.
  static constexpr double kNonStiffBound = 1.0;
  static constexpr int kNonStiffSteps = 15;

  explicit AutoSwitch(const StepperOptions& options);

  std::string_view name() const override { return active().name(); }
  void start(const OdeSystem& sys, double t0, const Vec& y0) override;
  StepStatus step(double t_limit) override;
  double t_prev() const override { return active().t_prev(); }
  double t() const override { return active().t(); }
  const Vec& y() const override { return active().y(); }
  void dense(double t, Vec& out) const override { active().dense(t, out); }
  const StepperStats& stats() const override;

  // True while RADAU5 is (or is about to be) the method.
  bool stiff() const { return stiff_ != switch_pending_; }

 private:
  const Stepper& active() const;
  Stepper& active();
  void switch_method();

  Dop853 explicit_;
  Radau5 implicit_;
  const OdeSystem* sys_ = nullptr;
  bool stiff_ = false;           // RADAU5 is the method
  bool switch_pending_ = false;  // the other method takes the next step
  int non_stiff_steps_ = 0;      // consecutive RADAU5 steps with h·‖J‖∞ <= kNonStiffBound
  long switches_ = 0;
  mutable StepperStats stats_;
};

}  // namespace vibro::integrators
