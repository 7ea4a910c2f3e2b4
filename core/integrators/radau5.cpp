#include "core/integrators/radau5.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/integrators/initial_step.h"
#include "core/integrators/step_fit.h"

namespace vibro::integrators {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// RADAU5's constants: nodes, error-estimate weights, eigenvalues of the inverse Radau matrix
// (u1 real, alph ± i·beta complex) and the transformation T (T⁻¹ = TI) that block-diagonalises it.
const double kSq6 = std::sqrt(6.0);
const double kC1 = (4.0 - kSq6) / 10.0;
const double kC2 = (4.0 + kSq6) / 10.0;
const double kC1m1 = kC1 - 1.0;
const double kC2m1 = kC2 - 1.0;
const double kC1mc2 = kC1 - kC2;
const double kDd1 = -(13.0 + 7.0 * kSq6) / 3.0;
const double kDd2 = (-13.0 + 7.0 * kSq6) / 3.0;
constexpr double kDd3 = -1.0 / 3.0;
const double kCbrt81 = std::cbrt(81.0);
const double kCbrt9 = std::cbrt(9.0);
const double kU1 = 30.0 / (6.0 + kCbrt81 - kCbrt9);
const double kAlph0 = (12.0 - kCbrt81 + kCbrt9) / 60.0;
const double kBeta0 = (kCbrt81 + kCbrt9) * std::sqrt(3.0) / 60.0;
const double kCno = kAlph0 * kAlph0 + kBeta0 * kBeta0;
const double kAlph = kAlph0 / kCno;
const double kBeta = kBeta0 / kCno;
constexpr double kT11 = 9.1232394870892942792e-02;
constexpr double kT12 = -0.14125529502095420843;
constexpr double kT13 = -3.0029194105147424492e-02;
constexpr double kT21 = 0.24171793270710701896;
constexpr double kT22 = 0.20412935229379993199;
constexpr double kT23 = 0.38294211275726193779;
constexpr double kT31 = 0.96604818261509293619;
constexpr double kTi11 = 4.3255798900631553510;
constexpr double kTi12 = 0.33919925181580986954;
constexpr double kTi13 = 0.54177053993587487119;
constexpr double kTi21 = -4.1787185915519047273;
constexpr double kTi22 = -0.32768282076106238708;
constexpr double kTi23 = 0.47662355450055045196;
constexpr double kTi31 = -0.50287263494578687595;
constexpr double kTi32 = 2.5719269498556054292;
constexpr double kTi33 = -0.59603920482822492497;

// RADAU5's default parameters.
constexpr int kNit = 7;          // Newton iterations per step
constexpr double kThet = 0.001;  // reuse the Jacobian while Newton contracts faster than this
constexpr double kSafe = 0.9;
constexpr double kCfac = kSafe * (1 + 2 * kNit);
constexpr double kFacl = 5.0;        // h_new/h >= 1/5
constexpr double kFacr = 1.0 / 8.0;  // h_new/h <= 8
constexpr double kQuot1 = 1.0;       // keep h (and the LU) when h_new/h is in [kQuot1, kQuot2]
constexpr double kQuot2 = 1.2;

// Our limits on unexpected rejections within one step() before giving up.
constexpr int kMaxSingular = 5;  // as RADAU5
constexpr int kMaxNewtonFailures = 10;

bool finite_nonzero_diagonal(const auto& lu) {
  for (Eigen::Index i = 0; i < lu.rows(); ++i) {
    const auto d = lu(i, i);
    if (!(std::abs(d) > 0.0) || !std::isfinite(std::abs(d))) return false;
  }
  return true;
}

}  // namespace

Radau5::Radau5(const StepperOptions& options) : options_(options) {
  // RADAU5 transforms the tolerances: its error estimate is of lower order than the method, so
  // rtol' = 0.1·rtol^(2/3) (and atol' keeps the ratio atol/rtol) makes the achieved accuracy
  // track the requested one.
  const double rtol = std::max(options.rtol, 10.0 * kEps);
  tol_.rtol = 0.1 * std::pow(rtol, 2.0 / 3.0);
  tol_.atol = tol_.rtol * (options.atol / rtol);
  fnewt_ = std::max(10.0 * kEps / tol_.rtol, std::min(0.03, std::sqrt(tol_.rtol)));
}

