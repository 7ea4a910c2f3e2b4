#include "core/run/negative_normal.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>

#include "core/events/polynomial_roots.h"
#include "core/integrators/series.h"
#include "core/model/dynamics.h"
#include "core/model/motion.h"

namespace vibro {
namespace {

using Series = std::array<double, kMaxPolynomialDegree + 1>;
constexpr int kMaxSamples = 32;

// Σ_{k≥1} |c[k]|·h^k, by Horner's rule: how far the polynomial can move from c[0] over [0, h].
double reach(std::span<const double> c, double h) {
  double r = 0.0;
  for (std::size_t k = c.size() - 1; k >= 1; --k) r = (r + std::abs(c[k])) * h;
  return r;
}

// Whether N stays positive over [0, h], proven from the reach d of φ, which bounds its distance
// from φ at either end (|τ^k − h^k| ≤ h^k): cos φ ≥ cos φ(h) − d − d²/2 (from the end's cosine,
// which the caller has), else cos φ ≥ cos φ0 − |sin φ0|·d − d²/2 with φ̇² ≥ (|φ̇0| − the reach
// of φ̇)² where that is positive.
bool stays_positive(const Model& model, std::span<const double> phi, std::span<const double> v,
                    double h, double cos_at_h) {
  const double d = reach(phi, h);
  if (cos_at_h - d - 0.5 * d * d > 0.0) return true;
  const double lowest_cos = std::cos(phi[0]) - std::abs(std::sin(phi[0])) * d - 0.5 * d * d;
  const double slowest = std::max(0.0, std::abs(v[0]) - reach(v, h));
  return model.g * lowest_cos + model.R * slowest * slowest > 0.0;
}

// N's series g·cos φ(τ) + R·φ̇(τ)², to the polynomials' degree: cos and sin by their recursions
// (C[k] = −(1/k) Σ j·φ[j]·S[k−j], S[k] = (1/k) Σ j·φ[j]·C[k−j]), the square by a Cauchy product.
void normal_series(const Model& model, std::span<const double> phi, std::span<const double> v,
                   Series& n) {
  const int d = static_cast<int>(phi.size()) - 1;
  Series C, S;
  C[0] = std::cos(phi[0]);
  S[0] = std::sin(phi[0]);
  for (int k = 1; k <= d; ++k) {
    double s = 0.0, c = 0.0;
    for (int j = 1; j <= k; ++j) {
      s += j * phi[j] * C[k - j];
      c += j * phi[j] * S[k - j];
    }
    S[k] = s / k;
    C[k] = -c / k;
  }
  for (int k = 0; k <= d; ++k) {
    double square = 0.0;
    for (int j = 0; j <= k; ++j) square += v[j] * v[k - j];
    n[k] = model.g * C[k] + model.R * square;
  }
}

// The coefficients of p(h − σ) in σ: p shifted to h (Horner's scheme, repeated), odd powers
// negated.
void reversed(std::span<const double> p, double h, Series& r) {
  const int d = static_cast<int>(p.size()) - 1;
  std::copy(p.begin(), p.end(), r.begin());
  for (int i = 0; i < d; ++i)
    for (int j = d - 1; j >= i; --j) r[j] += h * r[j + 1];
  for (int k = 1; k <= d; k += 2) r[k] = -r[k];
}

std::optional<NegativeStretch> on_polynomials(const Model& model, const StepPolynomials& p,
                                              int pellet, double t, double cos_at_t) {
  const double h = t - p.t0;
  const std::span<const double> phi = p.component(phi_index(pellet));
  const std::span<const double> v = p.component(dphi_index(pellet));
  if (!(h > 0.0) || p.degree > kMaxPolynomialDegree || stays_positive(model, phi, v, h, cos_at_t))
    return std::nullopt;
  Series n, back;
  normal_series(model, phi, v, n);
  const std::span<const double> N(n.data(), phi.size());
  if (stays_above(N, h, 0.0)) return std::nullopt;
  const std::optional<PolynomialBracket> in = first_polynomial_crossing(N, h);
  if (!in) return std::nullopt;
  reversed(N, h, back);
  const std::optional<PolynomialBracket> out =
      first_polynomial_crossing(std::span<const double>(back.data(), N.size()), h - in->hi);
  if (!out) return std::nullopt;
  return NegativeStretch{p.t0 + in->lo, p.t0 + in->hi, t - out->hi, t - out->lo};
}

// Golden-section search for a point of [lo, hi] where n is not positive, toward n's least value
// (one minimum between two samples: the passage over the top); NaN where there is none to
// round-off.
// Whether the parabola through (−1, n0), (0, n1), (1, n2) has a least value below `level`.
bool dips(double n0, double n1, double n2, double level) {
  const double curvature = n0 - 2.0 * n1 + n2;
  if (!(curvature > 0.0)) return n1 < level;
  return n1 - (n2 - n0) * (n2 - n0) / (8.0 * curvature) < level;
}

template <class F>
double dip_below_zero(F n, double lo, double hi) {
  constexpr double kInverseGolden = 0.6180339887498949;
  double x1 = hi - kInverseGolden * (hi - lo), x2 = lo + kInverseGolden * (hi - lo);
  double n1 = n(x1), n2 = n(x2);
  for (int k = 0; k < 60 && n1 > 0.0 && n2 > 0.0 && x1 < x2; ++k) {
    if (n1 < n2) {
      hi = x2;
      x2 = x1;
      n2 = n1;
      x1 = hi - kInverseGolden * (hi - lo);
      n1 = n(x1);
    } else {
      lo = x1;
      x1 = x2;
      n1 = n2;
      x2 = lo + kInverseGolden * (hi - lo);
      n2 = n(x2);
    }
  }
  if (!(n1 > 0.0)) return x1;
  if (!(n2 > 0.0)) return x2;
  return std::numeric_limits<double>::quiet_NaN();
}

std::optional<NegativeStretch> on_samples(const Model& model, const StepView& step, int pellet,
                                          double t, int samples) {
  const double a = step.t_prev();
  samples = std::clamp(samples, 1, kMaxSamples);
  Vec y;
  const auto n = [&](double s) {
    step.dense(s, y);
    return normal_per_mass(model, y[phi_index(pellet)], y[dphi_index(pellet)]);
  };
  const auto at = [&](int k) {
    return k <= 0 ? a : k > samples ? t : a + (t - a) * k / (samples + 1);
  };
  // The first and the last sample where N is not positive; the stretch lies between their
  // neighbours (a positive sample between them is taken into it).
  std::array<double, kMaxSamples + 2> ns;
  int first = -1, last = -1, least = 1;
  for (int k = 1; k <= samples; ++k) {
    ns[k] = n(at(k));
    if (ns[k] < ns[least]) least = k;
    if (ns[k] > 0.0) continue;
    if (first < 0) first = k;
    last = k;
  }
  if (first >= 0) return NegativeStretch{at(first - 1), at(first), at(last), at(last + 1)};
  // None: near its least value N is close to a parabola (over the top, cos φ ≈ −1 + δ²/2 at a
  // nearly steady speed), so its least value is searched for only where the parabola through
  // the least sample and its neighbours dips below a quarter of that sample.
  ns[0] = least == 1 ? n(a) : 0.0;
  ns[samples + 1] = least == samples ? n(t) : 0.0;
  if (!dips(ns[least - 1], ns[least], ns[least + 1], 0.25 * ns[least])) return std::nullopt;
  const double dip = dip_below_zero(n, at(least - 1), at(least + 1));
  if (std::isnan(dip)) return std::nullopt;
  return NegativeStretch{at(least - 1), dip, dip, at(least + 1)};
}

}  // namespace

std::optional<NegativeStretch> negative_normal_inside(const Model& model, const StepView& step,
                                                      int pellet, double t, double cos_at_t,
                                                      bool near_top, int samples) {
  if (const StepPolynomials* p = step.polynomials(); p && p->t0 == step.t_prev())
    return on_polynomials(model, *p, pellet, t, cos_at_t);
  if (!near_top) return std::nullopt;
  return on_samples(model, step, pellet, t, samples);
}

}  // namespace vibro
