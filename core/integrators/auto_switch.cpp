#include "core/integrators/auto_switch.h"

#include <limits>

namespace vibro::integrators {

namespace {

AutoSwitch::Kind kind_of(AutoExplicit method) {
  switch (method) {
    case AutoExplicit::dopri5:
      return AutoSwitch::Kind::dopri5;
    case AutoExplicit::taylor:
      return AutoSwitch::Kind::taylor;
    default:
      return AutoSwitch::Kind::dop853;
  }
}

}  // namespace

AutoSwitch::AutoSwitch(const StepperOptions& options)
    : dopri5_(options),
      dop853_(options),
      taylor_(options),
      implicit_(options),
      weighs_explicit_(auto_weighs_explicit(options.rtol, options.auto_explicit)),
      explicit_(kind_of(auto_explicit_for(options.rtol, options.auto_explicit))),
      taylor_home_(explicit_ == Kind::taylor),
      active_(explicit_) {}

const Stepper& AutoSwitch::stepper(Kind kind) const {
  switch (kind) {
    case Kind::dopri5:
      return dopri5_;
    case Kind::dop853:
      return dop853_;
    case Kind::taylor:
      return taylor_;
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
  if (taylor_home_ && !sys.has_taylor_coefficients()) {
    taylor_home_ = false;  // no jets: DOP853 alone, from the start
    if (explicit_ == Kind::taylor) explicit_ = Kind::dop853;
    if (active_ == Kind::taylor) active_ = Kind::dop853;
    if (pending_ == Kind::taylor) pending_.reset();
  }
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
  switch (active_) {
    case Kind::dopri5:
      h = dopri5_.step_size();
      break;
    case Kind::dop853:
      h = dop853_.step_size();
      break;
    case Kind::taylor:
      h = from.t() - from.t_prev();  // its last step, set by its series
      break;
    case Kind::radau5:
      h = implicit_.step_size();
      break;
  }
  switch (to) {
    case Kind::dopri5:
      dopri5_.resume(*sys_, from.t(), from.y(), h);
      break;
    case Kind::dop853:
      if (h > 0.0)
        dop853_.resume(*sys_, from.t(), from.y(), h);
      else
        dop853_.start(*sys_, from.t(), from.y());
      break;
    case Kind::taylor:
      taylor_.start(*sys_, from.t(), from.y());  // each step's size is its own series'
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
  // Taylor's step is held by its series' radius, which says nothing of stability: a stiff stretch
  // is found while DOP853 probes (probe_stiffness).
  const bool limited = explicit_ == Kind::dopri5   ? dopri5_.stability_limited()
                       : explicit_ == Kind::dop853 ? dop853_.stability_limited()
                                                   : false;
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
  probing_ = false;
  probe_steps_ = 0;
}

// Before a step while Taylor is the explicit method: after next_probe_ Taylor steps, at the first
// step where the system's stiffness_hint exceeds kStiffnessHint, DOP853 runs for kProbeSteps,
// and longer while its step is held by stability (up to kProbeMaxSteps), so that
// after_explicit_step can measure it and try RADAU5; otherwise Taylor goes on, and the next
// probe comes after twice as many steps. DOP853 back from RADAU5 hands over to Taylor at once.
void AutoSwitch::probe_stiffness() {
  if (active_ == Kind::taylor) {
    if (probe_steps_ < next_probe_) ++probe_steps_;
    if (probe_steps_ < next_probe_ ||
        sys_->stiffness_hint(taylor_.t(), taylor_.y()) <= kStiffnessHint)
      return;
    probing_ = true;
    probe_steps_ = 0;
    explicit_ = Kind::dop853;
    pending_ = Kind::dop853;
    return;
  }
  ++probe_steps_;
  if (probing_ && (probe_steps_ < kProbeSteps ||
                   (dop853_.stability_limited() && probe_steps_ < kProbeMaxSteps)))
    return;
  end_probe();
}

void AutoSwitch::end_probe() {
  probing_ = false;
  probe_steps_ = 0;
  next_probe_ = std::max(2 * next_probe_, kProbeRetrySteps);
  explicit_ = Kind::taylor;
  pending_ = Kind::taylor;
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
  return step_landing(t_limit, std::numeric_limits<double>::infinity());
}

StepStatus AutoSwitch::step_landing(double t_limit, double t_land) {
  if (weighs_explicit_ && !pending_ && active_ != Kind::radau5) weigh_explicit();
  if (taylor_home_ && !pending_ && active_ != Kind::radau5) probe_stiffness();
  if (pending_) switch_method();
  StepStatus status = active().step_landing(t_limit, t_land);
  if (status != StepStatus::ok && probing_ && active_ == Kind::dop853) {
    // A probe that DOP853 cannot step is no verdict on stiffness: Taylor, which may follow
    // where DOP853's step underflows, takes the step from the last one accepted.
    end_probe();
    switch_method();
    status = active().step_landing(t_limit, t_land);
  }
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
  const StepperStats& d = taylor_.stats();
  stats_.steps = a.steps + b.steps + c.steps + d.steps;
  stats_.rejected = a.rejected + b.rejected + c.rejected;
  stats_.rhs_evals = a.rhs_evals + b.rhs_evals + c.rhs_evals + d.rhs_evals;
  stats_.jac_evals = a.jac_evals + b.jac_evals + c.jac_evals;
  stats_.lu_decomps = a.lu_decomps + b.lu_decomps + c.lu_decomps;
  stats_.stiff_switches = switches_;
  stats_.dop853_steps = b.steps;
  stats_.dopri5_steps = a.steps;
  stats_.taylor_steps = d.steps;
  return stats_;
}

}  // namespace vibro::integrators
