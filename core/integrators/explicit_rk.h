// The driver shared by the explicit embedded Runge–Kutta methods (DOPRI5, DOP853): FSAL, Hairer's
// PI step-size control, step rejection, stiffness detection and lazily built dense output. The
// Scheme supplies the tableau: the stages and error estimate of one attempt, and the interpolant.
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

#include "core/integrators/error_norm.h"
#include "core/integrators/initial_step.h"
#include "core/integrators/pi_controller.h"
#include "core/integrators/step_fit.h"
#include "core/integrators/stepper.h"
#include "core/integrators/stiffness_detector.h"

namespace vibro::integrators {

// Scheme requirements (see Dopri5Scheme):
//   kName, kOrder (for HINIT), kControl (PiController::Params), kStiffBound (h·ρ of the stability
//   boundary), kAttemptEvals, kCompletionEvals, kDenseEvals (f calls of each phase);
//   resize(n);
//   attempt(sys, t, y, f, h, tol, y1, f1) -> scaled error; stages from (t, y) with f = f(t, y);
//     fills y1 and, if the scheme gets it for free, f1 = f(t + h, y1);
//   complete(sys, t1, y1, f1): makes f1 = f(t1, y1) after acceptance (FSAL);
//   last_stage_y(), last_stage_f(): the last stage's argument and value (the stiffness quotient);
//   prepare_dense(sys, t0, y0, f0, h, y1, f1); dense(theta, out) for theta in [0, 1].
template <class Scheme>
class ExplicitRk final : public Stepper {
 public:
  explicit ExplicitRk(const StepperOptions& options)
      : options_(options),
        tol_{options.atol, options.rtol, {}},
        control_(Scheme::kControl),
        near_bound_(near_bound_fraction(options.rtol)) {}

  std::string_view name() const override { return Scheme::kName; }

  void start(const OdeSystem& sys, double t0, const Vec& y0) override {
    begin(sys, t0, y0);
    const double guess =
        initial_step(sys, t0, y_, f_, Scheme::kOrder, options_.h_max, tol_, ytry_, ftry_);
    ++stats_.rhs_evals;
    h_ = first_step(h_, guess);
  }

  void continue_smoothly(const OdeSystem& sys, double t0, const Vec& y0) override {
    if (h_ <= 0.0) return start(sys, t0, y0);
    begin(sys, t0, y0);
  }

  // Continues at (t0, y0) with the first step h0, without HINIT: the hand-over from another
  // method (auto), which knows a good step size. Forgets the stiffness history.
  void resume(const OdeSystem& sys, double t0, const Vec& y0, double h0) {
    begin(sys, t0, y0);
    h_ = std::min(h0, options_.h_max);
    detector_.reset();
    near_bound_.reset();
  }

  // Sizes the work arrays for the dimension n ahead of time (no allocation in start() then).
  void reserve(int n) {
    if (n == n_) return;
    n_ = n;
    for (Vec* v : {&y_, &f_, &yp_, &fp_, &ytry_, &ftry_, &f_precise_}) v->resize(n);
    scheme_.resize(n);
    precise_.resize(n);
  }

  StepStatus step(double t_limit) override {
    const StepStatus status = advance(t_limit);
    if (status != StepStatus::ok) h_ = 0.0;  // a failure's step size is no hint for a restart
    return status;
  }

  double t_prev() const override { return t_prev_; }
  double t() const override { return t_; }
  const Vec& y() const override { return y_; }

  void dense(double t, Vec& out) const override {
    const double h = t_ - t_prev_;
    if (h <= 0.0) {  // no step taken since start()
      out = y_;
      return;
    }
    if (!dense_ready_) {
      scheme_.prepare_dense(*sys_, t_prev_, yp_, fp_, h, y_, f_);
      stats_.rhs_evals += Scheme::kDenseEvals;
      dense_ready_ = true;
    }
    out.resize(n_);  // a no-op at the right size
    scheme_.dense((t - t_prev_) / h, out);
  }

  const StepperStats& stats() const override { return stats_; }

  // One step of the method from the last step's start to t, without error control: the last
  // step passed it, and a shorter one errs less.
  void precise_state(double t, Vec& out) override {
    const double h = t - t_prev_;
    if (h <= 0.0) return dense(t, out);
    out.resize(n_);
    precise_.attempt(*sys_, t_prev_, yp_, fp_, h, tol_, out, f_precise_);
    stats_.rhs_evals += Scheme::kAttemptEvals;
  }

  // Hairer's stiffness detection has fired (h·ρ beyond the stability boundary in 15 steps); it
  // keeps its history across start(), so short segments between events still add up.
  bool stiffness_detected() const { return detector_.stiff(); }

  // h·ρ has stayed beyond near_bound_fraction(rtol) of the stability boundary for 15 steps: the
  // step size is held by a fast mode more than accuracy would hold it for a motion that varies
  // as fast, and an implicit method may be cheaper (auto tries it, see auto_switch.h).
  bool stability_limited() const { return near_bound_.stiff(); }