void Radau5::reserve(int n) {
  if (n == n_) return;
  n_ = n;
  for (Vec* v :
       {&y_,  &f_,   &y_new_, &y_prev_, &scal_, &z1_,    &z2_,    &z3_,    &w1_,        &w2_,
        &w3_, &tmp_, &ftmp_,  &f2_,     &err_,  &cont1_, &cont2_, &cont3_, &start_fix_, &dfdt_}) {
    v->resize(n);
  }
  jac_.resize(n, n);
  e1_.resize(n, n);
  e2_.resize(n, n);
  crhs_.resize(n);
  csol_.resize(n);
  lu1_ = Eigen::PartialPivLU<Mat>(n);
  lu2_ = Eigen::PartialPivLU<CMat>(n);
}

void Radau5::begin(const OdeSystem& sys, double t0, const Vec& y0) {
  reserve(static_cast<int>(y0.size()));
  sys_ = &sys;
  t_ = t_prev_ = t0;
  y_ = y0;
  tol_.take_periods(sys);
  sys.rhs(t0, y_, f_);
  ++stats_.rhs_evals;
  f_valid_ = true;
  update_scale();
  first_ = true;
  reject_ = false;
  need_jac_ = true;  // the right-hand side may have changed
  jac_fresh_ = false;
  h_lu_ = 0.0;
  h_acc_ = 0.0;
  faccon_ = 1.0;
}

void Radau5::start(const OdeSystem& sys, double t0, const Vec& y0) {
  begin(sys, t0, y0);
  const double guess = initial_step(sys, t0, y_, f_, 5, options_.h_max, tol_, tmp_, ftmp_);
  ++stats_.rhs_evals;
  h_ = first_step(h_, guess);
}

void Radau5::resume(const OdeSystem& sys, double t0, const Vec& y0, double h0) {
  begin(sys, t0, y0);
  h_ = std::min(h0, options_.h_max);
}

void Radau5::update_scale() {
  for (int i = 0; i < n_; ++i) scal_[i] = tol_.scale(i, y_[i]);
}

bool Radau5::decompose(double h) {
  const double fac1 = kU1 / h;
  const std::complex<double> fac2(kAlph / h, kBeta / h);
  for (int j = 0; j < n_; ++j) {
    for (int i = 0; i < n_; ++i) {
      e1_(i, j) = -jac_(i, j);
      e2_(i, j) = -jac_(i, j);
    }
    e1_(j, j) += fac1;
    e2_(j, j) += fac2;
  }
  lu1_.compute(e1_);
  lu2_.compute(e2_);
  ++stats_.lu_decomps;
  const bool ok =
      finite_nonzero_diagonal(lu1_.matrixLU()) && finite_nonzero_diagonal(lu2_.matrixLU());
  h_lu_ = ok ? h : 0.0;
  return ok;
}

// RADAU5's SLVRAD: one simplified-Newton correction of the transformed system. On entry z holds
// T⁻¹·(h-free stage values f(Y_i)); on exit the correction ΔW.
void Radau5::solve_stages(double h) {
  const double fac1 = kU1 / h;
  const double alphn = kAlph / h;
  const double betan = kBeta / h;
  for (int i = 0; i < n_; ++i) {
    const double s2 = -w2_[i];
    const double s3 = -w3_[i];
    z1_[i] -= w1_[i] * fac1;
    z2_[i] += s2 * alphn - s3 * betan;
    z3_[i] += s3 * alphn + s2 * betan;
  }
  tmp_ = lu1_.solve(z1_);
  z1_.swap(tmp_);
  for (int i = 0; i < n_; ++i) crhs_[i] = {z2_[i], z3_[i]};
  csol_ = lu2_.solve(crhs_);
  for (int i = 0; i < n_; ++i) {
    z2_[i] = csol_[i].real();
    z3_[i] = csol_[i].imag();
  }
}

