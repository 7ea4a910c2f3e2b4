// Hairer's weighted RMS norm of local error estimates, shared by all the integrators.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/ode.h"

namespace vibro::integrators {

// Per-component error scale sc_i = atol + rtol·max(|y0_i|, |y1_i|) (DOPRI5, DOP853, RADAU5).
struct Tolerance {
  double atol = 0.0;
  double rtol = 0.0;

  double scale(double y0, double y1) const {
    return atol + rtol * std::max(std::abs(y0), std::abs(y1));
  }
};

// sqrt(mean((e_i / sc_i)²)): 1 is the largest acceptable local error.
inline double rms_norm(const Vec& e, const Vec& y0, const Vec& y1, const Tolerance& tol) {
  const Eigen::Index n = e.size();
  double sum = 0.0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double r = e[i] / tol.scale(y0[i], y1[i]);
    sum += r * r;
  }
  return std::sqrt(sum / static_cast<double>(n));
}

inline bool all_finite(const Vec& v) {
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) return false;
  }
  return true;
}

}  // namespace vibro::integrators
