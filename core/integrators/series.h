// The normalized Taylor coefficients of compositions, by the standard recursions: a series x is
// x[0..], x[k] = x^(k)(t0)/k!, and coefficient k of a composition needs the inputs up to k only.
#pragma once

#include <array>
#include <cmath>
#include <span>

namespace vibro::integrators {

// 1/k for k = 1..kReciprocals − 1 (entry 0 unused), each the double nearest 1/k: the recursions
// below multiply by it where they would divide by k, a multiplication's latency on their chains
// instead of a division's. x·(1/k) differs from x/k by at most one unit in the last place.
inline constexpr int kReciprocals = 64;
inline constexpr std::array<double, kReciprocals> kReciprocal = [] {
  std::array<double, kReciprocals> r{};
  for (int k = 1; k < kReciprocals; ++k) r[k] = 1.0 / k;
  return r;
}();

// 1/k for k >= 1: the table's entry, or the division past it.
inline double reciprocal(int k) { return k < kReciprocals ? kReciprocal[k] : 1.0 / k; }

// p(τ) = Σ_k c[k]·τ^k by Horner's rule: p ← p·τ + c[k] from the top down, starting from 0.
// Two steps per pass (the same steps, so the same bits), half the loop's overhead.
inline double horner(std::span<const double> c, double tau) {
  double p = 0.0;
  std::size_t k = c.size();
  if (k % 2 == 1) {
    --k;
    p = p * tau + c[k];
  }
  for (; k > 0; k -= 2) {
    p = p * tau + c[k - 1];
    p = p * tau + c[k - 2];
  }
  return p;
}

// Coefficient k of the product a·b (Cauchy).
inline double product_coefficient(std::span<const double> a, std::span<const double> b, int k) {
  double sum = 0.0;
  for (int j = 0; j <= k; ++j) sum += a[j] * b[k - j];
  return sum;
}

// Coefficient k >= 1 of S = sin u and C = cos u, from u[1..k] and S, C up to k − 1:
// S[k] = (1/k) Σ_{j=1..k} j·u[j]·C[k−j], C[k] = −(1/k) Σ_{j=1..k} j·u[j]·S[k−j]
// (from S' = u'·C, C' = −u'·S). Coefficient 0 is sin u[0], cos u[0].
inline void sin_cos_coefficient(std::span<const double> u, std::span<double> S, std::span<double> C,
                                int k) {
  double s = 0.0, c = 0.0;
  for (int j = 1; j <= k; ++j) {
    const double ju = j * u[j];
    s += ju * C[k - j];
    c += ju * S[k - j];
  }
  S[k] = s * reciprocal(k);
  C[k] = -c * reciprocal(k);
}

// The factors A·Ωᵏ/k! of the series of A cos(Ω(t0 + τ) + ψ) in τ, k = 0..factors.size() − 1:
// those add_cosine_series below multiplies, the same products in the same order. They depend on
// the forcing alone, so a caller that steps one forcing takes them once.
inline void cosine_series_factors(double A, double Omega, std::span<double> factors) {
  double factor = A;  // A·Ωᵏ/k!
  for (std::size_t k = 0; k < factors.size(); ++k) {
    factors[k] = factor;
    factor *= Omega * reciprocal(static_cast<int>(k) + 1);
  }
}

// The series of A cos(Ω(t0 + τ) + ψ) in τ from its factors (cosine_series_factors) and its phase
// Ωt0 + ψ, added into out[0..factors.size() − 1]: factors[k]·cos(phase + kπ/2), the cosine's
// derivatives cycling through cos, −sin, −cos, sin. The same bits as the one-call form below.
inline void add_cosine_series(std::span<const double> factors, double phase,
                              std::span<double> out) {
  const double c = std::cos(phase), s = std::sin(phase);
  const std::size_t n = factors.size();
  std::size_t k = 0;
  for (; k + 4 <= n; k += 4) {
    out[k] += factors[k] * c;
    out[k + 1] += factors[k + 1] * -s;
    out[k + 2] += factors[k + 2] * -c;
    out[k + 3] += factors[k + 3] * s;
  }
  const double cycle[4] = {c, -s, -c, s};
  for (; k < n; ++k) out[k] += factors[k] * cycle[k % 4];
}

// The series of A cos(Ω(t0 + τ) + ψ) in τ up to `order`, added into out[0..order]:
// A·Ωᵏ/k!·cos(Ωt0 + ψ + kπ/2), the cosine's derivatives cycling through cos, −sin, −cos, sin.
inline void add_cosine_series(double A, double Omega, double phase, int order,
                              std::span<double> out) {
  const double c = std::cos(phase), s = std::sin(phase);
  const double cycle[4] = {c, -s, -c, s};
  double factor = A;  // A·Ωᵏ/k!
  for (int k = 0; k <= order; ++k) {
    out[k] += factor * cycle[k % 4];
    factor *= Omega * reciprocal(k + 1);
  }
}

}  // namespace vibro::integrators
