#include "core/integrators/auto_switch.h"

#include <limits>

namespace vibro::integrators {

AutoSwitch::AutoSwitch(const StepperOptions& options)
    : dopri5_(options),
      dop853_(options),
      implicit_(options),
      weighs_explicit_(auto_weighs_explicit(options.rtol, options.auto_explicit)),
      explicit_(auto_explicit_for(options.rtol, options.auto_explicit) == AutoExplicit::dopri5
                    ? Kind::dopri5
                    : Kind::dop853),
      active_(explicit_) {}

const Stepper& AutoSwitch::stepper(Kind kind) const {
  switch (kind) {
    case Kind::dopri5:
      return dopri5_;
    case Kind::dop853:
      return dop853_;
    case Kind::radau5:
      break;
  }
  return implicit_;
}

void AutoSwitch::start(const OdeSystem& sys, double t0, const Vec& y0) {
  prepare(sys, y0);
  active().start(sys, t0, y0);
}

void AutoSwitch::continue_smoothly(const OdeSystem& sys, double t0, const Vec& y0) {
  prepare(sys, y0);
  active().continue_smoothly(sys, t0, y0);
}

void AutoSwitch::prepare(const OdeSystem& sys, const Vec& y0) {
  sys_ = &sys;
  // Every method gets its work arrays now, so that a switch does not allocate.
  const int n = static_cast<int>(y0.size());
  dopri5_.reserve(n);
  dop853_.reserve(n);
  implicit_.reserve(n);
  if (pending_) take_pending();
}

void AutoSwitch::take_pending() {
  if ((*pending_ == Kind::radau5) != (active_ == Kind::radau5)) {
    non_stiff_steps_ = 0;
    ++switches_;
  }
  active_ = *pending_;
  pending_.reset();
}

void AutoSwitch::switch_method() {
  const Kind to = *pending_;
  const Stepper& from = active();
  double h = 0.0;
  if (active_ == Kind::radau5)
    h = implicit_.step_size();
  else
    h = active_ == Kind::dopri5 ? dopri5_.step_size() : dop853_.step_size();
  switch (to) {
    case Kind::dopri5:
      dopri5_.resume(*sys_, from.t(), from.y(), h);
      break;
    case Kind::dop853:
      dop853_.resume(*sys_, from.t(), from.y(), h);
      break;
    case Kind::radau5:
      implicit_.resume(*sys_, from.t(), from.y(), h);
      break;
  }
  take_pending();
}

double AutoSwitch::work() const {
  return static_cast<double>(dopri5_.stats().rhs_evals + dop853_.stats().rhs_evals) +
         kImplicitEvalCost * static_cast<double>(implicit_.stats().rhs_evals);
}

double AutoSwitch::explicit_work() const {
  double w = 0.0;
  for (const StepperStats* s : {&dopri5_.stats(), &dop853_.stats()})
    w +=
        static_cast<double>(s->rhs_evals) + kStepCost * static_cast<double>(s->steps + s->rejected);
  return w;
}

double AutoSwitch::rate(const Mark& from, double w) const {
  const double dt = active().t() - from.t;
  return dt > 0.0 ? (w - from.work) / dt : std::numeric_limits<double>::infinity();
}

void AutoSwitch::after_explicit_step() {
  ++explicit_steps_;
  const bool limited =
      explicit_ == Kind::dopri5 ? dopri5_.stability_limited() : dop853_.stability_limited();
  if (!limited || explicit_steps_ < retry_after_) {
    measure_from_ = mark(work());
    return;
  }
  if (steps_ - measure_from_.steps < kMeasureSteps) return;
  // Stiff: RADAU5 is tried from the explicit method now running, and a weighing stops.
  explicit_rate_ = rate(measure_from_, work());
  trial_ = true;
  trial_from_ = mark(work());
  pending_ = Kind::radau5;
  weighing_ = false;
  weighed_steps_ = 0;
}

// Before an explicit step, where the time reached is the run's (a step's end that an event cut
// short is not): the incumbent's cost per unit of time over its whole stretch, the challenger's
// over its trial after kExplicitWarmupSteps, each from one step's start to another's.
void AutoSwitch::weigh_explicit() {
  const Kind other = explicit_ == Kind::dopri5 ? Kind::dop853 : Kind::dopri5;
  if (!weighing_) {
    if (weighed_steps_ == 0) weigh_from_ = mark(explicit_work());
    if (weighed_steps_++ < next_weighing_) return;
    incumbent_rate_ = rate(weigh_from_, explicit_work());
    weighing_ = true;
    weighed_steps_ = 0;
    explicit_ = other;
    pending_ = other;
    return;
  }
  if (weighed_steps_ == kExplicitWarmupSteps) weigh_from_ = mark(explicit_work());
  if (weighed_steps_++ < kExplicitTrialSteps) return;
  weighing_ = false;
  weighed_steps_ = 0;
  if (rate(weigh_from_, explicit_work()) > kExplicitMargin * incumbent_rate_) {
    explicit_ = other;  // the incumbent goes on
    pending_ = other;
    next_weighing_ = 2 * next_weighing_;
  }
  next_weighing_ = std::max(next_weighing_, kExplicitRetrySteps);
}

void AutoSwitch::after_implicit_step() {
  if (trial_) {
    const long done = steps_ - trial_from_.steps;
    if (done == kTrialWarmupSteps) trial_from_ = {work(), active().t(), trial_from_.steps};
    if (done < kTrialSteps) return;
    trial_ = false;
    if (rate(trial_from_, work()) > explicit_rate_) {
      pending_ = explicit_;
      retry_after_ = retry_after_ == 0 ? kRetrySteps : 2 * retry_after_;
      explicit_steps_ = 0;
      return;
    }
    retry_after_ = 0;
  }
  non_stiff_steps_ = implicit_.stiffness_ratio() <= kNonStiffBound ? non_stiff_steps_ + 1 : 0;
  if (non_stiff_steps_ >= kNonStiffSteps) pending_ = explicit_;
}

StepStatus AutoSwitch::step(double t_limit) {
  if (weighs_explicit_ && !pending_ && active_ != Kind::radau5) weigh_explicit();
  if (pending_) switch_method();
  const StepStatus status = active().step(t_limit);
  if (status != StepStatus::ok) return status;
  ++steps_;
  if (active_ == Kind::radau5)
    after_implicit_step();
  else
    after_explicit_step();
  return status;
}

const StepperStats& AutoSwitch::stats() const {
  const StepperStats& a = dopri5_.stats();
  const StepperStats& b = dop853_.stats();
  const StepperStats& c = implicit_.stats();
  stats_.steps = a.steps + b.steps + c.steps;
  stats_.rejected = a.rejected + b.rejected + c.rejected;
  stats_.rhs_evals = a.rhs_evals + b.rhs_evals + c.rhs_evals;
  stats_.jac_evals = a.jac_evals + b.jac_evals + c.jac_evals;
  stats_.lu_decomps = a.lu_decomps + b.lu_decomps + c.lu_decomps;
  stats_.stiff_switches = switches_;
  stats_.dop853_steps = b.steps;
  stats_.dopri5_steps = a.steps;
  return stats_;
}

}  // namespace vibro::integrators
