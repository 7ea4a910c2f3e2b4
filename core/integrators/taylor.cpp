#include "core/integrators/taylor.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "core/integrators/series.h"
#include "core/integrators/step_fit.h"

namespace vibro::integrators {

int Taylor::jorba_zou_order(double rtol) {
  return static_cast<int>(std::ceil(-0.5 * std::log(rtol) + 1.0));
}

int Taylor::order_for(double rtol) {
  return std::clamp(jorba_zou_order(rtol) + kOrderAboveJorbaZou, 2, kMaxOrder);
}

double Taylor::safety_for(double rtol, int order) {
  const int p_jz = std::max(jorba_zou_order(rtol), 2);
  return std::exp(-0.7 / (order - 1)) * std::exp(-2.0 * p_jz / order);
}

Taylor::Taylor(const StepperOptions& options)
    : options_(options),
      tol_{options.atol, options.rtol, {}},
      order_(order_for(options.rtol)),
      safety_(safety_for(options.rtol, order_)),
      exponents_{1.0 / (order_ - 1), 1.0 / order_} {}

void Taylor::start(const OdeSystem& sys, double t0, const Vec& y0) {
  sys_ = &sys;
  n_ = static_cast<int>(y0.size());
  t_ = t_prev_ = t0;
  y_ = y0;
  y_next_.resize(n_);
  scale_.resize(n_);
  tol_.take_periods(sys);
  coefficients_.resize(static_cast<std::size_t>(n_) * (order_ + 1));
  poly_ = {t0, order_, coefficients_};
  stepped_ = false;
  dense_kept_ = false;
}

namespace {

// Whether every coefficient is finite. A sum of finite numbers is finite or overflows; one with
// an infinity or a NaN in it is not: only a sum that is not finite is looked at term by term.
// Two partial sums, so that the pass is short.
bool finite_coefficients(std::span<const double> c) {
  double sum[2] = {0.0, 0.0};
  std::size_t k = 0;
  for (; k + 1 < c.size(); k += 2) {
    sum[0] += c[k];
    sum[1] += c[k + 1];
  }
  if (k < c.size()) sum[0] += c[k];
  if (std::isfinite(sum[0] + sum[1])) return true;
  return std::all_of(c.begin(), c.end(), [](double x) { return std::isfinite(x); });
}

// log2 x within 0.09 for a normal x > 0: its exponent plus its mantissa less 1 (the chord of
// log2 over [1, 2), which lies below it by 0.086 at most).
double rough_log2(double x) {
  const auto bits = std::bit_cast<std::uint64_t>(x);
  const int exponent = static_cast<int>(bits >> 52) - 1023;
  const double mantissa =
      std::bit_cast<double>((bits & 0x000FFFFFFFFFFFFFull) | 0x3FF0000000000000ull);
  return exponent + (mantissa - 1.0);
}

// Which of a^ea and b^eb (a, b > 0; the exponents 1/k) is the smaller one by far more than the
// powers' round-off, judged from rough logarithms and their error bound: 0 (a's), 1 (b's), or
// −1 where that cannot be told cheaply (close, or not both normal).
int clearly_smaller(double a, double ea, double b, double eb) {
  if (!std::isnormal(a) || !std::isnormal(b) || a < 0.0 || b < 0.0) return -1;
  const double la = rough_log2(a) * ea, lb = rough_log2(b) * eb;
  const double margin = 0.1 * (ea + eb);
  return la + margin < lb ? 0 : lb + margin < la ? 1 : -1;
}

}  // namespace

double Taylor::step_size() {
  // min_i (w_i/|c_i|)^(1/k) = (min_i w_i/|c_i|)^(1/k): one power per order.
  for (int i = 0; i < n_; ++i) scale_[i] = tol_.scale(i, y_[i]);
  const int orders[2] = {order_ - 1, order_};
  double least[2];
  for (int o = 0; o < 2; ++o) {
    least[o] = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n_; ++i) {
      const double c =
          std::abs(coefficients_[static_cast<std::size_t>(i) * (order_ + 1) + orders[o]]);
      if (c > 0.0) least[o] = std::min(least[o], scale_[i] / (options_.rtol * c));
    }
  }
  // Where the two radii are clearly apart, only the smaller one's power is taken: the same
  // minimum, one power instead of two.
  if (const int o = clearly_smaller(least[0], exponents_[0], least[1], exponents_[1]); o >= 0)
    return safety_ * std::pow(least[o], exponents_[o]);
  double rho = std::numeric_limits<double>::infinity();
  for (int o = 0; o < 2; ++o)
    if (std::isfinite(least[o])) rho = std::min(rho, std::pow(least[o], exponents_[o]));
  return safety_ * rho;
}

StepStatus Taylor::step(double t_limit) {
  stepped_ = false;  // the series is overwritten: until the step is taken, dense() is y()
  dense_kept_ = false;
  if (!sys_->taylor_coefficients(t_, y_, order_, coefficients_)) return StepStatus::solver_failure;
  ++stats_.rhs_evals;
  // A coefficient that is not finite makes the step size nil or NaN (an underflow), or its
  // component's end not finite (Horner's rule carries an infinity or a NaN through): the
  // coefficients are looked at only on those paths, where they tell which failure it is.
  const StepFit fit = fit_step(step_size(), t_, t_limit, options_.h_max);
  if (step_underflows(fit.h, t_))
    return finite_coefficients(coefficients_) ? StepStatus::step_underflow : StepStatus::non_finite;
  const double t_new = fit.lands ? t_limit : t_ + fit.h;
  const double h = t_new - t_;
  const std::size_t n1 = static_cast<std::size_t>(order_) + 1;
  for (int i = 0; i < n_; ++i)
    y_next_[i] = horner(std::span<const double>(coefficients_).subspan(i * n1, n1), h);
  if (!all_finite(y_next_)) return StepStatus::non_finite;
  t_prev_ = t_;
  t_ = t_new;
  y_.swap(y_next_);
  poly_ = {t_prev_, order_, coefficients_};
  stepped_ = true;
  ++stats_.steps;
  return StepStatus::ok;
}

void Taylor::dense(double t, Vec& out) const {
  if (!stepped_) {
    out = y_;
    return;
  }
  if (dense_kept_ && t == dense_t_) {
    out = dense_y_;
    return;
  }
  out.resize(n_);
  const double tau = t - t_prev_;
  const std::size_t n1 = static_cast<std::size_t>(order_) + 1;
  for (int i = 0; i < n_; ++i)
    out[i] = horner(std::span<const double>(coefficients_).subspan(i * n1, n1), tau);
  dense_y_ = out;
  dense_t_ = t;
  dense_kept_ = true;
}

}  // namespace vibro::integrators
