#include "core/events/polynomial_roots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vibro {

namespace {

using Coefficients = std::array<double, kMaxPolynomialDegree + 1>;

// Round-off of a time τ in [0, h].
double time_round_off(double h) { return 4.0 * std::numeric_limits<double>::epsilon() * h; }

// Narrows [lo, hi], p(lo) > 0 >= p(hi) (or the reverse when `falling` is false), to round-off by
// bisection: p is monotone there, so each halving keeps the one sign change.
PolynomialBracket bisect(std::span<const double> c, PolynomialBracket b, bool falling) {
  for (int k = 0; k < 200 && b.hi - b.lo > time_round_off(b.hi); ++k) {
    const double mid = 0.5 * (b.lo + b.hi);
    if (!(mid > b.lo && mid < b.hi)) break;
    const double p = polynomial_value(c, mid);
    if ((p > 0.0) == falling) {
      b.lo = mid;
      b.p_lo = p;
    } else {
      b.hi = mid;
      b.p_hi = p;
    }
  }
  return b;
}

// The real roots of p (c[0..d]) strictly inside (0, h), increasing; returns how many. Between two
// turning points (the roots of p', found the same way) p is monotone and has one root where its
// sign changes; a turning point where p is zero is a root of its own.
int roots_inside(std::span<const double> c, double h, double* roots) {
  int d = static_cast<int>(c.size()) - 1;
  while (d > 0 && c[d] == 0.0) --d;
  if (d <= 0) return 0;
  Coefficients derivative{};
  for (int k = 1; k <= d; ++k) derivative[k - 1] = k * c[k];
  std::array<double, kMaxPolynomialDegree> turns{};
  const int m = roots_inside(std::span<const double>(derivative.data(), d), h, turns.data());
  const std::span<const double> p = c.first(d + 1);
  int n = 0;
  double a = 0.0, pa = polynomial_value(p, 0.0);
  for (int i = 0; i <= m; ++i) {
    const double b = i < m ? turns[i] : h;
    const double pb = polynomial_value(p, b);
    if (pa != 0.0 && pb != 0.0 && (pa > 0.0) != (pb > 0.0)) {
      const bool falling = pa > 0.0;
      const PolynomialBracket r = bisect(p, {a, b, pa, pb}, falling);
      roots[n++] = r.hi;
    } else if (pb == 0.0 && i < m) {
      roots[n++] = b;
    }
    a = b;
    pa = pb;
  }
  return n;
}

}  // namespace

double polynomial_value(std::span<const double> c, double tau) {
  double p = 0.0;
  for (std::size_t k = c.size(); k-- > 0;) p = p * tau + c[k];
  return p;
}

std::optional<PolynomialBracket> first_polynomial_crossing(std::span<const double> c, double h,
                                                           PolynomialMinima* minima) {
  if (minima) minima->count = 0;
  if (c.empty() || static_cast<int>(c.size()) > kMaxPolynomialDegree + 1) return std::nullopt;
  const int d = static_cast<int>(c.size()) - 1;
  Coefficients derivative{}, second{};
  for (int k = 1; k <= d; ++k) derivative[k - 1] = k * c[k];
  for (int k = 2; k <= d; ++k) second[k - 2] = k * (k - 1) * c[k];
  const auto dp = std::span<const double>(derivative.data(), std::max(d, 1));
  const auto ddp = std::span<const double>(second.data(), std::max(d - 1, 1));
  std::array<double, kMaxPolynomialDegree> turns{};
  const int m = roots_inside(dp, h, turns.data());
  double a = 0.0, pa = polynomial_value(c, 0.0);
  if (!(pa > 0.0)) return std::nullopt;
  for (int i = 0; i <= m; ++i) {
    const double b = i < m ? turns[i] : h;
    const double pb = polynomial_value(c, b);
    if (pb <= 0.0) return bisect(c, {a, b, pa, pb}, true);
    const double curvature = polynomial_value(ddp, b);
    if (minima && i < m && curvature > 0.0) minima->at[minima->count++] = {b, pb, 0.5 * curvature};
    a = b;
    pa = pb;
  }
  return std::nullopt;
}

}  // namespace vibro