  // Half the boundary at rtol 1e-6 and above; below, scaled as the accuracy-limited step of a
  // method of this order scales (rtol^(1/order)): at rtol 1e-12 DOP853 keeps h·ρ under 0.12 of
  // the boundary in 90 % of the steps on every non-stiff preset, while the stiff-friction preset
  // holds it at 0.18, where RADAU5 is 7 times cheaper.
  static double near_bound_fraction(double rtol) {
    return 0.5 * std::pow(std::min(1.0, rtol / 1e-6), 1.0 / Scheme::kOrder);
  }

  // The step size proposed for the next step.
  double step_size() const { return h_; }

 private:
  StepStatus advance(double t_limit);

  void begin(const OdeSystem& sys, double t0, const Vec& y0) {
    reserve(static_cast<int>(y0.size()));
    sys_ = &sys;
    t_ = t_prev_ = t0;
    y_ = y0;
    tol_.take_periods(sys);
    sys.rhs(t0, y_, f_);
    ++stats_.rhs_evals;
    f_finite_ = all_finite(f_);
    control_.reset();
    reject_ = false;
    dense_ready_ = false;
  }

  StepperOptions options_;
  Tolerance tol_;
  PiController control_;
  StiffnessDetector detector_;
  StiffnessDetector near_bound_;
  mutable Scheme scheme_;  // dense() builds the interpolant lazily: most steps never need it
  Scheme precise_;         // precise_state's step, which keeps scheme_'s stages for dense()
  mutable StepperStats stats_;
  mutable bool dense_ready_ = false;

  const OdeSystem* sys_ = nullptr;
  int n_ = -1;
  double t_ = 0.0;
  double t_prev_ = 0.0;
  double h_ = 0.0;  // next step to try; 0 before the first start() and after a failure
  bool reject_ = false;
  double rejected_h_ = 0.0, rejected_err_ = 0.0;  // the last rejected step, while reject_
  bool f_finite_ = true;
  Vec y_, f_;        // accepted point and f there
  Vec yp_, fp_;      // previous accepted point (start of the last step)
  Vec ytry_, ftry_;  // end of the step being attempted
  Vec f_precise_;    // f at the end of precise_state's step, if the scheme computes it
};

// One accepted step, retried until accepted or failed: DOPRI5's and DOP853's main loop (stages,
// error norm, stiffness detection, step control), kept whole and in Hairer's order so that it
// reads beside dopri5.f and dop853.f.
template <class Scheme>
StepStatus ExplicitRk<Scheme>::advance(double t_limit) {
  if (!f_finite_) return StepStatus::non_finite;
  for (;;) {
    if (step_underflows(h_, t_)) return StepStatus::step_underflow;
    const StepFit fit = fit_step(h_, t_, t_limit, options_.h_max);
    const double h = fit.h;
    double err = scheme_.attempt(*sys_, t_, y_, f_, h, tol_, ytry_, ftry_);
    stats_.rhs_evals += Scheme::kAttemptEvals;

    // NaN or overflow from f propagates into the error estimate or y1; the step is not taken.
    if (!std::isfinite(err) || !all_finite(ytry_)) return StepStatus::non_finite;
    // After a rejection, the error model that chose this step (err ∝ h^order) predicts its error
    // from the rejected one. An estimate far below that prediction is not credible: the step is
    // outside the range where the embedded estimate holds (evidence:
    // tests/differential/corpus/dop853-accepts-a-step-on-an-incredible-estimate.json).
    if (reject_) err = std::max(err, rejected_err_ * std::pow(h / rejected_h_, Scheme::kOrder));
    if (err > 1.0) {
      h_ = control_.rejected(h, err);
      rejected_h_ = h;
      rejected_err_ = err;
      reject_ = true;
      ++stats_.rejected;
      continue;
    }

    double h_new = std::min(control_.accepted(h, err), options_.h_max);
    if (reject_) h_new = std::min(h_new, h);  // Hairer: no growth right after a rejection
    // A step shortened to fit t_limit says little about the step size: keep the proposal.
    if (fit.shortened) h_new = std::max(h_new, std::min(h_, options_.h_max));

    const double t_new = fit.lands ? t_limit : t_ + h;
    scheme_.complete(*sys_, t_new, ytry_, ftry_);
    stats_.rhs_evals += Scheme::kCompletionEvals;

    // ρ ≈ ‖f(y1) − f(y_s)‖ / ‖y1 − y_s‖ between the last stage's argument y_s and y1.
    double num = 0.0;
    double den = 0.0;
    const Vec& ys = scheme_.last_stage_y();
    const Vec& fs = scheme_.last_stage_f();
    for (int i = 0; i < n_; ++i) {
      num += (ftry_[i] - fs[i]) * (ftry_[i] - fs[i]);
      den += (ytry_[i] - ys[i]) * (ytry_[i] - ys[i]);
    }
    if (den > 0.0) {
      const double h_rho = h * std::sqrt(num / den);
      detector_.record(h_rho, Scheme::kStiffBound);
      near_bound_.record(h_rho, Scheme::kStiffBound);
    }

    t_prev_ = t_;
    t_ = t_new;
    yp_.swap(y_);  // Eigen's swap exchanges the buffers: no copy, no allocation
    y_.swap(ytry_);
    fp_.swap(f_);
    f_.swap(ftry_);
    f_finite_ = all_finite(f_);
    h_ = h_new;
    reject_ = false;
    dense_ready_ = false;
    ++stats_.steps;
    return StepStatus::ok;
  }
}

}  // namespace vibro::integrators