// RADAU5's simplified-Newton loop (Hairer's radau5.f): the rate estimate, the
// divergence tests and the step-size hints are one decision, kept whole, in Hairer's order, so
// that it reads line for line beside the Fortran it was checked against.
Radau5::Newton Radau5::newton(double h, int& iterations) {
  if (first_) {
    for (Vec* v : {&z1_, &z2_, &z3_, &w1_, &w2_, &w3_}) v->setZero();
  } else {
    // Starting values from the last step's collocation polynomial, extrapolated.
    const double c3q = h / h_old_;
    const double c1q = kC1 * c3q;
    const double c2q = kC2 * c3q;
    for (int i = 0; i < n_; ++i) {
      const double ak1 = cont1_[i];
      const double ak2 = cont2_[i];
      const double ak3 = cont3_[i];
      const double z1i = c1q * (ak1 + (c1q - kC2m1) * (ak2 + (c1q - kC1m1) * ak3));
      const double z2i = c2q * (ak1 + (c2q - kC2m1) * (ak2 + (c2q - kC1m1) * ak3));
      const double z3i = c3q * (ak1 + (c3q - kC2m1) * (ak2 + (c3q - kC1m1) * ak3));
      z1_[i] = z1i;
      z2_[i] = z2i;
      z3_[i] = z3i;
      w1_[i] = kTi11 * z1i + kTi12 * z2i + kTi13 * z3i;
      w2_[i] = kTi21 * z1i + kTi22 * z2i + kTi23 * z3i;
      w3_[i] = kTi31 * z1i + kTi32 * z2i + kTi33 * z3i;
    }
  }

  faccon_ = std::pow(std::max(faccon_, kEps), 0.8);
  theta_ = kThet;
  double dynold = 0.0;
  double thqold = 0.0;
  for (iterations = 0;;) {
    if (iterations >= kNit) return Newton::diverged;
    for (int i = 0; i < n_; ++i) tmp_[i] = y_[i] + z1_[i];
    sys_->rhs(t_ + kC1 * h, tmp_, z1_);
    for (int i = 0; i < n_; ++i) tmp_[i] = y_[i] + z2_[i];
    sys_->rhs(t_ + kC2 * h, tmp_, z2_);
    for (int i = 0; i < n_; ++i) tmp_[i] = y_[i] + z3_[i];
    sys_->rhs(t_ + h, tmp_, z3_);
    stats_.rhs_evals += 3;
    for (int i = 0; i < n_; ++i) {
      const double a1 = z1_[i];
      const double a2 = z2_[i];
      const double a3 = z3_[i];
      z1_[i] = kTi11 * a1 + kTi12 * a2 + kTi13 * a3;
      z2_[i] = kTi21 * a1 + kTi22 * a2 + kTi23 * a3;
      z3_[i] = kTi31 * a1 + kTi32 * a2 + kTi33 * a3;
    }
    solve_stages(h);
    ++iterations;

    double dyno = 0.0;
    for (int i = 0; i < n_; ++i) {
      const double s = 1.0 / scal_[i];
      dyno +=
          (z1_[i] * s) * (z1_[i] * s) + (z2_[i] * s) * (z2_[i] * s) + (z3_[i] * s) * (z3_[i] * s);
    }
    dyno = std::sqrt(dyno / (3.0 * n_));
    if (!std::isfinite(dyno)) return Newton::non_finite;

    if (iterations > 1 && iterations < kNit) {
      const double thq = dyno / dynold;
      theta_ = iterations == 2 ? thq : std::sqrt(thq * thqold);
      thqold = thq;
      if (theta_ >= 0.99) return Newton::diverged;
      faccon_ = theta_ / (1.0 - theta_);
      // Predicted error after the remaining iterations: if it will not meet fnewt, give up early
      // with a step-size factor from the predicted shortfall.
      const double dyth = faccon_ * dyno * std::pow(theta_, kNit - 1 - iterations) / fnewt_;
      if (dyth >= 1.0) {
        const double qnewt = std::max(1e-4, std::min(20.0, dyth));
        hhfac_ = 0.8 * std::pow(qnewt, -1.0 / (4.0 + kNit - 1 - iterations));
        return Newton::slow;
      }
    }
    dynold = std::max(dyno, kEps);
    for (int i = 0; i < n_; ++i) {
      const double f1i = w1_[i] + z1_[i];
      const double f2i = w2_[i] + z2_[i];
      const double f3i = w3_[i] + z3_[i];
      w1_[i] = f1i;
      w2_[i] = f2i;
      w3_[i] = f3i;
      z1_[i] = kT11 * f1i + kT12 * f2i + kT13 * f3i;
      z2_[i] = kT21 * f1i + kT22 * f2i + kT23 * f3i;
      z3_[i] = kT31 * f1i + f2i;
    }
    if (faccon_ * dyno <= fnewt_) return Newton::converged;
  }
}

