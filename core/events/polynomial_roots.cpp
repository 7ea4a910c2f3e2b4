#include "core/events/polynomial_roots.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "core/events/narrow_bracket.h"
#include "core/integrators/series.h"

namespace vibro {

namespace {

using Coefficients = std::array<double, kMaxPolynomialDegree + 1>;

// k as a double, k = 0..kMaxPolynomialDegree: read from memory where a loop would convert it.
constexpr Coefficients kIndex = [] {
  Coefficients k{};
  for (int i = 0; i <= kMaxPolynomialDegree; ++i) k[i] = i;
  return k;
}();

// Round-off of a time τ in [0, h].
double time_round_off(double h) { return 4.0 * std::numeric_limits<double>::epsilon() * h; }

// Narrows [lo, hi], p(lo) > 0 >= p(hi) (or the reverse when `falling` is false), to round-off
// (narrow_bracket): some six cuts instead of bisection's fifty.
PolynomialBracket bisect(std::span<const double> c, PolynomialBracket b, bool falling) {
  const SignBracket n = narrow_bracket([&](double x) { return polynomial_value(c, x); },
                                       SignBracket{b.lo, b.hi, b.p_lo, b.p_hi}, falling,
                                       [](double hi) { return time_round_off(hi); });
  return {n.lo, n.hi, n.f_lo, n.f_hi};
}

// The Bernstein coefficients b[0..d] of p (c[0..d]) on [0, h]: those of p(h·x) on [0, 1],
// b_i = Σ_k C(i, k)·a_k with a_k = c[k]·h^k / C(d, k), the binomial sums taken by Pascal's rule.
// p lies in their convex hull, and has at most as many roots in (0, h) as they change sign.
void bernstein(std::span<const double> c, double h, Coefficients& b) {
  const int d = static_cast<int>(c.size()) - 1;
  double power = 1.0, binomial = 1.0;  // h^k, C(d, k)
  for (int k = 0; k <= d; ++k) {
    b[k] = c[k] * power / binomial;
    power *= h;
    binomial = binomial * (d - k) / (k + 1);
  }
  for (int r = 1; r <= d; ++r)
    for (int i = d; i >= r; --i) b[i] += b[i - 1];
}

// Whether every Bernstein coefficient of p (c[0..d]) on [0, h] lies above `level`: bernstein()'s
// sums, each coefficient judged as soon as it is final (b[r − 1] after Pascal's round r − 1), so
// a polynomial that dips stops at its first low coefficient with the same verdict.
bool bernstein_above(std::span<const double> c, double h, double level) {
  const int d = static_cast<int>(c.size()) - 1;
  Coefficients b;
  double power = 1.0, binomial = 1.0;  // h^k, C(d, k)
  for (int k = 0; k <= d; ++k) {
    b[k] = c[k] * power / binomial;
    power *= h;
    binomial = binomial * (d - k) / (k + 1);
  }
  for (int r = 1; r <= d; ++r) {
    if (!(b[r - 1] > level)) return false;
    for (int i = d; i >= r; --i) b[i] += b[i - 1];
  }
  return b[d] > level;
}

// The sign changes of b[0..d], zeros skipped.
int sign_changes(const Coefficients& b, int d) {
  int changes = 0, last = 0;
  for (int i = 0; i <= d; ++i) {
    const int sign = (b[i] > 0.0) - (b[i] < 0.0);
    if (sign != 0 && last != 0 && sign != last) ++changes;
    if (sign != 0) last = sign;
  }
  return changes;
}

// Whether |c[0]| exceeds Σ_{k≥1} |c[k]|·h^k by far more than round-off: then every Bernstein
// coefficient of p on [0, h] has c[0]'s sign and lies farther from zero than bernstein()'s
// round-off (each is c[0] plus a combination of the c[k]·h^k with weights in [0, 1], computed
// to a few d·ε of |c[0]| + Σ|c[k]|·h^k), so roots_inside would find no sign change: it answers
// 0 at the cost of one pass instead of the O(d²) coefficients.
bool clear_of_zero(std::span<const double> c, double h) {
  double spread = 0.0;
  for (std::size_t k = c.size() - 1; k >= 1; --k) spread = (spread + std::abs(c[k])) * h;
  const double c0 = std::abs(c[0]);
  return c0 - spread > 1e-12 * (c0 + spread);
}

// The real roots of p (c[0..d]) strictly inside (0, h), increasing; returns how many. Where p's
// Bernstein coefficients do not change sign it has none (Descartes' rule, as in the
// Vincent–Collins–Akritas scheme); where they change sign once and p's ends have opposite signs
// it has one, bracketed by the ends. Otherwise, between two turning points (the roots of p',
// found the same way) p is monotone and has one root where its sign changes; a turning point
// where p is zero is a root of its own.
int roots_inside(std::span<const double> c, double h, double* roots) {
  int d = static_cast<int>(c.size()) - 1;
  while (d > 0 && c[d] == 0.0) --d;
  if (d <= 0) return 0;
  if (clear_of_zero(c.first(d + 1), h)) return 0;
  {
    Coefficients b{};
    bernstein(c.first(d + 1), h, b);
    const int changes = sign_changes(b, d);
    if (b[0] != 0.0 && b[d] != 0.0) {
      if (changes == 0) return 0;
      const double p0 = polynomial_value(c.first(d + 1), 0.0);
      const double ph = polynomial_value(c.first(d + 1), h);
      if (changes == 1 && p0 != 0.0 && ph != 0.0 && (p0 > 0.0) != (ph > 0.0)) {
        roots[0] = bisect(c.first(d + 1), {0.0, h, p0, ph}, p0 > 0.0).hi;
        return 1;
      }
    }
  }
  Coefficients derivative;
  for (int k = 1; k <= d; ++k) derivative[k - 1] = k * c[k];
  std::array<double, kMaxPolynomialDegree> turns;
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

// Whether p stays above `level` over [0, h] by its quadratic part's least value there less a
// bound of the rest, Σ_{k≥3} |c[k]|·h^k (and a round-off allowance): tight where the motion over
// the step is nearly a parabola, as it is where c[0] − Σ |c[k]|·h^k is not (a gap closing fast).
bool quadratic_stays_above(std::span<const double> c, double h, double level) {
  const int d = static_cast<int>(c.size()) - 1;
  if (d < 2) return false;
  double rest = 0.0;
  for (int k = d; k >= 3; --k) rest = rest * h + std::abs(c[k]);
  rest *= h * h * h;
  const double c0 = c[0], c1 = c[1], c2 = c[2];
  double least = std::min(c0, c0 + h * (c1 + h * c2));
  const double vertex = -c1 / (2.0 * c2);
  if (c2 > 0.0 && vertex > 0.0 && vertex < h) least = std::min(least, c0 - c1 * c1 / (4.0 * c2));
  const double allowance = 1e-12 * (std::abs(c0) + h * (std::abs(c1) + h * std::abs(c2)));
  return least - rest - allowance > level;
}

}  // namespace

double polynomial_value(std::span<const double> c, double tau) {
  return integrators::horner(c, tau);
}

double polynomial_rate(std::span<const double> c, double tau) {
  // r ← r·τ + k·c[k] from the top down to k = 1, two steps per pass (the same steps).
  double r = 0.0;
  std::size_t k = c.size();
  if (k < 2) return r;
  if ((k - 1) % 2 == 1) {
    --k;
    r = r * tau + static_cast<double>(k) * c[k];
  }
  for (; k > 1; k -= 2) {
    r = r * tau + static_cast<double>(k - 1) * c[k - 1];
    r = r * tau + static_cast<double>(k - 2) * c[k - 2];
  }
  return r;
}

ValueAndRate polynomial_value_and_rate(std::span<const double> c, double tau) {
  // polynomial_value's steps p ← p·τ + c[k] and polynomial_rate's r ← r·τ + k·c[k], from the
  // top down, side by side in one pass.
  double p = 0.0, r = 0.0;
  for (std::size_t k = c.size(); k-- > 1;) {
    p = p * tau + c[k];
    r = r * tau + static_cast<double>(k) * c[k];
  }
  if (!c.empty()) p = p * tau + c[0];
  return {p, r};
}

bool stays_above(std::span<const double> c, double h, double level) {
  ValueAndRate end;
  return stays_above(c, h, level, end);
}

bool stays_above(std::span<const double> c, double h, double level, ValueAndRate& end) {
  const int d = static_cast<int>(c.size()) - 1;
  if (d < 0) {
    end = {};
    return false;
  }
  // Σ_{k≥1} |c[k]|·h^k beside polynomial_value_and_rate's steps, the same operations: three
  // chains in one pass, two coefficients per pass (the same steps, half the loop's overhead).
  double spread = 0.0, p = 0.0, r = 0.0;
  auto term = [&](int k, double kd) {  // kd: k as a double
    const double ck = c[k];
    spread = (spread + std::abs(ck)) * h;
    p = p * h + ck;
    r = r * h + kd * ck;
  };
  if (d > kMaxPolynomialDegree) {
    for (int k = d; k >= 1; --k) term(k, static_cast<double>(k));
  } else {
    int k = d;
    if (k % 2 == 1) {
      term(k, kIndex[k]);
      --k;
    }
    for (; k >= 2; k -= 2) {
      term(k, kIndex[k]);
      term(k - 1, kIndex[k - 1]);
    }
  }
  end = {p * h + c[0], r};
  if (d > kMaxPolynomialDegree) return false;
  if (c[0] - spread > level) return true;
  if (quadratic_stays_above(c, h, level)) return true;
  return bernstein_above(c, h, level);
}

std::optional<PolynomialBracket> first_polynomial_crossing(std::span<const double> c, double h,
                                                           PolynomialMinima* minima) {
  if (minima) minima->count = 0;
  if (c.empty() || static_cast<int>(c.size()) > kMaxPolynomialDegree + 1) return std::nullopt;
  const int d = static_cast<int>(c.size()) - 1;
  // Only the entries the spans below cover are written (a constant p's derivative is 0).
  Coefficients derivative, second;
  derivative[0] = 0.0;
  for (int k = 1; k <= d; ++k) derivative[k - 1] = k * c[k];
  const auto dp = std::span<const double>(derivative.data(), std::max(d, 1));
  const auto ddp = std::span<const double>(second.data(), std::max(d - 1, 1));
  std::array<double, kMaxPolynomialDegree> turns;
  const int m = roots_inside(dp, h, turns.data());
  // The curvature is read at the turning points only (there are some only where d >= 2).
  if (m > 0)
    for (int k = 2; k <= d; ++k) second[k - 2] = k * (k - 1) * c[k];
  double a = 0.0, pa = polynomial_value(c, 0.0);
  if (!(pa > 0.0)) return std::nullopt;
  for (int i = 0; i <= m; ++i) {
    const double b = i < m ? turns[i] : h;
    const double pb = polynomial_value(c, b);
    if (pb <= 0.0) return bisect(c, {a, b, pa, pb}, true);
    if (minima && i < m) {
      const double curvature = polynomial_value(ddp, b);
      if (curvature > 0.0) minima->at[minima->count++] = {b, pb, 0.5 * curvature};
    }
    a = b;
    pa = pb;
  }
  return std::nullopt;
}

}  // namespace vibro
