// The first crossing of a polynomial over a step, for events served by a stepper whose steps are
// polynomials (core/integrators/step_view.h). The roots are isolated between the polynomial's
// turning points (the real roots of its derivative, found the same way, degree by degree), so two
// roots inside one step, or a touch of zero between positive ends, are not stepped over.
#pragma once

#include <optional>
#include <span>

namespace vibro {

// Polynomials up to this degree are solved; a longer series is the caller's to sample instead.
inline constexpr int kMaxPolynomialDegree = 31;

// p(τ) = Σ_k c[k]·τ^k by Horner's rule.
double polynomial_value(std::span<const double> c, double tau);
// p'(τ), by Horner's rule on the derivative's coefficients k·c[k].
double polynomial_rate(std::span<const double> c, double tau);

// Both, in one pass: the same values to the bit.
struct ValueAndRate {
  double value = 0.0, rate = 0.0;
};
ValueAndRate polynomial_value_and_rate(std::span<const double> c, double tau);

// Whether p stays above `level` over [0, h], proven by a bound: c[0] − Σ_{k≥1} |c[k]|·h^k
// first, then its quadratic part's least value on [0, h] less Σ_{k≥3} |c[k]|·h^k, then the least
// of p's Bernstein coefficients on [0, h] (p lies in their convex hull).
// A step far from the watch's root costs a pass or two over its coefficients, not the
// isolation of its roots; false says nothing.
bool stays_above(std::span<const double> c, double h, double level);
// The same, and p's value and rate at h into `end` (polynomial_value_and_rate's, to the bit)
// from the first bound's pass over c: the end a step that stays above moves its watch to.
bool stays_above(std::span<const double> c, double h, double level, ValueAndRate& end);

// Where p first falls to zero or below on (0, h], given p(0) > 0: a bracket [lo, hi] with
// p(lo) > 0 >= p(hi), hi − lo within round-off of the root's time (or hi the turning point where
// p touches zero). `minimum` receives the turning points before it where p has a local minimum
// above zero (the near misses), in order; it may be null.
struct PolynomialBracket {
  double lo = 0.0, hi = 0.0, p_lo = 0.0, p_hi = 0.0;
};
struct PolynomialMinimum {
  double tau, value, half_curvature;  // no initializers: PolynomialMinima's array stays unwritten
};
// The local minima of p inside (0, h) with p > 0 before the first crossing, at most
// kMaxPolynomialDegree of them: at[0..count − 1] (the entries past count are not initialized,
// so that a search that finds few minima does not clear the whole array first).
struct PolynomialMinima {
  int count = 0;
  PolynomialMinimum at[kMaxPolynomialDegree];
};
std::optional<PolynomialBracket> first_polynomial_crossing(std::span<const double> c, double h,
                                                           PolynomialMinima* minima = nullptr);

}  // namespace vibro