// RADAU5's ESTRAD: the embedded difference, filtered through (I/(h·γ0) − J)⁻¹ so that stiff
// components do not inflate it; on a first or rejected step a second filtering with one more f
// evaluation (Hairer & Wanner IV.8).
double Radau5::estimate_error(double h) {
  const double hee1 = kDd1 / h;
  const double hee2 = kDd2 / h;
  const double hee3 = kDd3 / h;
  for (int i = 0; i < n_; ++i) {
    f2_[i] = hee1 * z1_[i] + hee2 * z2_[i] + hee3 * z3_[i];
    tmp_[i] = f2_[i] + f_[i];
  }
  err_ = lu1_.solve(tmp_);
  double err = std::max(rms_norm(err_, y_, y_new_, tol_), 1e-10);
  if (err >= 1.0 && (first_ || reject_)) {
    for (int i = 0; i < n_; ++i) tmp_[i] = y_[i] + err_[i];
    sys_->rhs(t_, tmp_, ftmp_);
    ++stats_.rhs_evals;
    for (int i = 0; i < n_; ++i) tmp_[i] = ftmp_[i] + f2_[i];
    err_ = lu1_.solve(tmp_);
    err = std::max(rms_norm(err_, y_, y_new_, tol_), 1e-10);
  }
  return err;
}

void Radau5::accept(double h, double t_new) {
  // The collocation polynomial through the stages, for dense output and the next starting values.
  for (int i = 0; i < n_; ++i) {
    const double z1i = z1_[i];
    const double z2i = z2_[i];
    const double ak = (z1i - z2i) / kC1mc2;
    const double acont3 = (ak - z1i / kC1) / kC2;
    cont1_[i] = (z2i - z3_[i]) / kC2m1;
    cont2_[i] = (ak - cont1_[i]) / kC1m1;
    cont3_[i] = cont2_[i] - acont3;
  }
  // The polynomial's slope at the step's start errs by O(h³) (its interior order is the stage
  // order, 3): a watch deflated at an event, (g(t) − g(t0))/(t − t0), would read that error in
  // place of g'(t0) and see a turn that is not there (a pellet starting from rest with a
  // round-off acceleration). Adding θ(1 − θ)⁸ times the slope's error takes the slope to
  // f(t0, y0), the right-hand side's own, keeps both ends, and fades within the first tenth of
  // the step: it moves no value by more than 4 % of the slope's error times h, less than the
  // polynomial's own error.
  for (int i = 0; i < n_; ++i) {
    const double r = cont2_[i] - kC1 * cont3_[i];  // R(−1), R(s) = cont2 + (s − c1 + 1)·cont3
    const double q = cont1_[i] - kC2 * r;          // Q(−1), Q(s) = cont1 + (s − c2 + 1)·R(s)
    const double slope = q - (r - kC2 * cont3_[i]);  // dP/ds at s = −1, P(s) = y + s·Q(s)
    start_fix_[i] = (t_new - t_) * f_[i] - slope;
  }
  y_prev_ = y_;
  y_.swap(y_new_);
  t_prev_ = t_;
  t_ = t_new;
  h_old_ = h;
  first_ = false;
  jac_fresh_ = false;
  f_valid_ = false;  // evaluated by the next step: a restart after an event would waste it
  update_scale();
  stiffness_ratio_ = h * jac_norm_;
  ++stats_.steps;
}

StepStatus Radau5::step(double t_limit) {
  const StepStatus status = advance(t_limit);
  if (status != StepStatus::ok) h_ = 0.0;  // a failure's step size is no hint for a restart
  return status;
}

