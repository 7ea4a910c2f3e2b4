// Brent's root finder, the refinement of every event's time (core/events/crossing_finder.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace vibro {

// Brent's root finder on [a, b] with f(a) > 0 >= f(b); returns the smallest bracketing point
// found with f <= 0, to round-off of t, or within `tolerance` (s) of the root where that is
// larger: its last steps, of the round-off's size, each cost an evaluation.
template <class F>
double brent_root(F&& f, double a, double b, double fa, double fb, double tolerance = 0.0) {
  // Keeps [lo, hi] with f(lo) > 0 >= f(hi) and returns hi: the event is then certainly
  // reached, never reported a hair before it.
  double lo = a, hi = b, flo = fa, fhi = fb;
  double c = lo, fc = flo, d = hi - lo, e = d;
  for (int iter = 0; iter < 200; ++iter) {
    const double tol = std::max(
        tolerance, 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::abs(hi)));
    if (hi - lo <= tol || fhi == 0.0) break;
    // Brent's step from the current best point hi, with the other end lo.
    double m = 0.5 * (lo - hi);
    double p, q;
    double x;
    if (std::abs(e) >= tol && std::abs(fc) > std::abs(fhi)) {
      double s = fhi / fc;
      if (c == lo) {
        p = 2.0 * m * s;
        q = 1.0 - s;
      } else {
        const double qq = fc / flo, r = fhi / flo;
        p = s * (2.0 * m * qq * (qq - r) - (hi - c) * (r - 1.0));
        q = (qq - 1.0) * (r - 1.0) * (s - 1.0);
      }
      if (p > 0.0)
        q = -q;
      else
        p = -p;
      if (2.0 * p < std::min(3.0 * m * q - std::abs(tol * q), std::abs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = m;
        e = m;
      }
    } else {
      d = m;
      e = m;
    }
    x = hi + (std::abs(d) > tol ? d : (m > 0 ? tol : -tol) * 0.5);
    if (!(x > lo && x < hi)) x = 0.5 * (lo + hi);
    const double fx = f(x);
    c = hi;
    fc = fhi;
    if (fx > 0.0) {
      lo = x;
      flo = fx;
    } else {
      hi = x;
      fhi = fx;
    }
  }
  return hi;
}

}  // namespace vibro
