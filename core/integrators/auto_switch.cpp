#include "core/integrators/auto_switch.h"

#include <limits>

namespace vibro::integrators {

template <class Explicit>
AutoSwitchWith<Explicit>::AutoSwitchWith(const StepperOptions& options)
    : explicit_(options), implicit_(options) {}

template <class Explicit>
const Stepper& AutoSwitchWith<Explicit>::active() const {
  return stiff_ ? static_cast<const Stepper&>(implicit_) : explicit_;
}

template <class Explicit>
Stepper& AutoSwitchWith<Explicit>::active() { return stiff_ ? static_cast<Stepper&>(implicit_) : explicit_; }

template <class Explicit>
void AutoSwitchWith<Explicit>::start(const OdeSystem& sys, double t0, const Vec& y0) {
  sys_ = &sys;
  // Both methods get their work arrays now, so that a switch does not allocate.
  explicit_.reserve(static_cast<int>(y0.size()));
  implicit_.reserve(static_cast<int>(y0.size()));
  if (switch_pending_) {
    stiff_ = !stiff_;
    switch_pending_ = false;
    non_stiff_steps_ = 0;
    ++switches_;
  }
  active().start(sys, t0, y0);
}

template <class Explicit>
void AutoSwitchWith<Explicit>::switch_method() {
  if (stiff_) {
    explicit_.resume(*sys_, implicit_.t(), implicit_.y(), implicit_.step_size());
  } else {
    implicit_.resume(*sys_, explicit_.t(), explicit_.y(), explicit_.step_size());
  }
  stiff_ = !stiff_;
  switch_pending_ = false;
  non_stiff_steps_ = 0;
  ++switches_;
}

template <class Explicit>
double AutoSwitchWith<Explicit>::work() const {
  return static_cast<double>(explicit_.stats().rhs_evals) +
         kImplicitEvalCost * static_cast<double>(implicit_.stats().rhs_evals);
}

template <class Explicit>
typename AutoSwitchWith<Explicit>::Mark AutoSwitchWith<Explicit>::mark() const {
  return {work(), active().t(), steps_};
}

template <class Explicit>
double AutoSwitchWith<Explicit>::cost_rate(const Mark& from) const {
  const double dt = active().t() - from.t;
  return dt > 0.0 ? (work() - from.work) / dt : std::numeric_limits<double>::infinity();
}

template <class Explicit>
void AutoSwitchWith<Explicit>::after_explicit_step() {
  ++explicit_steps_;
  if (!explicit_.stability_limited() || explicit_steps_ < retry_after_) {
    measure_from_ = mark();
    return;
  }
  if (steps_ - measure_from_.steps < kMeasureSteps) return;
  explicit_rate_ = cost_rate(measure_from_);
  trial_ = true;
  trial_from_ = mark();
  switch_pending_ = true;
}

template <class Explicit>
void AutoSwitchWith<Explicit>::after_implicit_step() {
  if (trial_) {
    const long done = steps_ - trial_from_.steps;
    if (done == kTrialWarmupSteps) trial_from_ = {work(), active().t(), trial_from_.steps};
    if (done < kTrialSteps) return;
    trial_ = false;
    if (cost_rate(trial_from_) > explicit_rate_) {
      switch_pending_ = true;
      retry_after_ = retry_after_ == 0 ? kRetrySteps : 2 * retry_after_;
      explicit_steps_ = 0;
      return;
    }
    retry_after_ = 0;
  }
  non_stiff_steps_ = implicit_.stiffness_ratio() <= kNonStiffBound ? non_stiff_steps_ + 1 : 0;
  switch_pending_ = non_stiff_steps_ >= kNonStiffSteps;
}

template <class Explicit>
StepStatus AutoSwitchWith<Explicit>::step(double t_limit) {
  if (switch_pending_) switch_method();
  const StepStatus status = active().step(t_limit);
  if (status != StepStatus::ok) return status;
  ++steps_;
  if (stiff_)
    after_implicit_step();
  else
    after_explicit_step();
  return status;
}

template <class Explicit>
const StepperStats& AutoSwitchWith<Explicit>::stats() const {
  const StepperStats& a = explicit_.stats();
  const StepperStats& b = implicit_.stats();
  stats_.steps = a.steps + b.steps;
  stats_.rejected = a.rejected + b.rejected;
  stats_.rhs_evals = a.rhs_evals + b.rhs_evals;
  stats_.jac_evals = a.jac_evals + b.jac_evals;
  stats_.lu_decomps = a.lu_decomps + b.lu_decomps;
  stats_.stiff_switches = switches_;
  return stats_;
}

template class AutoSwitchWith<Dopri5>;
template class AutoSwitchWith<Dop853>;

std::unique_ptr<AutoSwitch> make_auto_switch(const StepperOptions& options) {
  if (auto_explicit_for(options.rtol, options.auto_explicit) == AutoExplicit::dopri5)
    return std::make_unique<AutoSwitchWith<Dopri5>>(options);
  return std::make_unique<AutoSwitchWith<Dop853>>(options);
}

}  // namespace vibro::integrators