// One accepted step, retried until accepted or failed: RADAU5's main loop (Jacobian reuse,
// decompositions, Newton, error estimate, step control), kept whole and in Hairer's order for the
// same reason as newton().
StepStatus Radau5::advance(double t_limit) {
  if (!f_valid_) {
    sys_->rhs(t_, y_, f_);
    ++stats_.rhs_evals;
    f_valid_ = true;
  }
  if (!all_finite(f_)) return StepStatus::non_finite;
  int singular = 0;
  int diverged = 0;
  for (;;) {
    if (step_underflows(h_, t_)) return StepStatus::step_underflow;
    const StepFit fit = fit_step(h_, t_, t_limit, options_.h_max);
    const double h = fit.h;

    if (need_jac_) {
      sys_->jacobian(t_, y_, jac_, dfdt_);
      ++stats_.jac_evals;
      need_jac_ = false;
      jac_fresh_ = true;
      h_lu_ = 0.0;
      jac_norm_ = 0.0;
      for (int i = 0; i < n_; ++i) {
        double row = 0.0;
        for (int j = 0; j < n_; ++j) row += std::abs(jac_(i, j));
        jac_norm_ = std::max(jac_norm_, row);
      }
    }
    if (h != h_lu_ && !decompose(h)) {
      if (++singular >= kMaxSingular) return StepStatus::solver_failure;
      h_ = 0.5 * h;
      reject_ = true;
      ++stats_.rejected;
      if (!jac_fresh_) need_jac_ = true;
      continue;
    }

    int iterations = 0;
    Newton outcome = newton(h, iterations);
    double err = 0.0;
    if (outcome == Newton::converged) {
      for (int i = 0; i < n_; ++i) y_new_[i] = y_[i] + z3_[i];
      err = estimate_error(h);
      if (!std::isfinite(err) || !all_finite(y_new_)) outcome = Newton::non_finite;
    }
    if (outcome == Newton::non_finite) return StepStatus::non_finite;
    if (outcome != Newton::converged) {
      // RADAU5's unexpected rejection: a smaller step, and a new Jacobian unless it is current.
      reject_ = true;
      ++stats_.rejected;
      if (!jac_fresh_) need_jac_ = true;
      if (outcome == Newton::slow) {
        h_ = hhfac_ * h;
      } else {
        if (++diverged > kMaxNewtonFailures) return StepStatus::solver_failure;
        h_ = 0.5 * h;
      }
      continue;
    }

    // RADAU5's step-size selection: a slower Newton iteration makes the step more cautious.
    const double fac = std::min(kSafe, kCfac / (iterations + 2 * kNit));
    double quot = std::max(kFacr, std::min(kFacl, std::pow(err, 0.25) / fac));
    double h_new = h / quot;
    if (err >= 1.0) {
      h_ = first_ ? 0.1 * h : h_new;
      reject_ = true;
      ++stats_.rejected;
      if (!jac_fresh_) need_jac_ = true;
      continue;
    }

    if (h_acc_ > 0.0) {
      // Gustafsson's predictive controller, from the last two accepted steps.
      const double facgus = std::max(
          kFacr, std::min(kFacl, (h_acc_ / h) * std::pow(err * err / err_acc_, 0.25) / kSafe));
      quot = std::max(quot, facgus);
      h_new = h / quot;
    }
    h_acc_ = h;
    err_acc_ = std::max(1e-2, err);
    accept(h, fit.lands ? t_limit : t_ + h);

    h_new = std::min(h_new, options_.h_max);
    if (reject_) h_new = std::min(h_new, h);
    // A step shortened to fit t_limit says little about the step size: keep the proposal.
    if (fit.shortened) h_new = std::max(h_new, std::min(h_, options_.h_max));
    reject_ = false;
    // A small change of h is not worth a new factorisation while Newton converges well.
    const double qt = h_new / h;
    h_ = (theta_ <= kThet && qt >= kQuot1 && qt <= kQuot2) ? h : h_new;
    if (theta_ > kThet) need_jac_ = true;
    return StepStatus::ok;
  }
}

void Radau5::precise_state(double t, Vec& out) {
  if (!(t > t_prev_) || first_) {  // no step taken since start()
    dense(t, out);
    return;
  }
  if (!probe_) probe_ = std::make_unique<Radau5>(options_);
  const StepperStats before = probe_->stats();
  probe_->resume(*sys_, t_prev_, y_prev_, t - t_prev_);
  StepStatus status = StepStatus::ok;
  while (status == StepStatus::ok && probe_->t() < t) status = probe_->step(t);
  const StepperStats& after = probe_->stats();
  stats_.rhs_evals += after.rhs_evals - before.rhs_evals;
  stats_.jac_evals += after.jac_evals - before.jac_evals;
  stats_.lu_decomps += after.lu_decomps - before.lu_decomps;
  if (status == StepStatus::ok) {
    out = probe_->y();
  } else {
    dense(t, out);  // the probe failed where the step succeeded: the polynomial is all there is
  }
}

void Radau5::dense(double t, Vec& out) const {
  const double h = t_ - t_prev_;
  if (h <= 0.0) {
    out = y_;
    return;
  }
  out.resize(n_);
  const double s = (t - t_) / h;
  const double theta = s + 1.0;
  const double u = (1.0 - theta) * (1.0 - theta), u2 = u * u;
  const double bump = theta * u2 * u2;  // θ(1 − θ)⁸
  for (int i = 0; i < n_; ++i) {
    out[i] = y_[i] + s * (cont1_[i] + (s - kC2m1) * (cont2_[i] + (s - kC1m1) * cont3_[i])) +
             bump * start_fix_[i];
  }
}

}  // namespace vibro::integrators
